// Time integration (thesis section 2.3.2): exact quaternion rotation (eqs. 2.8-2.10, corrected),
// exact ballistic flight for velocity Verlet, and the convergence order of each scheme measured on
// a harmonic contact oscillator: a sphere pressed into a linear-spring floor under gravity that
// never leaves contact, y(t) = y_eq + A cos(w t), w = sqrt(k/m).
#include <boost/test/unit_test.hpp>
#include <boost/mpl/list.hpp>
#include <cmath>
#include <random>
#include <Eigen/Geometry>
#include "verification/scenes.hpp"

using namespace blaze;
using namespace blaze::test;

BOOST_AUTO_TEST_SUITE(integrators)

// One revolution per second about x for 1 s at dt = 1e-5 (the thesis's Fig 2.9 case, where its
// eq. 2.9 dropped dt): the cube-free version, a sphere spinning with no torque.
BOOST_AUTO_TEST_CASE(quaternion_spin_one_revolution) {
  ParticleState<double> s;
  s.add_sphere({0, 0, 0}, 0.01, 2500, 0);
  s.angular_velocity[0] = {2 * kPi, 0, 0};
  SphereSim<LinearLaw<double>> sim(params<double>(1e-5), one_law(LinearLaw<double>{LinearSpringDashpot<double>::from_restitution(1e5, 1), HistoryFreeFriction<double>::make(0, 0)}), World<double>{}, s);
  double max_norm_error = 0;
  for (int k = 0; k < 4; ++k) {
    sim.run(25000);  // quarter turns
    const auto q = sim.state().orientation[0];
    max_norm_error = std::fmax(max_norm_error, std::fabs(std::sqrt(q.w * q.w + q.x * q.x + q.y * q.y + q.z * q.z) - 1));
    // After k+1 quarter turns the angle is (k+1) pi/2: q = (cos, sin, 0, 0) of half of it.
    const double half = (k + 1) * kPi / 4;
    BOOST_TEST(std::fabs(q.w - std::cos(half)) <= tol::spin_angle_double);
    BOOST_TEST(std::fabs(q.x - std::sin(half)) <= tol::spin_angle_double);
    // A body-fixed point stays on its circle.
    const auto p = rotate(q, Vec3<double>{0, 1, 0});
    BOOST_TEST(std::fabs(p.y * p.y + p.z * p.z - 1) <= tol::spin_angle_double);
  }
  BOOST_TEST(max_norm_error <= tol::quaternion_norm_drift);
}

// One orientation step (core/quat.hpp) against the exact rotation by |w| dt about w, for step
// angles from 1e-9 to 1 rad: both sides of the switch from the Taylor series to the sines (half
// angle 0.05), random axes and starting orientations, double and float.
using Reals = boost::mpl::list<float, double>;
BOOST_AUTO_TEST_CASE_TEMPLATE(orientation_step_is_the_exact_rotation, Real, Reals) {
  std::mt19937_64 rng(12345);
  std::normal_distribution<double> g;
  double worst = 0;
  for (int k = 0; k < 2000; ++k) {
    const double angle = std::pow(10.0, -9 + 9 * (k % 200) / 199.0) * (k % 2 ? 1.0 : 0.999);  // rad, per step
    const Eigen::Vector3d axis = Eigen::Vector3d(g(rng), g(rng), g(rng)).normalized();
    const Eigen::Quaterniond q0 = Eigen::Quaterniond(g(rng), g(rng), g(rng), g(rng)).normalized();
    const double dt = 1e-5, rate = angle / dt;
    const Quat<Real> q{Real(q0.w()), Real(q0.x()), Real(q0.y()), Real(q0.z())};
    const Vec3<Real> w{Real(rate * axis.x()), Real(rate * axis.y()), Real(rate * axis.z())};
    const Quat<Real> step = integrate_orientation(q, w, Real(dt));
    // The reference rotates the rounded inputs exactly (long double).
    using L = long double;
    const L wx = w.x, wy = w.y, wz = w.z, wn = std::sqrt(wx * wx + wy * wy + wz * wz), h = wn * L(Real(dt)) / 2;
    const L c = std::cos(h), sn = std::sin(h) / wn;
    const L dw = c, dx = sn * wx, dy = sn * wy, dz = sn * wz, qw = q.w, qx = q.x, qy = q.y, qz = q.z;
    const L ew = dw * qw - dx * qx - dy * qy - dz * qz, ex = dw * qx + dx * qw + dy * qz - dz * qy;
    const L ey = dw * qy - dx * qz + dy * qw + dz * qx, ez = dw * qz + dx * qy - dy * qx + dz * qw;
    const L nq = std::sqrt(qw * qw + qx * qx + qy * qy + qz * qz);  // the rounded start is a unit quaternion only to rounding
    for (L e : {std::fabs(step.w - ew / nq), std::fabs(step.x - ex / nq), std::fabs(step.y - ey / nq), std::fabs(step.z - ez / nq)})
      worst = std::max(worst, static_cast<double>(e));
  }
  BOOST_TEST_MESSAGE("orientation step, " << (sizeof(Real) == 8 ? "double" : "float") << ": worst component error " << worst);
  BOOST_TEST(worst <= (sizeof(Real) == 8 ? tol::orientation_step_double : tol::orientation_step_float));
}

