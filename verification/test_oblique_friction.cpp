// Oblique impact with friction (thesis section 3.3.2, Figs 3.16-3.17). History-free friction
// (thesis eq. 2.3, laws/history_free_friction.hpp):
//   F_t = -min(mu F_n, K_T |v_t|) v_t / |v_t|     (N; v_t: slip at the contact point, m/s)
// Once a body slides on a flat face, F_n = m g and F_t = mu m g, so (Coulomb)
//   v_t(t) = v_t(t_0) - mu g (t - t_0)
// until K_T |v_t| < mu m g. During an impact F_n >> m g, so with K_T |v_t| < mu F_n the viscous
// branch carries the friction even at high slip speed (the thesis's "steps" in Fig 3.16b).
//
// Asserted scene: a cube (bounding radius 0.25 cm, cases/single_body.hpp) landing flat, 0.5 mm
// above the floor with v_t = 0.5 m/s, v_n = -0.5 m/s; Hertz K_n = 1e9 N/m^(3/2), K_D = 5e4
// kg s^-1 m^-1/2, with the no-tension clamp (a pulling dashpot acting at the contact point
// would tip a flat face over: cube_at_rest); mu = 0.5, below the tipping limit of a cube sliding on a face (mu = (a/2)/h = 1),
// so it slides without tipping; K_T = 0.5 kg/s, so that K_T |v_t| (0.25 N at 0.5 m/s) is below
// mu F_n during the impact (F_n ~ 10 N) and far above mu m g = 3e-4 N while sliding.
// Checked: the slope of v_t(t) while sliding, both friction branches, and that the total energy
// (kinetic + gravitational + elastic 2/5 K_n delta^(5/2)) never rises.
//
// Figure scene (thesis): the octahedron, vertex down, v_t = 2 m/s, v_n = -0.5 m/s from 0.75 cm,
// mu = 1.54, K_D = 2e5, K_T = 4e3 (thesis "kg.cm.s^-1", read as kg/s). With these masses
// (5e-5 kg) K_T |v_t| exceeds mu F_n above |v_t| ~ 1 mm/s, so the thesis's viscous regime at high
// slip speed does not occur with its own numbers in SI; mu = 1.54 is also beyond the octahedron's
// tipping limits (0.71 towards an edge, 1.41 towards a vertex), so it tumbles instead of sliding.
// The full run (0.5 s) is made only for the figure; the test starts 0.1 mm above the first touch
// (with the throw's ballistic velocity there), follows the first impact for 3 ms and checks that
// the energy never rises.
#include <boost/test/unit_test.hpp>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include "verification/cases/single_body.hpp"
#include "verification/report.hpp"
#include "verification/scenes.hpp"

using namespace blaze;
using namespace blaze::test;
namespace cs = blaze::test::cases;

