// Head-on elastic collision, octahedron onto a resting free cube (thesis section 3.3.1.1, Table 3.1,
// Figs 3.9-3.11). Closed forms (cases/octahedron_on_cube.hpp; Hertz 1881, Johnson, Contact
// Mechanics, 1985, section 11.4):
//   separation speed = approach speed v;  v_o' = -(m_o - m_c)/(m_o + m_c) v,  v_c' = -2 m_o/(m_o + m_c) v
//   delta_max = (5 m_eff v^2 / (4 K_n))^(2/5) (m),  t_c = 2.9432 delta_max / v (s)
//   loading and unloading follow the same F = K_n delta^(3/2) (N): an elastic contact has no hysteresis.
// Bounding radii 0.25 cm, K_n = 1e9 N/m^(3/2), rho = 2500 kg/m^3 (assumed), speeds 0.0625-4 m/s.
// The step is a fixed fraction of each speed's contact time. The thesis used dt = 1e-5 s for all
// speeds: with these masses t_c runs from 21 us (0.0625 m/s) down to 9.3 us (4 m/s), so its
// fastest contacts lasted about one step.
#include <boost/test/unit_test.hpp>
#include <algorithm>
#include <cmath>
#include <cstdio>
#include "verification/cases/octahedron_on_cube.hpp"
#include "verification/report.hpp"
#include "verification/tolerances.hpp"

using namespace blaze;
using namespace blaze::test;
namespace cs = blaze::test::cases;

namespace {

struct TableRow {
  double speed;         // m/s
  const char* thesis;   // |% Diff| of thesis Table 3.1
};
const TableRow kTable31[] = {{0.0625, "0.13%"}, {0.125, "0.20%"}, {0.25, "0.061%"}, {0.5, "0.36%"},
                             {1.0, "0.32%"},    {2.0, "0.14%"},   {4.0, "0.33%"}};

const char* kCase = "Octahedron onto cube, elastic (3.3.1.1, Table 3.1)";
const char* kSource = "1-D elastic collision; Hertz delta_max = (5 m_eff v^2 / 4 K_n)^(2/5)";

std::string format(const char* fmt, double a) {
  char buf[128];
  std::snprintf(buf, sizeof buf, fmt, a);
  return buf;
}

// Peak penetration from the samples, refined by the parabola through the largest sample and its
// neighbours (the sampled maximum alone is low by O((dt/t_c)^2)).
double peak_penetration(const std::vector<cs::HeadOnSample>& s) {
  std::size_t k = 0;
  for (std::size_t i = 1; i < s.size(); ++i)
    if (s[i].delta > s[k].delta) k = i;
  if (k == 0 || k + 1 >= s.size()) return s[k].delta;
  const double a = s[k - 1].delta, b = s[k].delta, c = s[k + 1].delta;
  const double den = a - 2 * b + c;
  return den < 0 ? b - 0.125 * (c - a) * (c - a) / den : b;
}

}  // namespace

BOOST_AUTO_TEST_SUITE(octahedron_on_cube)

// Table 3.1 with the closed forms: rebound speed, each body's final velocity and the peak
// penetration for the seven speeds; figure data for Figs 3.9 (penetration vs time) and 3.11
// (velocities vs time).
BOOST_AUTO_TEST_CASE(elastic_rebound_and_peak_penetration) {
  const cs::OctahedronOnCubeScene scene;
  BOOST_TEST_MESSAGE("octahedron-on-cube: m_o = " << scene.m_octa() << " kg, m_c = " << scene.m_cube() << " kg, r_eff = "
                                                  << scene.r_eff() << " m");
  FigureData fig9("fig-3.9", "t_us delta_um (one block per speed)");
  FigureData fig11("fig-3.11", "t_over_tc v_octa_over_V v_cube_over_V v_octa_exact_over_V v_cube_exact_over_V");
  FigureData peaks("fig-3.9-peaks", "V_m_per_s delta_max_um delta_max_exact_um t_c_us");
  const double steps = tol::octahedron_steps_per_contact;
  double worst_velocity = 0, worst_delta = 0;
  std::vector<double> log_v, log_delta;
  for (const auto& row : kTable31) {
    const double v = row.speed, dt = scene.contact_time(v) / steps;
    const auto r = cs::octahedron_on_cube<double, VelocityVerlet>(scene, v, dt, true);
    BOOST_TEST_REQUIRE(r.separated);
    const double delta_max = peak_penetration(r.samples);
    const double velocity_error = std::max(std::fabs(r.v_octa - r.v_octa_exact), std::fabs(r.v_cube - r.v_cube_exact)) / v;
    const double delta_error = std::fabs(delta_max / r.delta_max_exact - 1);
    worst_velocity = std::max(worst_velocity, velocity_error);
    worst_delta = std::max(worst_delta, delta_error);
    log_v.push_back(std::log(v));
    log_delta.push_back(std::log(delta_max));
    BOOST_TEST_MESSAGE("V = " << v << " m/s: t_c = " << r.contact_time_exact << " s (thesis dt 1e-5 s = "
                              << 1e-5 / r.contact_time_exact << " t_c), dt = " << dt << " s, rebound " << r.rebound_ratio
                              << ", v_o' = " << r.v_octa << " (exact " << r.v_octa_exact << "), v_c' = " << r.v_cube
                              << " (exact " << r.v_cube_exact << "), delta_max = " << delta_max << " m (exact "
                              << r.delta_max_exact << "), final |w| = " << r.max_spin << " rad/s");
    check_relative({kCase, format("separation / approach speed, V = %g m/s, double, dt = t_c/200", v), row.thesis, kSource},
                   r.rebound_ratio, 1.0, tol::octahedron_rebound_speed);
    fig9.block(format("V = %g m/s", v));
    fig11.block(format("V = %g m/s", v));
    const double t_touch = (0.05 * r.delta_max_exact) / v;
    for (const auto& s : r.samples) {
      if (s.delta > -0.05 * r.delta_max_exact) fig9.row((s.t - t_touch) * 1e6, s.delta * 1e6);
      fig11.row((s.t - t_touch) / r.contact_time_exact, s.v_octa / v, s.v_cube / v, r.v_octa_exact / v, r.v_cube_exact / v);
    }
    peaks.row(v, delta_max * 1e6, r.delta_max_exact * 1e6, r.contact_time_exact * 1e6);
  }
  check_at_most({kCase, "max |v' - v'_exact| / V of either body, 7 speeds, double, dt = t_c/200", "-", "1-D elastic collision, two masses"},
                worst_velocity, tol::octahedron_final_velocity);
  check_at_most({kCase, "max |delta_max / closed form - 1|, 7 speeds, dt = t_c/200", "-", kSource}, worst_delta,
                tol::octahedron_peak_penetration);
  // Least-squares slope of log delta_max against log v: the closed form's 4/5.
  const double n = static_cast<double>(log_v.size());
  double sx = 0, sy = 0, sxx = 0, sxy = 0;
  for (std::size_t k = 0; k < log_v.size(); ++k)
    sx += log_v[k], sy += log_delta[k], sxx += log_v[k] * log_v[k], sxy += log_v[k] * log_delta[k];
  const double slope = (n * sxy - sx * sy) / (n * sxx - sx * sx);
  check_near({kCase, "exponent of delta_max ~ v^p over 0.0625-4 m/s", "-", "Hertz: p = 4/5"}, slope, 0.8,
             tol::octahedron_penetration_exponent);
}

