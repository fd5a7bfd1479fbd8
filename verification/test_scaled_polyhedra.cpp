// Scaled polyhedra (issue 20, "a scale distribution of one shape file"; PolyhedronShape::Body):
// a particle of bounding radius s R of a table type of radius R is that type's shape scaled by s.
// - contact geometry: every pairing of the shipped shapes and a sphere type, each body scaled by
//   its own s (0.37 .. 2.9), against the same pair from a table of the shapes scaled beforehand
//   (the scaled ConvexShape, same body frame): the same contacts, overlaps, normals, points and
//   patches, to rounding; likewise against a planar wall with rim edges and a drum;
// - dynamics: bodies scaled by powers of two (every product exact) fall through a scene of a
//   floor with a rim, a drum and a mesh valley, with Hertz-Mindlin history: the run is bit for
//   bit the run of pre-scaled table types (contacts, mass s^3, principal moments s^5, rotation).
// (A body at its type's own size has s = 1 exactly, every product with it exact: the rest of the
// suite, unscaled, checks that path.)
// Feeding polyhedra with a size distribution is in test_feeding.cpp.
#include <boost/test/unit_test.hpp>
#include <cmath>
#include <cstring>
#include <random>
#include "blaze/shapes/polyhedron_shape.hpp"
#include "blaze/shapes/shape_io.hpp"
#include "verification/report.hpp"
#include "verification/scenes.hpp"
#include "verification/tolerances.hpp"

using namespace blaze;
using namespace blaze::test;

namespace {

const char* kCase = "Scaled polyhedra";
const char* kShapes[] = {"cube", "tetrahedron", "dodecahedron", "prism", "corn"};

// The shape scaled by k in its own body frame (what a table type of that size holds).
ConvexShape scaled(ConvexShape s, double k) {
  for (auto& v : s.vertices) v *= k;
  for (auto& c : s.centroids) c *= k;
  s.volume *= k * k * k;
  s.inertia_per_density *= k * k * k * k * k;
  s.bounding_radius *= k;
  return s;
}

Quat<double> random_orientation(std::mt19937_64& rng) {
  std::normal_distribution<double> g;
  return normalized(Quat<double>{g(rng), g(rng), g(rng), g(rng)});
}

// Largest difference of two contact geometries over their length scale `size`: overlap, point
// and patch points over size, normal components; a contact in one only: infinity.
template <class G>
double geometry_difference(const G& a, const G& b, double size) {
  if (a.touching != b.touching) return INFINITY;
  if (!a.touching) return 0;
  double d = std::fabs(a.overlap - b.overlap) / size;
  d = std::max(d, norm(a.normal - b.normal));
  d = std::max(d, norm(a.point - b.point) / size);
  d = std::max(d, std::fabs(a.r_eff - b.r_eff) / size);
  if (a.patch.count != b.patch.count) return INFINITY;
  for (int k = 0; k < a.patch.count; ++k)
    d = std::max({d, norm(a.patch.point[k] - b.patch.point[k]) / size, std::fabs(a.patch.weight[k] - b.patch.weight[k])});
  return d;
}

}  // namespace

BOOST_AUTO_TEST_SUITE(scaled_polyhedra)

