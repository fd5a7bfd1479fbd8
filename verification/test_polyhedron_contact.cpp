// Polyhedron contact detection (issue 3, acceptance 3): the kernel's separating-axis collide()
// against the brute-force reference, on 10^5 random pairs of every combination of the shipped
// shapes at random orientations near contact (centre distance between the sum of the inradii and
// the sum of the bounding radii): no missed contact deeper than 1e-6 of the size, no false
// contact, the same overlap, and normals within 1 degree where the reference defines one (its
// least-penetration axis is shallower than every other axis by more than rounding).
#include <boost/test/unit_test.hpp>
#include <random>
#include "blaze/shapes/polyhedron_shape.hpp"
#include "blaze/shapes/shape_io.hpp"
#include "verification/reference_sat.hpp"
#include "verification/tolerances.hpp"

using namespace blaze;
using namespace blaze::test;

namespace {

const char* kShapes[] = {"cube", "box", "tetrahedron", "octahedron", "icosahedron", "dodecahedron", "prism", "corn"};

Eigen::Quaterniond random_rotation(std::mt19937_64& rng) {
  std::normal_distribution<double> g;
  Eigen::Quaterniond q(g(rng), g(rng), g(rng), g(rng));
  return q.normalized();
}

double inradius(const ConvexShape& s) {
  double r = 1e300;
  for (std::size_t f = 0; f < s.faces.size(); ++f) r = std::min(r, s.normals[f].dot(s.centroids[f]));
  return r;
}

struct Tally {
  long pairs = 0, touching = 0, missed = 0, false_contacts = 0, depth_off = 0, normals_checked = 0, normals_off = 0;
  double worst_angle = 0;
};

}  // namespace

BOOST_AUTO_TEST_SUITE(polyhedron_contact)

BOOST_AUTO_TEST_CASE(agrees_with_brute_force_separating_axes) {
  std::vector<ConvexShape> shapes;
  for (const char* f : kShapes) shapes.push_back(load_shape(std::string("data/shapes/") + f + ".shape"));
  const int n_shapes = static_cast<int>(shapes.size());
  Tally total;
  for (int ta = 0; ta < n_shapes; ++ta)
    for (int tb = ta; tb < n_shapes; ++tb) {
      PolyhedronShape<double> shape;
      shape.table.add(shapes[ta], 1000);
      shape.table.add(shapes[tb], 1000);
      const ConvexShape &a = shapes[ta], &b = shapes[tb];
      const double size = a.bounding_radius + b.bounding_radius;
      const double d_min = inradius(a) + inradius(b), d_max = size;
      Tally t;
#pragma omp parallel
      {
        Tally mine;
        auto& t_ = mine;
#pragma omp for schedule(static)
        for (int k = 0; k < static_cast<int>(tol::contact_pairs_per_combination); ++k) {
          std::mt19937_64 rng(1000003ull * (100 * ta + tb) + static_cast<unsigned long long>(k));  // per pair: thread-count independent
          std::uniform_real_distribution<double> u(0, 1);
          std::normal_distribution<double> g;
          const Eigen::Quaterniond qa = random_rotation(rng), qb = random_rotation(rng);
          Eigen::Vector3d dir(g(rng), g(rng), g(rng));
          dir.normalize();
          const Eigen::Vector3d xa(0.3 * (u(rng) - 0.5), 0.3 * (u(rng) - 0.5), 0.3 * (u(rng) - 0.5));
          const Eigen::Vector3d xb = xa + (d_min + (d_max - d_min) * u(rng)) * dir;
          const auto ref = reference_contact(a, xa, qa.toRotationMatrix(), b, xb, qb.toRotationMatrix());
          const PolyhedronShape<double>::Body ba{{xa.x(), xa.y(), xa.z()}, {qa.w(), qa.x(), qa.y(), qa.z()}, 0, 0};
          const PolyhedronShape<double>::Body bb{{xb.x(), xb.y(), xb.z()}, {qb.w(), qb.x(), qb.y(), qb.z()}, 1, 1};
          const auto c = shape.collide(ba, bb);
          ++t_.pairs;
          t_.touching += c.touching;
          if (ref.touching && -ref.separation > tol::contact_missed_depth * size && !c.touching) ++t_.missed;
          if (c.touching && ref.separation > tol::contact_false_gap * size) ++t_.false_contacts;
          if (c.touching && ref.touching &&
              std::fabs(c.overlap + ref.separation) > tol::contact_axis_tie * size + tol::contact_false_gap * size)
            ++t_.depth_off;
          // The reference defines the normal when its axis beats all others by more than rounding.
          if (c.touching && ref.touching && ref.second - (-ref.separation) > 2 * tol::contact_axis_tie * size) {
            ++t_.normals_checked;
            const double cosine = c.normal.x * ref.normal.x() + c.normal.y * ref.normal.y() + c.normal.z * ref.normal.z();
            const double angle = std::acos(std::min(1.0, cosine)) * 180 / 3.14159265358979323846;
            t_.worst_angle = std::max(t_.worst_angle, angle);
            if (angle > tol::contact_normal_degrees) ++t_.normals_off;
          }
        }
#pragma omp critical
        {
          t.pairs += mine.pairs, t.touching += mine.touching, t.missed += mine.missed;
          t.false_contacts += mine.false_contacts, t.depth_off += mine.depth_off;
          t.normals_checked += mine.normals_checked, t.normals_off += mine.normals_off;
          t.worst_angle = std::max(t.worst_angle, mine.worst_angle);
        }
      }
      BOOST_TEST_CONTEXT(kShapes[ta] << "-" << kShapes[tb] << ": " << t.pairs << " pairs, " << t.touching
                                     << " touching, " << t.normals_checked << " normals checked") {
        BOOST_TEST(t.missed == 0);
        BOOST_TEST(t.false_contacts == 0);
        BOOST_TEST(t.depth_off == 0);
        BOOST_TEST(t.normals_off == 0);
        BOOST_TEST(t.touching > t.pairs / 10);  // the sample does reach contact
      }
      total.pairs += t.pairs;
      total.touching += t.touching;
      total.normals_checked += t.normals_checked;
      total.worst_angle = std::max(total.worst_angle, t.worst_angle);
    }
  BOOST_TEST_MESSAGE("polyhedron contact vs reference: " << total.pairs << " pairs, " << total.touching << " touching, "
                                                         << total.normals_checked << " normals checked, worst angle "
                                                         << total.worst_angle << " deg");
}

