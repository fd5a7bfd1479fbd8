// Rim edges of a mesh against polyhedra (issue 20: "face, edge and vertex regions" for convex
// polyhedra; polyhedron_shape.hpp collide_mesh):
// - a cube tipped over the open edge of a mesh table, its face pressed by the edge, gets one
//   edge contact: the overlap the placement gave, the face's normal, the point on the edge;
//   raised clear of it, none;
// - a cube lying flat across that edge meets the table through its vertices only (one contact of
//   the right depth: the edge under a flush face is not a second one);
// - a vertex that came round the open edge (the line from the centre crosses the table's plane
//   beyond it) is not pushed up through the table;
// - a cube laid flat over a table's edge (0.8 of its half-width beyond it), on a mesh or a planar
//   table, settles flat (the edge under the face is part of the table's contact);
// - a cube dropped flat onto a roof's ridge (two 15-degree slopes: a convex edge) is held by the
//   ridge: at rest the ridge reaches at most a few static overlaps into it (without the edge
//   contact the ridge cut in to where the slopes held its vertices, ~27% of the half edge).
#include <boost/test/unit_test.hpp>
#include <cmath>
#include "blaze/shapes/polyhedron_shape.hpp"
#include "blaze/shapes/shape_io.hpp"
#include "verification/report.hpp"
#include "verification/scenes.hpp"
#include "verification/tolerances.hpp"
#include "verification/wall_scenes.hpp"

using namespace blaze;
using namespace blaze::test;

namespace {

const char* const kCase = "Mesh rims (issue 20)";

// A mesh held as the kernels read it (WorldStore's arrays, on the host).
struct HostMesh {
  MeshArrays<double> a;
  MeshSurfaceView<double> view;
  MeshObject<double> object;
  HostMesh(const TriangleMesh& mesh, double reach) : a(mesh_arrays<double>({MeshWall{"m", mesh, 1}}, reach)) {
    view = {a.vertex.data(), a.triangle.data(), a.neighbour.data(), a.adjacency_start.data(), a.adjacency.data(), a.normal.data()};
    object = a.objects[0];
    object.bins.start = a.bin_start.data();
    object.bins.entry = a.bin_entry.data();
  }
  MeshContacts<double, 4, PatchGeometry<double>> contacts(const PolyhedronShape<double>& shape, const PolyhedronShape<double>::Body& b) const {
    MeshContacts<double, 4, PatchGeometry<double>> out;
    shape.collide_mesh(b, view, object, nullptr, out);
    return out;
  }
};

// The table: a square of half-width 0.05 m at y = 0, normal +y, two triangles (open edges all round).
TriangleMesh table() { return mesh_of({{-0.05, 0, -0.05}, {0.05, 0, -0.05}, {0.05, 0, 0.05}, {-0.05, 0, 0.05}}, {{0, 2, 1}, {0, 3, 2}}); }

}  // namespace

BOOST_AUTO_TEST_SUITE(mesh_rims)

BOOST_AUTO_TEST_CASE(an_open_edge_pushes_into_a_tipped_face) {
  PolyhedronShape<double> shape;
  shape.table.add(load_scaled_shape("data/shapes/cube.shape", 0.01), 2500);
  const double h = 0.01 / std::sqrt(3.0);  // half the edge
  const HostMesh mesh(table(), 0.02);
  double worst = 0;
  for (const double degrees : {5.0, 20.0, 40.0})
    for (const double delta : {1e-6, 1e-4, 5e-4}) {
      const double th = degrees * kPi / 180;
      // the face's outward normal d turned from -y towards -x by th: the face falls towards +x, over the edge
      const Vec3<double> d{-std::sin(th), -std::cos(th), 0}, u{std::cos(th), -std::sin(th), 0}, edge{0.05, 0, 0.002};
      const Quat<double> q = face_turn(shape.table.type[0], d, {0, 0, 1});
      // the edge line inside the face's plane by delta, under the face 0.3 h from its middle (centre over the table)
      const Vec3<double> c = edge - d * (h - delta) - u * (0.3 * h);
      const auto g = mesh.contacts(shape, {c, q, 0, 0});
      BOOST_TEST_REQUIRE(g.count == 1);
      const auto& k = g.contact[0];
      BOOST_TEST((k.kind == ContactKind::edge_edge));
      worst = std::max({worst, std::fabs(k.overlap - delta) / h, norm(k.normal - d), std::fabs(k.point.x - 0.05) / h,
                        std::fabs(k.point.y) / h, std::fabs(k.point.z - c.z) / h});
      BOOST_TEST(mesh.contacts(shape, {c + d * (-2 * delta), q, 0, 0}).count == 0);  // raised clear by delta
    }
  check_at_most({kCase, "cube tipped over a mesh table's open edge: |overlap - delta|, |n - n_face|, point off the edge (over h)", "-",
                 "the edge pushes into the face (rounding)"},
                worst, tol::geometry_double);
}

