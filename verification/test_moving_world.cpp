// Moving world objects (issue 19): prescribed motions (blaze/world/motion.hpp), the move-world
// phase and the wall's velocity in the contact (kernels/world_forces.hpp).
// - Poses: for rotation (ramped), translation (ramped) and vibration (ramped), the velocity field
//   the pose reports equals the time derivative of the placed points (central differences), and
//   the placed geometry keeps its shape (distances between placed points).
// - A sphere (no rotation) resting on a turntable that spins up is carried at omega x r (1%), for
//   radii and speeds whose centripetal need stays below mu g.
// - A sphere resting on a plate vibrating vertically at Gamma = A w^2 / g: it stays on the plate
//   at Gamma = 0.98 and leaves it at Gamma = 1.02 (the 2% around the threshold), at two
//   frequencies.
// - A sphere at rest hit by a wall translating at V: it leaves at (1 + e) V (the restitution in
//   the wall's frame, 1%), for e = 0.5 and 0.9 and two speeds; with e = 1 the drive work the
//   run's log books equals the kinetic energy given, 2 m V^2, and the balance holds.
// - A sphere in a drum spun up rides with the shell while below the friction angle.
// - A wall removed at t_r: a sphere resting on it is at rest before and falls freely after.
// - A moving world restarted from a snapshot ends bitwise where the uninterrupted run does.
#include <boost/test/unit_test.hpp>
#include <cmath>
#include <filesystem>
#include "blaze/scene/mill_geometry.hpp"
#include "blaze/sim/centrifuging.hpp"
#include "blaze/sim/charge_field.hpp"
#include "blaze/sim/charge_profile.hpp"
#include "pipeline/run_log.hpp"
#include "verification/report.hpp"
#include "verification/run_program.hpp"
#include "verification/scenes.hpp"
#include "verification/tolerances.hpp"

using namespace blaze;
using namespace blaze::test;

namespace {

const char* const kCase = "Moving world objects (issue 19)";
constexpr double kG = 9.81;

template <class Law>
using LeanSim = Simulation<DefaultSpace, SphereShape, Law, VelocityVerlet, ContactPointVelocity, TranslationOnly>;

Motion rotation(Vec3<double> axis, Vec3<double> point, double omega, double ramp, double start = 0) {
  Motion m;
  m.kind = MotionKind::rotation, m.axis = axis * (1 / norm(axis)), m.point = point, m.omega = omega, m.ramp = ramp,
  m.start = start;
  return m;
}
Motion translation(Vec3<double> v, double ramp, double start = 0) {
  Motion m;
  m.kind = MotionKind::translation, m.velocity = v, m.ramp = ramp, m.start = start;
  return m;
}
Motion vibration(Vec3<double> d, double amplitude, double frequency, double ramp, double start = 0) {
  Motion m;
  m.kind = MotionKind::vibration, m.direction = d * (1 / norm(d)), m.amplitude = amplitude, m.frequency = frequency,
  m.ramp = ramp, m.start = start;
  return m;
}

// The largest |v_pose(x) - dx/dt| over a few points and times, relative to the largest speed.
double velocity_field_error(const Motion& m) {
  const Vec3<double> pts[3] = {{0.1, 0.2, -0.3}, {-0.4, 0.05, 0.2}, {0.3, -0.2, 0.1}};
  double worst = 0, speed = 0;
  const double h = 1e-6;
  for (double t : {0.05, 0.13, 0.37, 0.77, 1.9}) {  // away from the ramps' ends (kinks)
    const Pose<double> p = pose_at<double>(m, t), a = pose_at<double>(m, t - h), b = pose_at<double>(m, t + h);
    for (const auto& x : pts) {
      const Vec3<double> fd = (b.place(x) - a.place(x)) * (1 / (2 * h));
      worst = std::fmax(worst, norm(p.velocity_at(p.place(x)) - fd));
      speed = std::fmax(speed, norm(fd));
      // rigid: distances between placed points are kept
      BOOST_TEST(std::fabs(norm(p.place(pts[0]) - p.place(pts[1])) - norm(pts[0] - pts[1])) < 1e-12);
    }
  }
  BOOST_TEST_REQUIRE(speed > 0);
  return worst / speed;
}

}  // namespace

BOOST_AUTO_TEST_SUITE(moving_world)

