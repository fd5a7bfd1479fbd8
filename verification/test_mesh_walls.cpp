// Triangle-mesh walls in the simulation (issue 20; blaze/world/mesh_wall.hpp, kernels/
// world_contacts.hpp): a mesh is one world object whose triangles are found through its bins and
// whose contacts are merged per point of the surface.
// - A flat square tessellated into 800 triangles (interior vertices jittered in the plane) moves
//   spheres as the one polygon does: spheres bouncing, sliding and rolling across hundreds of
//   triangle edges and vertices down a tilted gravity, history-free and with a Mindlin spring,
//   agree with the polygon's run to 1e-9 of their travel (double). With the spring this needs the
//   contact's history handed from triangle to triangle (kernels/contact_history.hpp): reset at
//   every crossing, a rolling sphere's static friction would drop and the runs part.
// - The same plate moving (vibrating, turning) as a mesh and as a polygon: the same trajectories.
// - A sphere dropped on a pyramid's apex (a vertex) and on a tent's ridge (an edge) rebounds
//   straight up (the contact normal is vertical there); one dropped off-centre into a valley
//   (a crease) settles on its axis at the height two Hertz overlaps give.
// - World lists on and off, and a checkpoint restart, change nothing (bitwise, Mindlin).
// - Cubes slide and tumble over the tessellated plate as over the polygon (a vertex counts once
//   per plane), and one settles in a valley on both faces at the height two overlaps give.
#include <boost/test/unit_test.hpp>
#include <cmath>
#include <random>
#include <sstream>
#include "blaze/shapes/polyhedron_shape.hpp"
#include "blaze/shapes/shape_io.hpp"
#include "verification/report.hpp"
#include "verification/scenes.hpp"
#include "verification/tolerances.hpp"
#include "verification/wall_scenes.hpp"

using namespace blaze;
using namespace blaze::test;

