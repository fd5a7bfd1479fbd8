// Properties every contact law must have, checked for each law, in both precisions, on random
// contacts: no force without overlap and motion; Newton's third law and conservation of angular
// momentum (each side of a pair evaluates the law itself, in the real contact kernel); damping and
// friction never add energy (their force opposes the relative velocity at the contact point).
#include <boost/test/unit_test.hpp>
#include <boost/mpl/list.hpp>
#include <random>
#include "verification/scenes.hpp"

using namespace blaze;
using namespace blaze::test;

namespace {

template <class Real>
LinearLaw<Real> linear_law() {
  return {LinearSpringDashpot<Real>::from_restitution(1e5, 0.4), HistoryFreeFriction<Real>::make(0.5, 2.0)};
}
template <class Real>
HertzLaw<Real> hertz_law() {
  return {Hertz<Real>::from_stiffness(1e9, 2.5e-3, 1e5), HistoryFreeFriction<Real>::make(0.5, 2.0)};
}

template <class Law>
Law make_law() {
  using Real = typename Law::real_type;
  if constexpr (std::is_same_v<Law, LinearLaw<Real>>) return linear_law<Real>();
  else return hertz_law<Real>();
}

template <class Real>
double third_law_tolerance() {
  return sizeof(Real) == 8 ? tol::newton_third_law_double : tol::newton_third_law_float;
}

}  // namespace

BOOST_AUTO_TEST_SUITE(law_properties)

using Laws = boost::mpl::list<LinearLaw<float>, LinearLaw<double>, HertzLaw<float>, HertzLaw<double>>;

BOOST_AUTO_TEST_CASE_TEMPLATE(no_force_without_overlap_or_motion, Law, Laws) {
  using Real = typename Law::real_type;
  const Law law = make_law<Law>();
  const ContactGeometry<Real> g{true, {0, 0, 1}, Real(0), {0, 0, 0}, Real(2.5e-3)};
  const auto f = law.force(g, {0, 0, 0}, Real(1e-3));
  BOOST_TEST(f.x == Real(0));
  BOOST_TEST(f.y == Real(0));
  BOOST_TEST(f.z == Real(0));
}

BOOST_AUTO_TEST_CASE_TEMPLATE(newton_third_law_and_angular_momentum, Law, Laws) {
  using Real = typename Law::real_type;
  std::mt19937_64 rng(7);
  std::uniform_real_distribution<double> u(-1, 1);
  for (int trial = 0; trial < 200; ++trial) {
    ParticleState<Real> s;
    const double r1 = 2e-3 * (1.5 + u(rng)), r2 = 2e-3 * (1.5 + u(rng));
    Vec3<double> dir{u(rng), u(rng), u(rng)};
    dir *= 1 / norm(dir);
    const double dist = (r1 + r2) * (1 - 0.01 * (1 + u(rng)));  // up to 2% overlap
    auto rv = [&](double scale) { return vec_cast<Real>(Vec3<double>{scale * u(rng), scale * u(rng), scale * u(rng)}); };
    s.add_sphere(rv(0.01), Real(r1), Real(2500), 0, rv(1.0));
    s.add_sphere(s.position[0] + vec_cast<Real>(dir * dist), Real(r2), Real(7800), 1, rv(1.0));
    s.angular_velocity = {rv(100.0), rv(100.0)};
    const Law law = make_law<Law>();
    SphereSim<Law> sim(params<Real>(1e-7, {0, 0, 0}, 0.1, 1e-3), one_law(law), World<Real>{}, s);
    const auto st = sim.state();
    const auto f = sim.forces(), t = sim.torques();
    const double scale = norm(vec_cast<double>(f[0]));
    BOOST_TEST_REQUIRE(scale > 0);
    const auto sum = vec_cast<double>(f[0] + f[1]);
    BOOST_TEST(norm(sum) <= third_law_tolerance<Real>() * scale);
    // Total angular momentum change about the origin: sum of x x F + T.
    Vec3<double> l{0, 0, 0};
    for (int k = 0; k < 2; ++k) l += cross(vec_cast<double>(st.position[k]), vec_cast<double>(f[k])) + vec_cast<double>(t[k]);
    BOOST_TEST(norm(l) <= third_law_tolerance<Real>() * scale * (r1 + r2));
  }
}

BOOST_AUTO_TEST_CASE_TEMPLATE(damping_and_friction_never_add_energy, Law, Laws) {
  using Real = typename Law::real_type;
  std::mt19937_64 rng(11);
  std::uniform_real_distribution<double> u(-1, 1);
  const Law law = make_law<Law>();
  int dissipating = 0;
  for (int trial = 0; trial < 1000; ++trial) {
    const ContactGeometry<Real> g{true, {0, 1, 0}, Real(1e-5 * (1.5 + u(rng))), {0, 0, 0}, Real(2.5e-3)};
    const Vec3<Real> v_rel = vec_cast<Real>(Vec3<double>{u(rng), u(rng), u(rng)});
    const auto f_moving = law.force(g, v_rel, Real(1e-3)), f_still = law.force(g, {0, 0, 0}, Real(1e-3));
    const double power = dot(vec_cast<double>(f_moving - f_still), vec_cast<double>(v_rel));
    BOOST_TEST(power <= tol::dissipation_rounding * norm(vec_cast<double>(f_moving)));
    dissipating += power < 0;
  }
  BOOST_TEST(dissipating > 900);  // and it does dissipate
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