BOOST_AUTO_TEST_CASE(a_flat_face_over_an_edge_meets_the_table_through_its_vertices) {
  PolyhedronShape<double> shape;
  shape.table.add(load_scaled_shape("data/shapes/cube.shape", 0.01), 2500);
  const double h = 0.01 / std::sqrt(3.0);
  const HostMesh mesh(table(), 0.02);
  const Quat<double> flat = face_turn(shape.table.type[0], {0, -1, 0}, {0, 0, 1});
  for (const double over : {0.2, 0.5, 0.8}) {  // how far the face reaches past the edge (of its width 2h)
    const double delta = 1e-4;
    const Vec3<double> c{0.05 + (2 * over - 1) * h, h - delta, 0};
    const auto g = mesh.contacts(shape, {c, flat, 0, 0});
    BOOST_TEST_REQUIRE(g.count == 1);
    BOOST_TEST((g.contact[0].kind == ContactKind::vertex_face));
    BOOST_TEST(g.contact[0].overlap == delta, boost::test_tools::tolerance(tol::geometry_double));
    BOOST_TEST(g.contact[0].normal.y == -1.0);
  }
}

BOOST_AUTO_TEST_CASE(a_vertex_round_an_open_edge_is_not_pushed_through_the_table) {
  PolyhedronShape<double> shape;
  shape.table.add(load_scaled_shape("data/shapes/cube.shape", 0.01), 2500);
  const double h = 0.01 / std::sqrt(3.0);
  const HostMesh mesh(table(), 0.02);
  // tipped 70 degrees past the edge, centre beyond it and half an edge above the plane: its
  // lowest vertices (c + h (d + u) +- h z) hook back under the table
  const double th = 70 * kPi / 180;
  const Vec3<double> d{-std::sin(th), -std::cos(th), 0}, u{std::cos(th), -std::sin(th), 0};
  const Quat<double> q = face_turn(shape.table.type[0], d, {0, 0, 1});
  const Vec3<double> c{0.05 + 0.3 * h, 0.5 * h, 0};
  const Vec3<double> low = c + (d + u) * h;
  BOOST_TEST_REQUIRE(low.y < 0);     // below the table
  BOOST_TEST_REQUIRE(low.x < 0.05);  // its foot on it
  const auto g = mesh.contacts(shape, {c, q, 0, 0});
  BOOST_TEST(g.count >= 1);  // the edge inside the body
  for (int k = 0; k < g.count; ++k) {
    BOOST_TEST_MESSAGE("round the edge: contact " << k << " kind " << int(g.contact[k].kind) << " overlap " << g.contact[k].overlap);
    BOOST_TEST((g.contact[k].kind == ContactKind::edge_edge));  // the edge in the face, not the vertex through the table
  }
}

BOOST_AUTO_TEST_CASE(a_cube_dropped_on_a_ridge_is_held_by_it) {
  PolyhedronShape<double> shape;
  shape.table.add(load_scaled_shape("data/shapes/cube.shape", 0.01), 2500);
  const double h = 0.01 / std::sqrt(3.0), slope = std::tan(15 * kPi / 180), w = 0.06;
  World<double> world;  // a roof along z: the ridge at x = 0, y = 0, slopes falling 15 degrees to x = +-w
  world.meshes.push_back({"roof", mesh_of({{-w, -w * slope, -w}, {0, 0, -w}, {w, -w * slope, -w}, {-w, -w * slope, w}, {0, 0, w}, {w, -w * slope, w}},
                                          {{0, 4, 1}, {0, 3, 4}, {1, 5, 2}, {1, 4, 5}}),
                          1});
  auto normal = LinearSpringDashpot<double>::from_restitution(2e4, 0.2);
  normal.no_tension = true;
  const LinearSpringLaw<double> law{normal, TangentialSpring<double>::linear(0.6, 2.0 / 7.0 * 2e4, normal.beta)};  // holds on 15 degrees
  ParticleState<double> p;
  const Quat<double> flat = face_turn(shape.table.type[0], {0, -1, 0}, {0, 0, 1});
  add_polyhedron(p, shape.table, 0, Vec3<double>{0.05 * h, h + 2e-4, 0}, flat, 0);
  Simulation<DefaultSpace, PolyhedronShape<double>, LinearSpringLaw<double>, VelocityVerlet, ContactPointVelocity, FullFeatures> sim(
      params<double>(2e-6, {0, -9.81, 0}, 0.2, 1e-3), one_law(law), world, p, shape);
  sim.run(250000);  // 0.5 s
  const auto st = sim.state();
  BOOST_TEST_REQUIRE(st.size() == 1u);
  // how far the ridge line reaches into the cube at rest (rim_in_body: its deepest point's least depth)
  double depth = 0;
  Vec3<double> n{0, 0, 0}, at{0, 0, 0};
  PolyhedronShape<double>::rim_in_body({st.position[0], st.orientation[0], 0, 0}, shape.table.type[0],
                                       Mat3<double>::rotation(st.orientation[0]), {0, 0, -w}, {0, 0, w}, depth, n, at);
  const double static_overlap = 2500 * 8 * h * h * h * 9.81 / 2e4;  // m g / k
  BOOST_TEST_MESSAGE("cube on a ridge: ridge depth " << depth << " m (m g / k " << static_overlap << "), centre " << st.position[0].x << ", "
                                                     << st.position[0].y << ", speed " << norm(st.velocity[0]));
  BOOST_TEST(norm(st.velocity[0]) < 1e-3);
  check_at_most({kCase, "cube dropped flat on a 15-degree ridge, at rest: the ridge's depth in it over m g / k", "-",
                 "held by the ridge (tol::mesh_rim_ridge_depth)"},
                depth / static_overlap, tol::mesh_rim_ridge_depth);
}