namespace {

const char* const kCase = "Mesh walls (issue 20)";

// The square [-a, a]^2 in the plane z = 0, normal +z, as nx x nx cells of two triangles
// (diagonals alternating), interior vertices moved in the plane by up to `jitter` of a cell.
TriangleMesh flat_grid(double a, int nx, double jitter, unsigned seed) {
  TriangleMesh m;
  std::mt19937_64 rng(seed);
  std::uniform_real_distribution<double> u(-1, 1);
  const double h = 2 * a / nx;
  for (int j = 0; j <= nx; ++j)
    for (int i = 0; i <= nx; ++i) {
      const bool inner = i > 0 && i < nx && j > 0 && j < nx;
      const double dx = inner ? jitter * h * u(rng) : 0, dy = inner ? jitter * h * u(rng) : 0;
      m.vertices.push_back({-a + i * h + dx, -a + j * h + dy, 0});
    }
  const auto at = [&](int i, int j) { return j * (nx + 1) + i; };
  for (int j = 0; j < nx; ++j)
    for (int i = 0; i < nx; ++i) {
      const int p = at(i, j), q = at(i + 1, j), r = at(i + 1, j + 1), s = at(i, j + 1);
      if ((i + j) % 2 == 0) m.triangles.push_back({p, q, r}), m.triangles.push_back({p, r, s});
      else m.triangles.push_back({p, q, s}), m.triangles.push_back({q, r, s});
    }
  return m;
}

template <class Real>
World<Real> plate_world(bool as_mesh, double a, int nx, double jitter = 0.3) {
  World<Real> w;
  if (as_mesh) w.meshes.push_back({"plate", flat_grid(a, nx, jitter, 5), 1});
  else w.polygons.push_back(PlanarPolygon<Real>::make({{-a, -a, 0}, {a, -a, 0}, {a, a, 0}, {-a, a, 0}}, 1));
  return w;
}

// Spheres in lanes along y (no two meet), just above the plate, each with its own velocity and
// spin: some bounce, some slide, some roll.
template <class Real>
ParticleState<Real> lane_spheres(double r) {
  ParticleState<Real> s;
  std::mt19937_64 rng(11);
  std::uniform_real_distribution<double> u(-1, 1);
  for (int k = 0; k < 12; ++k) {
    const double y = -0.33 + 0.06 * k;
    const Vec3<double> x{-0.3 + 0.05 * u(rng), y, r * (k % 3 == 0 ? 1.5 : 0.995)};
    const Vec3<double> v{0.4 + 0.3 * u(rng), 0.02 * u(rng), k % 3 == 0 ? -0.3 : 0.0};
    const Vec3<double> w{0, (k % 2 ? 1 : -1) * 20 * u(rng), 5 * u(rng)};
    s.add_sphere(vec_cast<Real>(x), Real(r), Real(2500), 0, vec_cast<Real>(v));
    s.angular_velocity.back() = vec_cast<Real>(w);
  }
  return s;
}

// Spheres rolling and sliding along the grid lines x = -a + i h of an unjittered plate (the edges
// between cells), starting on vertices and mid-edge: each sits over an edge or a vertex the whole
// way, where two to six triangles offer it the same contact (merged into one: MeshContacts).
template <class Real>
ParticleState<Real> line_spheres(double r, double a, int nx) {
  ParticleState<Real> s;
  const double h = 2 * a / nx;
  for (int k = 0; k < 8; ++k) {
    const int i = 2 + 2 * k;
    const Vec3<double> x{-a + i * h, -a + (3 + (k % 2) * 0.5) * h, r * 0.999};
    s.add_sphere(vec_cast<Real>(x), Real(r), Real(2500), 0, vec_cast<Real>(Vec3<double>{0, 0.2 + 0.1 * k, 0}));
    s.angular_velocity.back() = vec_cast<Real>(Vec3<double>{k % 3 == 0 ? -(0.2 + 0.1 * k) / r : 0.0, 0, 0});
  }
  return s;
}

template <class Law>
using MeshSim = Simulation<DefaultSpace, SphereShape, Law, VelocityVerlet, ContactPointVelocity, FullFeatures>;

// Row of each particle id in a state (states come in memory order).
template <class Real>
std::vector<std::size_t> rows(const ParticleState<Real>& s) {
  std::vector<std::size_t> r(s.size());
  for (std::size_t k = 0; k < s.size(); ++k) r[static_cast<std::size_t>(s.id[k])] = k;
  return r;
}

// max over spheres of (|x_a - x_b| + |v_a - v_b| 0.01 s) / (their travel + r), and the largest
// travel (start: ids in order).
template <class Real>
std::pair<double, double> parting(const ParticleState<Real>& a, const ParticleState<Real>& b, const ParticleState<Real>& start) {
  double worst = 0, travel = 0;
  BOOST_TEST_REQUIRE(a.size() == start.size());
  BOOST_TEST_REQUIRE(b.size() == start.size());
  const auto ra = rows(a), rb = rows(b);
  for (std::size_t id = 0; id < start.size(); ++id) {
    const std::size_t i = ra[id], j = rb[id];
    const double t = norm(vec_cast<double>(a.position[i] - start.position[id]));
    travel = std::fmax(travel, t);
    const double d = norm(vec_cast<double>(a.position[i] - b.position[j])) + norm(vec_cast<double>(a.velocity[i] - b.velocity[j])) * 0.01;
    worst = std::fmax(worst, d / (t + static_cast<double>(a.radius[i])));
  }
  return {worst, travel};
}

template <class Law>
void flat_mesh_as_polygon(const Law& law, const std::string& name, double seconds) {
  using Real = typename Law::real_type;
  const double r = 0.02, dt = 2e-5;
  const auto start = lane_spheres<Real>(r);
  std::vector<ParticleState<Real>> out;
  long builds = 0;
  for (bool as_mesh : {false, true}) {
    MeshSim<Law> sim(params<Real>(dt, {2.0, 0, -9.81}, 0.6, 0.2 * r), one_law(law), plate_world<Real>(as_mesh, 0.5, 20), start);
    sim.run(static_cast<std::uint64_t>(std::llround(seconds / dt)));
    out.push_back(sim.state());
    builds = static_cast<long>(sim.neighbour_builds());
  }
  const auto [worst, travel] = parting(out[1], out[0], start);
  BOOST_TEST_MESSAGE("flat mesh vs polygon, " << name << ": " << worst << " of the travel (" << travel << " m, "
                                             << travel / 0.05 << " cells; " << builds << " rebuilds)");
  BOOST_TEST(travel > 0.5);  // across 10 cells or more: hundreds of edges and vertices in all
  for (std::size_t k = 0; k < start.size(); ++k) BOOST_TEST(out[0].position[k].z < Real(1.01 * r));  // on the plate at the end
  const double limit = sizeof(Real) == 8 ? tol::mesh_walls_flat_trajectory : tol::mesh_walls_flat_trajectory_float;
  check_at_most({kCase, "spheres rolling, sliding and bouncing over 800 triangles vs one polygon, " + name +
                            ": max |x_mesh - x_polygon| / travel",
                 "-", "one contact per surface point (mesh_surface.hpp)"},
                worst, limit);
  // along the edges of an unjittered grid
  const double a = 0.5;
  const auto on_lines = line_spheres<Real>(r, a, 20);
  out.clear();
  for (bool as_mesh : {false, true}) {
    MeshSim<Law> sim(params<Real>(dt, {0, 1.5, -9.81}, 0.6, 0.2 * r), one_law(law), plate_world<Real>(as_mesh, a, 20, 0), on_lines);
    sim.run(static_cast<std::uint64_t>(std::llround(seconds / dt)));
    out.push_back(sim.state());
  }
  const auto [worst_lines, travel_lines] = parting(out[1], out[0], on_lines);
  BOOST_TEST_MESSAGE("along the grid lines, " << name << ": " << worst_lines << " of the travel (" << travel_lines << " m)");
  BOOST_TEST(travel_lines > 0.3);
  const auto row = rows(out[1]);
  for (std::size_t k = 0; k < on_lines.size(); ++k) BOOST_TEST(out[1].position[row[k]].x == on_lines.position[k].x);  // still on its line
  check_at_most({kCase, "spheres rolling along mesh edges and over vertices vs one polygon, " + name + ": max |x_mesh - x_polygon| / travel",
                 "-", "offers of one surface point merged (mesh_surface.hpp)"},
                worst_lines, limit);
}

// The plate moving: one motion for the polygon and the mesh.
template <class Law>
void moving_plate_as_polygon(const Law& law, const Motion& motion, const std::string& name) {
  using Real = typename Law::real_type;
  const double r = 0.02, dt = 2e-5;
  const auto start = lane_spheres<Real>(r);
  std::vector<ParticleState<Real>> out;
  for (bool as_mesh : {false, true}) {
    World<Real> w = plate_world<Real>(as_mesh, 0.5, 20);
    w.motions = {motion};
    MeshSim<Law> sim(params<Real>(dt, {0, 0, -9.81}, 0.7, 0.2 * r), one_law(law), w, start);
    BOOST_TEST_REQUIRE(sim.world_moves());
    sim.run(static_cast<std::uint64_t>(std::llround(0.3 / dt)));
    out.push_back(sim.state());
  }
  const auto [worst, travel] = parting(out[1], out[0], start);
  BOOST_TEST_MESSAGE(name << " plate, mesh vs polygon: " << worst << " of the travel (" << travel << " m)");
  BOOST_TEST(travel > 0.05);
  check_at_most({kCase, "spheres on a " + name + " plate, 800 triangles vs one polygon: max |x_mesh - x_polygon| / travel", "-",
                 "the mesh's pose moves the particle into its frame (mesh_wall.hpp)"},
                worst, tol::mesh_walls_flat_trajectory);
}

// A mesh of the given triangles over the vertices.
// A sphere dropped straight down on a vertex or an edge of a convex mesh rebounds straight up.
void drop_on(const TriangleMesh& mesh, const Vec3<double>& above, const std::string& feature) {
  using Law = HertzLaw<double>;
  const double r = 0.01;
  const Law law{Hertz<double>::from_restitution(1e9, 0.8), HistoryFreeFriction<double>::make(0.3, 0)};
  World<double> w;
  w.meshes.push_back({feature, mesh, 1});
  ParticleState<double> s;
  s.add_sphere(above + Vec3<double>{0, 0, r + 0.002}, r, 2500, 0, Vec3<double>{0, 0, -0.5});
  MeshSim<Law> sim(params<double>(1e-6, {0, 0, 0}, 0.2, 1e-3), one_law(law), w, s);
  sim.run(12000);  // 4 ms to contact, the impact, and away
  const auto st = sim.state();
  const Vec3<double> v = st.velocity[0];
  BOOST_TEST_REQUIRE(v.z > 0.3);  // rebounded (e = 0.8)
  BOOST_TEST_MESSAGE("dropped on a " << feature << ": v = (" << v.x << ", " << v.y << ", " << v.z << ")");
  check_at_most({kCase, "sphere dropped on a mesh " + feature + ": |v_horizontal| / |v| after the rebound", "-",
                 "the contact normal at a vertex or a convex edge is x - p (vertical here)"},
                std::hypot(v.x, v.y) / norm(v), tol::mesh_walls_feature_normal);
}

}  // namespace

