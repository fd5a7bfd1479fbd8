// History-free tangential force (thesis eq. 2.3, section 2.3.1; Bell et al. 2005).
//
//   F_t = -min(mu F_n, K_T |v_t|) v_t / |v_t|
//
// v_t: tangential slip velocity at the contact point (m/s); F_n: normal force (N), taken as 0 when
// the dashpot makes it tensile (a pulling contact transmits no friction); mu: Coulomb friction
// coefficient (-); K_T: viscous tangential coefficient (kg/s). K_T governs low-slip and oblique
// impacts, mu sliding. No spring: nothing is remembered between steps.
#pragma once
#include <stdexcept>
#include "blaze/core/vec3.hpp"

namespace blaze {

template <class Real>
struct HistoryFreeFriction {
  Real mu;  // -
  Real kt;  // kg/s

  static HistoryFreeFriction make(double mu, double kt) {
    if (!(mu >= 0)) throw std::invalid_argument("friction: mu must be >= 0");
    if (!(kt >= 0)) throw std::invalid_argument("friction: K_T must be >= 0 kg/s");
    return {static_cast<Real>(mu), static_cast<Real>(kt)};
  }

  BLAZE_HD Vec3<Real> tangential_force(const Vec3<Real>& v_t, Real f_n) const {
    const Real speed = norm(v_t);
    if (speed == Real(0)) return {0, 0, 0};
    const Real magnitude = min_r(mu * max_r(f_n, Real(0)), kt * speed);
    return v_t * (-magnitude / speed);
  }
};

// Frictionless contacts: the tangential force is zero and compiles to nothing.
template <class Real>
struct NoFriction {
  BLAZE_HD Vec3<Real> tangential_force(const Vec3<Real>&, Real) const { return {0, 0, 0}; }
};

}  // namespace blaze
