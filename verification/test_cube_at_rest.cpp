// A cube dropped on its face comes to rest (thesis section 3.3.1.3, Figs 3.14-3.15). Cube of
// bounding radius 0.25 cm (cases/single_body.hpp), Hertz K_n = 1e9 N/m^(3/2) with the thesis's
// delta^(1/2) damping K_D = 5e4 kg s^-1 m^-1/2 (eqs. 3.6-3.7), gravity 9.81 m/s^2, planar floor.
// Closed form at rest: the polyhedron-wall contact (polyhedron_shape.hpp collide_world) takes the depth
// of the deepest penetrating vertex as the overlap and acts at that vertex, spread over the
// vertices within 1% of its depth. A cube lying flat has its four lower vertices at one depth
// delta, so the point is the face centre below the centre of mass (no torque), and the one
// contact carries the weight:
//   K_n delta_s^(3/2) = m g  ->  delta_s = (m g / K_n)^(2/3) = 7.0e-9 m,
//   rest height of the centre of mass  y_rest = h - delta_s,  h = half edge = 1.443 mm,
// with K_n exact for this contact (Hertz::from_stiffness with r_ref = the cube's bounding radius,
// the r_eff of a polyhedron-wall contact). The damping force vanishes at rest, so the rest state
// is a fixed point of the integrator whatever dt: y_rest is exact up to rounding. The contact
// then stores (2/5) K_n delta_s^(5/2) = (2/5) m g delta_s (hertz.hpp).
#include <boost/test/unit_test.hpp>
#include <cmath>
#include <random>
#include "verification/cases/single_body.hpp"
#include "verification/report.hpp"
#include "verification/scenes.hpp"

using namespace blaze;
using namespace blaze::test;
namespace cs = blaze::test::cases;

BOOST_AUTO_TEST_SUITE(cube_at_rest)

BOOST_AUTO_TEST_CASE(cube_dropped_on_face_settles_at_static_penetration) {
  using Law = ContactLaw<double, Hertz, NoFriction>;
  const ConvexShape cube = cs::thesis_cube();
  const double g = 9.81, m = cs::kThesisDensity * cube.volume, h = cs::cube_half_edge(cube);
  const double kd = 5e4;  // kg s^-1 m^-1/2, thesis Figs 3.14-3.15
  const Law law{Hertz<double>::from_stiffness(cs::kThesisKn, cube.bounding_radius, kd).without_tension(), {}};
  const double delta_s = std::pow(m * g / cs::kThesisKn, 2.0 / 3.0), y_rest = h - delta_s;
  // Dropped from 0.2 mm (the thesis gives no height). dt resolves the damping of the impact where
  // it acts at a corner (effective mass 1/(1/m + r^2/I) ~ 1e-5 kg, K_D delta^(1/2) ~ 30 kg/s: the
  // explicit limit is ~5e-7 s; the thesis's 1e-5 s is far beyond it). The no-tension clamp:
  // while the cube rises out of the floor the dashpot pulls, and a pulling force at the contact
  // point tips a flat face over (negative rocking stiffness); without the clamp the rocking grew
  // from rounding during the rebound and, undamped by a dashpot acting at the face centre, left
  // |w| R ~ 4e-6 m/s for some dt. 12 ms: the fall (6.4 ms), the impact and ~5 ms of settling (the
  // rest state's damping rate is ~3e4 /s).
  const double drop = 2e-4, dt = 2e-7, duration = 0.012;
  const Eigen::Vector3d up(0, 1, 0), side(1, 0, 0);
  auto sim = cs::body_over_floor(cube, cs::kThesisDensity, law, floor_square<double>(0.0, 0.02),
                                 cs::cube_facing<double>(cube, -up, side), {0, h + drop, 0}, {0, 0, 0}, {0, -g, 0}, dt,
                                 {-0.01, -0.01, -0.01}, {0.01, 0.02, 0.01});
  FigureData fig("fig-3.14", "t_s y_mm y_rest_mm penetration_nm delta_s_nm vy_m_per_s");
  const long steps = static_cast<long>(duration / dt), every = 10;
  int contacts = 0;
  bool touching = false;
  double last_contact_start = 0;
  for (long k = 1; k <= steps; ++k) {
    sim.step();
    if (k % every != 0) continue;
    const auto st = sim.state();
    const double y = st.position[0].y;
    if ((y < h) != touching) {
      touching = !touching;
      if (touching) ++contacts, last_contact_start = sim.time();
    }
    fig.row(sim.time(), y * 1e3, y_rest * 1e3, (h - y) * 1e9, delta_s * 1e9, st.velocity[0].y);
  }
  const auto st = sim.state();
  const double y = st.position[0].y;
  const double speed = norm(st.velocity[0]) + norm(st.angular_velocity[0]) * cube.bounding_radius;
  BOOST_TEST_MESSAGE("cube at rest: m = " << m << " kg, delta_s = " << delta_s << " m, y = " << y << " m (exact " << y_rest
                                          << "), penetration " << h - y << " m, " << contacts
                                          << " contact starts (last at " << last_contact_start << " s), |v| + |w| R = " << speed
                                          << " m/s");
  check_relative({"Cube dropped on its face (3.3.1.3, Figs 3.14-3.15)",
                  "static penetration h - y vs delta_s = (m g / K_n)^(2/3) = 7.0e-9 m, double, dt = 2e-7 s",
                  "qualitative", "K_n delta^(3/2) = m g, deepest-vertex overlap"},
                 h - y, delta_s, tol::cube_rest_penetration);
  check_at_most({"Cube dropped on its face (3.3.1.3, Figs 3.14-3.15)", "|v| + |w| R after settling (m/s), double", "qualitative",
                 "rest"},
                speed, tol::rest_speed_double);
  // The energy the resting contact stores (Simulation::contact_energy(), the polyhedron path):
  // (2/5) K_n delta_s^(5/2) = (2/5) m g delta_s, in the one wall contact.
  const ContactEnergy stored = sim.contact_energy();
  BOOST_TEST(stored.wall_contacts == 1);
  BOOST_TEST(stored.pairs == 0.0);
  check_relative({"Cube dropped on its face (3.3.1.3, Figs 3.14-3.15)",
                  "stored elastic energy at rest vs (2/5) m g delta_s, double, dt = 2e-7 s", "-",
                  "U = (2/5) K_n delta^(5/2), K_n delta_s^(3/2) = m g"},
                 stored.walls, 0.4 * m * g * delta_s, 2.5 * tol::cube_rest_penetration);
}