BOOST_AUTO_TEST_CASE(pose_velocities_are_the_derivatives_of_the_placement) {
  const double rot = velocity_field_error(rotation({0.3, 1, -0.2}, {0.1, -0.2, 0.3}, 4.0, 0.4, 0.02));
  const double tra = velocity_field_error(translation({0.5, -0.2, 0.1}, 0.3, 0.01));
  const double vib = velocity_field_error(vibration({0, 1, 0.2}, 2e-3, 7.0, 0.25, 0.03));
  for (const auto& [what, err] : {std::pair{"rotation", rot}, {"translation", tra}, {"vibration", vib}})
    check_at_most({kCase, std::string("pose velocity vs d/dt of the placement, ") + what, "-",
                   "central difference, h = 1e-6 s"},
                  err, tol::pose_velocity_difference);
  // removal
  Motion gate;
  gate.remove = 0.5;
  BOOST_TEST(pose_at<double>(gate, 0.4999).active);
  BOOST_TEST(!pose_at<double>(gate, 0.5).active);
}

// A sphere that cannot spin (so it cannot roll) resting on a turntable spun up over T_r: once
// the table turns steadily the sphere moves with it, v = omega x r, as long as omega^2 r < mu g.
BOOST_AUTO_TEST_CASE(a_sphere_on_a_turntable_is_carried_at_omega_cross_r) {
  using Law = LinearSpringLaw<double>;
  const double r = 5e-3, kn = 2e4, mu = 0.5;
  const auto normal = LinearSpringDashpot<double>::from_restitution(kn, 0.3);
  const Law law{normal, TangentialSpring<double>::linear(mu, 2.0 / 7.0 * kn, normal.beta)};
  for (double radius : {0.05, 0.12})
    for (double omega : {2.0, 5.0}) {
      if (omega * omega * radius > 0.5 * mu * kG) continue;  // would slide
      ParticleState<double> s;
      const double m = 2500 * 4.0 / 3.0 * kPi * r * r * r;
      const double rest = m * kG / kn;  // the spring's compression at rest
      s.add_sphere({radius, r - rest, 0}, r, 2500, 0);
      World<double> w;
      w.polygons.push_back(floor_square<double>(0, 0.2));
      w.set_motion(0, rotation({0, 1, 0}, {0, 0, 0}, omega, 0.5, 0.1));
      const double dt = 0.02 * 2 * kPi * std::sqrt(m / kn);
      LeanSim<Law> sim(params<double>(dt, {0, -kG, 0}, 0.5, 1e-3), one_law(law), w, s);
      sim.run(static_cast<std::uint64_t>(std::llround(1.2 / dt)));
      const auto st = sim.state();
      const Vec3<double> x = st.position[0], v = st.velocity[0];
      const Vec3<double> expected = cross(Vec3<double>{0, omega, 0}, x);
      BOOST_TEST_MESSAGE("turntable: rho = " << radius << " m, omega = " << omega << " rad/s: |v| = " << norm(v) << " m/s, omega rho = "
                                             << omega * radius << ", |x_xz| = " << std::hypot(x.x, x.z));
      check_relative({kCase, "sphere on a turntable: |v - omega x r| / (omega r)", "-", "no slip once spun up"},
                     norm(v - expected) + omega * radius, omega * radius, tol::carried_by_wall);
      check_relative({kCase, "sphere on a turntable: distance from the axis kept", "-", "no slip"}, std::hypot(x.x, x.z), radius,
                     tol::carried_by_wall);
    }
}