// The edge pairs the separating-axis test visits (bit sets, polyhedron_shape.hpp) must be exactly those
// whose Gauss-map arcs cross, tested pair by pair in the textbook form: a, b the normals beside
// A's edge, c, d the negated normals beside B's edge,
//   (c.(b x a)) (d.(b x a)) < 0,  (a.(d x c)) (b.(d x c)) < 0,  (c.(b x a)) (b.(d x c)) > 0.
// Every shape combination, random relative orientations.
BOOST_AUTO_TEST_CASE(edge_pair_selection_is_the_arc_test) {
  using polyhedron_detail::ArcSets;
  std::vector<ConvexShape> shapes;
  for (const char* f : kShapes) shapes.push_back(load_shape(std::string("data/shapes/") + f + ".shape"));
  long orientations = 0, selected = 0, differ = 0;
  for (std::size_t ta = 0; ta < shapes.size(); ++ta)
    for (std::size_t tb = ta; tb < shapes.size(); ++tb) {
      PolyhedronTable<double> table;
      table.add(shapes[ta], 1000), table.add(shapes[tb], 1000);
      const PolyhedronData<double>&A = table.type[0], &B = table.type[1];
      std::mt19937_64 rng(7919 * (ta + 1) + tb);
      for (long k = 0; k < tol::edge_pair_enumeration_pairs; ++k) {
        const Eigen::Matrix3d m = random_rotation(rng).toRotationMatrix();
        Mat3<double> r;
        for (int i = 0; i < 3; ++i)
          for (int j = 0; j < 3; ++j) r.m[i][j] = m(i, j);
        ArcSets sets;
        polyhedron_detail::arc_sets(A, B, r, sets);
        ++orientations;
        for (int ea = 0; ea < A.edge_count; ++ea) {
          const std::uint64_t chosen = polyhedron_detail::crossing_edges(
              B, polyhedron_detail::edge_axis_of(A, r, ea), sets, A.edge_face[ea][0], A.edge_face[ea][1]);
          const Vec3<double> a = r * A.normal[A.edge_face[ea][0]], b = r * A.normal[A.edge_face[ea][1]];
          for (int eb = 0; eb < B.edge_count; ++eb) {
            const Vec3<double> c = -B.normal[B.edge_face[eb][0]], d = -B.normal[B.edge_face[eb][1]];
            const Vec3<double> bxa = cross(b, a), dxc = cross(d, c);
            const double cba = dot(c, bxa), dba = dot(d, bxa), adc = dot(a, dxc), bdc = dot(b, dxc);
            const bool cross_arcs = cba * dba < 0 && adc * bdc < 0 && cba * bdc > 0;
            const bool in_set = (chosen >> eb) & 1;
            selected += in_set;
            differ += in_set != cross_arcs;
          }
        }
      }
    }
  BOOST_TEST_MESSAGE("edge-pair selection: " << orientations << " orientations, " << selected << " pairs selected, "
                                             << differ << " differ from the pairwise arc test");
  BOOST_TEST(differ == 0);
  BOOST_TEST(selected > orientations);  // the sets do select pairs
}

