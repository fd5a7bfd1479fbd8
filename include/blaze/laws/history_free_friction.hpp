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
#include "blaze/laws/tangential_spring.hpp"

namespace blaze {

template <class Real>
struct HistoryFreeFriction {
  static constexpr int kStateReals = 0;
  Real mu;  // -
  Real kt;  // kg/s

  static HistoryFreeFriction make(double mu, double kt) {
    if (!(mu >= 0)) throw std::invalid_argument("friction: mu must be >= 0");
    if (!(kt >= 0)) throw std::invalid_argument("friction: K_T must be >= 0 kg/s");
    return {static_cast<Real>(mu), static_cast<Real>(kt)};
  }

  // The viscous branch, K_T |v_t| <= mu F_n (compared as squares), is -K_T v_t: no square root
  // and no division. It is the common one in a dense bed (most contacts barely slip), and the
  // two were 25-30% of the CPU contact kernel's samples (bench/compare/README.md). Only a
  // sliding contact takes |v_t|. At v_t = 0 the viscous branch gives zero.
  BLAZE_HD Vec3<Real> tangential_force(const Vec3<Real>& v_t, Real f_n) const {
    const Real cap = mu * max_r(f_n, Real(0));
    const Real speed2 = norm2(v_t);
    if (kt * kt * speed2 <= cap * cap) return v_t * (-kt);
    return v_t * (-cap / sqrt_r(speed2));
  }
  // The tangential-law interface (tangential_spring.hpp); no state.
  template <class State>
  BLAZE_HD TangentialForce<Real> force(const TangentialInput<Real>& in, State&, int) const {
    return {tangential_force(in.v_t, in.f_n), false};
  }
};

// Frictionless contacts: the tangential force is zero and compiles to nothing.
template <class Real>
struct NoFriction {
  static constexpr int kStateReals = 0;
  BLAZE_HD Vec3<Real> tangential_force(const Vec3<Real>&, Real) const { return {0, 0, 0}; }
  template <class State>
  BLAZE_HD TangentialForce<Real> force(const TangentialInput<Real>&, State&, int) const {
    return {{0, 0, 0}, false};
  }
};

}  // namespace blaze
