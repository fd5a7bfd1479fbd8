// Hertzian spring with two dashpot forms (thesis eqs. 3.6-3.7, section 3.3.1).
//
//   F_n = K_n delta^(3/2) + [K_D delta^(1/2) + eta sqrt(m_eff K_n) delta^(1/4)] v_n,   force on i: -F_n n
//   K_n = (4/3) E* sqrt(R*)
//
// delta: overlap (m); v_n: approach speed (m/s, > 0 closing); E*: effective modulus (Pa), for one
// material E / (2 (1 - nu^2)), for two 1/E* = (1 - nu1^2)/E1 + (1 - nu2^2)/E2; R* = r_eff (m);
// m_eff: effective mass (kg).
// - K_D (kg s^-1 m^-1/2): the thesis's delta^(1/2) damping (after Bell et al. 2005). Its
//   restitution falls with impact speed (e depends on K_D m^-2/5 K_n^-3/5 v^1/5).
// - eta (-): delta^(1/4) damping (Tsuji et al. 1992): restitution independent of speed, mass and
//   stiffness; from_restitution() picks eta so that e is exact (hertz_restitution.hpp).
// Use one or the other (both may be set; they add).
// no_tension clamps F_n at 0: near separation either dashpot outpulls the vanishing spring and
// the contact would attract (thesis Fig 3.12 shows it); the clamp removes that.
// The thesis tunes K_n by hand for one particle size; from_stiffness() reproduces that K_n exactly
// for contacts of effective radius r_ref and scales it with sqrt(R*) for the others, as Hertz does.
// Elastic head-on impact at speed v:
//   delta_max = (5 m_eff v^2 / (4 K_n))^(2/5),  t_c = (4/5) B(2/5, 1/2) delta_max / v = 2.9432 delta_max / v,
//   F_max = K_n delta_max^(3/2).
// Stored elastic energy (J), the integral of K_n delta^(3/2) d(delta) (Johnson, Contact
// Mechanics, 1985, section 4.2: the Hertzian potential):
//   U = (2/5) K_n delta^(5/2) = (2/5) k_hat sqrt(R*) delta^(5/2)      (k_hat = (4/3) E*, Pa)
// With no_tension it is still the spring's: the clamp only removes the part of the dashpots'
// pull that exceeds the spring near separation, a force against the opening speed that only
// dissipates (linear_spring_dashpot.hpp gives the argument); dissipated_J carries it.
#pragma once
#include <cmath>
#include <stdexcept>
#include "blaze/core/math.hpp"
#include "blaze/laws/hertz_restitution.hpp"

namespace blaze {

template <class Real>
struct Hertz {
  Real k_hat;               // (4/3) E*, Pa
  Real kd;                  // kg s^-1 m^-1/2, delta^(1/2) damping
  Real eta = 0;             // -, delta^(1/4) damping
  bool no_tension = false;  // clamp F_n >= 0

  static Hertz from_modulus(double e_star, double kd) {
    if (!(e_star > 0)) throw std::invalid_argument("hertz: effective modulus E* must be > 0 Pa");
    if (!(kd >= 0)) throw std::invalid_argument("hertz: damping K_D must be >= 0");
    return {static_cast<Real>(4.0 / 3.0 * e_star), static_cast<Real>(kd)};
  }
  // K_n in N/m^(3/2) as the thesis gives it, valid for contacts of effective radius r_ref (m).
  static Hertz from_stiffness(double kn, double r_ref, double kd) {
    if (!(kn > 0) || !(r_ref > 0)) throw std::invalid_argument("hertz: K_n and r_ref must be > 0");
    return from_modulus(0.75 * kn / std::sqrt(r_ref), kd);
  }
  // Exact coefficient of restitution e in (0, 1] for every contact (delta^(1/4) damping).
  static Hertz from_restitution(double e_star, double e, bool clamp_tension = false) {
    Hertz h = from_modulus(e_star, 0);
    h.eta = static_cast<Real>(hertz_damping_for_restitution(e, clamp_tension));
    h.no_tension = clamp_tension;
    return h;
  }
  Hertz without_tension() const {
    Hertz h = *this;
    h.no_tension = true;
    return h;
  }

  // Elastic part K_n delta^(3/2) (N), for diagnostics.
  BLAZE_HD Real elastic_force(Real delta, Real r_eff) const { return k_hat * contact_radius(delta, r_eff) * delta; }

  // With a = sqrt(R* delta) (contact_radius): K_n delta^(3/2) = k_hat a delta and
  // sqrt(m_eff K_n) delta^(1/4) = sqrt(m_eff k_hat a), so a contact takes one square root for the
  // spring (shared with a Mindlin spring's k_t) and one per dashpot in use.
  BLAZE_HD Real normal_force(Real delta, Real v_n, Real m_eff, Real r_eff) const {
    const Real a = contact_radius(delta, r_eff);
    Real damping = kd != Real(0) ? kd * sqrt_r(delta) : Real(0);
    if (eta != Real(0)) damping += eta * sqrt_r(m_eff * k_hat * a);
    const Real f = k_hat * a * delta + damping * v_n;
    return no_tension ? max_r(f, Real(0)) : f;
  }
  // Stored elastic energy (2/5) k_hat sqrt(R*) delta^(5/2) (J), in double whatever Real; 0 at
  // delta <= 0.
  BLAZE_HD double stored_energy(Real delta, Real r_eff) const {
    if (!(delta > Real(0))) return 0;
    const double d = static_cast<double>(delta);
    return 0.4 * static_cast<double>(k_hat) * sqrt_r(static_cast<double>(r_eff)) * d * d * sqrt_r(d);
  }
  // dF/d(delta) of the spring, 1.5 K_n sqrt(delta) (N/m): a rolling spring's k_n.
  BLAZE_HD Real tangent_stiffness(Real delta, Real r_eff) const { return Real(1.5) * k_hat * contact_radius(delta, r_eff); }
  // dF/d(delta) (N/m), for the critical time step.
  Real stiffness(Real delta, Real r_eff) const { return Real(1.5) * k_hat * std::sqrt(r_eff * delta); }
};

}  // namespace blaze