BOOST_AUTO_TEST_CASE(a_scaled_body_collides_as_its_scaled_shape) {
  std::vector<ConvexShape> shapes;
  for (const char* f : kShapes) shapes.push_back(load_scaled_shape(std::string("data/shapes/") + f + ".shape", 0.01));
  shapes.push_back(ConvexShape{});  // a sphere type (radius 0.01)
  const int n = static_cast<int>(shapes.size());
  const double scales[] = {0.37, 0.8, 1.0, 1.3, 2.9};
  std::mt19937_64 rng(20261204);
  std::uniform_real_distribution<double> u(0, 1);
  double worst_pair = 0, worst_wall = 0;
  long touching = 0, pairs = 0;
  // shape c (no vertices: a sphere type of radius 0.01) scaled by k, a table type of `shape`
  const auto add = [](PolyhedronShape<double>& shape, const ConvexShape& c, double k) {
    if (c.vertices.empty()) shape.table.add_sphere(0.01 * k, 2500);
    else shape.table.add(scaled(c, k), 2500);
  };
  for (int ta = 0; ta < n; ++ta)
    for (int tb = ta; tb < n; ++tb)
      for (const double sa : scales)
        for (const double sb : scales) {
          // the types at 1 cm, scaled per body; against the table of the scaled shapes
          PolyhedronShape<double> unit, pre;
          add(unit, shapes[ta], 1), add(unit, shapes[tb], 1);
          add(pre, shapes[ta], sa), add(pre, shapes[tb], sb);
          const double size = 0.01 * (sa + sb);
          for (int k = 0; k < 40; ++k) {
            const Quat<double> qa = random_orientation(rng), qb = random_orientation(rng);
            Vec3<double> dir{u(rng) - 0.5, u(rng) - 0.5, u(rng) - 0.5};
            dir *= 1 / norm(dir);
            const Vec3<double> xa{0.1 * u(rng), 0.1 * u(rng), 0.1 * u(rng)};
            const Vec3<double> xb = xa + dir * (size * (0.55 + 0.45 * u(rng)));
            const auto g_scaled = unit.collide({xa, qa, 0, 0, sa}, {xb, qb, 1, 1, sb});
            const auto g_pre = pre.collide({xa, qa, 0, 0}, {xb, qb, 1, 1});
            worst_pair = std::max(worst_pair, geometry_difference(g_scaled, g_pre, size));
            touching += g_pre.touching, ++pairs;
          }
        }
  // walls: a floor whose rim (an active edge) crosses the bodies, and a drum
  const auto floor = PlanarPolygon<double>::make({{-1, 0, 1}, {1, 0, 1}, {1, 0, 0}, {-1, 0, 0}}, 1);
  const auto drum = Cylinder<double>::make({0, 0, -1}, {0, 0, 1}, 0.2, 2, 1);
  for (int t = 0; t < n; ++t)
    for (const double s : scales) {
      PolyhedronShape<double> unit, pre;
      add(unit, shapes[t], 1), add(pre, shapes[t], s);
      const double size = 0.01 * s;
      for (int k = 0; k < 200; ++k) {
        const Quat<double> q = random_orientation(rng);
        const Vec3<double> on_floor{0.1 * u(rng), size * (1.2 * u(rng) - 0.1), size * (2 * u(rng) - 1)};
        worst_wall = std::max(worst_wall, geometry_difference(unit.collide_world({on_floor, q, 0, 0, s}, floor),
                                                              pre.collide_world({on_floor, q, 0, 0}, floor), size));
        const double phi = 6.283 * u(rng), rho = 0.2 - size * (1.2 * u(rng) - 0.1);
        const Vec3<double> in_drum{rho * std::cos(phi), rho * std::sin(phi), 0.5 * u(rng)};
        worst_wall = std::max(worst_wall, geometry_difference(unit.collide_world({in_drum, q, 0, 0, s}, drum),
                                                              pre.collide_world({in_drum, q, 0, 0}, drum), size));
      }
    }
  BOOST_TEST_MESSAGE("scaled pairs: " << touching << " of " << pairs << " touching");
  BOOST_TEST(touching > pairs / 4);
  check_at_most({kCase, "scaled body vs pre-scaled shape, pairs: largest geometry difference (over the size)", "-",
                 "rounding (tol::scaled_geometry)"},
                worst_pair, tol::scaled_geometry);
  check_at_most({kCase, "scaled body vs pre-scaled shape, floor with rim and drum: largest geometry difference", "-",
                 "rounding (tol::scaled_geometry)"},
                worst_wall, tol::scaled_geometry);
}

