// Guards while running (issue 5): a state that turns NaN stops the run at the step it appears,
// naming the particle (and is never mistaken for a particle leaving the domain); penetration is
// tracked per particle over every step, follows the particles through re-sorting, and equals the
// static overlap of a resting sphere.
#include <boost/test/unit_test.hpp>
#include <cmath>
#include <limits>
#include "verification/scenes.hpp"

using namespace blaze;
using namespace blaze::test;

namespace {

// A normal law that breaks the moment bodies touch, as a blown-up contact would.
template <class Real>
struct BrokenOnTouch {
  BLAZE_HD Real normal_force(Real delta, Real, Real, Real) const {
    return delta > Real(0) ? sqrt_r(-delta) : Real(0);  // NaN (host and device alike)
  }
};
using BrokenLaw = ContactLaw<double, BrokenOnTouch, HistoryFreeFriction>;

template <class Law>
using MonitoredSim = Simulation<DefaultSpace, SphereShape, Law, VelocityVerlet, ContactPointVelocity, MonitoredFeatures>;

}  // namespace

BOOST_AUTO_TEST_SUITE(guards)

// Two spheres approach at 1 m/s each; the step after their first overlap must stop the run.
BOOST_AUTO_TEST_CASE(nan_stops_the_run_at_its_step_and_names_the_particle) {
  const double r = 1e-3, v = 1.0, dt = 1e-6, gap = 10.3e-6;  // touch after 5.15 steps: off the step grid
  ParticleState<double> p;
  p.add_sphere({-r - gap / 2, 0, 0}, r, 2500, 0, {v, 0, 0});
  p.add_sphere({r + gap / 2, 0, 0}, r, 2500, 0, {-v, 0, 0});
  p.id = {7, 9};
  PairTable<BrokenLaw> laws;
  laws.set(0, 0, BrokenLaw{{}, HistoryFreeFriction<double>::make(0, 0)});
  // Free flight until the first step whose positions overlap: forces there are NaN, velocities
  // after it too, positions at the next step's drift, caught by that step's check. Single steps
  // and a batch of steps (stopped at the flagged step, which is then finished as step() would) alike.
  const long first_overlap = static_cast<long>(std::ceil(gap / (2 * v * dt)));
  for (bool batched : {false, true}) {
    SphereSim<BrokenLaw> sim(params<double>(dt, {0, 0, 0}, 0.01, 0), laws, World<double>{}, p);
    std::uint64_t stopped_at = 0;
    Index named = -1;
    try {
      if (batched) sim.run(100);
      else
        for (int s = 0; s < 100; ++s) sim.step();
    } catch (const NonFiniteState& e) {
      stopped_at = e.step;
      named = e.id;
      BOOST_TEST_MESSAGE("NaN guard" << (batched ? " (batched)" : "") << ": " << e.what());
    }
    BOOST_TEST(stopped_at == static_cast<std::uint64_t>(first_overlap + 1), "batched " << batched);
    BOOST_TEST((named == 7 || named == 9));
    BOOST_TEST(sim.removed_count() == 0);  // not counted as having left the domain
  }
}

BOOST_AUTO_TEST_CASE(nan_in_the_initial_state_is_named) {
  auto p = random_spheres<double>(20, 1e-3, 1e-3, 0.05, 4);
  p.angular_velocity[13].z = std::numeric_limits<double>::infinity();
  std::string message;
  Index named = -1;
  try {
    SphereSim<LinearLaw<double>> sim(params<double>(1e-6), one_law(LinearLaw<double>{LinearSpringDashpot<double>::from_restitution(1e4, 0.5), HistoryFreeFriction<double>::make(0, 0)}), World<double>{}, p);
  } catch (const NonFiniteState& e) {
    message = e.what();
    named = e.id;
  }
  BOOST_TEST(named == p.id[13]);
  BOOST_TEST(message.find("step 0") != std::string::npos, message);
}

// A sphere resting on a floor at its static overlap mg/k: the monitor reports exactly that ratio
// of the radius, for this particle, and again after a reset.
BOOST_AUTO_TEST_CASE(penetration_of_a_resting_sphere_is_its_static_overlap) {
  const double r = 2e-3, k = 1e3, rho = 2500, g = 9.81;
  const double m = rho * 4.0 / 3.0 * kPi * r * r * r, delta = m * g / k;
  ParticleState<double> p;
  p.add_sphere({0, r - delta, 0}, r, rho, 0);
  p.id = {42};
  World<double> w;
  w.polygons.push_back(floor_square<double>(0, 0.05));
  using Law = LinearLaw<double>;
  const Law law{LinearSpringDashpot<double>::from_restitution(k, 0.5), HistoryFreeFriction<double>::make(0, 0)};
  MonitoredSim<Law> sim(params<double>(1e-5, {0, -g, 0}, 0.1), one_law(law), w, p);
  sim.run(100);
  const double ratio = delta / r;
  const PenetrationReport a = sim.take_penetration(0.999 * ratio);
  BOOST_TEST(a.worst == ratio, boost::test_tools::tolerance(tol::static_overlap_monitor));
  BOOST_TEST(a.worst_id == 42);
  BOOST_TEST(a.over == 1);
  sim.run(10);
  const PenetrationReport b = sim.take_penetration(1.001 * ratio);
  BOOST_TEST(b.worst == ratio, boost::test_tools::tolerance(tol::static_overlap_monitor));
  BOOST_TEST(b.over == 0);
}

// Spheres of different sizes slide past each other on a frictionless floor, so the particle
// order changes at every rebuild; the deepest overlap must stay with the largest sphere (its
// static overlap ratio mg/(k r) grows as r^2).
BOOST_AUTO_TEST_CASE(penetration_follows_particles_through_resorting) {
  const double k = 1e3, rho = 2500, g = 9.81;
  ParticleState<double> p;
  for (int row = 0; row < 2; ++row)
    for (int c = 0; c < 8; ++c) {
      const double r = 1e-3 * (1 + 0.05 * (8 * row + c));
      const double delta = rho * 4.0 / 3.0 * kPi * r * r * r * g / k;
      const double dir = row == 0 ? 1 : -1;  // the rows cross each other
      p.add_sphere({dir * (-0.035 + 0.005 * c), r - delta, 0.004 * row}, r, rho, 0, {0.3 * dir, 0, 0});
    }
  World<double> w;
  w.polygons.push_back(floor_square<double>(0, 0.05));
  using Law = LinearLaw<double>;
  const Law law{LinearSpringDashpot<double>::from_restitution(k, 0.5), HistoryFreeFriction<double>::make(0, 0)};
  MonitoredSim<Law> sim(params<double>(1e-5, {0, -g, 0}, 0.1, 0), one_law(law), w, p);
  for (int sample = 0; sample < 4; ++sample) {
    sim.run(2000);
    const PenetrationReport r = sim.take_penetration(1);
    BOOST_TEST(r.worst_id == 15);
  }
  BOOST_TEST(sim.neighbour_builds() > 1000u);
}

BOOST_AUTO_TEST_SUITE_END()
