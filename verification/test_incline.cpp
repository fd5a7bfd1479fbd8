// A ball on an incline (standard rigid-body check; e.g. Goldstein, Classical Mechanics, or any
// text on rolling with Coulomb friction). A solid sphere (I = 2/5 m r^2) released at rest on a plane
// tilted by theta, friction coefficient mu:
//   rolls without slipping iff tan(theta) <= (7/2) mu, with a = (5/7) g sin(theta)   (F_t = (2/7) m g sin(theta))
//   otherwise slides and spins up, with  a = g (sin(theta) - mu cos(theta))        (F_t = mu m g cos(theta))
// (m/s^2). The history-free law (thesis eq. 2.3) F_t = -min(mu F_n, K_T |v_t|) v_t/|v_t| has no
// static friction: rolling needs a steady slip v_t = F_t / K_T = 2 m g sin(theta) / (7 K_T) at the
// contact point. The slip is constant, so it does not change the acceleration; it settles with
// the time constant 2 m / (7 K_T) = 0.37 ms.
// The plane is the floor y = 0 and gravity is tilted instead: g = 9.81 (sin(theta), -cos(theta), 0).
// Sphere r = 5 mm, 2500 kg/m^3; linear normal spring k = 1e4 N/m (static overlap 1.3e-6 m, 2.6e-4 r),
// e = 0.3; K_T = 1 kg/s. The acceleration is the least-squares slope of v(t) over 20-150 ms.
#include <boost/test/unit_test.hpp>
#include <cmath>
#include <cstdio>
#include "verification/report.hpp"
#include "verification/scenes.hpp"

using namespace blaze;
using namespace blaze::test;

namespace {

constexpr double kG = 9.81, kRadius = 5e-3, kDensity = 2500, kStiffness = 1e4, kKt = 1.0;
constexpr double kDt = 2e-5;  // s: t_c/56 of the normal contact, t/18 of the slip's settling time

struct InclineCase {
  double theta_deg, mu;
};
// On both sides of the threshold tan(theta) = 3.5 mu, two of them within 10% of it.
const InclineCase kCases[] = {{10, 0.3}, {30, 0.2}, {33, 0.2}, {55, 0.5}, {37, 0.2}, {45, 0.2}, {20, 0.05}, {70, 0.5}};

struct InclineResult {
  double acceleration;  // m/s^2, fitted
  double slip;          // m/s, contact-point slip at the end
  double speed;         // m/s, at the end
};

InclineResult roll_down(const InclineCase& c, FigureData& fig) {
  const double theta = c.theta_deg * kPi / 180;
  const Vec3<double> g{kG * std::sin(theta), -kG * std::cos(theta), 0};
  const auto law = LinearLaw<double>{LinearSpringDashpot<double>::from_restitution(kStiffness, 0.3),
                                     HistoryFreeFriction<double>::make(c.mu, kKt)};
  const double m = kDensity * 4.0 / 3.0 * kPi * std::pow(kRadius, 3);
  const double overlap = m * kG * std::cos(theta) / kStiffness;
  ParticleState<double> s;
  s.add_sphere({0, kRadius - overlap, 0}, kRadius, kDensity, 0);
  World<double> world;
  world.polygons.push_back(floor_square<double>(0.0, 1.0));
  const double t_end = 0.15, t_fit = 0.02, dt = kDt;
  const SimulationParams<double> prm{dt, g, {-0.05, -0.05, -0.05}, {0.5 * kG * t_end * t_end + 0.05, 0.05, 0.05}, 0.2 * kRadius};
  SphereSim<LinearLaw<double>> sim(prm, one_law(law), world, s);
  double n = 0, st = 0, sv = 0, stt = 0, stv = 0, slip = 0, speed = 0;
  const long steps = static_cast<long>(std::llround(t_end / dt));
  for (long k = 1; k <= steps; ++k) {
    sim.step();
    if (k % 10 != 0) continue;
    const auto p = sim.state();
    const double t = sim.time(), v = p.velocity[0].x;
    // Contact point below the centre at r - overlap/2 (sphere_shape.hpp): slip = v_x + w_z (r - delta/2).
    const double arm = kRadius - 0.5 * (kRadius - p.position[0].y);
    slip = v + p.angular_velocity[0].z * arm;
    speed = v;
    fig.row(t, v, slip);
    if (t < t_fit) continue;
    n += 1, st += t, sv += v, stt += t * t, stv += t * v;
  }
  return {(n * stv - st * sv) / (n * stt - st * st), slip, speed};
}

}  // namespace

BOOST_AUTO_TEST_SUITE(incline)

BOOST_AUTO_TEST_CASE(rolls_iff_tan_theta_below_three_and_a_half_mu) {
  FigureData fig("fig-incline", "t_s v_m_per_s slip_m_per_s (one block per case)");
  FigureData summary("fig-incline-summary", "tan_theta_over_mu a_over_g_sin_theta theta_deg mu rolls");
  const double m = kDensity * 4.0 / 3.0 * kPi * std::pow(kRadius, 3);
  int wrong_regime = 0;
  double worst_slip = 0;
  for (const auto& c : kCases) {
    const double theta = c.theta_deg * kPi / 180, ratio = std::tan(theta) / c.mu;
    const bool rolls = ratio <= 3.5;
    const double expected = rolls ? 5.0 / 7.0 * kG * std::sin(theta) : kG * (std::sin(theta) - c.mu * std::cos(theta));
    char title[96];
    std::snprintf(title, sizeof title, "theta = %g deg, mu = %g (%s)", c.theta_deg, c.mu, rolls ? "rolls" : "slides");
    fig.block(title);
    const InclineResult r = roll_down(c, fig);
    // Rolling keeps the slip at its steady F_t / K_T; sliding lets it grow with the speed.
    const double steady_slip = 2 * m * kG * std::sin(theta) / (7 * kKt);
    const bool measured_rolls = r.slip < 0.01 * r.speed;
    wrong_regime += measured_rolls != rolls;
    if (rolls) worst_slip = std::max(worst_slip, std::fabs(r.slip / steady_slip - 1));
    BOOST_TEST_MESSAGE(title << ": a = " << r.acceleration << " m/s^2 (expected " << expected << "), slip at the end "
                             << r.slip << " m/s (steady rolling slip " << steady_slip << "), speed " << r.speed << " m/s");
    char quantity[128];
    std::snprintf(quantity, sizeof quantity, "acceleration, theta = %g deg, mu = %g, tan/mu = %.2f (%s), dt = %g s",
                  c.theta_deg, c.mu, ratio, rolls ? "rolls" : "slides", kDt);
    check_relative({"Ball rolling on an incline (standard check)", quantity, "-",
                    rolls ? "rolling: a = (5/7) g sin(theta)" : "sliding: a = g (sin(theta) - mu cos(theta))"},
                   r.acceleration, expected, tol::incline_acceleration);
    summary.row(ratio, r.acceleration / (kG * std::sin(theta)), c.theta_deg, c.mu, rolls ? 1 : 0);
  }
  check_at_most({"Ball rolling on an incline (standard check)", "cases whose regime (slip < 1% of speed) contradicts tan(theta) <= 3.5 mu",
                 "-", "rolling iff tan(theta) <= (7/2) mu"},
                wrong_regime, 0);
  check_at_most({"Ball rolling on an incline (standard check)", "rolling cases: |slip / (2 m g sin(theta) / 7 K_T) - 1|",
                 "-", "history-free friction: F_t = K_T v_t"},
                worst_slip, tol::incline_rolling_slip);
}

BOOST_AUTO_TEST_SUITE_END()