// A drum (horizontal axis, gravity down) spun up from rest: a sphere that cannot spin, resting at
// its bottom with mu = 1, rides up with the shell (the spring holds it) while the tilt stays below
// the friction angle (45 degrees): at theta = 0.5 rad its contact point moves with the shell.
BOOST_AUTO_TEST_CASE(a_sphere_in_a_drum_spun_up_rides_with_the_shell) {
  using Law = LinearSpringLaw<double>;
  const double r = 5e-3, kn = 5e4, drum = 0.1;
  const auto normal = LinearSpringDashpot<double>::from_restitution(kn, 0.3);
  const Law law{normal, TangentialSpring<double>::linear(1.0, 2.0 / 7.0 * kn, normal.beta)};
  const double m = 2500 * 4.0 / 3.0 * kPi * r * r * r;
  for (double sign : {1.0, -1.0}) {
    ParticleState<double> s;
    s.add_sphere({0, -(drum - r) - m * kG / kn, 0.02}, r, 2500, 0);
    World<double> w;
    w.cylinders.push_back(Cylinder<double>::make({0, 0, 0}, {0, 0, 1}, drum, 0.04, 1));
    w.set_motion(0, rotation({0, 0, sign}, {0, 0, 0}, 0.5, 1.0));
    const double dt = 0.02 * 2 * kPi * std::sqrt(m / kn);
    LeanSim<Law> sim(params<double>(dt, {0, -kG, 0}, 0.2, 1e-3), one_law(law), w, s);
    sim.run(static_cast<std::uint64_t>(std::llround(1.5 / dt)));
    const auto st = sim.state();
    const Vec3<double> x = st.position[0], v = st.velocity[0];
    const Vec3<double> omega{0, 0, sign * 0.5};  // after the ramp
    // A sphere that cannot spin moves as its contact point does, and that point sticks to the
    // shell: v = omega x (contact point), the contact point at radius R on the line to the centre;
    // its centre (at R - r) so turns by theta R / (R - r).
    const double tilt = std::atan2(sign * x.x, -x.y);
    const Vec3<double> contact = Vec3<double>{x.x, x.y, 0} * (drum / std::hypot(x.x, x.y));
    BOOST_TEST_MESSAGE("drum: tilt " << tilt << " rad (theta R / (R - r) = " << 0.5 * drum / (drum - r) << "), |v| = " << norm(v)
                                     << " m/s, omega R = " << 0.5 * drum);
    check_relative({kCase, "sphere in a drum spun up: |v - omega x x_c| / (omega R)", "-", "carried below the friction angle"},
                   norm(v - cross(omega, contact)) + 0.5 * drum, 0.5 * drum, tol::carried_by_wall);
    check_relative({kCase, "sphere in a drum spun up: tilt vs theta(t) R / (R - r)", "-", "no slip at the shell"}, tilt,
                   0.5 * drum / (drum - r), tol::carried_by_wall);
  }
}

// A plate vibrating along y at A sin(w t) (ramped in over 0.2 s): a sphere on it stays in contact
// while the plate's downward acceleration A w^2 stays below g, and leaves it above.
BOOST_AUTO_TEST_CASE(a_sphere_on_a_vibrating_plate_lifts_off_at_gamma_one) {
  using Law = LinearLaw<double>;
  const double r = 4e-3, kn = 4e5;
  const Law law{LinearSpringDashpot<double>::from_restitution(kn, 0.5), HistoryFreeFriction<double>::make(0, 0)};
  const double m = 2500 * 4.0 / 3.0 * kPi * r * r * r;
  for (double f : {15.0, 40.0})
    for (double gamma : {0.98, 1.02}) {
      const double w = 2 * kPi * f, amplitude = gamma * kG / (w * w);
      ParticleState<double> s;
      s.add_sphere({0, r - m * kG / kn, 0}, r, 2500, 0);
      World<double> world;
      world.polygons.push_back(floor_square<double>(0, 0.05));
      world.set_motion(0, vibration({0, 1, 0}, amplitude, f, 0.2));
      const double dt = 0.02 * 2 * kPi * std::sqrt(m / kn);
      LeanSim<Law> sim(params<double>(dt, {0, -kG, 0}, 0.2, 1e-3), one_law(law), world, s);
      // after the ramp, 10 periods: the largest gap between the sphere and the plate
      sim.run(static_cast<std::uint64_t>(std::llround(0.25 / dt)));
      double gap = -1;
      const auto steps = static_cast<std::uint64_t>(std::llround(10 / f / dt));
      for (std::uint64_t k = 0; k < steps; ++k) {
        sim.step();
        const double plate = sim.world_poses()[0].shift.y;
        gap = std::fmax(gap, sim.state().position[0].y - r - plate);
      }
      BOOST_TEST_MESSAGE("vibrating plate: f = " << f << " Hz, Gamma = " << gamma << ": largest gap " << gap * 1e6 << " um (A = "
                                                 << amplitude * 1e6 << " um)");
      if (gamma < 1)
        check_at_most({kCase, "sphere on a vibrating plate, Gamma = 0.98: largest gap / A", "-", "stays on (A w^2 < g)"},
                      gap / amplitude, 0.0);
      else
        check_at_least({kCase, "sphere on a vibrating plate, Gamma = 1.02: largest gap / A", "-", "lifts off (A w^2 > g)"},
                       gap / amplitude, tol::lift_off_gap);
    }
}

