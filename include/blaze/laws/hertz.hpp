// Hertzian spring with delta^(1/2) dashpot (thesis eqs. 3.6-3.7, section 3.3.1; damping after
// Bell et al. and Tsuji et al. 1992).
//
//   F_n = K_n delta^(3/2) + K_D delta^(1/2) v_n,     force on body i: -F_n n
//   K_n = (4/3) E* sqrt(R*)
//
// delta: overlap (m); v_n: approach speed (m/s); E*: effective modulus (Pa), for one material
// E / (2 (1 - nu^2)); R* = r_eff (m); K_D: damping coefficient (kg s^-1 m^-1/2).
// The thesis tunes K_n by hand for one particle size; from_stiffness() reproduces that K_n exactly
// for contacts of effective radius r_ref and scales it with sqrt(R*) for the others, as Hertz does.
// Contact duration of an elastic head-on impact at speed v:
//   delta_max = (5 m_eff v^2 / (4 K_n))^(2/5),  t_c = (4/5) B(2/5, 1/2) delta_max / v = 2.9432 delta_max / v.
#pragma once
#include <cmath>
#include <stdexcept>
#include "blaze/core/math.hpp"

namespace blaze {

template <class Real>
struct Hertz {
  Real k_hat;  // (4/3) E*, Pa
  Real kd;     // kg s^-1 m^-1/2

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

  BLAZE_HD Real normal_force(Real delta, Real v_n, Real /*m_eff*/, Real r_eff) const {
    const Real sd = sqrt_r(delta);
    return k_hat * sqrt_r(r_eff) * delta * sd + kd * sd * v_n;
  }
  // dF/d(delta) (N/m), for the critical time step.
  Real stiffness(Real delta, Real r_eff) const { return Real(1.5) * k_hat * std::sqrt(r_eff * delta); }
};

}  // namespace blaze
