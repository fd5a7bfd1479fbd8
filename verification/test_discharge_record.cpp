// The hopper study's discharge measures (studies/hopper/discharge_record.hpp), on synthetic beds
// whose answers are known, over several rates, bed sizes and sampling intervals:
// - particles leaving at a constant rate give that mass flow rate (to the sampling's rounding)
//   with R^2 = 1, and the residual is the fraction never sampled as gone;
// - a bed draining from its centre column down (exit time growing with the distance from the axis,
//   falling with height: funnel flow) is called funnel flow; one descending as a whole (the bottom
//   layer first, whatever its x: mass flow) is not;
// - a flow that stops with particles over the orifice has arched; one that stops with particles
//   only in the dead zones at the sides has drained;
// - a record saved (a checkpoint's part) and restored goes on as the uninterrupted one, exactly.
#include <boost/test/unit_test.hpp>
#include <cmath>
#include <sstream>
#include <stdexcept>
#include <string>
#include "blaze/particles/particle_state.hpp"
#include "studies/hopper/discharge_record.hpp"

using namespace blaze;

namespace {

// A bed of nx x ny spheres (d = 10 mm) in the x-y plane around x = 0, ids row by row from the bottom.
ParticleState<double> bed(int nx, int ny) {
  ParticleState<double> s;
  for (int j = 0; j < ny; ++j)
    for (int i = 0; i < nx; ++i)
      s.add_sphere({0.01 * (i - 0.5 * (nx - 1)), 0.005 + 0.01 * j, 0}, 0.005, 1000, 0, {0, 0, 0});
  for (std::size_t k = 0; k < s.size(); ++k) s.id[k] = static_cast<int>(k);
  return s;
}

// Replays a discharge: particle k leaves at exit(k) (inf: never), sampled every `dt`; `arch_span`
// as the study's [study] arch_time.
// Samples k = k0, k0 + 1, ... at t = k dt while t <= t_end into `r`.
template <class Exit>
void sample(hopper::DischargeRecord& r, const ParticleState<double>& s, Exit exit, double dt, int k0, double t_end) {
  for (int k = k0; k * dt <= t_end + 1e-12; ++k) {
    const double t = k * dt;
    ParticleState<double> left;
    for (std::size_t j = 0; j < s.size(); ++j)
      if (!(exit(j) <= t)) left.add_sphere(s.position[j], s.radius[j], 1000, 0, {0, 0, 0}), left.id.back() = s.id[j];
    r.sample(t, left);
  }
}
template <class Exit>
hopper::DischargeSummary replay(const ParticleState<double>& s, Exit exit, double dt, double t_end, double arch_span = 0) {
  hopper::DischargeRecord r;
  r.open(s, 0.0, 0.025);
  sample(r, s, exit, dt, 0, t_end);
  return r.summary(0.025, arch_span);
}

}  // namespace

BOOST_AUTO_TEST_SUITE(discharge_record)

BOOST_AUTO_TEST_CASE(a_constant_rate_is_measured_and_the_residual_counted) {
  for (const int nx : {16, 31})
    for (const double rate : {200.0, 1000.0, 5000.0})   // particles/s
      for (const double dt : {0.001, 0.01}) {
        const ParticleState<double> s = bed(nx, 40);
        const std::size_t n = s.size(), kept = n / 5;      // the last fifth never leaves
        const auto exit = [&](std::size_t k) { return k < n - kept ? (static_cast<double>(k) + 0.5) / rate : hopper::DischargeRecord::kNever; };
        const double t_end = static_cast<double>(n) / rate + 5 * dt;
        const hopper::DischargeSummary d = replay(s, exit, dt, t_end);
        const double m = static_cast<double>(s.mass[0]);
        BOOST_TEST_CONTEXT("nx " << nx << ", rate " << rate << "/s, sampled every " << dt << " s") {
          BOOST_TEST(d.discharged == n - kept);
          BOOST_TEST(d.residual == static_cast<double>(kept) / static_cast<double>(n), boost::test_tools::tolerance(1e-12));
          // a staircase sampled at dt: its least-squares slope is the rate to within one sample's particles
          BOOST_TEST(std::fabs(d.flow_rate / (rate * m) - 1) < 0.02 + 2 * rate * dt / static_cast<double>(n));
          BOOST_TEST(d.flow_r2 > 0.99);
        }
      }
}

BOOST_AUTO_TEST_CASE(funnel_flow_is_told_from_mass_flow) {
  for (const int nx : {12, 16, 24}) {
    const ParticleState<double> s = bed(nx, 30);
    const double width = 0.005 * nx;
    // funnel: the core above the orifice drains top down first, the sides later, the bottom
    // corners never
    const auto funnel = [&](std::size_t k) {
      const double x = std::fabs(s.position[k].x), y = s.position[k].y;
      if (x > 0.6 * width && y < 0.08) return hopper::DischargeRecord::kNever;
      return x < 0.025 ? 0.5 - 1.0 * y : 0.5 + 4 * x + (0.3 - y);
    };
    // mass flow: the bed descends as a whole, layer by layer
    const auto mass = [&](std::size_t k) { return 5 * s.position[k].y; };
    BOOST_TEST_CONTEXT("nx " << nx) {
      const hopper::DischargeSummary f = replay(s, funnel, 0.01, 3.0), m = replay(s, mass, 0.01, 3.0);
      BOOST_TEST(f.funnel());
      BOOST_TEST(std::isinf(f.t_bottom_side));
      BOOST_TEST(f.residual > 0);
      BOOST_TEST(!m.funnel());
      BOOST_TEST(m.t_bottom_side < m.t_top_centre);
      BOOST_TEST(m.residual == 0);
    }
  }
}

