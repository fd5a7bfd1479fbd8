// Contact stiffness per material pair and the critical time step of a scene.
//
// Linear spring (thesis section 2.3.2): a contact of stiffness k between bodies of effective mass
// m* = m_i m_j / (m_i + m_j) (m* = m_i against a wall) is an oscillator of angular frequency
// w = sqrt(k / m*); the Verlet scheme is stable for dt < 2 / w (the thesis writes 2/sqrt(k/m)).
// A stiffness given as a contact time is the undamped half period t_c = pi sqrt(m*/k) of the
// lightest particle pair of those materials: k = pi^2 m* / t_c^2.
//
// Hertz (section 3.3.1, eq. 3.6): F = (4/3) E* sqrt(R*) delta^(3/2) stiffens with overlap,
// dF/d delta = (3/2) K_n sqrt(delta); at the deepest overlap of an impact at speed v,
// delta_max = (5 m* v^2 / (4 K_n))^(2/5), the oscillator bound is dt < 2 / sqrt(k(delta_max) / m*).
// The Rayleigh time T_R = pi r sqrt(rho / G) / (0.1631 nu + 0.8766), G = E / (2 (1 + nu)), is the
// customary second estimate (the time a surface wave crosses the particle); the smaller governs.
// v is the scene's max_impact_speed, or the largest initial speed plus a fall through the whole
// domain height, sqrt(2 |g| H), plus the fastest moving wall's speed (at least 0.1 m/s).
//
// Tangential spring (tangential = "mindlin" | "linear_spring", tangential_spring.hpp): the contact
// point's tangential oscillation has stiffness k_t and inverse mass kappa / m*, kappa = 1 + m r^2/I
// per body for the contact arm r (a solid sphere: 1 + 5/2 = 3.5, so k_t = 2/7 k_n has the normal
// period; polyhedra are taken at 6, above a cube's 5.5 at its bounding radius). Its bound
// 2 / sqrt(kappa k_t / m*) enters like the normal one; Mindlin's k_t = 8 G* sqrt(R* delta) is taken
// at the impact overlap delta_max above (G* from the two materials' E and nu).
//
// Rolling spring (rolling = "epsd", rolling_resistance.hpp): k_r = 2.25 k_n mu_r^2 R*^2 on a rolling
// inertia I_r >= 1.4 m* R*^2: dt < 2 / sqrt(k_r / I_r) = 2 / sqrt((2.25/1.4) mu_r^2 k_n / m*).
//
// Safe fraction: in a packing with z contacts per particle the fastest mode is at most sqrt(z)
// times the pair frequency (Gershgorin bound of the stiffness matrix), so dt < 2 / (sqrt(z) w);
// 0.2 of the pair limit covers z <= 25 (12 for equal spheres). A scene whose dt exceeds that is
// rejected unless force_dt is set; every run prints the ratio.
//
// Impact overlap: the deepest elastic overlap of a head-on impact at v, delta = v sqrt(m*/k)
// (linear) or the Hertz delta_max above, over every pairing of particle types and walls, as a
// share of the smaller radius. Beyond half the radius a fast particle nears tunnelling (its centre
// crosses a wall's plane at 1), so such a scene is refused unless forced; the run prints the value.
// It grows with size (delta / r ~ sqrt(r) at fixed density), so the largest types govern.
//
// Units: kg, m, s, N/m (linear k), Pa (E, E*).
#pragma once
#include <algorithm>
#include <cmath>
#include <string>
#include "blaze/scene/scene.hpp"

