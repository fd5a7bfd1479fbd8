// Drag fall (thesis section 2.5.1, Fig 2.11): a 1 kg sphere falls from rest under gravity and
// quadratic drag F = m g - alpha v^2, alpha = 0.5 kg/m, for 3 s (6.6 time constants).
//   closed forms  v = V tanh(t/tau),  x = (m/alpha) ln cosh(t/tau),  V = sqrt(m g/alpha), tau = sqrt(m/(g alpha))
//   reference     the same ODE by GSL odeiv2 rk8pd at abs/rel 1e-12 (proves the closed forms as coded)
// Checks: closed forms vs GSL within 1e-10; velocity Verlet within 0.01% of both at dt = 1e-3 s
// (thesis: 0.10%) in float and double, and within 1e-6 at 1e-4 s (thesis: 0.010%); the measured
// order of each integrator as dt halves (1e-3, 5e-4, 2.5e-4 s, double): velocity Verlet 2 (the
// drag is evaluated at the predicted full-step velocity), forward Euler 1, and 1 for the
// half-step and thesis Verlet variants, which lag the velocity-dependent force (integrators.hpp).
// Error metric (cases/drag_fall.hpp): max over the run of |y - y_ref|, over max |y_ref|, for
// y = x (m) and y = v (m/s) separately, sampled every 0.01 s.
#include <boost/test/unit_test.hpp>
#include <boost/mpl/list.hpp>
#include <cmath>
#include <string>
#include "verification/cases/drag_fall.hpp"
#include "verification/report.hpp"

using namespace blaze;
using namespace blaze::test;
using namespace blaze::test::cases;

namespace {

const char* const kCase = "Drag fall (2.5.1, Fig 2.11)";
const char* const kClosedForm = "v = V tanh(t/tau), x = (m/alpha) ln cosh(t/tau), m = 1 kg, alpha = 0.5 kg/m";
const char* const kGsl = "same ODE, GSL odeiv2 rk8pd, abs/rel 1e-12";
const char* const kMetric = "max |y - y_ref| / max |y_ref| over 0-3 s";

template <class Real>
std::string precision_name() {
  return sizeof(Real) == 4 ? "float" : "double";
}

// Order of convergence with a velocity-dependent force: only the predicted-velocity Verlet is second order.
template <class Integrator>
constexpr double formal_order = 1;
template <>
constexpr double formal_order<VelocityVerlet> = 2;

}  // namespace

BOOST_AUTO_TEST_SUITE(drag_fall)

BOOST_AUTO_TEST_CASE(closed_form_agrees_with_gsl) {
  const DragFall p;
  std::vector<double> t;
  for (int k = 0; k <= 300; ++k) t.push_back(0.01 * k);
  const TrajectoryError d = max_relative_error(drag_fall_gsl(p, t), drag_fall_exact(p, t));
  BOOST_TEST_MESSAGE("closed form vs GSL: x " << d.x << ", v " << d.v);
  check_at_most({kCase, std::string("closed form vs GSL, larger of x and v, ") + kMetric, "-", kGsl}, d.worst(),
                tol::drag_reference_agreement);
}

using Reals = boost::mpl::list<float, double>;

BOOST_AUTO_TEST_CASE_TEMPLATE(velocity_verlet_error_at_1e_3, Real, Reals) {
  const DragFall p;
  const auto r = cases::drag_fall<Real, VelocityVerlet>(1e-3, p);
  const TrajectoryError gsl = max_relative_error(r.samples, drag_fall_gsl(p, r.samples.t));
  BOOST_TEST_MESSAGE("velocity Verlet, " << precision_name<Real>() << ", dt = 1e-3 s: x " << r.errors.x << ", v "
                                         << r.errors.v << " (vs GSL: x " << gsl.x << ", v " << gsl.v << "), "
                                         << r.steps << " steps in " << r.wall_s << " s");
  const std::string setting = ", velocity Verlet, " + precision_name<Real>() + ", dt = 1e-3 s";
  check_at_most({kCase, "x: " + std::string(kMetric) + setting, "0.10%", kClosedForm}, r.errors.x, tol::drag_fall_verlet);
  check_at_most({kCase, "v: " + std::string(kMetric) + setting, "0.10%", kClosedForm}, r.errors.v, tol::drag_fall_verlet);
  check_at_most({kCase, "vs GSL, larger of x and v" + setting, "0.10%", kGsl}, gsl.worst(), tol::drag_fall_verlet);
}

// Fig 2.11: x(t), v(t) at dt = 1e-3 and 1e-4 s against the closed forms, and the pointwise
// relative errors.
BOOST_AUTO_TEST_CASE(figure_2_11_and_error_at_1e_4) {
  const DragFall p;
  FigureData fig("fig-2.11", "t_s x_m v_m_per_s x_exact_m v_exact_m_per_s rel_err_x rel_err_v");
  for (double dt : {1e-3, 1e-4}) {
    const auto r = cases::drag_fall<double, VelocityVerlet>(dt, p);
    char title[64];
    std::snprintf(title, sizeof title, "velocity Verlet, double, dt = %g s", dt);
    fig.block(title);
    for (std::size_t k = 0; k < r.samples.t.size(); ++k) {
      const double t = r.samples.t[k], xe = p.x_exact(t), ve = p.v_exact(t);
      if (t == 0) continue;  // relative error 0/0
      fig.row(t, r.samples.x[k], r.samples.v[k], xe, ve, std::fabs(r.samples.x[k] / xe - 1), std::fabs(r.samples.v[k] / ve - 1));
    }
    BOOST_TEST_MESSAGE("velocity Verlet, double, dt = " << dt << " s: x " << r.errors.x << ", v " << r.errors.v);
    if (dt == 1e-4)
      check_at_most({kCase, "larger of x and v: " + std::string(kMetric) + ", velocity Verlet, double, dt = 1e-4 s", "0.010%", kClosedForm},
                    r.error, tol::drag_fall_verlet_fine);
  }
}

using Integrators = boost::mpl::list<ForwardEuler, VelocityVerlet, HalfStepVerlet, ThesisVerlet>;

// Slope of log2(error) over dt = 1e-3, 5e-4, 2.5e-4 s (the mean of the two halvings).
BOOST_AUTO_TEST_CASE_TEMPLATE(convergence_order, Integrator, Integrators) {
  const DragFall p;
  const auto e1 = cases::drag_fall<double, Integrator>(1e-3, p).errors, e2 = cases::drag_fall<double, Integrator>(5e-4, p).errors,
             e3 = cases::drag_fall<double, Integrator>(2.5e-4, p).errors;
  const double order_x = 0.5 * std::log2(e1.x / e3.x), order_v = 0.5 * std::log2(e1.v / e3.v);
  BOOST_TEST_MESSAGE(Integrator::name << ": x errors " << e1.x << " " << e2.x << " " << e3.x << " (order " << order_x
                                      << "), v errors " << e1.v << " " << e2.v << " " << e3.v << " (order " << order_v << ")");
  const std::string setting = " as dt halves 1e-3 -> 2.5e-4 s, double, " + std::string(Integrator::name);
  const std::string source = "formal order with a velocity-dependent force (integrators.hpp)";
  check_near({kCase, "order of x error" + setting, "-", source}, order_x, formal_order<Integrator>, tol::convergence_order);
  check_near({kCase, "order of v error" + setting, "-", source}, order_v, formal_order<Integrator>, tol::convergence_order);
}

BOOST_AUTO_TEST_SUITE_END()