// Fig 3.10: the elastic force against penetration at V = 2 m/s. Loading and unloading must lie on
// one curve; the unloading force is compared with the loading branch interpolated at the same
// penetration. The force comes from the simulation's force array and the penetration from the
// body positions, so the check also covers the contact's overlap and normal.
BOOST_AUTO_TEST_CASE(loading_and_unloading_coincide) {
  const cs::OctahedronOnCubeScene scene;
  const double v = 2.0, dt = scene.contact_time(v) / tol::octahedron_steps_per_contact;
  const auto r = cs::octahedron_on_cube<double, VelocityVerlet>(scene, v, dt, true);
  std::vector<cs::HeadOnSample> load, unload;
  bool past_peak = false;
  for (std::size_t k = 0; k < r.samples.size(); ++k) {
    const auto& s = r.samples[k];
    if (!(s.delta > 0)) continue;
    past_peak = past_peak || (k > 0 && s.delta < r.samples[k - 1].delta);
    (past_peak ? unload : load).push_back(s);
  }
  BOOST_TEST_REQUIRE(load.size() > 10u);
  BOOST_TEST_REQUIRE(unload.size() > 10u);
  double f_max = 0, worst = 0, worst_hertz = 0;
  for (const auto& s : r.samples) f_max = std::max(f_max, s.force);
  for (const auto& u : unload) {
    // Loading penetrations increase: find the bracketing pair.
    const auto it = std::lower_bound(load.begin(), load.end(), u.delta,
                                     [](const cs::HeadOnSample& a, double d) { return a.delta < d; });
    if (it == load.begin() || it == load.end()) continue;
    const auto& a = *(it - 1);
    const auto& b = *it;
    const double f_load = a.force + (b.force - a.force) * (u.delta - a.delta) / (b.delta - a.delta);
    worst = std::max(worst, std::fabs(u.force - f_load) / f_max);
  }
  for (const auto& s : r.samples)
    if (s.delta > 0) worst_hertz = std::max(worst_hertz, std::fabs(s.force - r.k_n * std::pow(s.delta, 1.5)) / f_max);
  BOOST_TEST_MESSAGE("V = 2 m/s: " << load.size() << " loading and " << unload.size() << " unloading samples, F_max = " << f_max
                                   << " N, max |F_unload - F_load| / F_max = " << worst
                                   << ", max |F - K_n delta^1.5| / F_max = " << worst_hertz);
  check_at_most({"Octahedron onto cube, elastic (3.3.1.1, Fig 3.10)",
                 "max |F_unload(delta) - F_load(delta)| / F_max, V = 2 m/s, dt = t_c/200", "symmetric (qualitative)",
                 "elastic contact: no hysteresis"},
                worst, tol::octahedron_load_unload);
  check_at_most({"Octahedron onto cube, elastic (3.3.1.1, Fig 3.10)", "max |F - K_n delta^1.5| / F_max, V = 2 m/s", "-",
                 "eq. 3.6 with delta from the positions"},
                worst_hertz, tol::octahedron_load_unload);
  FigureData fig("fig-3.10", "delta_um F_N K_n_delta^1.5_N");
  fig.block("loading");
  for (const auto& s : load) fig.row(s.delta * 1e6, s.force, r.k_n * std::pow(s.delta, 1.5));
  fig.block("unloading");
  for (const auto& s : unload) fig.row(s.delta * 1e6, s.force, r.k_n * std::pow(s.delta, 1.5));
}

BOOST_AUTO_TEST_SUITE_END()