BOOST_AUTO_TEST_SUITE(mesh_walls)

BOOST_AUTO_TEST_CASE(flat_mesh_moves_spheres_as_one_polygon) {
  const auto hertz = Hertz<double>::from_restitution(2e8, 0.5);
  const double g_star = 2e8 / (2 * (1 - 0.25)) / 2.5;  // Poisson 0.25 (E* to G*)
  flat_mesh_as_polygon(HertzLaw<double>{hertz, HistoryFreeFriction<double>::make(0.3, 50)}, "Hertz, history-free friction", 0.6);
  flat_mesh_as_polygon(HertzMindlinLaw<double>{hertz, TangentialSpring<double>::mindlin(0.3, g_star, 0.5)}, "Hertz-Mindlin", 0.6);
  const auto hertz_f = Hertz<float>::from_restitution(2e8, 0.5);
  flat_mesh_as_polygon(HertzMindlinLaw<float>{hertz_f, TangentialSpring<float>::mindlin(0.3, g_star, 0.5)}, "Hertz-Mindlin, float", 0.6);
}

BOOST_AUTO_TEST_CASE(moving_mesh_moves_spheres_as_one_polygon) {
  const auto hertz = Hertz<double>::from_restitution(2e8, 0.5);
  const double g_star = 2e8 / (2 * (1 - 0.25)) / 2.5;
  const HertzMindlinLaw<double> law{hertz, TangentialSpring<double>::mindlin(0.4, g_star, 0.5)};
  Motion shake;
  shake.kind = MotionKind::vibration, shake.amplitude = 2e-3, shake.frequency = 25, shake.direction = {0, 0.3, 1};
  shake.direction = shake.direction * (1 / norm(shake.direction));
  moving_plate_as_polygon(law, shake, "vibrating");
  Motion turn;
  turn.kind = MotionKind::rotation, turn.axis = {0, 0, 1}, turn.point = {0.05, 0, 0}, turn.omega = 3, turn.ramp = 0.05;
  moving_plate_as_polygon(law, turn, "turning");
}

