// Chung & Ooi (2011), "Benchmark tests for verifying discrete element modelling codes at particle
// impact level", Granular Matter 13:643-656, tests 1-3, with the Hertz law (hertz.hpp).
//
// Elastic Hertz impact, relative approach speed v, effective mass m* and radius R*, modulus E*:
//   K_n = (4/3) E* sqrt(R*)                           (N/m^1.5)
//   delta_max = (5 m* v^2 / (4 K_n))^(2/5)           (m)       peak overlap
//   F_max = K_n delta_max^(3/2)                       (N)       peak force
//   t_c = (4/5) B(2/5, 1/2) delta_max / v = 2.9432 delta_max / v   (s)  contact time
//   t(delta) = (delta_max / v) (2/5) B(2/5, 1/2) I_{(delta/delta_max)^(5/2)}(2/5, 1/2) on loading
//   (I: regularised incomplete beta; unloading mirrors it), which gives the force history F(t).
// (Johnson, Contact Mechanics 1985, sec. 11.4.)
// Test 1: two identical spheres, R = 10 mm, each at 10 m/s towards the other (v = 20 m/s,
//   m* = m/2, R* = R/2, E* = E / (2 (1 - nu^2))); glass (E 48 GPa, nu 0.20, 2800 kg/m^3) and
//   limestone (20 GPa, 0.25, 2500).
// Test 2: a sphere onto a rigid plane (infinite modulus: E* = E / (1 - nu^2), m* = m, R* = R),
//   R = 0.1 m, v = 0.2 m/s; aluminium alloy (70 GPa, nu 0.30, 2699) and magnesium alloy (40 GPa,
//   0.35, 1800). The paper's aluminium alloy of test 2 has nu = 0.30 (as the Yade and PySPH
//   implementations of the benchmark use; 0.33 is its test-5 alloy).
// Test 3: a sphere onto a rigid plane, R = 2.5 mm, v = 3.9 m/s, input restitution 0.2 ... 1.0;
//   alumina (380 GPa, 0.23, 4000) and cast iron (100 GPa, 0.25, 7000). The law is
//   Hertz::from_restitution (delta^(1/4) damping with eta chosen for exact e), so the output
//   restitution must equal the input. Every test runs with the free contact and with the
//   no-tension clamp (without_tension(); from_restitution(..., true) re-solves eta for it).
// Time step: t_c / 1000 of the elastic contact (tol::chung_ooi_steps_per_contact). The elastic
// quantities then agree with theory to ~1e-6; the restitution to ~4e-4, converging at order ~5/4
// only, because the delta^(1/4) dashpot has an unbounded derivative at touch and separation.
#include <boost/test/unit_test.hpp>
#include <gsl/gsl_sf_gamma.h>
#include <algorithm>
#include <cmath>
#include <string>
#include <vector>
#include "verification/report.hpp"
#include "verification/scenes.hpp"

using namespace blaze;
using namespace blaze::test;

