// Properties every contact law must have, checked for every law combination: normal law (linear
// spring-dashpot, Hertz) x tangential law (HistoryFreeFriction, NoFriction) x precision (float,
// double) as template cases, and inside each the damping variants (linear: elastic, dashpot, dashpot
// with no-tension clamp; Hertz: elastic, K_D delta^(1/2), eta delta^(1/4) from a restitution, each
// damped one also clamped). Random contacts; one row per combination and property.
// - Zero force at zero overlap. Hertz: both dashpots vanish with the overlap (delta^(1/2),
//   delta^(1/4)), so the force is exactly 0 at delta = 0 whatever the motion, and friction with
//   it (mu max(F_n, 0) = 0). Linear: the dashpot does not vanish; at first touch the force jumps
//   from 0 to C_n v_n (Cundall & Strack), with friction min(mu C_n v_n, K_T |v_t|); with the clamp
//   max(C_n v_n, 0). Asserted as such, and that it is 0 without motion.
// - Newton's third law and angular momentum per pair: each side of a pair evaluates the law itself
//   in the real contact kernel; the two forces must cancel and the torques balance x F.
// - Damping never adds energy: the velocity-dependent part (force at v_rel minus force at rest)
//   has power <= 0 on the relative velocity (dashpots, clamp and friction all oppose motion).
#include <boost/test/unit_test.hpp>
#include <boost/mpl/list.hpp>
#include <algorithm>
#include <cmath>
#include <random>
#include <string>
#include <type_traits>
#include <utility>
#include <vector>
#include "verification/report.hpp"
#include "verification/scenes.hpp"

using namespace blaze;
using namespace blaze::test;

namespace {

template <class Real, template <class> class Normal, template <class> class Tangential>
using Law = ContactLaw<Real, Normal, Tangential>;

template <class L>
constexpr bool is_linear = std::is_same_v<decltype(L::normal), LinearSpringDashpot<typename L::real_type>>;
template <class L>
constexpr bool has_friction = std::is_same_v<decltype(L::tangential), HistoryFreeFriction<typename L::real_type>>;

template <class L>
std::string law_name() {
  return std::string(is_linear<L> ? "linear" : "Hertz") + (has_friction<L> ? " + friction" : " + no friction") +
         (sizeof(typename L::real_type) == 8 ? ", double" : ", float");
}

// Every damping variant of the law type, with its name.
template <class L>
std::vector<std::pair<std::string, L>> variants() {
  using Real = typename L::real_type;
  decltype(L::tangential) tangential{};
  if constexpr (has_friction<L>) tangential = HistoryFreeFriction<Real>::make(0.5, 2.0);
  std::vector<std::pair<std::string, L>> out;
  if constexpr (is_linear<L>) {
    const auto damped = LinearSpringDashpot<Real>::from_restitution(1e5, 0.4);
    out.push_back({"elastic", L{LinearSpringDashpot<Real>::from_restitution(1e5, 1.0), tangential}});
    out.push_back({"dashpot", L{damped, tangential}});
    out.push_back({"dashpot, no tension", L{damped.without_tension(), tangential}});
  } else {
    const auto kd = Hertz<Real>::from_stiffness(1e9, 2.5e-3, 1e5);
    const auto eta = Hertz<Real>::from_restitution(1e10, 0.4);
    out.push_back({"elastic", L{Hertz<Real>::from_stiffness(1e9, 2.5e-3, 0), tangential}});
    out.push_back({"K_D delta^1/2", L{kd, tangential}});
    out.push_back({"K_D delta^1/2, no tension", L{kd.without_tension(), tangential}});
    out.push_back({"eta delta^1/4", L{eta, tangential}});
    out.push_back({"eta delta^1/4, no tension", L{Hertz<Real>::from_restitution(1e10, 0.4, true), tangential}});
  }
  return out;
}

template <class Real>
double third_law_tolerance() {
  return sizeof(Real) == 8 ? tol::newton_third_law_double : tol::newton_third_law_float;
}
}  // namespace

BOOST_AUTO_TEST_SUITE(law_properties)

using Laws = boost::mpl::list<Law<float, LinearSpringDashpot, HistoryFreeFriction>, Law<double, LinearSpringDashpot, HistoryFreeFriction>,
                              Law<float, LinearSpringDashpot, NoFriction>, Law<double, LinearSpringDashpot, NoFriction>,
                              Law<float, Hertz, HistoryFreeFriction>, Law<double, Hertz, HistoryFreeFriction>,
                              Law<float, Hertz, NoFriction>, Law<double, Hertz, NoFriction>>;