BOOST_AUTO_TEST_CASE(sphere_on_a_vertex_and_a_ridge_rebounds_along_the_vertical) {
  // a square pyramid, apex at the origin, faces sloping down at 20 degrees
  const double s = 0.05, drop = s * std::tan(20 * kPi / 180);
  drop_on(mesh_of({{0, 0, 0}, {s, s, -drop}, {-s, s, -drop}, {-s, -s, -drop}, {s, -s, -drop}}, {{0, 4, 1}, {0, 1, 2}, {0, 2, 3}, {0, 3, 4}}),
          {0, 0, 0}, "vertex (pyramid apex)");
  // a tent: two faces meeting along the y axis, split into triangles differently on each side
  drop_on(mesh_of({{0, -s, 0}, {0, 0, 0}, {0, s, 0}, {s, -s, -drop}, {s, s, -drop}, {-s, -s, -drop}, {-s, s, -drop}},
                  {{0, 3, 4}, {0, 4, 1}, {1, 4, 2}, {0, 1, 5}, {1, 6, 5}, {1, 2, 6}}),
          {0, 0.013, 0}, "edge (tent ridge, over a vertex of one side)");
}

BOOST_AUTO_TEST_CASE(sphere_settles_in_a_valley_on_two_overlaps) {
  using Law = HertzLaw<double>;
  const double r = 0.01, theta = 30 * kPi / 180, s = 0.05, k = 1e9, m = 2500 * 4.0 / 3.0 * kPi * r * r * r, g = 9.81;
  const Law law{Hertz<double>::from_restitution(k, 0.1), HistoryFreeFriction<double>::make(0, 0)};
  const double rise = s * std::tan(theta);
  World<double> w;  // faces rising at theta on both sides of the crease along y
  w.meshes.push_back({"valley", mesh_of({{0, -s, 0}, {0, s, 0}, {s, -s, rise}, {s, s, rise}, {-s, -s, rise}, {-s, s, rise}},
                                        {{0, 2, 3}, {0, 3, 1}, {0, 1, 5}, {0, 5, 4}}), 1});
  ParticleState<double> p;
  p.add_sphere(Vec3<double>{0.3 * r, 0.004, r / std::cos(theta) + 0.003}, r, 2500, 0);
  MeshSim<Law> sim(params<double>(2e-6, {0, 0, -g}, 0.2, 1e-3), one_law(law), w, p);
  sim.run(400000);  // 0.8 s
  const auto st = sim.state();
  // each face pushes along its normal with N = m g / (2 cos theta); Hertz: N = k_n delta^1.5,
  // k_n from the law's own stiffness with R* = r (a plane)
  const double n = m * g / (2 * std::cos(theta));
  const double delta = std::pow(n / (law.normal.k_hat * std::sqrt(r)), 2.0 / 3.0);
  const double z_rest = (r - delta) / std::cos(theta);
  BOOST_TEST_MESSAGE("valley: x / r " << st.position[0].x / r << ", (z - z_rest) / delta " << (st.position[0].z - z_rest) / delta << " (overlap "
                                      << delta << " m)");
  check_at_most({kCase, "sphere at rest in a mesh valley: |x - x_axis| / r", "-", "symmetry: two faces, two contacts"},
                std::fabs(st.position[0].x) / r, tol::mesh_walls_valley_rest);
  check_at_most({kCase, "sphere at rest in a mesh valley: |z - (r - delta) / cos theta| / delta", "-",
                 "Hertz: each face carries m g / (2 cos theta)"},
                std::fabs(st.position[0].z - z_rest) / delta, tol::mesh_walls_valley_rest);
}