namespace {

using Law = ContactLaw<double, Hertz, NoFriction>;
using Sim = Simulation<DefaultSpace, SphereShape, Law, VelocityVerlet>;

const std::string kPaper = "Chung & Ooi 2011, Granular Matter 13:643";

struct Material {
  const char* name;
  double young, poisson, density;  // Pa, -, kg/m^3
};

// Closed-form elastic Hertz impact.
struct HertzImpact {
  double k_n, v, delta_max, f_max, t_c;
  HertzImpact(double e_star, double r_star, double m_star, double speed) : k_n(4.0 / 3.0 * e_star * std::sqrt(r_star)), v(speed) {
    delta_max = std::pow(5 * m_star * v * v / (4 * k_n), 0.4);
    f_max = k_n * std::pow(delta_max, 1.5);
    t_c = 0.8 * gsl_sf_beta(0.4, 0.5) * delta_max / v;
  }
  // Force (N) at time t (s) after first touch: invert t(delta) by bisection.
  double force(double t) const {
    if (t <= 0 || t >= t_c) return 0;
    const double tl = std::min(t, t_c - t), scale = 0.4 * gsl_sf_beta(0.4, 0.5) * delta_max / v;
    double lo = 0, hi = 1;
    for (int it = 0; it < 60; ++it) {
      const double u = 0.5 * (lo + hi);
      (scale * gsl_sf_beta_inc(0.4, 0.5, std::pow(u, 2.5)) < tl ? lo : hi) = u;
    }
    return f_max * std::pow(0.5 * (lo + hi), 1.5);
  }
};

struct Measured {
  double peak_force = 0, peak_overlap = 0, duration = 0, rebound = 0;  // N, m, s, m/s
  double worst_force_history = 0;  // max |F(t) - F_Hertz(t)| / F_max
  std::vector<double> t, f;        // force history from first touch (s, N)
};

// Follows one impact until the bodies separate. gap(state) is the signed gap (m, < 0 in contact),
// force(state, forces) the contact force magnitude (N), speed(state) the separation speed (m/s).
template <class Gap, class Force, class Speed>
Measured follow(Sim& sim, const HertzImpact* theory, Gap gap, Force force, Speed speed) {
  Measured m;
  double t_prev = 0, g_prev = gap(sim.state()), t_touch = -1;
  for (long k = 0; k < 10000000L; ++k) {
    sim.step();
    const auto st = sim.state();
    const double t = sim.time(), g = gap(st);
    if (t_touch < 0 && g < 0) t_touch = t_prev + (t - t_prev) * g_prev / (g_prev - g);
    if (t_touch >= 0 && g < 0) {
      const double f = force(st, sim.forces());
      m.peak_force = std::max(m.peak_force, f);
      m.peak_overlap = std::max(m.peak_overlap, -g);
      m.t.push_back(t - t_touch);
      m.f.push_back(f);
      if (theory) m.worst_force_history = std::max(m.worst_force_history, std::fabs(f - theory->force(t - t_touch)) / theory->f_max);
    }
    if (t_touch >= 0 && g >= 0) {
      m.duration = t_prev + (t - t_prev) * g_prev / (g_prev - g) - t_touch;
      m.rebound = speed(st);
      return m;
    }
    t_prev = t;
    g_prev = g;
  }
  BOOST_FAIL("impact did not end");
  return m;
}

// Test 1: spheres along x, a few steps apart, closing at v_each each.
Measured two_spheres(const Law& law, const Material& mat, double r, double v_each, const HertzImpact& h) {
  const double dt = h.t_c / tol::chung_ooi_steps_per_contact, gap0 = 20 * 2 * v_each * dt;
  ParticleState<double> s;
  s.add_sphere({-(r + 0.5 * gap0), 0, 0}, r, mat.density, 0, {v_each, 0, 0});
  s.add_sphere({r + 0.5 * gap0, 0, 0}, r, mat.density, 0, {-v_each, 0, 0});
  Sim sim(params<double>(dt, {0, 0, 0}, 20 * r, 0.1 * r), one_law(law), World<double>{}, s);
  const auto ordered = [](const ParticleState<double>& st) { return std::pair<int, int>{st.id[0] == 0 ? 0 : 1, st.id[0] == 0 ? 1 : 0}; };
  return follow(
      sim, &h,
      [&](const ParticleState<double>& st) {
        const auto [a, b] = ordered(st);
        return st.position[b].x - st.position[a].x - 2 * r;
      },
      [&](const ParticleState<double>& st, const std::vector<Vec3<double>>& f) { return std::fabs(f[ordered(st).first].x); },
      [&](const ParticleState<double>& st) {
        const auto [a, b] = ordered(st);
        return st.velocity[b].x - st.velocity[a].x;
      });
}

// Tests 2 and 3: a sphere falling (no gravity) onto the plane y = 0 at speed v.
Measured sphere_on_plane(const Law& law, const Material& mat, double r, double v, const HertzImpact& h, bool with_theory) {
  const double dt = h.t_c / tol::chung_ooi_steps_per_contact;
  ParticleState<double> s;
  s.add_sphere({0, r + 20 * v * dt, 0}, r, mat.density, 0, {0, -v, 0});
  World<double> world;
  world.polygons.push_back(floor_square<double>(0, 10 * r, 1));
  Sim sim(params<double>(dt, {0, 0, 0}, 20 * r, 0.1 * r), one_law(law), world, s);
  return follow(
      sim, with_theory ? &h : nullptr, [&](const ParticleState<double>& st) { return st.position[0].y - r; },
      [](const ParticleState<double>&, const std::vector<Vec3<double>>& f) { return std::fabs(f[0].y); },
      [](const ParticleState<double>& st) { return st.velocity[0].y; });
}

void write_force_history(FigureData& fig, const std::string& title, const Measured& m, const HertzImpact& h) {
  fig.block(title);
  for (std::size_t k = 0; k < m.t.size(); ++k) fig.row(m.t[k] * 1e6, m.f[k] * 1e-3, h.force(m.t[k]) * 1e-3);
}

// Checks one elastic impact: both law variants, worst of the two, as rows.
void check_elastic(const std::string& test, const Material& mat, const HertzImpact& h, const Measured& free,
                   const Measured& clamped) {
  const std::string name = test + ", " + mat.name;
  const auto worst = [](double a, double b) { return std::max(a, b); };
  const double steps = tol::chung_ooi_steps_per_contact;
  const std::string setting = ", free and no-tension (worst), dt = t_c/" + std::to_string(static_cast<int>(steps));
  BOOST_TEST_MESSAGE(name << ": F_max " << free.peak_force << " N (Hertz " << h.f_max << "), delta_max " << free.peak_overlap
                          << " m (" << h.delta_max << "), t_c " << free.duration << " s (" << h.t_c << "), rebound/v "
                          << free.rebound / h.v);
  check_at_most({name, "peak force vs K_n delta_max^1.5" + setting, "-", kPaper + "; Hertz theory"},
                worst(std::fabs(free.peak_force / h.f_max - 1), std::fabs(clamped.peak_force / h.f_max - 1)),
                tol::chung_ooi_elastic);
  check_at_most({name, "peak overlap vs (5 m* v^2 / 4 K_n)^0.4" + setting, "-", kPaper + "; Hertz theory"},
                worst(std::fabs(free.peak_overlap / h.delta_max - 1), std::fabs(clamped.peak_overlap / h.delta_max - 1)),
                tol::chung_ooi_elastic);
  check_at_most({name, "contact time vs 2.9432 delta_max / v" + setting, "-", kPaper + "; Hertz theory"},
                worst(std::fabs(free.duration / h.t_c - 1), std::fabs(clamped.duration / h.t_c - 1)), tol::chung_ooi_elastic);
  check_at_most({name, "max |F(t) - F_Hertz(t)| / F_max over the contact" + setting, "-", "Hertz F(t) via incomplete beta"},
                worst(free.worst_force_history, clamped.worst_force_history), tol::chung_ooi_elastic);
}

}  // namespace