namespace blaze {

constexpr double kSafeStepFraction = 0.2;
constexpr double kMaxImpactOverlap = 0.5;

// The lightest and the smallest particle type of a material (the stiffest pairing); none: mass 0.
struct MaterialExtremes {
  double mass = 0, radius = 0;
};
inline MaterialExtremes extremes(const Scene& s, int material) {
  MaterialExtremes e;
  for (const auto& t : s.types) {
    if (t.material != material) continue;
    const double m = s.materials[static_cast<std::size_t>(t.material)].density * t.volume;
    if (e.mass == 0 || m < e.mass) e.mass = m;
    if (e.radius == 0 || t.size() < e.radius) e.radius = t.size();
  }
  return e;
}

// One material pairing as seen by the contact law: a particle of material a against a particle of
// material b, or (wall = true) against a wall of material b.
struct PairPhysics {
  double m_eff = 0;      // kg
  double r_eff = 0;      // m
  double k_linear = 0;   // N/m (linear law)
  double e_star = 0;     // Pa (Hertz law)
  double g_star = 0;     // Pa, 1/G* = (2 - nu_a)/G_a + (2 - nu_b)/G_b (Mindlin)
  double k_tangential = 0;  // N/m, linear_spring k_t
};

inline double plane_strain_modulus(const MaterialSpec& m) {
  return m.youngs_modulus / (1 - m.poisson_ratio * m.poisson_ratio);
}

// Linear stiffness of a pair (N/m): given, or from its contact time for the lightest
// particle-particle pairing of its materials (particle-wall when one material only makes walls).
inline double linear_stiffness(const Scene& s, const PairSpec& spec) {
  if (spec.stiffness > 0) return spec.stiffness;
  const double ma = extremes(s, spec.a).mass, mb = extremes(s, spec.b).mass;
  const double m_ref = ma > 0 && mb > 0 ? ma * mb / (ma + mb) : std::max(ma, mb);
  return m_ref > 0 ? 9.869604401089358 * m_ref / (spec.contact_time * spec.contact_time) : 1.0;  // 1: wall-wall, unused
}

inline PairPhysics pair_physics(const Scene& s, int a, int b, bool wall) {
  const MaterialExtremes ea = extremes(s, a), eb = extremes(s, b);
  PairPhysics p;
  p.m_eff = wall ? ea.mass : ea.mass * eb.mass / (ea.mass + eb.mass);
  p.r_eff = wall ? ea.radius : ea.radius * eb.radius / (ea.radius + eb.radius);
  const PairSpec* spec = s.pair(a, b);
  if (spec && s.law == LawKind::linear) p.k_linear = linear_stiffness(s, *spec);
  const MaterialSpec &ma = s.materials[static_cast<std::size_t>(a)], &mb = s.materials[static_cast<std::size_t>(b)];
  if (ma.youngs_modulus > 0 && mb.youngs_modulus > 0) {
    p.e_star = 1 / (1 / plane_strain_modulus(ma) + 1 / plane_strain_modulus(mb));
    const double ga = ma.youngs_modulus / (2 * (1 + ma.poisson_ratio)), gb = mb.youngs_modulus / (2 * (1 + mb.poisson_ratio));
    p.g_star = 1 / ((2 - ma.poisson_ratio) / ga + (2 - mb.poisson_ratio) / gb);
  }
  if (spec && s.law == LawKind::linear && s.tangential == TangentialKind::linear_spring)
    p.k_tangential = spec->tangential_stiffness > 0 ? spec->tangential_stiffness : 2.0 / 7.0 * p.k_linear;
  return p;
}

// The largest initial speed of any placement or feed (m/s; a feed's particles leave at up to
// |velocity| + velocity_spread), and (key) the scene key that gives it.
inline double largest_initial_speed(const Scene& s, std::string* key = nullptr) {
  double v0 = 0;
  const auto consider = [&](double v, const char* what, std::size_t k, const char* field) {
    if (v <= v0) return;
    v0 = v;
    if (key) *key = std::string(what) + "[" + std::to_string(k) + "]." + field;
  };
  for (std::size_t k = 0; k < s.lattices.size(); ++k) consider(norm(s.lattices[k].velocity), "lattice", k, "velocity");
  for (std::size_t k = 0; k < s.fills.size(); ++k) consider(norm(s.fills[k].velocity), "fill", k, "velocity");
  for (std::size_t k = 0; k < s.lists.size(); ++k)
    for (const auto& v : s.lists[k].velocity) consider(norm(v), "particles", k, "velocities");
  for (std::size_t k = 0; k < s.feeds.size(); ++k)
    consider(norm(s.feeds[k].velocity) + s.feeds[k].spread, "feed", k, s.feeds[k].spread > 0 ? "velocity_spread" : "velocity");
  return v0;
}

inline double reference_impact_speed(const Scene& s) {
  if (s.max_impact_speed > 0) return s.max_impact_speed;
  const double v0 = largest_initial_speed(s);
  const double g = norm(s.gravity);
  const Vec3<double> span = s.domain_hi - s.domain_lo;
  const double height = g > 0 ? std::fabs(dot(span, s.gravity)) / g : 0;
  return std::max(0.1, v0 + std::sqrt(2 * g * height) + s.fastest_wall());  // a moving wall meets them at its own speed more
}

struct CriticalStep {
  double dt_critical = 0;  // s, the smallest bound over pairings (and Rayleigh for Hertz)
  double contact_time = 0;  // s, the shortest contact (undamped), for steps_per_contact
  std::string governing;   // which pairing or estimate sets dt_critical
  double impact_speed = 0;  // m/s, of the Hertz and overlap estimates
  double impact_overlap = 0;  // deepest elastic impact overlap / smaller radius
  std::string overlap_governing;
  int overlap_a = -1, overlap_b = -1;  // the materials of that pairing
};

// Deepest elastic overlap (m) of a head-on impact at v between effective mass m*, radius r*.
inline double impact_overlap(const Scene& s, const PairSpec& spec, double e_star, double m_eff, double r_eff, double v) {
  if (s.law == LawKind::linear) return v * std::sqrt(m_eff / linear_stiffness(s, spec));
  const double kn = 4.0 / 3.0 * e_star * std::sqrt(r_eff);
  return std::pow(5 * m_eff * v * v / (4 * kn), 0.4);
}

inline CriticalStep critical_step(const Scene& s) {
  CriticalStep c;
  c.dt_critical = c.contact_time = INFINITY;
  c.impact_speed = reference_impact_speed(s);
  auto consider = [&](int a, int b, bool wall) {
    const PairPhysics p = pair_physics(s, a, b, wall);
    if (!(p.m_eff > 0)) return;
    double k, t_c, k_t = 0;
    if (s.law == LawKind::linear) {
      k = p.k_linear;
      t_c = 3.141592653589793 * std::sqrt(p.m_eff / k);
      k_t = p.k_tangential;
    } else {
      const double kn = 4.0 / 3.0 * p.e_star * std::sqrt(p.r_eff), v = c.impact_speed;
      const double delta = std::pow(5 * p.m_eff * v * v / (4 * kn), 0.4);
      k = 1.5 * kn * std::sqrt(delta);
      t_c = 2.9432 * delta / v;
      if (s.tangential == TangentialKind::mindlin) k_t = 8 * p.g_star * std::sqrt(p.r_eff * delta);
    }
    const double bound = 2 / std::sqrt(k / p.m_eff);
    const std::string name = "\"" + s.materials[static_cast<std::size_t>(a)].name + "\"-" + (wall ? "wall " : "") + "\"" +
                             s.materials[static_cast<std::size_t>(b)].name + "\" contact";
    if (bound < c.dt_critical) c.dt_critical = bound, c.governing = name + " (2/sqrt(k/m*))";
    bool polyhedra = false;
    for (const auto& t : s.types) polyhedra = polyhedra || !t.is_sphere();
    const double kappa = polyhedra ? 6.0 : 3.5;
    const double bound_t = k_t > 0 ? 2 / std::sqrt(kappa * k_t / p.m_eff) : INFINITY;
    if (bound_t < c.dt_critical) c.dt_critical = bound_t, c.governing = name + ", tangential spring (2/sqrt(kappa k_t/m*))";
    // The rolling spring (epsd): k_r = 2.25 k mu_r^2 R*^2 turning a rolling inertia of at least
    // I + m r^2 = 1.4 m* R*^2 (a sphere about its contact point).
    const PairSpec* spec = s.pair(a, b);
    if (s.rolling == RollingKind::epsd && spec && spec->rolling_friction > 0) {
      const double mu_r = spec->rolling_friction, bound_r = 2 / std::sqrt(2.25 / 1.4 * mu_r * mu_r * k / p.m_eff);
      if (bound_r < c.dt_critical) c.dt_critical = bound_r, c.governing = name + ", rolling spring (2/sqrt(k_r/I_r))";
    }
    c.contact_time = std::min(c.contact_time, t_c);
  };
  std::vector<bool> particle(s.materials.size()), world(s.materials.size());
  for (const auto& t : s.types) particle[static_cast<std::size_t>(t.material)] = true;
  for (const auto& w : s.walls) world[static_cast<std::size_t>(w.material)] = true;
  for (const auto& cy : s.cylinders) world[static_cast<std::size_t>(cy.material)] = true;
  for (const auto& m : s.meshes) world[static_cast<std::size_t>(m.material)] = true;
  const int n = static_cast<int>(s.materials.size());
  for (int a = 0; a < n; ++a) {
    if (!particle[static_cast<std::size_t>(a)]) continue;
    for (int b = a; b < n; ++b)
      if (particle[static_cast<std::size_t>(b)]) consider(a, b, false);
    for (int b = 0; b < n; ++b)
      if (world[static_cast<std::size_t>(b)]) consider(a, b, true);
  }
  // Impact overlap over every pairing of types, and of each type with each wall material.
  std::vector<int> walls;
  for (int b = 0; b < n; ++b)
    if (world[static_cast<std::size_t>(b)]) walls.push_back(b);
  auto mass = [&](const ParticleTypeSpec& t) { return s.materials[static_cast<std::size_t>(t.material)].density * t.volume; };
  for (std::size_t i = 0; i < s.types.size(); ++i) {
    const ParticleTypeSpec& ti = s.types[i];
    auto check = [&](const PairSpec* spec, double e_star, double m_eff, double r_eff, double r_min, const std::string& name) {
      if (!spec) return;
      const double ratio = impact_overlap(s, *spec, e_star, m_eff, r_eff, c.impact_speed) / r_min;
      if (ratio > c.impact_overlap || !(ratio == ratio))
        c.impact_overlap = ratio, c.overlap_governing = name, c.overlap_a = spec->a, c.overlap_b = spec->b;
    };
    for (std::size_t j = i; j < s.types.size(); ++j) {
      const ParticleTypeSpec& tj = s.types[j];
      const double mi = mass(ti), mj = mass(tj);
      check(s.pair(ti.material, tj.material), pair_physics(s, ti.material, tj.material, false).e_star, mi * mj / (mi + mj),
            ti.size() * tj.size() / (ti.size() + tj.size()), std::min(ti.size(), tj.size()),
            "\"" + ti.name + "\" on \"" + tj.name + "\"");
    }
    for (int w : walls)
      check(s.pair(ti.material, w), pair_physics(s, ti.material, w, true).e_star, mass(ti), ti.size(), ti.size(),
            "\"" + ti.name + "\" on a \"" + s.materials[static_cast<std::size_t>(w)].name + "\" wall");
  }
  if (s.law == LawKind::hertz)
    for (const auto& t : s.types) {
      const MaterialSpec& m = s.materials[static_cast<std::size_t>(t.material)];
      const double shear = m.youngs_modulus / (2 * (1 + m.poisson_ratio));
      const double t_r = 3.141592653589793 * t.size() * std::sqrt(m.density / shear) / (0.1631 * m.poisson_ratio + 0.8766);
      if (t_r < c.dt_critical) c.dt_critical = t_r, c.governing = "Rayleigh time of \"" + t.name + "\"";
    }
  return c;
}

}  // namespace blaze