BOOST_AUTO_TEST_CASE(a_run_of_scaled_bodies_is_the_run_of_scaled_shapes) {
  using Law = HertzMindlinLaw<double>;
  const auto hertz = Hertz<double>::from_restitution(5e7, 0.4);
  const Law law{hertz, TangentialSpring<double>::mindlin(0.4, 5e7 / (2 * (1 - 0.25)) / 2.5, 0.4)};
  const ConvexShape cube = load_scaled_shape("data/shapes/cube.shape", 0.008);
  const ConvexShape dodeca = load_scaled_shape("data/shapes/dodecahedron.shape", 0.008);
  // a floor (its +x edge a rim), a drum round it, a mesh valley beside it
  World<double> w;
  w.polygons.push_back(PlanarPolygon<double>::make({{-0.1, 0, 0.1}, {-0.03, 0, 0.1}, {-0.03, 0, -0.1}, {-0.1, 0, -0.1}}, 1));
  w.cylinders.push_back(Cylinder<double>::make({0, -0.05, 0}, {0, 1, 0}, 0.09, 0.3, 1));
  TriangleMesh valley;
  valley.vertices = {{0.02, -0.04, -0.1}, {0.02, -0.04, 0.1}, {0.08, 0.02, -0.1}, {0.08, 0.02, 0.1}, {-0.04, 0.02, -0.1}, {-0.04, 0.02, 0.1}};
  valley.triangles = {{0, 3, 2}, {0, 1, 3}, {0, 5, 1}, {0, 4, 5}};  // normals up, into the valley
  w.meshes.push_back({"valley", valley, 1});
  // the same bodies: the table's 8 mm types scaled by 1/2 or 2, or types of those sizes
  PolyhedronShape<double> unit, pre;
  unit.table.add(cube, 2500), unit.table.add(dodeca, 2500), unit.table.add_sphere(0.008, 2500);
  pre.table.add(scaled(cube, 0.5), 2500), pre.table.add(scaled(cube, 2), 2500), pre.table.add(scaled(dodeca, 2), 2500);
  pre.table.add_sphere(0.004, 2500);
  struct Body {
    int unit_type;
    double s;
    int pre_type;
  };
  const Body kinds[] = {{0, 0.5, 0}, {0, 2, 1}, {1, 2, 2}, {2, 0.5, 3}};
  ParticleState<double> a, b;
  std::mt19937_64 rng(7);
  for (int i = 0; i < 8; ++i) {
    const Body& k = kinds[i % 4];
    const Quat<double> q = random_orientation(rng);
    const Vec3<double> x{-0.075 + 0.035 * (i % 4), 0.04 + 0.04 * (i / 4), 0.005 * (i % 3)};
    const Vec3<double> v{0.1, -0.2, 0}, om{3.0 * (i % 2), 1, -2};
    add_polyhedron(a, unit.table, k.unit_type, x, q, 0, v, om, unit.table.type[k.unit_type].bounding_radius * k.s);
    add_polyhedron(b, pre.table, k.pre_type, x, q, 0, v, om);
  }
  for (std::size_t i = 0; i < a.size(); ++i) {  // mass s^3, moments s^5, exactly
    BOOST_TEST(a.mass[i] == b.mass[i]);
    BOOST_TEST(a.radius[i] == b.radius[i]);
    BOOST_TEST((a.inertia[i].x == b.inertia[i].x && a.inertia[i].y == b.inertia[i].y && a.inertia[i].z == b.inertia[i].z));
  }
  const auto p = params<double>(2e-6, {0, -9.81, 0}, 0.3, 1e-3);
  Simulation<DefaultSpace, PolyhedronShape<double>, Law, VelocityVerlet, ContactPointVelocity, FullFeatures> sa(p, one_law(law), w, a, unit);
  Simulation<DefaultSpace, PolyhedronShape<double>, Law, VelocityVerlet, ContactPointVelocity, FullFeatures> sb(p, one_law(law), w, b, pre);
  sa.run(80000), sb.run(80000);  // 0.16 s: the bodies reach the floor, the valley and the drum
  const auto ra = sa.state(), rb = sb.state();
  BOOST_TEST_REQUIRE(ra.size() == 8u);  // none lost through a wall
  BOOST_TEST_REQUIRE(rb.size() == 8u);
  long different = 0;
  double moved = 0;
  for (std::size_t i = 0; i < ra.size(); ++i) {
    different += std::memcmp(&ra.position[i], &rb.position[i], sizeof ra.position[i]) != 0;
    different += std::memcmp(&ra.velocity[i], &rb.velocity[i], sizeof ra.velocity[i]) != 0;
    different += std::memcmp(&ra.orientation[i], &rb.orientation[i], sizeof ra.orientation[i]) != 0;
    different += std::memcmp(&ra.angular_velocity[i], &rb.angular_velocity[i], sizeof ra.angular_velocity[i]) != 0;
    moved = std::max(moved, norm(ra.position[i] - a.position[i]));
  }
  // they fell and met the world: the lowest is below the valley's rim, and contacts took energy
  double lowest = 1, kinetic = 0, fall = 0;
  for (std::size_t i = 0; i < ra.size(); ++i) {
    lowest = std::min(lowest, ra.position[i].y);
    kinetic += 0.5 * ra.mass[i] * norm2(ra.velocity[i]);
    fall += 0.5 * ra.mass[i] * (norm2(a.velocity[i]) + 2 * 9.81 * (a.position[i].y - ra.position[i].y));
  }
  BOOST_TEST(moved > 0.02);
  BOOST_TEST(lowest < 0.02);
  BOOST_TEST(kinetic < 0.8 * fall);
  check_at_most({kCase, "bodies scaled by 1/2 and 2 vs pre-scaled types, 0.16 s of floor, drum and mesh: fields differing bitwise",
                 "-", "0: products with powers of two are exact"},
                static_cast<double>(different), 0);
}

BOOST_AUTO_TEST_SUITE_END()
