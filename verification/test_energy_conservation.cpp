// Energy conservation (thesis section 2.3.2, Fig 2.8): "a system of particles falling under
// gravity for 1 s onto a planar surface". 48 elastic, frictionless spheres fall into a box and
// bounce off the floor, the walls and each other (cases/falling_particles.hpp: scene, energy
// bookkeeping, contact time 5 ms = 50 steps of the thesis's dt = 1e-4 s).
//   E = kinetic + rotational + m g y + stored contact energy (Hertz (2/5) K_n delta^(5/2), linear
//       spring K_n delta^2 / 2) is constant; error = max over 1 s of |E(t) - E(0)| / E(0).
// Checks, velocity Verlet, double, for the Hertz law and the linear spring:
// - error <= 0.1% at dt = 1e-4 s (thesis: ~1%) in each of 8 scenes (seeds 1-8), and in float;
// - bounded: the max error in the last quarter of the run is no larger than in the first (mean
//   over the 8 scenes; an error that drifts would grow several-fold);
// - second order as dt halves (1e-4, 5e-5, 2.5e-5 s), measured on the mean over the 8 scenes: the
//   scene is chaotic, so one run's maximum is an extreme value that scatters between dt. Hertz:
//   2 +- 0.1. Linear spring: 2 +- 0.25; its force kink at first touch leaves an erratic O(dt^2)
//   energy residual per contact (explained and measured in cases/falling_particles.hpp).
// Fig 2.8: relative energy error vs t for four dt (scene 1), fig-2.8-hertz.dat and -linear.dat.
#include <boost/test/unit_test.hpp>
#include <cmath>
#include <string>
#include "verification/cases/falling_particles.hpp"
#include "verification/report.hpp"

using namespace blaze;
using namespace blaze::test;
using namespace blaze::test::cases;

namespace {

const char* const kCase = "Energy conservation (2.3.2, Fig 2.8)";
const double kSteps[] = {1e-4, 5e-5, 2.5e-5};  // s
constexpr double kFigureExtraStep = 1.25e-5;   // s, the figure's fourth dt (only when it is written)

struct EnsembleOutcome {
  double worst_at_largest_step = 0;  // max over the scenes of the error at dt = 1e-4 s
  double mean_error[3] = {};         // mean over the scenes, per dt
  double drift_ratio = 0;            // mean last-quarter max / mean first-quarter max at dt = 1e-4 s
  double max_overlap = 0;            // m
  long removed = 0;
};

// Scenes 1..tol::energy_scenes at the three dt; scene 1's histories go to the figure.
template <template <class> class NormalLaw>
EnsembleOutcome run_ensemble(const std::string& figure) {
  EnsembleOutcome out;
  double first = 0, last = 0;
  FigureData fig(figure, "t_s relative_energy_error");
  for (int scene = 1; scene <= tol::energy_scenes; ++scene) {
    FallingParticles p;
    p.seed = static_cast<unsigned>(scene);
    for (int k = 0; k < 3; ++k) {
      const auto r = falling_particles<double, VelocityVerlet, NormalLaw>(kSteps[k], p);
      out.mean_error[k] += r.error / tol::energy_scenes;
      out.max_overlap = std::fmax(out.max_overlap, r.max_overlap);
      out.removed += r.removed;
      if (k == 0) {
        out.worst_at_largest_step = std::fmax(out.worst_at_largest_step, r.error);
        first += r.error_first_quarter;
        last += r.error_last_quarter;
      }
      if (scene == 1 && fig.enabled()) {
        fig.block("dt = " + std::to_string(kSteps[k]) + " s");
        for (std::size_t i = 0; i < r.t.size(); ++i) fig.row(r.t[i], r.relative_error[i]);
      }
    }
    if (scene == 1 && fig.enabled()) {
      const auto r = falling_particles<double, VelocityVerlet, NormalLaw>(kFigureExtraStep, p);
      fig.block("dt = " + std::to_string(kFigureExtraStep) + " s");
      for (std::size_t i = 0; i < r.t.size(); ++i) fig.row(r.t[i], r.relative_error[i]);
    }
  }
  out.drift_ratio = last / first;
  return out;
}

template <template <class> class NormalLaw>
void check_ensemble(const char* law_name, const std::string& figure, double drift_limit, double order_tolerance,
                    const char* order_source) {
  const EnsembleOutcome o = run_ensemble<NormalLaw>(figure);
  const double order = 0.5 * std::log2(o.mean_error[0] / o.mean_error[2]);
  BOOST_TEST_MESSAGE(law_name << ": mean max error over " << tol::energy_scenes << " scenes " << o.mean_error[0] << " "
                              << o.mean_error[1] << " " << o.mean_error[2] << " at dt = 1e-4, 5e-5, 2.5e-5 s (order "
                              << order << "), worst at 1e-4 s " << o.worst_at_largest_step << ", last/first quarter "
                              << o.drift_ratio << ", deepest overlap " << o.max_overlap / FallingParticles{}.radius << " r");
  BOOST_TEST(o.removed == 0);
  const std::string setting = std::string(", ") + law_name + ", velocity Verlet, double";
  const std::string scenes = std::to_string(tol::energy_scenes) + " scenes of 48 spheres";
  check_at_most({kCase, "max |E - E0| / E0 over 1 s, worst of " + scenes + setting + ", dt = 1e-4 s", "~1%", "E constant (elastic, frictionless)"},
                o.worst_at_largest_step, tol::energy_conservation);
  check_at_most({kCase, "max error in last quarter / in first quarter, mean of " + scenes + setting + ", dt = 1e-4 s", "-",
                 "bounded error (no drift)"},
                o.drift_ratio, drift_limit);
  check_near({kCase, "order of the max error (mean of " + scenes + ") as dt halves 1e-4 -> 2.5e-5 s" + setting, "-", order_source},
             order, 2.0, order_tolerance);
}

}  // namespace

BOOST_AUTO_TEST_SUITE(energy_conservation)

BOOST_AUTO_TEST_CASE(hertz_bounded_second_order) {
  check_ensemble<Hertz>("Hertz", "fig-2.8-hertz", tol::energy_drift_ratio_hertz, tol::convergence_order,
                        "velocity Verlet, smooth force (second order)");
}

BOOST_AUTO_TEST_CASE(linear_spring_bounded_second_order) {
  check_ensemble<LinearSpringDashpot>("linear spring", "fig-2.8-linear", tol::energy_drift_ratio_linear, tol::energy_order_kinked,
                                      "velocity Verlet; force kink at touch: erratic O(dt^2) per contact");
}

BOOST_AUTO_TEST_CASE(hertz_float) {
  const auto r = falling_particles<float, VelocityVerlet, Hertz>(1e-4);
  BOOST_TEST_MESSAGE("Hertz, float, dt = 1e-4 s: max error " << r.error);
  BOOST_TEST(r.removed == 0);
  check_at_most({kCase, "max |E - E0| / E0 over 1 s, scene 1, Hertz, velocity Verlet, float, dt = 1e-4 s", "~1%",
                 "E constant (elastic, frictionless)"},
                r.error, tol::energy_conservation);
}

BOOST_AUTO_TEST_SUITE_END()