// The rest state above rests on the polyhedron-wall contact point. The overlap is the deepest
// vertex's depth, so the force is conservative only if it acts through that vertex (it is the
// gradient of 2/5 K_n delta^(5/2) with delta = max_k depth_k); polyhedron_shape.hpp spreads the point
// over the vertices within 1% of that depth. The thesis's point, the mean of all penetrating
// vertices, is not that gradient: an elastic cube dropped almost flat left the floor with up to
// 2.2 times the kinetic energy it arrived with. Here 32 near-flat (tilts ~1 degree) and 32 random
// orientations, elastic and frictionless, no gravity, V = 0.5 m/s, dt = t_c/800 of a flat impact:
// after 20 t_c each cube's energy (translation + rotation + elastic 2/5 K_n delta^(5/2), for the
// few still touching) must equal the energy it arrived with, to the issue-3 bound for elastic
// polyhedron collisions (0.5%).
BOOST_AUTO_TEST_CASE(elastic_drops_keep_their_energy) {
  using Law = ContactLaw<double, Hertz, NoFriction>;
  const ConvexShape cube = cs::thesis_cube();
  PolyhedronShape<double> shape;
  shape.table.add(cube, cs::kThesisDensity);
  const double m = cs::kThesisDensity * cube.volume, v = 0.5, r = cube.bounding_radius;
  const double delta_max = std::pow(5 * m * v * v / (4 * cs::kThesisKn), 0.4), t_c = 2.9432 * delta_max / v;
  const double dt = t_c / 800, spacing = 4 * r;
  std::mt19937_64 rng(11);
  std::normal_distribution<double> normal;
  const Quat<double> flat = cs::cube_facing<double>(cube, Eigen::Vector3d(0, -1, 0), Eigen::Vector3d(1, 0, 0));
  ParticleState<double> s;
  const int side = 8, n = side * side;
  for (int k = 0; k < n; ++k) {
    const double tilt = 1.0 * kPi / 180;
    const Quat<double> q = k < n / 2 ? normalized(Quat<double>{1, 0.5 * tilt * normal(rng), 0, 0.5 * tilt * normal(rng)} * flat)
                                     : normalized(Quat<double>{normal(rng), normal(rng), normal(rng), normal(rng)});
    double lowest = 0;  // lowest vertex below the centre, m
    for (const auto& p : cube.vertices) lowest = std::min(lowest, rotate(q, Vec3<double>{p.x(), p.y(), p.z()}).y);
    add_polyhedron(s, shape.table, 0, Vec3<double>{(k % side) * spacing, -lowest + 0.02 * delta_max, (k / side) * spacing}, q, 0,
                   Vec3<double>{0, -v, 0});
  }
  PairTable<Law> laws;
  laws.set(0, 1, Law{Hertz<double>::from_stiffness(cs::kThesisKn, r, 0), {}});
  laws.set(0, 0, laws(0, 1));
  World<double> world;
  world.polygons.push_back(floor_square<double>(0.0, side * spacing));
  const double extent = side * spacing;
  const SimulationParams<double> prm{dt, {0, 0, 0}, {-spacing, -spacing, -spacing}, {extent, 2 * r + spacing, extent}, 0.2 * r};
  Simulation<DefaultSpace, PolyhedronShape<double>, Law, VelocityVerlet> sim(prm, laws, world, s, shape);
  sim.run(static_cast<std::uint64_t>(std::ceil(20 * t_c / dt)));
  const auto st = sim.state();
  const double k_n = cs::kThesisKn;  // exact for this contact (r_ref = bounding radius)
  double worst = 0;
  int touching = 0;
  for (std::size_t i = 0; i < st.size(); ++i) {
    const auto g = sim.shape().collide_world({st.position[i], st.orientation[i], st.type[i], 0}, world.polygons[0]);
    touching += g.touching;
    const Mat3<double> rot = Mat3<double>::rotation(st.orientation[i]);
    const Vec3<double> wb = rot.transpose_times(st.angular_velocity[i]);
    const double energy = 0.5 * m * norm2(st.velocity[i]) +
                          0.5 * (wb.x * wb.x * st.inertia[i].x + wb.y * wb.y * st.inertia[i].y + wb.z * wb.z * st.inertia[i].z) +
                          (g.touching ? 0.4 * k_n * std::pow(g.overlap, 2.5) : 0.0);
    worst = std::max(worst, std::fabs(energy / (0.5 * m * v * v) - 1));
  }
  BOOST_TEST_MESSAGE("elastic cube drops: " << n - touching << " of " << n << " have left the floor, worst |dE|/E " << worst);
  check_at_most({"Cube dropped on its face (3.3.1.3, Figs 3.14-3.15)",
                 "elastic drops, 32 near-flat + 32 random orientations: max |E / E_0 - 1| (kinetic + elastic), dt = t_c/800",
                 "-", "conservative contact: the force acts through the deepest vertex"},
                worst, tol::polyhedron_collision_energy);
}

BOOST_AUTO_TEST_SUITE_END()