BOOST_AUTO_TEST_SUITE_END()

// Sphere against each shipped polyhedron: a sphere placed outside a face, an edge and a vertex
// (along the outward direction of that feature's normal cone) and with its centre inside the
// body, at a known overlap; overlap, normal and contact side must follow (closed forms in the
// body frame). Also sphere-sphere through the same mixed policy.
BOOST_AUTO_TEST_SUITE(sphere_polyhedron_contact)

BOOST_AUTO_TEST_CASE(face_edge_vertex_and_inside_cases) {
  const double r = 0.002, delta = 1e-4;
  for (const char* f : kShapes) {
    const ConvexShape s = load_shape(std::string("data/shapes/") + f + ".shape");
    PolyhedronShape<double> shape;
    shape.table.add(s, 1000);
    shape.table.add_sphere(r, 1000);
    const std::mt19937_64::result_type seed = 11;
    std::mt19937_64 rng(seed);
    const Eigen::Quaterniond q = random_rotation(rng);
    const Eigen::Matrix3d rot = q.toRotationMatrix();
    const Eigen::Vector3d x(0.01, -0.02, 0.03);
    const PolyhedronShape<double>::Body poly{{x.x(), x.y(), x.z()}, {q.w(), q.x(), q.y(), q.z()}, 0, 0};
    // (surface point, outward direction, gap of the sphere centre from the surface) in the body frame.
    struct Case { const char* feature; Eigen::Vector3d point, dir; double gap; };
    const auto& e = s.edges[0];
    const Eigen::Vector3d edge_mid = 0.5 * (s.vertices[e.v0] + s.vertices[e.v1]);
    const Eigen::Vector3d edge_dir = (s.normals[e.left] + s.normals[e.right]).normalized();
    Eigen::Vector3d vertex_dir = Eigen::Vector3d::Zero();  // inside the vertex's normal cone
    for (std::size_t g = 0; g < s.faces.size(); ++g)
      for (int v : s.faces[g]) if (v == 0) vertex_dir += s.normals[g];
    vertex_dir.normalize();
    const Case cases[] = {{"face", s.centroids[0], s.normals[0], r - delta},
                          {"edge", edge_mid, edge_dir, r - delta},
                          {"vertex", s.vertices[0], vertex_dir, r - delta},
                          {"centre inside", s.centroids[0], s.normals[0], -0.2 * r}};
    for (const auto& c : cases) {
      const Eigen::Vector3d centre = x + rot * (c.point + c.gap * c.dir), normal = rot * c.dir;
      const PolyhedronShape<double>::Body ball{{centre.x(), centre.y(), centre.z()}, Quat<double>::identity(), 1, 1};
      for (int order = 0; order < 2; ++order) {
        const auto g = order == 0 ? shape.collide(poly, ball) : shape.collide(ball, poly);
        const double sign = order == 0 ? 1 : -1;  // normals point from the first body to the second
        BOOST_TEST_CONTEXT(f << ", " << c.feature << (order ? ", sphere first" : "")) {
          BOOST_TEST_REQUIRE(g.touching);
          BOOST_TEST(g.overlap == r - c.gap, boost::test_tools::tolerance(tol::geometry_double));
          const double cosine = sign * (g.normal.x * normal.x() + g.normal.y * normal.y() + g.normal.z * normal.z());
          BOOST_TEST(cosine == 1.0, boost::test_tools::tolerance(tol::geometry_double));
        }
      }
      // Moved out of reach along the same direction: no contact.
      const Eigen::Vector3d away = x + rot * (c.point + (r + delta) * c.dir);
      const PolyhedronShape<double>::Body far{{away.x(), away.y(), away.z()}, Quat<double>::identity(), 1, 1};
      if (c.gap > 0) BOOST_TEST(!shape.collide(poly, far).touching);
    }
  }
}