// A cube laid flat over a table's edge, its centre over the table by 0.2 h (0.8 h of its face beyond
// the edge), settles flat: the edge under the face is part of the table's contact, on a mesh table
// (an open edge) and on a planar polygon (an active rim edge) alike.
BOOST_AUTO_TEST_CASE(a_cube_over_a_table_edge_rests_flat) {
  PolyhedronShape<double> shape;
  shape.table.add(load_scaled_shape("data/shapes/cube.shape", 0.01), 2500);
  const double h = 0.01 / std::sqrt(3.0);
  auto normal = LinearSpringDashpot<double>::from_restitution(2e4, 0.2);
  normal.no_tension = true;
  const LinearSpringLaw<double> law{normal, TangentialSpring<double>::linear(0.6, 2.0 / 7.0 * 2e4, normal.beta)};
  const Quat<double> flat = face_turn(shape.table.type[0], {0, -1, 0}, {0, 0, 1});
  Vec3<double> rest[2];
  for (const bool as_mesh : {true, false}) {
    World<double> world;
    if (as_mesh) world.meshes.push_back({"table", table(), 1});
    else world.polygons.push_back(PlanarPolygon<double>::make({{-0.05, 0, 0.05}, {0.05, 0, 0.05}, {0.05, 0, -0.05}, {-0.05, 0, -0.05}}, 1));
    ParticleState<double> p;
    add_polyhedron(p, shape.table, 0, Vec3<double>{0.05 - 0.2 * h, h + 1e-4, 0}, flat, 0);
    Simulation<DefaultSpace, PolyhedronShape<double>, LinearSpringLaw<double>, VelocityVerlet, ContactPointVelocity, FullFeatures> sim(
        params<double>(2e-6, {0, -9.81, 0}, 0.2, 1e-3), one_law(law), world, p, shape);
    sim.run(150000);  // 0.3 s
    const auto st = sim.state();
    BOOST_TEST_REQUIRE(st.size() == 1u);
    // the tilt: the angle between the face that was down and -y
    const Vec3<double> down = rotate(st.orientation[0], shape.table.type[0].normal[0]);  // face_turn took normal[0] down
    const double tilt = std::acos(std::fmin(1.0, -down.y)) * 180 / kPi;
    const double static_overlap = 2500 * 8 * h * h * h * 9.81 / 2e4;
    BOOST_TEST_MESSAGE((as_mesh ? "mesh" : "planar") << " table: tilt " << tilt << " deg, centre " << st.position[0].x << ", "
                                                     << st.position[0].y - h << " (m g / k " << static_overlap << "), speed " << norm(st.velocity[0]));
    check_at_most({kCase, std::string("cube flat over the edge of a ") + (as_mesh ? "mesh" : "planar") + " table, at rest: tilt (degrees)", "-",
                   "rests flat on the table and its edge (tol::mesh_rim_flat_tilt)"},
                  tilt, tol::mesh_rim_flat_tilt);
    rest[as_mesh] = st.position[0];
  }
  // one algorithm for a rim edge under a flush face: the same rest on both tables (the planar
  // wall's deeper-of-two rule left this cube creeping at 2e-7 m/s, 3e-7 m from the mesh's rest)
  check_at_most({kCase, "cube flat over a table's edge: |rest on the mesh table - rest on the planar table| / h", "-",
                 "the same contacts (tol::mesh_rim_same_rest)"},
                norm(rest[1] - rest[0]) / h, tol::mesh_rim_same_rest);
}

BOOST_AUTO_TEST_SUITE_END()