BOOST_AUTO_TEST_CASE(velocity_verlet_is_exact_for_constant_acceleration) {
  ParticleState<double> s;
  s.add_sphere({0, 0, 0}, 0.1, 2500, 0, {1.0, 2.0, -0.5});
  const Vec3<double> g{0.3, -9.81, 0.1};
  SphereSim<LinearLaw<double>> sim(params<double>(1e-4, g, 5.0), one_law(LinearLaw<double>{LinearSpringDashpot<double>::from_restitution(1e5, 1), HistoryFreeFriction<double>::make(0, 0)}), World<double>{}, s);
  sim.run(10000);
  const double t = sim.time();
  const auto x = sim.state().position[0];
  BOOST_TEST(std::fabs(x.x - (1.0 * t + 0.5 * g.x * t * t)) <= tol::ballistic_position);
  BOOST_TEST(std::fabs(x.y - (2.0 * t + 0.5 * g.y * t * t)) <= tol::ballistic_position);
  BOOST_TEST(std::fabs(x.z - (-0.5 * t + 0.5 * g.z * t * t)) <= tol::ballistic_position);
}

namespace {

// Phase-space error |(y, v/w) - exact| after 3.25 periods of the contact oscillator, for a given
// number of steps per period. (Position alone would hide Euler's first-order amplitude growth
// at a zero crossing, and a phase error at an extremum.)
template <class Integrator>
double oscillator_error(int steps_per_period) {
  const double r = 5e-3, rho = 2500, k = 1e5, g = 9.81;
  const double m = rho * 4.0 / 3.0 * kPi * r * r * r, w = std::sqrt(k / m);
  const double y_eq = r - m * g / k, amplitude = 0.5 * m * g / k;  // stays in contact
  const double period = 2 * kPi / w, dt = period / steps_per_period;
  ParticleState<double> s;
  s.add_sphere({0, y_eq + amplitude, 0}, r, rho, 0);
  World<double> world;
  world.polygons.push_back(floor_square<double>(0.0, 0.05));
  using Law = LinearLaw<double>;
  SphereSim<Law, Integrator> sim(params<double>(dt, {0, -g, 0}, 0.5, 0.1 * r),
                                 one_law(Law{LinearSpringDashpot<double>::from_restitution(k, 1), HistoryFreeFriction<double>::make(0, 0)}),
                                 world, s);
  sim.run(static_cast<std::uint64_t>(13 * steps_per_period / 4));
  const auto st = sim.state();
  const double t = sim.time();
  const double dy = st.position[0].y - (y_eq + amplitude * std::cos(w * t));
  const double dv = st.velocity[0].y - (-amplitude * w * std::sin(w * t));
  return std::hypot(dy, dv / w);
}

template <class Integrator>
double measured_order() {
  const double e1 = oscillator_error<Integrator>(400), e2 = oscillator_error<Integrator>(800),
               e3 = oscillator_error<Integrator>(1600);
  BOOST_TEST_MESSAGE(Integrator::name << " errors " << e1 << " " << e2 << " " << e3);
  return 0.5 * (std::log2(e1 / e2) + std::log2(e2 / e3));
}

}  // namespace

BOOST_AUTO_TEST_CASE(convergence_orders) {
  BOOST_TEST(std::fabs(measured_order<VelocityVerlet>() - 2) <= tol::convergence_order);
  BOOST_TEST(std::fabs(measured_order<ForwardEuler>() - 1) <= tol::convergence_order);
  // The thesis's modified Verlet (eqs. 2.5-2.6) is first order: its velocity update is centred a
  // half step too early.
  BOOST_TEST(std::fabs(measured_order<ThesisVerlet>() - 1) <= tol::convergence_order);
}

BOOST_AUTO_TEST_SUITE_END()