BOOST_AUTO_TEST_CASE(lists_and_restart_change_nothing_on_a_mesh) {
  using Law = HertzMindlinLaw<double>;
  const auto hertz = Hertz<double>::from_restitution(2e8, 0.5);
  const Law law{hertz, TangentialSpring<double>::mindlin(0.3, 2e8 / 1.5 / 2.5, 0.5)};
  const double r = 0.02, dt = 2e-5;
  const auto start = lane_spheres<double>(r);
  auto prm = params<double>(dt, {2.0, 0, -9.81}, 0.6, 0.2 * r);
  std::vector<ParticleState<double>> out;
  for (WorldLists mode : {WorldLists::on, WorldLists::off}) {
    prm.world_lists = mode;
    MeshSim<Law> sim(prm, one_law(law), plate_world<double>(true, 0.5, 20), start);
    BOOST_TEST_REQUIRE(sim.world_lists().on() == (mode == WorldLists::on));
    sim.run(5000);
    if (mode == WorldLists::off) {  // and a restart halfway through
      MeshSim<Law> resumed(prm, one_law(law), plate_world<double>(true, 0.5, 20), sim.snapshot());
      sim.run(5000);
      resumed.run(5000);
      out.push_back(sim.state());
      out.push_back(resumed.state());
    } else {
      sim.snapshot();  // the same extra rebuild as the other run's
      sim.run(5000);
      out.push_back(sim.state());
    }
  }
  for (std::size_t k = 1; k < out.size(); ++k) {
    bool same = out[0].size() == out[k].size();
    for (std::size_t i = 0; same && i < out[0].size(); ++i)
      same = out[0].id[i] == out[k].id[i] && out[0].position[i].x == out[k].position[i].x && out[0].position[i].z == out[k].position[i].z &&
             out[0].angular_velocity[i].y == out[k].angular_velocity[i].y;
    BOOST_TEST(same, (k == 1 ? "world lists on vs off" : "restart vs straight through") << ": bitwise the same on a mesh");
  }
}