BOOST_AUTO_TEST_CASE(spheres_in_the_mixed_policy_collide_as_spheres) {
  PolyhedronShape<double> shape;
  shape.table.add_sphere(0.002, 1000);
  shape.table.add_sphere(0.003, 1000);
  const PolyhedronShape<double>::Body a{{0, 0, 0}, Quat<double>::identity(), 0, 0}, b{{0.0049, 0, 0}, Quat<double>::identity(), 1, 1};
  const auto g = shape.collide(a, b);
  BOOST_TEST(g.touching);
  BOOST_TEST(g.overlap == 1e-4, boost::test_tools::tolerance(tol::geometry_double));
  BOOST_TEST(g.normal.x == 1.0);
}

BOOST_AUTO_TEST_SUITE_END()

// Polyhedron against world objects (thesis Algorithm 2): a cube face-down on a floor polygon,
// tilted onto one vertex, beside the polygon's edge, and in a drum.
BOOST_AUTO_TEST_SUITE(polyhedron_world_contact)

BOOST_AUTO_TEST_CASE(cube_on_floor_and_in_drum) {
  const ConvexShape cube = load_shape("data/shapes/cube.shape");
  PolyhedronShape<double> shape;
  shape.table.add(cube, 2500);
  const double half = 0.005, delta = 1e-4;
  // The body frame of a cube may be any rotation of the input (isotropic inertia): orient it so
  // that body face 0 points down.
  const Eigen::Vector3d n0 = cube.normals[0];
  const Eigen::Quaterniond face_down = Eigen::Quaterniond::FromTwoVectors(n0, -Eigen::Vector3d::UnitY());
  const Quat<double> q{face_down.w(), face_down.x(), face_down.y(), face_down.z()};
  const auto floor = PlanarPolygon<double>::make({{-1, 0, 1}, {1, 0, 1}, {1, 0, -1}, {-1, 0, -1}}, 0);
  const PolyhedronShape<double>::Body flat{{0.1, half - delta, -0.2}, q, 0, 0};
  const auto g = shape.collide_world(flat, floor);
  BOOST_TEST_REQUIRE(g.touching);
  BOOST_TEST(g.overlap == delta, boost::test_tools::tolerance(tol::geometry_double));
  BOOST_TEST(g.normal.y == -1.0);
  // Contact point: the mean of the four penetrating vertices, under the centre.
  BOOST_TEST(g.point.x == 0.1, boost::test_tools::tolerance(tol::geometry_double));
  BOOST_TEST(g.point.z == -0.2, boost::test_tools::tolerance(tol::geometry_double));
  // Lifted clear of the floor, or centre below it (line 1 of Algorithm 2): no contact.
  BOOST_TEST(!shape.collide_world(PolyhedronShape<double>::Body{{0.1, half + delta, -0.2}, q, 0, 0}, floor).touching);
  BOOST_TEST(!shape.collide_world(PolyhedronShape<double>::Body{{0.1, -0.001, -0.2}, q, 0, 0}, floor).touching);
  // Standing on a vertex: overlap of that vertex alone, point at the vertex.
  const Eigen::Vector3d v0 = cube.vertices[0];
  const Eigen::Quaterniond on_vertex = Eigen::Quaterniond::FromTwoVectors(v0, -Eigen::Vector3d::UnitY());
  const double reach = v0.norm();
  const PolyhedronShape<double>::Body tip{{0, reach - delta, 0}, {on_vertex.w(), on_vertex.x(), on_vertex.y(), on_vertex.z()}, 0, 0};
  const auto gv = shape.collide_world(tip, floor);
  BOOST_TEST_REQUIRE(gv.touching);
  BOOST_TEST(gv.overlap == delta, boost::test_tools::tolerance(tol::geometry_double));
  BOOST_TEST(std::fabs(gv.point.x) <= tol::geometry_double * reach);
  // Beyond the polygon's edge the containment test rejects the vertices.
  const auto small = PlanarPolygon<double>::make({{-0.001, 0, 0.001}, {0.001, 0, 0.001}, {0.001, 0, -0.001}, {-0.001, 0, -0.001}}, 0);
  BOOST_TEST(!shape.collide_world(PolyhedronShape<double>::Body{{0.02, half - delta, 0}, q, 0, 0}, small).touching);
  // In a drum of radius R along z, face-down at the bottom.
  const double drum = 0.1;
  const auto cyl = Cylinder<double>::make({0, 0, -0.05}, {0, 0, 1}, drum, 0.1, 0);
  const PolyhedronShape<double>::Body in_drum{{0, -(drum - half) - delta, 0}, q, 0, 0};
  const auto gc = shape.collide_world(in_drum, cyl);
  BOOST_TEST_REQUIRE(gc.touching);
  // The corners reach furthest out: sqrt((R - half + delta)^2... exactly: corner radius minus R.
  const double corner = std::hypot(drum - half + delta + half, half) - drum;
  BOOST_TEST(gc.overlap == corner, boost::test_tools::tolerance(tol::geometry_double));
  BOOST_TEST(gc.normal.y == -1.0, boost::test_tools::tolerance(tol::geometry_double));
}