namespace {

constexpr double kG = 9.81;
// Time steps: the damping force K_D delta^(1/2) v_n acts at a corner when the body tilts, where the
// effective mass 1/(1/m + r^2/I) is ~1e-5 kg; explicit integration needs K_D delta^(1/2) dt below
// twice that (~2e-7 s for the impacts here; at 5e-7 s the cube's impact rang at the step rate and
// threw it off the floor). The cube is resumed at 1e-6 s once the impact is over (resting on its
// face, the same limit gives ~4e-6 s).
constexpr double kCubeImpactDt = 2e-7, kCubeSlidingDt = 1e-6, kOctahedronDt = 1e-7;  // s
constexpr double kCubeKt = 0.5;                          // kg/s
using Law = ContactLaw<double, Hertz, HistoryFreeFriction>;

struct Sample {
  double t, x, y, vx, vy;  // centre of mass, m and m/s
  double slip;             // |v_t| at the contact point (m/s), 0 when not touching
  double fn, ft;           // N: normal force, |tangential force| (0 when not touching)
  double aligned;          // smallest cosine between a contact-patch point's slip and the mean slip (1: one point)
  double energy;           // J: kinetic + m g y + 2/5 K_n delta^(5/2)
};

struct Scene {
  bool no_tension;         // Hertz::without_tension()
  ConvexShape body;
  Quat<double> orientation;
  double height;           // centre of mass above the floor at t = 0, m
  double vt, vn;           // m/s (vn > 0: downwards)
  double mu, kt, kd;       // -, kg/s, kg s^-1 m^-1/2
  double dt_impact;        // s, up to t_settled
  double t_settled;        // s: the impacts are over; the body is resumed with dt from here
  double dt, duration;     // s
  double dense_until;      // s: every step is sampled before this time, then every `every` steps
  long every;
};

double kinetic(const ParticleState<double>& s) {
  const Mat3<double> r = Mat3<double>::rotation(s.orientation[0]);
  const Vec3<double> wb = r.transpose_times(s.angular_velocity[0]);
  return 0.5 * s.mass[0] * norm2(s.velocity[0]) +
         0.5 * (wb.x * wb.x * s.inertia[0].x + wb.y * wb.y * s.inertia[0].y + wb.z * wb.z * s.inertia[0].z);
}

std::vector<Sample> run(const Scene& sc) {
  auto hertz = Hertz<double>::from_stiffness(cs::kThesisKn, sc.body.bounding_radius, sc.kd);
  if (sc.no_tension) hertz = hertz.without_tension();
  const Law law{hertz, HistoryFreeFriction<double>::make(sc.mu, sc.kt)};
  const auto floor = floor_square<double>(0.0, 1.0);
  const Vec3<double> g{0, -kG, 0}, lo{-0.02, -0.01, -0.02}, hi{sc.vt * sc.duration + 0.05, 0.02, 0.02};
  const double k_n = hertz.k_hat * std::sqrt(sc.body.bounding_radius);
  std::vector<Sample> out;
  // Steps `sim` to t_end (s; its clock starts at t0), sampling as the scene says.
  const auto advance = [&](auto& sim, double t0, double t_end) {
    const long steps = static_cast<long>(std::llround((t_end - t0) / sim.params().dt));
    for (long k = 1; k <= steps; ++k) {
      sim.step();
      const double t = t0 + sim.time();
      if (t > sc.dense_until && k % sc.every != 0) continue;
      if (sim.size() != 1u) BOOST_FAIL("the body left the domain at t = " << t << " s");
      const auto st = sim.state();
      const Vec3<double> f = sim.forces()[0];
      const auto c = sim.shape().collide_world({st.position[0], st.orientation[0], st.type[0], 0}, floor);
      double slip = 0, elastic = 0, aligned = 1;
      if (c.touching) {
        const auto slip_at = [&](const Vec3<double>& p) {
          const Vec3<double> v = st.velocity[0] + cross(st.angular_velocity[0], p - st.position[0]);
          return Vec3<double>{v.x, 0, v.z};
        };
        const Vec3<double> vc = slip_at(c.point);
        slip = norm(vc);
        elastic = 0.4 * k_n * std::pow(c.overlap, 2.5);
        // A face contact acts over a patch (contact_patch.hpp), each point sliding its own way: on
        // the Coulomb branch at every point, |F_t| = |sum_k mu F_n,k t_k| >= mu F_n min_k t_k . t.
        for (int q = 0; q < c.patch.count && slip > 0; ++q) {
          const Vec3<double> vk = slip_at(c.patch.point[q]);
          aligned = std::min(aligned, norm(vk) > 0 ? dot(vk, vc) / (norm(vk) * slip) : -1.0);
        }
      }
      out.push_back({t, st.position[0].x, st.position[0].y, st.velocity[0].x, st.velocity[0].y, slip, f.y,
                     std::hypot(f.x, f.z), aligned, kinetic(st) + st.mass[0] * kG * st.position[0].y + elastic});
    }
  };
  auto impact = cs::body_over_floor(sc.body, cs::kThesisDensity, law, floor, sc.orientation, {0, sc.height, 0},
                                    {sc.vt, -sc.vn, 0}, g, sc.dt_impact, lo, hi);
  advance(impact, 0, std::min(sc.t_settled, sc.duration));
  if (sc.duration > sc.t_settled) {
    auto rest = cs::body_over_floor(sc.body, cs::kThesisDensity, law, floor, impact.state(), g, sc.dt, lo, hi);
    advance(rest, sc.t_settled, sc.duration);
  }
  return out;
}

// Which branch of min(mu F_n, K_T |v_t|) a sample's force is on: the Coulomb cap is met to
// rounding, the viscous branch lies below it. (The floor normal is exactly +y, so F_n = F_y and
// the tangential force is (F_x, F_z).)
// Over a contact patch the points slide in slightly different directions (a turning body), so the
// resultant of their Coulomb forces is mu F_n times at least the smallest cosine between a point's
// slip and the mean slip.
bool on_coulomb_branch(const Sample& s, double mu) {
  return s.ft >= mu * s.fn * (s.aligned - tol::friction_branch_tie);
}

// Largest rise of the total energy above its starting value, relative to the starting value.
double energy_rise(const std::vector<Sample>& s, double e0) {
  double worst = 0;
  for (const auto& p : s) worst = std::max(worst, (p.energy - e0) / e0);
  return worst;
}

void write_figures(const std::vector<Sample>& s, const Scene& sc, const std::string& title) {
  FigureData f16("fig-3.16-" + title, "t_s x_mm y_mm v_x_m_per_s");
  FigureData f17("fig-3.17-" + title, "slip_m_per_s F_t_N F_n_N (touching samples)");
  for (std::size_t k = 0; k < s.size(); ++k) {
    if (s[k].t > sc.dense_until && (k % 10) != 0) continue;  // plot density
    f16.row(s[k].t, s[k].x * 1e3, s[k].y * 1e3, s[k].vx);
    if (s[k].fn > 0 && s[k].slip > 0) f17.row(s[k].slip, s[k].ft, s[k].fn);
  }
}

const char* kCase = "Oblique impact with friction (3.3.2, Figs 3.16-3.17)";

}  // namespace

