// Restitution of the Hertzian contact with delta^(1/4) damping (Tsuji et al., Powder Technol. 71
// (1992) 239), checked against an independent integration with GSL.
//
//   y'' = -y^(3/2) - eta y^(1/4) y',   y(0) = 0, y'(0) = 1        (scaled: hertz_restitution.hpp)
//   e(eta) = -y'(s_end) at the return to y = 0 (free contact); with the no-tension clamp the force
//   max(y^(3/2) + eta y^(1/4) y', 0) vanishes for good once y^(5/4) = -eta y' on unloading (after
//   that the body coasts), so e_clamped = -y' at that point.
//
// The y^(1/4) term has an unbounded derivative at y = 0, where every contact starts and ends, so
// a plain integration in time loses its order there. The reference removes the singularity by a
// change of variables instead of small steps: near y = 0 the overlap itself, written y = w^4, is
// the independent variable,
//   dv/dw = -4 w^3 (w^6 + eta w v) / v,   ds/dw = 4 w^3 / v      (v = y', s = time),
// which is analytic at w = 0 (and well conditioned while |v| stays away from 0). Around the
// turning point (v = 0) the integration runs in time s, where y is bounded away from 0. Three
// legs: loading in w (until v < 1/2), the turn in s (until the body is back below the overlap
// where it switched), unloading in w down to w = 0. Every leg is GSL odeiv2 rk8pd with absolute
// and relative error 1e-12; the clamp point (G = y^(5/4) + eta v = 0, a smooth function on the
// unclamped trajectory, which it follows up to that point) is found by bisection on the leg.
// Independent check of the reference itself: for eta = 0 the scaled contact lasts
// (4/5) B(2/5, 1/2) (5/4)^(2/5) (the closed-form Hertz duration).
// Without the clamp the contact sticks for eta > sqrt(5) (hertz_restitution.hpp derives it from the
// equation's scale invariance and stops there); the reference finds it on its own, through the
// energy bound e^2 <= v^2 + (4/5) y^(5/2), and the eta list straddles the threshold (2.0, 2.25).
#include <boost/test/unit_test.hpp>
#include <gsl/gsl_errno.h>
#include <gsl/gsl_odeiv2.h>
#include <cmath>
#include <functional>
#include <vector>
#include "blaze/laws/hertz.hpp"
#include "verification/report.hpp"
#include "verification/tolerances.hpp"

using namespace blaze;
using namespace blaze::test;

namespace {

struct Reference {
  double e_free;      // -y' at y = 0
  double e_clamped;   // -y' where the clamped force vanishes on unloading
  double duration;    // scaled contact time of the free contact
};

// One leg of the integration: a 2-state system in an independent variable t (w or s).
class Leg {
 public:
  using Rhs = int (*)(double, const double[], double[], void*);
  Leg(Rhs rhs, double* eta) : sys_{rhs, nullptr, 2, eta} {}

  // Integrates state y from t0 to t1 (either direction), as accurately as the tolerances allow.
  void to(double t0, double t1, double y[2]) const {
    if (t0 == t1) return;
    const double h0 = (t1 > t0 ? 1 : -1) * 1e-6;
    gsl_odeiv2_driver* d = gsl_odeiv2_driver_alloc_y_new(&sys_, gsl_odeiv2_step_rk8pd, h0, kEps, kEps);
    double t = t0;
    const int status = gsl_odeiv2_driver_apply(d, &t, t1, y);
    gsl_odeiv2_driver_free(d);
    BOOST_REQUIRE_MESSAGE(status == GSL_SUCCESS, "GSL driver failed: " << gsl_strerror(status));
  }

  // Steps adaptively from t0 towards t_end until stop(t, y) holds after a step; returns the t
  // reached. on_step(t_prev, y_prev, t, y) sees every accepted step.
  double until(double t0, double t_end, double y[2], const std::function<bool(double, const double*)>& stop,
               const std::function<void(double, const double*, double, const double*)>& on_step) const {
    gsl_odeiv2_step* s = gsl_odeiv2_step_alloc(gsl_odeiv2_step_rk8pd, 2);
    gsl_odeiv2_control* c = gsl_odeiv2_control_y_new(kEps, kEps);
    gsl_odeiv2_evolve* e = gsl_odeiv2_evolve_alloc(2);
    double t = t0, h = (t_end > t0 ? 1 : -1) * 1e-6;
    for (int k = 0; k < 1000000; ++k) {
      const double t_prev = t, y_prev[2] = {y[0], y[1]};
      const int status = gsl_odeiv2_evolve_apply(e, c, s, &sys_, &t, t_end, &h, y);
      BOOST_REQUIRE_MESSAGE(status == GSL_SUCCESS, "GSL step failed: " << gsl_strerror(status));
      on_step(t_prev, y_prev, t, y);
      if (stop(t, y) || t == t_end) break;
    }
    gsl_odeiv2_evolve_free(e);
    gsl_odeiv2_control_free(c);
    gsl_odeiv2_step_free(s);
    return t;
  }