// A wall approaching a sphere at rest at V: in the wall's frame the sphere comes in at V and
// leaves at e V, so in the lab it leaves at (1 + e) V.
BOOST_AUTO_TEST_CASE(a_sphere_hit_by_a_translating_wall_rebounds_with_the_restitution_in_its_frame) {
  using Law = LinearLaw<double>;
  const double r = 5e-3, kn = 1e4;
  for (double e : {0.5, 0.9, 1.0})
    for (double speed : {0.5, 2.0}) {
      const Law law{LinearSpringDashpot<double>::from_restitution(kn, e), HistoryFreeFriction<double>::make(0, 0)};
      const double m = 2500 * 4.0 / 3.0 * kPi * r * r * r;
      ParticleState<double> s;
      s.add_sphere({0, 0.02, 0}, r, 2500, 0);
      World<double> world;
      world.polygons.push_back(floor_square<double>(0, 0.05));  // y = 0, normal +y, moving up
      world.set_motion(0, translation({0, speed, 0}, 0));
      const double t_c = kPi * std::sqrt(m / kn);
      const double dt = t_c / 200;
      using Logged = Simulation<DefaultSpace, SphereShape, Law, VelocityVerlet, ContactPointVelocity, MonitoredFeatures>;
      Logged sim(params<double>(dt, {0, 0, 0}, 0.5, 1e-3), one_law(law), world, s);
      const std::string csv = (std::filesystem::temp_directory_path() / "blaze_moving_wall.csv").string();
      {
        RunLog<double> log(csv, 0.05, 0.05, Vec3<double>{0, 0, 0}, 1.0);
        log.sample(sim);
        // the wall reaches the sphere after (0.02 - r) / V, the contact lasts t_c
        sim.run(static_cast<std::uint64_t>(std::llround(((0.02 - r) / speed + 3 * t_c) / dt)));
        log.sample(sim);
      }  // the log's file is complete
      const double v = sim.state().velocity[0].y;
      BOOST_TEST_MESSAGE("translating wall: e = " << e << ", V = " << speed << " m/s: sphere leaves at " << v << " m/s ((1 + e) V = "
                                                  << (1 + e) * speed << ")");
      check_relative({kCase, "sphere hit by a translating wall: rebound speed vs (1 + e) V", "-", "restitution in the wall's frame"},
                     v, (1 + e) * speed, tol::moving_wall_restitution);
      if (e == 1.0) {
        const auto rows = read_csv(csv);
        const double work = rows.at("drive_work_J").back(), dissipated = rows.at("dissipated_J").back();
        const double given = 0.5 * m * v * v;
        check_relative({kCase, "elastic hit by a moving wall: drive work vs kinetic energy given", "-", "W = 1/2 m v^2 = 2 m V^2"},
                       work, given, tol::moving_wall_work);
        check_at_most({kCase, "elastic hit by a moving wall: |dissipated| / W", "-", "E(0) + W = E(t) + dissipated"},
                      std::fabs(dissipated) / work, tol::moving_wall_work);
      }
      std::filesystem::remove(csv);
    }
}

