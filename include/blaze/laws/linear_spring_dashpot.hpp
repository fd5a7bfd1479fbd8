// Linear spring-dashpot normal force (thesis eq. 2.2, section 2.3.1; Cundall & Strack 1979).
//
//   F_n = K_n delta + C_n v_n,        force on body i: -F_n n
//   C_n = beta sqrt(K_n m_eff),       beta = -2 ln(e) / sqrt(ln(e)^2 + pi^2)
//
// delta: overlap (m); v_n: normal approach speed (m/s, > 0 closing); K_n: stiffness (N/m);
// m_eff = (1/m_i + 1/m_j)^-1 (kg; m_j = infinity for walls); e: coefficient of restitution in
// (0, 1]. For this law, e is exactly the ratio of separation to approach speed of an isolated
// contact (the damped oscillator's half period), whatever the impact speed.
// Contact duration: t_c = pi / sqrt(K_n/m_eff - (C_n / 2 m_eff)^2).
// The thesis writes C_n with a positive ln(e) factor, i.e. negative; beta here is >= 0.
// no_tension clamps F_n at 0 (the dashpot pulls near separation; a clamped contact does not, and
// then e is no longer the formula's: the contact ends early, at F_n = 0).
// At first touch the dashpot makes the force jump from 0 to C_n v_n (Cundall & Strack's model).
//
// Stored elastic energy (J), the spring's potential, the integral of K_n delta d(delta):
//   U = 1/2 K_n delta^2
// With no_tension it is still the spring's: the clamp cuts the force only where the dashpot's
// pull exceeds the spring's push (F_n = 0 while K_n delta > 0, the contact opening), so the
// clamped force is K_n delta plus a non-conservative part -K_n delta that acts against the
// opening speed: it only dissipates (its power -K_n delta v_n > 0 out of the system at v_n < 0),
// and the elastic potential is unchanged. The energy balance then charges the clamp to
// dissipated_J, as it does the dashpot.
#pragma once
#include <cmath>
#include <stdexcept>
#include "blaze/core/math.hpp"

namespace blaze {

template <class Real>
struct LinearSpringDashpot {
  Real kn;    // N/m
  Real beta;  // dimensionless damping factor, 2x the damping ratio
  bool no_tension = false;

  static LinearSpringDashpot from_restitution(double kn, double e) {
    if (!(kn > 0)) throw std::invalid_argument("linear spring-dashpot: stiffness kn must be > 0 N/m");
    if (!(e > 0 && e <= 1)) throw std::invalid_argument("linear spring-dashpot: restitution must lie in (0, 1]");
    const double pi = 3.14159265358979323846;
    const double le = std::log(e);
    return {static_cast<Real>(kn), static_cast<Real>(-2 * le / std::sqrt(le * le + pi * pi))};
  }

  // Scalar normal force (N, positive = repulsive) for overlap delta and approach speed v_n.
  BLAZE_HD Real normal_force(Real delta, Real v_n, Real m_eff, Real /*r_eff*/) const {
    const Real f = kn * delta + beta * sqrt_r(kn * m_eff) * v_n;
    return no_tension ? max_r(f, Real(0)) : f;
  }
  LinearSpringDashpot without_tension() const {
    LinearSpringDashpot l = *this;
    l.no_tension = true;
    return l;
  }
  // Elastic part K_n delta (N), for diagnostics.
  BLAZE_HD Real elastic_force(Real delta, Real /*r_eff*/) const { return kn * delta; }
  // Stored elastic energy 1/2 K_n delta^2 (J), in double whatever Real (energy bookkeeping sums
  // it over every contact); 0 at delta <= 0.
  BLAZE_HD double stored_energy(Real delta, Real /*r_eff*/) const {
    const double d = delta > Real(0) ? static_cast<double>(delta) : 0.0;
    return 0.5 * static_cast<double>(kn) * d * d;
  }
  // The spring's stiffness (N/m): a rolling spring's k_n.
  BLAZE_HD Real tangent_stiffness(Real, Real) const { return kn; }
  // Normal stiffness at this overlap (N/m), for the critical time step.
  Real stiffness(Real /*delta*/, Real /*r_eff*/) const { return kn; }
};

}  // namespace blaze