  static constexpr double kEps = 1e-12;

 private:
  mutable gsl_odeiv2_system sys_;
};

// State (v, s) against w = y^(1/4).
int rhs_in_w(double w, const double y[], double dydw[], void* p) {
  const double eta = *static_cast<double*>(p), v = y[0];
  const double w3 = w * w * w;
  dydw[0] = -4 * w3 * (w3 * w3 + eta * w * v) / v;
  dydw[1] = 4 * w3 / v;
  return GSL_SUCCESS;
}
// State (y, v) against time s.
int rhs_in_s(double, const double y[], double dyds[], void* p) {
  const double eta = *static_cast<double*>(p), x = std::fmax(y[0], 0.0);
  dyds[0] = y[1];
  dyds[1] = -(x * std::sqrt(x) + eta * std::sqrt(std::sqrt(x)) * y[1]);
  return GSL_SUCCESS;
}

Reference gsl_reference(double eta) {
  Leg in_w(rhs_in_w, &eta), in_s(rhs_in_s, &eta);
  Reference out{0, -1, 0};
  // Clamp condition G = y^(5/4) + eta v (the force is y^(1/4) G); the first sign change on
  // unloading is located by bisection on the leg that contains it.
  const auto find_clamp = [&](const Leg& leg, double t0, const double* y0, double t1, const double* y1, auto g_of) {
    if (out.e_clamped >= 0 || !(g_of(t0, y0) >= 0 && g_of(t1, y1) < 0)) return;
    double lo = t0, hi = t1, y[2];
    for (int it = 0; it < 200 && lo != hi; ++it) {
      const double mid = 0.5 * (lo + hi);
      if (mid == lo || mid == hi) break;
      y[0] = y0[0];
      y[1] = y0[1];
      leg.to(t0, mid, y);
      (g_of(mid, y) >= 0 ? lo : hi) = mid;
    }
    y[0] = y0[0];
    y[1] = y0[1];
    leg.to(t0, lo, y);
    return void(out.e_clamped = -y[&leg == &in_s ? 1 : 0]);
  };
  const auto g_w = [&](double w, const double* y) { return std::pow(w, 5) + eta * y[0]; };
  const auto g_s = [&](double, const double* y) { return std::pow(std::fmax(y[0], 0.0), 1.25) + eta * y[1]; };

  // 1. Loading, in w from 0 with v = 1, s = 0, until v < 1/2.
  double vs[2] = {1, 0};
  const double w1 = in_w.until(0, 2, vs, [](double, const double* y) { return y[0] < 0.5; },
                               [](double, const double*, double, const double*) {});
  BOOST_REQUIRE(vs[0] > 0);  // still loading
  // 2. Through the turning point, in s, until back below the switching overlap.
  const double y_switch = std::pow(w1, 4);
  double yv[2] = {y_switch, vs[0]};
  const double s1 = vs[1];
  const double s2 = in_s.until(
      s1, s1 + 100, yv, [&](double, const double* y) { return y[1] < 0 && y[0] <= y_switch; },
      [&](double t0, const double* y0, double t1, const double* y1) {
        if (y1[1] < 0) find_clamp(in_s, t0, y0, t1, y1, g_s);
      });
  BOOST_REQUIRE(yv[1] < 0);  // unloading
  BOOST_REQUIRE(yv[0] > 0);
  // 3. Unloading, in w down to 0. Energy bounds what is left: v^2/2 + (2/5) y^(5/2) only falls,
  // so e^2 <= v^2 + (4/5) w^10; once that is below 1e-14 the body is taken to stick (it creeps
  // out with v -> 0, and s grows without bound).
  vs[0] = yv[1];
  vs[1] = s2;
  const auto stuck = [](double w, const double* y) { return y[0] * y[0] + 0.8 * std::pow(w, 10) < 1e-28; };
  const double w_end = in_w.until(std::pow(yv[0], 0.25), 0, vs, stuck, [&](double t0, const double* y0, double t1, const double* y1) {
    find_clamp(in_w, t0, y0, t1, y1, g_w);
  });
  out.e_free = w_end > 0 ? 0 : -vs[0];
  out.duration = w_end > 0 ? HUGE_VAL : vs[1];
  if (out.e_clamped < 0) out.e_clamped = out.e_free;  // the force never turned tensile (eta = 0)
  return out;
}

const Row kDuration{"Hertz restitution e(eta), GSL reference", "scaled elastic contact time vs (4/5) B(2/5,1/2) (5/4)^(2/5)",
                    "-", "closed-form Hertz duration (Johnson 1985, sec. 11.4)"};

}  // namespace