// An arch: the core drains from the bottom up until, at t_stop, the flow stops with rows of the
// core still over the orifice (a clog); a drained hopper stops with particles only at its sides.
// Both stop; only the first has arched, with its last exit at t_stop (to the sampling).
BOOST_AUTO_TEST_CASE(an_arch_is_told_from_a_drained_hopper) {
  for (const int nx : {12, 20})
    for (const double t_stop : {0.3, 0.8})
      for (const double dt : {0.005, 0.02}) {
        const ParticleState<double> s = bed(nx, 30);
        const auto clogged = [&](std::size_t k) {
          const double x = std::fabs(s.position[k].x), y = s.position[k].y;
          const double t = x < 0.025 ? 2 * y : 0.3 + 2 * y + 4 * x;  // the core first, then the sides
          return t < t_stop ? t : hopper::DischargeRecord::kNever;
        };
        const auto drained = [&](std::size_t k) {  // all but the bottom corners, by 2 s
          const double x = std::fabs(s.position[k].x), y = s.position[k].y;
          if (x > 0.4 * 0.01 * nx && y < 0.03) return hopper::DischargeRecord::kNever;
          return x < 0.025 ? 2 * y : 0.3 + 2 * y + 4 * x;
        };
        BOOST_TEST_CONTEXT("nx " << nx << ", stop at " << t_stop << " s, sampled every " << dt << " s") {
          const hopper::DischargeSummary a = replay(s, clogged, dt, t_stop + 1.0, 0.5);
          BOOST_TEST(a.arched);
          BOOST_TEST(a.last_exit <= t_stop + 1e-12);
          BOOST_TEST(a.last_exit > t_stop - dt - 0.02 - 1e-12);  // the last exit before the stop, to a sample and a row
          const double last = 2 * 0.005 + 2 * 0.01 * 29 + 4 * 0.005 * (nx - 1) + 0.3;  // the drained bed's last exit
          const hopper::DischargeSummary d = replay(s, drained, dt, last + 1.0, 0.5);
          BOOST_TEST(!d.arched);
          BOOST_TEST(d.residual > 0);
          // not judged without a span, nor before the span has passed
          BOOST_TEST(!replay(s, clogged, dt, t_stop + 1.0, 0).arched);
          BOOST_TEST(!replay(s, clogged, dt, t_stop + 0.3, 0.5).arched);
        }
      }
}

// A record saved mid-discharge (study_hopper's checkpoint) and restored into a fresh one, then fed
// the rest, has the uninterrupted record's text and summary bit for bit; a damaged text is refused.
BOOST_AUTO_TEST_CASE(a_saved_record_goes_on_as_the_uninterrupted_one) {
  for (const int cut : {0, 7, 40})  // samples before the checkpoint
    for (const double dt : {0.005, 0.02}) {
      const ParticleState<double> s = bed(14, 25);
      const auto exit = [&](std::size_t k) {  // funnel flow that arches at 0.45 s
        const double x = std::fabs(s.position[k].x), y = s.position[k].y;
        const double t = x < 0.025 ? 2 * y : 0.3 + 2 * y + 4 * x;
        return t < 0.45 ? t : hopper::DischargeRecord::kNever;
      };
      BOOST_TEST_CONTEXT("saved after " << cut << " samples " << dt << " s apart") {
        hopper::DischargeRecord whole, first;
        whole.open(s, 0.0, 0.025), first.open(s, 0.0, 0.025);
        sample(whole, s, exit, dt, 0, 1.2);
        sample(first, s, exit, dt, 0, (cut - 0.5) * dt);
        hopper::DischargeRecord rest;
        std::istringstream in(first.save());
        rest.restore(in);
        BOOST_TEST(rest.save() == first.save());
        sample(rest, s, exit, dt, cut, 1.2);
        BOOST_TEST(rest.save() == whole.save());
        const hopper::DischargeSummary a = whole.summary(0.025, 0.5), b = rest.summary(0.025, 0.5);
        BOOST_TEST(a.arched);
        BOOST_TEST(b.arched);
        BOOST_TEST(a.discharged == b.discharged);
        BOOST_TEST(a.flow_rate == b.flow_rate);  // bitwise: every number saved to 17 digits
        BOOST_TEST(a.last_exit == b.last_exit);
        BOOST_TEST(a.t_top_centre == b.t_top_centre);
        // cut short, or a word where a number belongs: refused
        const std::string text = whole.save();
        for (const std::string& bad : {text.substr(0, text.size() / 2), std::string("discharge record 2\n"),
                                       text.substr(0, 20) + "#" + text.substr(21)}) {  // "0#0.025 ..."
          hopper::DischargeRecord r;
          std::istringstream damaged(bad);
          BOOST_CHECK_THROW(r.restore(damaged), std::runtime_error);
        }
      }
    }
}

BOOST_AUTO_TEST_SUITE_END()