// A cube tipping into an orifice (issue 20's hopper of dodecahedra read overlaps of 65% of the
// radius there): the plate x < 0 has its orifice edge (x = 0, along z) active. A face-down cube
// whose left face lies delta past that edge, centre above or below the plate, has the edge inside
// it: the contact is the edge against its nearest face (overlap delta, normal -x, unless the top
// or bottom face is nearer), not its left vertices' depth below the plane (up to the half edge).
// Across a seam (an inactive edge between coplanar plates) the vertices still count, as before.
BOOST_AUTO_TEST_CASE(rim_edges_of_an_orifice_meet_the_body_at_their_depth) {
  const ConvexShape cube = load_shape("data/shapes/cube.shape");
  PolyhedronShape<double> shape;
  shape.table.add(cube, 2500);
  const double h = 0.005;
  const Eigen::Quaterniond face_down = Eigen::Quaterniond::FromTwoVectors(cube.normals[0], -Eigen::Vector3d::UnitY());
  const Quat<double> q{face_down.w(), face_down.x(), face_down.y(), face_down.z()};
  const auto plate = PlanarPolygon<double>::make({{-0.05, 0, 0.05}, {0, 0, 0.05}, {0, 0, -0.05}, {-0.05, 0, -0.05}}, 0, 1u << 1);
  for (const double delta : {1e-5, 1e-4, 5e-4, 2e-3})
    for (const double yc : {0.9 * h, 0.5 * h, 0.1 * h, -0.3 * h, -0.8 * h}) {
      const PolyhedronShape<double>::Body b{{h - delta, yc, 0.01}, q, 0, 0};
      const auto g = shape.collide_world(b, plate);
      // the edge's least depth: below the left face (delta), above the bottom one (h - yc) or
      // below the top one (h + yc), the normal that face's
      const double depth = std::min({delta, h - yc, h + yc});
      const Vec3<double> normal = depth == delta ? Vec3<double>{-1, 0, 0} : depth == h - yc ? Vec3<double>{0, -1, 0} : Vec3<double>{0, 1, 0};
      BOOST_TEST_CONTEXT("delta " << delta << ", centre height " << yc / h << " h") {
        BOOST_TEST_REQUIRE(g.touching);
        BOOST_TEST(g.overlap == depth, boost::test_tools::tolerance(tol::geometry_double));
        BOOST_TEST(norm(g.normal - normal) <= tol::geometry_double);
        if (depth == delta) BOOST_TEST(std::fabs(g.point.x) <= tol::geometry_double);
      }
    }
  // clear of the edge: nothing
  BOOST_TEST(!shape.collide_world(PolyhedronShape<double>::Body{{h + 1e-4, 0.1 * h, 0}, q, 0, 0}, plate).touching);
  // a seam: the same plate with its edge at x = 0 inactive (a coplanar neighbour continues the
  // floor): a cube sunk delta, centred over the neighbour, meets this plate with its vertices
  for (const double delta : {1e-5, 1e-4}) {
    const auto seam = PlanarPolygon<double>::make({{-0.05, 0, 0.05}, {0, 0, 0.05}, {0, 0, -0.05}, {-0.05, 0, -0.05}}, 0, 0u);
    const auto g = shape.collide_world(PolyhedronShape<double>::Body{{0.3 * h, h - delta, 0}, q, 0, 0}, seam);
    BOOST_TEST_REQUIRE(g.touching);
    BOOST_TEST(g.overlap == delta, boost::test_tools::tolerance(tol::geometry_double));
    BOOST_TEST(g.normal.y == -1.0);
  }
}

BOOST_AUTO_TEST_SUITE_END()