BOOST_AUTO_TEST_SUITE(hertz_restitution_mapping)

// The reference reproduces the one closed form the problem has: the elastic contact time.
BOOST_AUTO_TEST_CASE(gsl_reference_reproduces_elastic_contact_time) {
  const Reference r = gsl_reference(0);
  const double beta = std::tgamma(0.4) * std::tgamma(0.5) / std::tgamma(0.9);
  const double expected = 0.8 * beta * std::pow(1.25, 0.4);
  BOOST_TEST_MESSAGE("GSL elastic: e = " << r.e_free << ", scaled duration " << r.duration << " (closed form " << expected << ")");
  check_relative(kDuration, r.duration, expected, tol::gsl_elastic_duration);
  check_relative({kDuration.case_name, "elastic e(0) (energy conservation)", "-", "Hertz: conservative"}, r.e_free, 1.0,
                 tol::gsl_elastic_duration);
}

// blaze's fixed-step RK4 mapping (used by Hertz::from_restitution) against the GSL reference.
BOOST_AUTO_TEST_CASE(mapping_matches_gsl_reference) {
  double worst_free = 0, worst_clamped = 0;
  for (double eta : {0.0, 0.02, 0.1, 0.3, 0.6, 1.0, 1.5, 2.0, 2.25, 2.5, 4.0}) {
    const Reference r = gsl_reference(eta);
    const double free = hertz_restitution(eta, false), clamped = hertz_restitution(eta, true);
    BOOST_TEST_MESSAGE("eta " << eta << ": e free " << r.e_free << " (blaze " << free << "), e clamped " << r.e_clamped
                              << " (blaze " << clamped << "), duration " << r.duration);
    worst_free = std::fmax(worst_free, std::fabs(free - r.e_free));
    worst_clamped = std::fmax(worst_clamped, std::fabs(clamped - r.e_clamped));
    // The clamp removes the tensile end of the contact, which only decelerated the separation.
    if (eta > 0) BOOST_TEST(r.e_clamped > r.e_free);
  }
  const std::string src = "GSL odeiv2 rk8pd, 1e-12, singularity removed by y = w^4";
  check_at_most({"Hertz restitution e(eta), delta^(1/4) damping", "max |e_blaze - e_GSL|, eta 0..4, free contact", "-", src},
                worst_free, tol::hertz_restitution_mapping);
  check_at_most({"Hertz restitution e(eta), delta^(1/4) damping", "max |e_blaze - e_GSL|, eta 0..4, no-tension clamp", "-", src},
                worst_clamped, tol::hertz_restitution_mapping);
}

// Round trip: the eta that from_restitution picks gives back e (by the independent reference).
BOOST_AUTO_TEST_CASE(from_restitution_round_trip) {
  for (bool clamp : {false, true}) {
    double worst = 0;
    for (double e : {0.1, 0.2, 0.4, 0.6, 0.8, 0.95, 0.99}) {
      const auto law = Hertz<double>::from_restitution(1e10, e, clamp);
      const Reference r = gsl_reference(law.eta);
      const double got = clamp ? r.e_clamped : r.e_free;
      BOOST_TEST_MESSAGE("e " << e << (clamp ? " clamped" : " free") << ": eta " << law.eta << ", GSL e " << got);
      BOOST_TEST(law.no_tension == clamp);
      worst = std::fmax(worst, std::fabs(got - e));
    }
    check_at_most({"Hertz restitution e(eta), delta^(1/4) damping",
                   std::string("round trip max |e_GSL(eta(e)) - e|, e 0.1..0.99, ") + (clamp ? "no-tension clamp" : "free contact"),
                   "-", "Hertz::from_restitution vs GSL odeiv2 rk8pd 1e-12"},
                  worst, tol::hertz_restitution_mapping);
  }
}

BOOST_AUTO_TEST_SUITE_END()