BOOST_AUTO_TEST_CASE_TEMPLATE(zero_force_at_zero_overlap, L, Laws) {
  using Real = typename L::real_type;
  std::mt19937_64 rng(3);
  std::uniform_real_distribution<double> u(-1, 1);
  const Real m_eff = Real(1e-3);
  double worst = 0;  // Hertz: max |F| / (F scale); linear: max |F - expected| / |expected|
  for (const auto& variant : variants<L>()) {
    const L& law = variant.second;
    for (int trial = 0; trial < 500; ++trial) {
      Vec3<double> n{u(rng), u(rng), u(rng)};
      n *= 1 / norm(n);
      const ContactGeometry<Real> g{true, vec_cast<Real>(n), Real(0), {0, 0, 0}, Real(2.5e-3)};
      const Vec3<Real> v_rel = vec_cast<Real>(Vec3<double>{u(rng), u(rng), u(rng)});
      const Vec3<double> f = vec_cast<double>(law.force(g, v_rel, m_eff));
      // Without motion nothing at all, for every law.
      const Vec3<double> f_still = vec_cast<double>(law.force(g, {0, 0, 0}, m_eff));
      worst = std::max(worst, norm(f_still));
      if constexpr (is_linear<L>) {
        // The dashpot's jump at first touch, C_n v_n (clamped: >= 0), and the friction it carries.
        const double v_n = dot(vec_cast<double>(v_rel), vec_cast<double>(g.normal));
        double f_n = static_cast<double>(law.normal.beta) * std::sqrt(1e5 * static_cast<double>(m_eff)) * v_n;
        if (law.normal.no_tension) f_n = std::max(f_n, 0.0);
        Vec3<double> expected = vec_cast<double>(g.normal) * -f_n;
        const Vec3<double> v_t = vec_cast<double>(v_rel) - v_n * vec_cast<double>(g.normal);
        if constexpr (has_friction<L>) {
          const double mu = law.tangential.mu, kt = law.tangential.kt;
          expected -= v_t * (std::min(mu * std::max(f_n, 0.0), kt * norm(v_t)) / norm(v_t));
        }
        // Relative to the dashpot force at the full relative speed (v_n itself is rounded from a
        // dot product); 1 mN for the elastic variant, which must give 0.
        const double scale = std::max(static_cast<double>(law.normal.beta) * std::sqrt(1e5 * static_cast<double>(m_eff)) *
                                          norm(vec_cast<double>(v_rel)), 1e-3);
        worst = std::max(worst, norm(f - expected) / scale);
      } else {
        worst = std::max(worst, norm(f));  // exactly 0 N
      }
    }
  }
  if constexpr (is_linear<L>)
    check_at_most({"Law properties: force at zero overlap", law_name<L>() + ", all variants: |F - C_n v_n jump| / |jump|", "-",
                   "Cundall & Strack: the dashpot jumps at touch"},
                  worst, sizeof(Real) == 8 ? tol::zero_overlap_jump_double : tol::zero_overlap_jump_float);
  else
    check_at_most({"Law properties: force at zero overlap", law_name<L>() + ", all variants: max |F| (N) at delta = 0", "-",
                   "delta^1/2, delta^1/4 dashpots vanish with delta"},
                  worst, 0.0);
}

BOOST_AUTO_TEST_CASE_TEMPLATE(newton_third_law_and_angular_momentum, L, Laws) {
  using Real = typename L::real_type;
  std::mt19937_64 rng(7);
  std::uniform_real_distribution<double> u(-1, 1);
  double worst_force = 0, worst_momentum = 0;
  for (const auto& variant : variants<L>()) {
    const L& law = variant.second;
    for (int trial = 0; trial < 60; ++trial) {
      ParticleState<Real> s;
      const double r1 = 2e-3 * (1.5 + u(rng)), r2 = 2e-3 * (1.5 + u(rng));
      Vec3<double> dir{u(rng), u(rng), u(rng)};
      dir *= 1 / norm(dir);
      const double dist = (r1 + r2) * (1 - 0.01 * (1 + u(rng)));  // up to 2% overlap
      auto rv = [&](double scale) { return vec_cast<Real>(Vec3<double>{scale * u(rng), scale * u(rng), scale * u(rng)}); };
      s.add_sphere(rv(0.01), Real(r1), Real(2500), 0, rv(1.0));
      s.add_sphere(s.position[0] + vec_cast<Real>(dir * dist), Real(r2), Real(7800), 1, rv(1.0));
      s.angular_velocity = {rv(100.0), rv(100.0)};
      SphereSim<L> sim(params<Real>(1e-7, {0, 0, 0}, 0.1, 1e-3), one_law(law), World<Real>{}, s);
      const auto st = sim.state();
      const auto f = sim.forces(), t = sim.torques();
      const double scale = norm(vec_cast<double>(f[0]));
      if (!(scale > 0)) continue;  // a clamped contact that is separating fast: no force at all
      worst_force = std::max(worst_force, norm(vec_cast<double>(f[0] + f[1])) / scale);
      // Total angular momentum change about the origin: sum of x x F + T.
      Vec3<double> l{0, 0, 0};
      for (int k = 0; k < 2; ++k) l += cross(vec_cast<double>(st.position[k]), vec_cast<double>(f[k])) + vec_cast<double>(t[k]);
      worst_momentum = std::max(worst_momentum, norm(l) / (scale * (r1 + r2)));
    }
  }
  check_at_most({"Law properties: Newton's third law per pair", law_name<L>() + ", all variants: max |F_ij + F_ji| / |F_ij|", "-",
                 "action = reaction"},
                worst_force, third_law_tolerance<Real>());
  check_at_most({"Law properties: Newton's third law per pair",
                 law_name<L>() + ", all variants: max |sum x x F + T| / (|F| (r_i + r_j))", "-", "angular momentum conserved"},
                worst_momentum, third_law_tolerance<Real>());
}