// Cubes on the tessellated plate and on the polygon: dropped turned at random while moving along
// x, they land, tumble and slide across triangle edges and vertices; the history-free law and a
// linear spring.
template <class Law>
void cubes_on_mesh_as_on_polygon(const Law& law, const std::string& name) {
  std::istringstream text("vertices 8\n0 0 0\n0.02 0 0\n0.02 0.02 0\n0 0.02 0\n0 0 0.02\n0.02 0 0.02\n0.02 0.02 0.02\n"
                          "0 0.02 0.02\nfaces 6\n4 0 3 2 1\n4 4 5 6 7\n4 0 1 5 4\n4 1 2 6 5\n4 2 3 7 6\n4 3 0 4 7\n");
  PolyhedronShape<double> shape;
  shape.table.add(parse_blaze_shape(text, "cube-20mm"), 2500);
  ParticleState<double> s;
  std::mt19937_64 rng(8);
  std::uniform_real_distribution<double> u(-1, 1);
  for (int k = 0; k < 10; ++k) {  // dropped from just above the plate, turned at random, moving along x
    const double a = 3 * u(rng);
    const Vec3<double> axis = Vec3<double>{u(rng), u(rng), u(rng) + 1.5} * 1.0;
    const Vec3<double> e = axis * (std::sin(a / 2) / norm(axis));
    add_polyhedron(s, shape.table, 0, Vec3<double>{-0.3, -0.3 + 0.065 * k, 0.02 + 0.005 * (k % 3)}, Quat<double>{std::cos(a / 2), e.x, e.y, e.z}, 0,
                   Vec3<double>{0.8 + 0.3 * u(rng), 0.05 * u(rng), 0});
  }
  std::vector<ParticleState<double>> out;
  const double dt = 1e-5;
  for (bool as_mesh : {false, true}) {
    Simulation<DefaultSpace, PolyhedronShape<double>, Law, VelocityVerlet> sim(params<double>(dt, {0, 0, -9.81}, 0.6, 2e-3), one_law(law),
                                                                               plate_world<double>(as_mesh, 0.5, 20), s, shape);
    sim.run(static_cast<std::uint64_t>(std::llround(0.3 / dt)));
    out.push_back(sim.state());
  }
  const auto [worst, travel] = parting(out[1], out[0], s);
  BOOST_TEST_MESSAGE("cubes on a mesh vs a polygon, " << name << ": " << worst << " of the travel (" << travel << " m)");
  BOOST_TEST(travel > 0.1);
  for (std::size_t k = 0; k < s.size(); ++k) BOOST_TEST(out[1].position[k].z > 0.009);  // on the plate, not through it
  check_at_most({kCase, "cubes sliding and tumbling over 800 triangles vs one polygon, " + name + ": max |x_mesh - x_polygon| / travel",
                 "-", "a vertex counts once per plane (polyhedron_shape.hpp collide_mesh)"},
                worst, tol::mesh_walls_flat_trajectory);
}