BOOST_AUTO_TEST_SUITE(oblique_friction)

BOOST_AUTO_TEST_CASE(cube_slides_with_slope_mu_g_after_viscous_impact) {
  const ConvexShape cube = cs::thesis_cube();
  const Eigen::Vector3d up(0, 1, 0), along(1, 0, 0);
  const double h = cs::cube_half_edge(cube), m = cs::kThesisDensity * cube.volume;
  const Scene sc{true, cube, cs::cube_facing<double>(cube, -up, along), h + 0.5e-3, 0.5, 0.5, 0.5, kCubeKt, 5e4,
                 kCubeImpactDt, 8e-3, kCubeSlidingDt, 0.095, 2e-3, 10};
  const auto s = run(sc);
  write_figures(s, sc, "cube");
  const double e0 = 0.5 * m * (sc.vt * sc.vt + sc.vn * sc.vn) + m * kG * sc.height;
  // Impact: the normal force well above the weight; fast: slip above half the initial speed.
  long impact_fast = 0, impact_fast_viscous = 0, impact = 0, impact_viscous = 0;
  for (const auto& p : s) {
    if (!(p.fn > 10 * m * kG)) continue;
    const bool viscous = !on_coulomb_branch(p, sc.mu);
    ++impact, impact_viscous += viscous;
    if (p.slip > 0.5 * sc.vt) ++impact_fast, impact_fast_viscous += viscous;
  }
  // Sliding: from when the impact has died out (normal speed below 1 mm/s and the normal force
  // below the impact's 10 m g: the normal speed also passes through zero at the impact's deepest
  // point, where the contact patch's rocking now left a sample) until the slip falls below 10% of
  // the initial speed; v_t(t) fitted by least squares.
  std::size_t a = 0;
  while (a < s.size() && !(s[a].fn > 0)) ++a;
  while (a < s.size() && (std::fabs(s[a].vy) > 1e-3 || s[a].fn > 10 * m * kG)) ++a;
  std::size_t b = a;
  while (b < s.size() && s[b].vx > 0.1 * sc.vt) ++b;
  BOOST_TEST_REQUIRE(b > a + 100);
  double n = 0, st = 0, sv = 0, stt = 0, stv = 0;
  long sliding_viscous = 0;
  for (std::size_t k = a; k < b; ++k) {
    n += 1, st += s[k].t, sv += s[k].vx, stt += s[k].t * s[k].t, stv += s[k].t * s[k].vx;
    sliding_viscous += !on_coulomb_branch(s[k], sc.mu);
  }
  const double slope = (n * stv - st * sv) / (n * stt - st * st);
  FigureData fit("fig-3.16-cube-fit", "t_s v_coulomb_m_per_s (v(t_a) - mu g (t - t_a) over the fitted window)");
  fit.row(s[a].t, s[a].vx);
  fit.row(s[b].t, s[a].vx - sc.mu * kG * (s[b].t - s[a].t));
  const double fast_fraction = impact_fast > 0 ? static_cast<double>(impact_fast_viscous) / impact_fast : 0;
  BOOST_TEST_MESSAGE("oblique cube: impact (F_n > 10 m g) " << impact << " samples, " << impact_viscous
                     << " on the viscous branch; with |v_t| > " << 0.5 * sc.vt << " m/s: " << impact_fast_viscous << " of "
                     << impact_fast << " (" << 100 * fast_fraction << "%); sliding fit over t = " << s[a].t << " .. "
                     << s[b].t << " s (v_t " << s[a].vx << " -> " << s[b].vx << " m/s), " << sliding_viscous << " of "
                     << b - a << " samples viscous; slope " << slope << " m/s^2 vs -mu g = " << -sc.mu * kG
                     << "; largest energy rise " << energy_rise(s, e0));
  check_relative({kCase, "sliding slope dv_t/dt vs -mu g, cube, mu = 0.5, dt = 1e-6 s (impact 2e-7 s)", "linear (qualitative)",
                  "Coulomb sliding, F_t = mu m g"},
                 slope, -sc.mu * kG, tol::sliding_slope);
  check_at_least({kCase, "share of impact samples with |v_t| > v_t0/2 on the viscous branch K_T|v_t| < mu F_n",
                  "visible (qualitative)", "eq. 2.3, K_T = 0.5 kg/s, F_n > 10 m g"},
                 fast_fraction, tol::viscous_impact_share);
  check_at_most({kCase, "sliding samples off the Coulomb branch (count)", "-", "eq. 2.3: K_T|v_t| >> mu m g"},
                static_cast<double>(sliding_viscous), 0);
  check_at_most({kCase, "largest rise of kinetic + potential + elastic energy / E_0, cube", "-",
                 "dissipative contact: energy never rises"},
                energy_rise(s, e0), tol::oblique_energy_rise);
}