// A run with a moving wall and a wall removed on the way, stopped half way for a checkpoint: the
// restored run (the world placed from the step count, the drive-work accounts restored) ends
// bitwise where the uninterrupted one does, on the CPU.
BOOST_AUTO_TEST_CASE(a_moving_world_restarts_bitwise) {
  using Law = LinearSpringLaw<double>;
  const double r = 3e-3, kn = 2e4;
  const auto normal = LinearSpringDashpot<double>::from_restitution(kn, 0.5);
  const Law law{normal, TangentialSpring<double>::linear(0.5, 2.0 / 7.0 * kn, normal.beta)};
  ParticleState<double> s;
  for (int i = 0; i < 6; ++i)
    for (int k = 0; k < 6; ++k) s.add_sphere({-0.02 + 0.0075 * i, 0.004 + 0.0002 * ((i + k) % 3), -0.02 + 0.0075 * k}, r, 2500, 0);
  World<double> w;
  w.polygons.push_back(floor_square<double>(0, 0.05));
  w.polygons.push_back(PlanarPolygon<double>::make({{-0.05, 0.03, -0.05}, {0.05, 0.03, -0.05}, {0.05, 0.03, 0.05}, {-0.05, 0.03, 0.05}}, 1));
  w.set_motion(0, vibration({0, 1, 0}, 1e-3, 25, 0.05));
  Motion lid;
  lid.remove = 0.05;
  w.set_motion(1, lid);
  using Logged = Simulation<DefaultSpace, SphereShape, Law, VelocityVerlet, ContactPointVelocity, MonitoredFeatures>;
  const auto prm = params<double>(2e-5, {0, -kG, 0}, 0.2, 1e-3);
  Logged whole(prm, one_law(law), w, s);
  whole.run(4000);
  Logged first(prm, one_law(law), w, s);
  first.run(2000);
  Logged second(prm, one_law(law), w, first.snapshot());
  // the same rebuild the snapshot made, in the uninterrupted run's history too
  Logged reference(prm, one_law(law), w, s);
  reference.run(2000);
  (void)reference.snapshot();
  reference.run(2000);
  second.run(2000);
  const auto a = reference.state(), b = second.state();
  bool same = a.size() == b.size();
  for (std::size_t k = 0; same && k < a.size(); ++k)
    same = a.position[k].x == b.position[k].x && a.position[k].y == b.position[k].y && a.velocity[k].y == b.velocity[k].y &&
           a.angular_velocity[k].z == b.angular_velocity[k].z;
  BOOST_TEST(same, "restored run bitwise the same as the uninterrupted one");
  BOOST_TEST(second.sample(1).drive_work == reference.sample(1).drive_work);
  BOOST_TEST((whole.world_poses()[0].shift.y == second.world_poses()[0].shift.y));
  BOOST_TEST(!second.world_poses()[1].active);
}

// A wall removed at t_r = 0.2 s: a sphere resting on it stays put before and falls freely after.
BOOST_AUTO_TEST_CASE(a_removed_wall_lets_its_load_fall) {
  using Law = LinearLaw<double>;
  const double r = 5e-3, kn = 2e4;
  const Law law{LinearSpringDashpot<double>::from_restitution(kn, 0.3), HistoryFreeFriction<double>::make(0, 0)};
  const double m = 2500 * 4.0 / 3.0 * kPi * r * r * r;
  ParticleState<double> s;
  s.add_sphere({0, r - m * kG / kn, 0}, r, 2500, 0);
  World<double> world;
  world.polygons.push_back(floor_square<double>(0, 0.05));
  Motion gate;
  gate.remove = 0.2;
  world.set_motion(0, gate);
  const double dt = 0.02 * 2 * kPi * std::sqrt(m / kn);
  LeanSim<Law> sim(params<double>(dt, {0, -kG, 0}, 0.5, 1e-3), one_law(law), world, s);
  sim.run(static_cast<std::uint64_t>(std::floor(0.199 / dt)));
  BOOST_TEST(std::fabs(sim.state().velocity[0].y) < 1e-6);
  sim.run(static_cast<std::uint64_t>(std::llround(0.1 / dt)));
  const double fall = sim.time() - 0.2;
  check_relative({kCase, "sphere on a removed wall: speed 0.1 s after the removal vs g t", "-", "free fall from rest"},
                 -sim.state().velocity[0].y, kG * fall, tol::removed_wall_fall);
}