BOOST_AUTO_TEST_CASE_TEMPLATE(damping_never_adds_energy, L, Laws) {
  using Real = typename L::real_type;
  std::mt19937_64 rng(11);
  std::uniform_real_distribution<double> u(-1, 1);
  double worst = -HUGE_VAL;  // max power / (|F| |v|) of the damped variants, must be <= rounding
  long dissipating = 0, damped_trials = 0;
  for (const auto& [name, law] : variants<L>()) {
    const bool damped = name != "elastic" || has_friction<L>;
    for (int trial = 0; trial < 500; ++trial) {
      Vec3<double> n{u(rng), u(rng), u(rng)};
      n *= 1 / norm(n);
      const ContactGeometry<Real> g{true, vec_cast<Real>(n), Real(1e-5 * (1.5 + u(rng))), {0, 0, 0}, Real(2.5e-3)};
      const Vec3<Real> v_rel = vec_cast<Real>(Vec3<double>{u(rng), u(rng), u(rng)});
      const auto f_moving = law.force(g, v_rel, Real(1e-3)), f_still = law.force(g, {0, 0, 0}, Real(1e-3));
      const double power = dot(vec_cast<double>(f_moving - f_still), vec_cast<double>(v_rel));
      const double scale =
          std::max({norm(vec_cast<double>(f_moving)), norm(vec_cast<double>(f_still)), 1e-30}) * norm(vec_cast<double>(v_rel));
      if (!damped) {
        BOOST_TEST(power == 0.0);  // elastic and frictionless: no velocity dependence at all
        continue;
      }
      worst = std::max(worst, power / scale);
      ++damped_trials;
      dissipating += power < 0;
    }
  }
  check_at_most({"Law properties: damping never adds energy",
                 law_name<L>() + ", damped variants: max (F(v) - F(0)) . v / (|F| |v|)", "-", "dissipation >= 0"},
                worst, tol::dissipation_rounding);
  // And the damped variants really do dissipate (a test of a dead dashpot would pass the above).
  check_at_least({"Law properties: damping never adds energy", law_name<L>() + ", damped variants: fraction of contacts dissipating",
                  "-", "dashpot / friction active"},
                 static_cast<double>(dissipating) / static_cast<double>(damped_trials), 0.9);
}

// The thesis's w_R = (w_i + w_j)/2 shortcut (with the sign of w x r) is exact when the contact is
// midway between the centres (equal spheres: r_j = -r_i) and wrong otherwise.
BOOST_AUTO_TEST_CASE(thesis_mean_omega_option_is_exact_only_for_equal_arms) {
  const Vec3<double> v{0.1, 0, 0}, w_i{0, 3, 0}, w_j{0, 0, 0}, r_i{0, 0, 1};
  const auto equal_exact = ContactPointVelocity::relative(v, w_i, r_i, v, w_j, -r_i);
  const auto equal_mean = ThesisMeanOmegaVelocity::relative(v, w_i, r_i, v, w_j, -r_i);
  BOOST_TEST(norm(equal_exact - equal_mean) == 0.0);
  const Vec3<double> r_j{0, 0, -3};  // a sphere three times larger
  const auto exact = ContactPointVelocity::relative(v, w_i, r_i, v, w_j, r_j);
  const auto mean = ThesisMeanOmegaVelocity::relative(v, w_i, r_i, v, w_j, r_j);
  BOOST_TEST(exact.x == 3.0);  // w_i x r_i: only i spins
  BOOST_TEST(mean.x == 6.0);   // the shortcut doubles the slip
}

BOOST_AUTO_TEST_SUITE_END()