BOOST_AUTO_TEST_CASE(polyhedra_on_a_mesh_move_as_on_one_polygon) {
  const auto normal = LinearSpringDashpot<double>::from_restitution(1e5, 0.5);
  cubes_on_mesh_as_on_polygon(LinearLaw<double>{normal, HistoryFreeFriction<double>::make(0.3, 20)}, "history-free");
  cubes_on_mesh_as_on_polygon(LinearSpringLaw<double>{normal, TangentialSpring<double>::linear(0.3, 2.0 / 7.0 * 1e5, normal.beta)},
                              "linear spring");
}

// A cube settling in a valley rests on both faces: two contacts, at the height two overlaps give.
BOOST_AUTO_TEST_CASE(cube_in_a_valley_rests_on_both_faces) {
  std::istringstream text("vertices 8\n0 0 0\n0.02 0 0\n0.02 0.02 0\n0 0.02 0\n0 0 0.02\n0.02 0 0.02\n0.02 0.02 0.02\n"
                          "0 0.02 0.02\nfaces 6\n4 0 3 2 1\n4 4 5 6 7\n4 0 1 5 4\n4 1 2 6 5\n4 2 3 7 6\n4 3 0 4 7\n");
  PolyhedronShape<double> shape;
  shape.table.add(parse_blaze_shape(text, "cube-20mm"), 2500);
  const double s = 0.05, rise = s;  // faces at 45 degrees: the cube's edge sits in the crease
  World<double> w;
  w.meshes.push_back({"valley", mesh_of({{0, -s, 0}, {0, s, 0}, {s, -s, rise}, {s, s, rise}, {-s, -s, rise}, {-s, s, rise}},
                                        {{0, 2, 3}, {0, 3, 1}, {0, 1, 5}, {0, 5, 4}}), 1});
  // turned so that two face normals a, b of its (principal) body frame become the valley's
  // u1 = (1, 0, 1) / sqrt 2 and y (then a x b becomes u1 x y = u2, the other face's)
  const Quat<double> turn = face_turn(shape.table.type[0], {std::sqrt(0.5), 0, std::sqrt(0.5)}, {0, 1, 0});
  ParticleState<double> p;
  add_polyhedron(p, shape.table, 0, Vec3<double>{0.001, 0, 0.01 * std::sqrt(2.0) + 0.002}, turn, 0, Vec3<double>{0, 0, 0});
  using Law = LinearLaw<double>;
  auto normal = LinearSpringDashpot<double>::from_restitution(1e5, 0.2);
  normal.no_tension = true;  // damped flat contacts want it (polyhedron_shape.hpp)
  const Law law{normal, HistoryFreeFriction<double>::make(0.0, 0)};
  Simulation<DefaultSpace, PolyhedronShape<double>, Law, VelocityVerlet, ContactPointVelocity, FullFeatures> sim(
      params<double>(1e-5, {0, 0, -9.81}, 0.2, 1e-3), one_law(law), w, p, shape);
  sim.run(100000);  // 1 s
  const auto st = sim.state();
  BOOST_TEST_REQUIRE(st.size() == 1u);
  // each face carries m g / (2 cos 45); the linear spring: delta = N / k
  const double m = 2500 * 8e-6, delta = m * 9.81 / (2 * std::cos(kPi / 4)) / 1e5;
  const double z_rest = (0.01 - delta) * std::sqrt(2.0);  // the centre's height over the crease
  BOOST_TEST_MESSAGE("cube in a valley: x " << st.position[0].x << ", z - z_rest " << st.position[0].z - z_rest << " (delta " << delta << ")");
  check_at_most({kCase, "cube at rest in a mesh valley: |z - z_rest| / delta", "-", "two planes, two patch contacts"},
                std::fabs(st.position[0].z - z_rest) / delta, tol::mesh_walls_valley_rest_cube);
}

BOOST_AUTO_TEST_SUITE_END()