// The mill's lifters (include/blaze/scene/mill_geometry.hpp): every face's normal points out of
// its bar; the top lies h inside the shell; a sphere touching a bar is touched once, whether it
// sits on the top, against a face or over a convex edge (the edge belongs to the top face only),
// for square and trapezoidal bars at several row angles.
BOOST_AUTO_TEST_CASE(mill_lifters_are_closed_bars_touched_once) {
  for (double lean : {0.0, 20.0}) {
    MillSpec m;
    m.axis = {0, 0, 1}, m.diameter = 0.9, m.length = 0.15;
    m.lifters.push_back({5, 0.04, 0.05, lean, 10});
    const auto walls = mill_walls(m);
    BOOST_TEST_REQUIRE(walls.size() == 2u + 3u * 5u);
    const double r = 0.45;
    for (int k = 0; k < 5; ++k) {
      std::vector<PlanarPolygon<double>> bar;
      Vec3<double> centre{0, 0, 0};
      for (int f = 0; f < 3; ++f) {
        const auto& w = walls[2 + 3 * k + f];
        bar.push_back(PlanarPolygon<double>::make(w.vertices, 0, w.rim_edges));
        centre += bar.back().centroid * (1.0 / 3);
      }
      for (const auto& p : bar) BOOST_TEST(dot(p.normal, p.centroid - centre) > 0, "a lifter face looks into its bar");
      const Vec3<double> top = bar[0].centroid;
      BOOST_TEST(std::fabs(std::hypot(top.x, top.y) - (std::sqrt(r * r - 0.025 * 0.025) - 0.04)) < 1e-12);
      // spheres of 1 cm touching the top, each face and each long edge, 1 mm deep
      const Vec3<double> in = top * (-1 / norm(top));  // from the top towards the axis
      const Vec3<double> across = cross(Vec3<double>{0, 0, 1}, in * -1.0);
      const double rs = 0.01, depth = 0.001;
      std::vector<Vec3<double>> probes = {top + in * (rs - depth)};
      for (int f = 1; f < 3; ++f) probes.push_back(bar[f].centroid + bar[f].normal * (rs - depth));
      for (double side : {-1.0, 1.0}) {
        // over the long edge on this side: its point halfway along, approached along the bisector
        const Vec3<double> edge = top + across * (side * 0.5 * (0.05 - 2 * 0.04 * std::tan(lean * kPi / 180)));
        const Vec3<double> face_normal = bar[side < 0 ? 1 : 2].normal;
        Vec3<double> bisector = in + face_normal;
        bisector = bisector * (1 / norm(bisector));
        probes.push_back(edge + bisector * (rs - depth));
      }
      for (const auto& x : probes) {
        int touching = 0;
        for (const auto& p : bar) touching += collide_sphere(x, rs, p).touching;
        BOOST_TEST(touching == 1, "lifter " << k << ", lean " << lean << ": a sphere at (" << x.x << ", " << x.y << ") touches "
                                             << touching << " of its bar's polygons");
      }
    }
  }
}

// The charge profile (include/blaze/sim/charge_profile.hpp) of synthetic charges: a packed run of
// balls against the shell from the toe to the shoulder with sparse balls elsewhere, for both
// senses of rotation and a run across the drum's top (phi = 180 deg); a band 2 cm deep.
BOOST_AUTO_TEST_CASE(charge_profile_finds_toe_and_shoulder) {
  const double R = 0.45;
  struct Case {
    double toe, shoulder, sign;
  };
  for (const Case c : {Case{-40, 100, 1}, Case{-40, 100, -1}, Case{-75, 35, 1}, Case{150, -150, 1}}) {
    std::vector<Vec3<double>> x;
    const auto place = [&](double deg, double depth) {
      const double phi = c.sign * deg * kPi / 180;  // world angle about +z from -y
      x.push_back(Vec3<double>{std::sin(phi), -std::cos(phi), 0.01} * (R - depth));
    };
    const double span = c.shoulder > c.toe ? c.shoulder - c.toe : c.shoulder + 360 - c.toe;
    for (double d = 0.25; d < span; d += 0.5) place(c.toe + d, 0.01);           // packed
    for (double d = span + 5; d < 355; d += 10) place(c.toe + d, 0.01);           // sparse
    for (double d = 0; d < 360; d += 3) place(d, 0.1);                             // inside, not in the band
    const ChargeProfile p = charge_profile(x, {0, 0, 0}, {0, 0, 1}, R, 0.02, c.sign);
    BOOST_TEST_REQUIRE(p.found);
    BOOST_TEST(p.toe_deg == c.toe, "toe " << p.toe_deg << " vs " << c.toe);
    BOOST_TEST(p.shoulder_deg == c.shoulder, "shoulder " << p.shoulder_deg << " vs " << c.shoulder);
  }
  BOOST_TEST(!charge_profile(std::vector<Vec3<double>>{{0, 0, 0}}, {0, 0, 0}, {0, 0, 1}, R, 0.02, 1).found);
}