BOOST_AUTO_TEST_SUITE(chung_ooi)

BOOST_AUTO_TEST_CASE(test1_two_spheres_elastic) {
  const double r = 0.010, v_each = 10;
  FigureData fig("fig-chung-ooi-1", "t_us F_kN F_hertz_kN  (test 1: two spheres R = 10 mm, 2 x 10 m/s)");
  for (const Material& mat : {Material{"glass", 4.8e10, 0.20, 2800}, Material{"limestone", 2.0e10, 0.25, 2500}}) {
    const double e_star = mat.young / (2 * (1 - mat.poisson * mat.poisson));
    const double m = mat.density * 4.0 / 3.0 * kPi * r * r * r;
    const HertzImpact h(e_star, 0.5 * r, 0.5 * m, 2 * v_each);
    const Law law{Hertz<double>::from_modulus(e_star, 0), {}};
    const Measured free = two_spheres(law, mat, r, v_each, h);
    const Measured clamped = two_spheres(Law{law.normal.without_tension(), {}}, mat, r, v_each, h);
    check_elastic("Chung & Ooi test 1 (sphere-sphere)", mat, h, free, clamped);
    write_force_history(fig, std::string("test 1 ") + mat.name, free, h);
  }
}

BOOST_AUTO_TEST_CASE(test2_sphere_on_rigid_plane_elastic) {
  const double r = 0.10, v = 0.2;
  FigureData fig("fig-chung-ooi-2", "t_us F_kN F_hertz_kN  (test 2: sphere R = 0.1 m on a rigid plane, 0.2 m/s)");
  for (const Material& mat : {Material{"aluminium alloy", 7.0e10, 0.30, 2699}, Material{"magnesium alloy", 4.0e10, 0.35, 1800}}) {
    const double e_star = mat.young / (1 - mat.poisson * mat.poisson);
    const double m = mat.density * 4.0 / 3.0 * kPi * r * r * r;
    const HertzImpact h(e_star, r, m, v);
    const Law law{Hertz<double>::from_modulus(e_star, 0), {}};
    const Measured free = sphere_on_plane(law, mat, r, v, h, true);
    const Measured clamped = sphere_on_plane(Law{law.normal.without_tension(), {}}, mat, r, v, h, true);
    check_elastic("Chung & Ooi test 2 (sphere-plane)", mat, h, free, clamped);
    write_force_history(fig, std::string("test 2 ") + mat.name, free, h);
  }
}