// The thesis's own scene; without BLAZE_FIGURE_DIR only its first impact.
BOOST_AUTO_TEST_CASE(thesis_octahedron_never_gains_energy) {
  const ConvexShape octa = cs::thesis_octahedron();
  const Eigen::Vector3d up(0, 1, 0), along(1, 0, 0);
  const double m = cs::kThesisDensity * octa.volume;
  const char* figure_dir = std::getenv("BLAZE_FIGURE_DIR");
  const bool full = figure_dir != nullptr && *figure_dir != 0;
  // Without figures the flight is skipped: the body starts 0.1 mm above touching with the
  // ballistic velocity of the thesis's throw there, and 3 ms cover the first impact.
  const double r = octa.bounding_radius, drop = full ? 0 : 7.5e-3 - (r + 1e-4);
  const double vn = std::sqrt(0.25 + 2 * kG * drop), duration = full ? 0.5 : 3e-3;
  const Scene sc{false, octa, cs::octahedron_pointing<double>(octa, -up, along), 7.5e-3 - drop, 2.0, vn, 1.54, 4e3, 2e5,
                 kOctahedronDt, duration, kOctahedronDt, duration, 0.02, 10};
  const auto s = run(sc);
  write_figures(s, sc, "octahedron");
  const double e0 = 0.5 * m * (sc.vt * sc.vt + sc.vn * sc.vn) + m * kG * sc.height;
  long touching = 0, viscous = 0;
  for (const auto& p : s)
    if (p.fn > 0) ++touching, viscous += !on_coulomb_branch(p, sc.mu);
  BOOST_TEST_MESSAGE("thesis octahedron: " << touching << " samples touching, " << viscous
                     << " on the viscous branch; v_x at the end " << s.back().vx << " m/s; largest energy rise "
                     << energy_rise(s, e0));
  check_at_most({kCase, "largest rise of kinetic + potential + elastic energy / E_0, octahedron (thesis scene), first impact",
                 "-", "dissipative contact: energy never rises"},
                energy_rise(s, e0), tol::oblique_energy_rise);
}

BOOST_AUTO_TEST_SUITE_END()