// Centrifuging balls (include/blaze/sim/centrifuging.hpp) of a synthetic revolution: a full ring
// of balls on the shell and a partial second ring one diameter in turn with the drum, a stray ball
// deeper in, a cascading heap that rocks back and forth, and a ball flying past the axis whose
// angle jumps by ~3 rad between samples (it would count 0.9 turns and more); both senses of rotation.
BOOST_AUTO_TEST_CASE(centrifuging_balls_and_their_layers) {
  const double R = 0.275, r = 0.011, d = 2 * r;
  for (double sign : {1.0, -1.0}) {
    CentrifugeTracker tracker({0, 0, 0}, {0, 0, 1}, R, sign);
    const int ring1 = 60, ring2 = 20, heap = 30, samples = 72;
    for (int k = 0; k <= samples; ++k) {
      const double turn = sign * 2 * kPi * k / samples;  // the drum's angle
      std::vector<Vec3<double>> x;
      std::vector<double> radius;
      std::vector<int> id;
      const auto put = [&](double phi, double rho) {
        x.push_back({rho * std::sin(phi), -rho * std::cos(phi), 0});
        radius.push_back(r);
        id.push_back(static_cast<int>(id.size()));
      };
      for (int b = 0; b < ring1; ++b) put(2 * kPi * b / ring1 + turn, R - r);
      for (int b = 0; b < ring2; ++b) put(2 * kPi * b / ring2 + turn, R - r - 0.95 * d);
      put(turn, R - r - 3 * d);  // one ball deeper in: a stray, not a layer
      for (int b = 0; b < heap; ++b) put(0.3 * std::sin(0.7 * k + b), R - r - d * (b % 4));  // rocks, never turns
      // a cataracting ball crossing near the axis, its angle jumping by ~3 rad per sample
      put(sign * 3.0 * k, 0.02);
      tracker.add(x, radius, id);
    }
    const CentrifugingReport rep = tracker.report();
    BOOST_TEST(rep.tracked == ring1 + ring2 + 1 + heap + 1);
    BOOST_TEST(rep.balls == ring1 + ring2 + 1);
    BOOST_TEST(rep.layers == 2);
  }
}

// The time-averaged charge (include/blaze/sim/charge_field.hpp) of a synthetic drum turning as a
// rigid body (v = omega x r) about the z axis and about the x axis (gravity -y): every visited
// cell's mean velocity is omega x r at the balls' mean position, its occupancy the balls per sample;
// the in-plane axes are u = w x a (right, seen from +a), w up; a ball outside the square is left out.
BOOST_AUTO_TEST_CASE(charge_field_averages_a_rigid_rotation) {
  const double R = 0.5, h = 0.05, omega = 2.0;
  for (const Vec3<double> a : {Vec3<double>{0, 0, 1}, Vec3<double>{1, 0, 0}}) {
    ChargeField field({0, 0, 0}, a, {0, -9.81, 0}, R, h);
    const Vec3<double> w_up{0, 1, 0}, u = cross(w_up, a);
    const int samples = 40;
    for (int k = 0; k < samples; ++k) {
      std::vector<Vec3<double>> x, v;
      for (int b = 0; b < 3; ++b) {  // three balls at a cell centre, 0.325 m right of and 0.225 m below the axis
        const Vec3<double> p = u * 0.325 + w_up * (-0.225);
        x.push_back(p), v.push_back(cross(a * omega, p));
      }
      x.push_back(u * 0.9), v.push_back({1, 1, 1});  // outside [-R, R]^2
      field.add(x, v);
    }
    BOOST_TEST(field.samples() == samples);
    const int cell = field.cell_of(0.325, -0.225);
    BOOST_TEST_REQUIRE(cell >= 0);
    BOOST_TEST(field.occupancy(cell) == 3.0);
    const Vec3<double> p = u * 0.325 + w_up * (-0.225), expected = cross(a * omega, p);
    const Vec3<double> mean = field.mean_velocity(cell);
    BOOST_TEST(std::fabs(mean.x - dot(expected, u)) < 1e-12);
    BOOST_TEST(std::fabs(mean.y - dot(expected, w_up)) < 1e-12);
    BOOST_TEST(field.cell_of(0.9, 0) == -1);
    BOOST_TEST(field.occupancy(field.cell_of(0, 0)) == 0.0);
  }
  BOOST_CHECK_THROW(ChargeField({0, 0, 0}, {0, 0, 1}, {0, -9.81, 0}, 0.5, 0.0), std::invalid_argument);
}

BOOST_AUTO_TEST_SUITE_END()