BOOST_AUTO_TEST_CASE(test3_restitution_sphere_on_rigid_plane) {
  const double r = 2.5e-3, v = 3.9;
  const double inputs[] = {0.2, 0.4, 0.6, 0.8, 1.0};
  FigureData fig("fig-chung-ooi-3", "e_in e_out_free e_out_no_tension  (test 3: R = 2.5 mm, 3.9 m/s onto a rigid plane)");
  for (const Material& mat : {Material{"alumina (Al2O3)", 3.8e11, 0.23, 4000}, Material{"cast iron", 1.0e11, 0.25, 7000}}) {
    const double e_star = mat.young / (1 - mat.poisson * mat.poisson);
    const double m = mat.density * 4.0 / 3.0 * kPi * r * r * r;
    const HertzImpact h(e_star, r, m, v);
    fig.block(std::string("test 3 ") + mat.name);
    double worst[2] = {0, 0};
    for (double e : inputs) {
      double out[2];
      for (int clamp = 0; clamp < 2; ++clamp) {
        const Law law{Hertz<double>::from_restitution(e_star, e, clamp == 1), {}};
        out[clamp] = sphere_on_plane(law, mat, r, v, h, false).rebound / v;
        worst[clamp] = std::max(worst[clamp], std::fabs(out[clamp] / e - 1));
      }
      BOOST_TEST_MESSAGE("test 3 " << mat.name << ": e_in " << e << ", e_out free " << out[0] << ", no-tension " << out[1]);
      fig.row(e, out[0], out[1]);
    }
    for (int clamp = 0; clamp < 2; ++clamp)
      check_at_most({std::string("Chung & Ooi test 3 (restitution), ") + mat.name,
                     std::string("max |e_out / e_in - 1|, e_in 0.2..1.0, ") + (clamp ? "no-tension clamp" : "free contact") +
                         ", dt = t_c/" + std::to_string(static_cast<int>(tol::chung_ooi_steps_per_contact)),
                     "-", kPaper + "; e exact by Hertz::from_restitution"},
                    worst[clamp], tol::chung_ooi_restitution);
  }
}

BOOST_AUTO_TEST_SUITE_END()
