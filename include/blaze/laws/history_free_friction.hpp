// History-free tangential force (thesis eq. 2.3, section 2.3.1; Bell et al. 2005).
//
//   F_t = -min(mu F_n, K_T |v_t|) v_t / |v_t|
//
// v_t: tangential slip velocity at the contact point (m/s); F_n: normal force (N), taken as 0 when
// the dashpot makes it tensile (a pulling contact transmits no friction); mu: Coulomb friction
// coefficient (-); K_T: viscous tangential coefficient (kg/s). K_T governs low-slip and oblique
// impacts, mu sliding. No spring: nothing is remembered between steps.
// K_T may also grow with the contact's effective mass m* and the step dt, as in the thesis's GPU
// friction for mills (eq. 4.3, section 4.1.4: F_T = -min[mu |F_N|, min(min(|V_1T|, |V_2T|),
// mu |V_T|) m*/dt]):
//   K_T = kt + rate m* / dt    (rate = mu reproduces eq. 4.3's mu |V_T| m*/dt branch)
// We leave out eq. 4.3's min(|V_1T|, |V_2T|): the particles' own tangential velocities depend on
// the frame of reference (a moving wall's contact would change with the lab frame), so it cannot
// be physics. With rate > 0 the viscous branch removes the share `rate` of the slip per step.
#pragma once
#include <stdexcept>
#include "blaze/laws/tangential_spring.hpp"

namespace blaze {

template <class Real>
struct HistoryFreeFriction {
  static constexpr int kStateReals = 0;
  Real mu;        // -
  Real kt;        // kg/s
  Real rate = 0;  // -, K_T grows by rate m*/dt (eq. 4.3: rate = mu)

  static HistoryFreeFriction make(double mu, double kt, double rate = 0) {
    if (!(mu >= 0)) throw std::invalid_argument("friction: mu must be >= 0");
    if (!(kt >= 0)) throw std::invalid_argument("friction: K_T must be >= 0 kg/s");
    if (!(rate >= 0 && rate < 1)) throw std::invalid_argument("friction: the rate of eq. 4.3 must lie in [0, 1)");
    return {static_cast<Real>(mu), static_cast<Real>(kt), static_cast<Real>(rate)};
  }

  // The viscous branch, K_T |v_t| <= mu F_n (compared as squares), is -K_T v_t: no square root
  // and no division. It is the common one in a dense bed (most contacts barely slip), and the
  // two were 25-30% of the CPU contact kernel's samples (bench/compare/README.md). Only a
  // sliding contact takes |v_t|. At v_t = 0 the viscous branch gives zero.
  BLAZE_HD Vec3<Real> tangential_force(const Vec3<Real>& v_t, Real f_n) const { return tangential_force(v_t, f_n, kt); }
  BLAZE_HD Vec3<Real> tangential_force(const Vec3<Real>& v_t, Real f_n, Real k) const {
    const Real cap = mu * max_r(f_n, Real(0));
    const Real speed2 = norm2(v_t);
    if (k * k * speed2 <= cap * cap) return v_t * (-k);
    return v_t * (-cap / sqrt_r(speed2));
  }
  // The tangential-law interface (tangential_spring.hpp); no state. At dt = 0 (the forces before
  // the first step) a rate's K_T is unbounded: the contact is at the Coulomb limit if it slips.
  template <class State>
  BLAZE_HD TangentialForce<Real> force(const TangentialInput<Real>& in, State&, int) const {
    if (rate == Real(0)) return {tangential_force(in.v_t, in.f_n, kt), false};
    if (!(in.dt > Real(0))) {
      const Real speed2 = norm2(in.v_t);
      const Real cap = mu * max_r(in.f_n, Real(0));
      return {speed2 > Real(0) ? in.v_t * (-cap / sqrt_r(speed2)) : Vec3<Real>{0, 0, 0}, false};
    }
    return {tangential_force(in.v_t, in.f_n, kt + rate * in.m_eff / in.dt), false};
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
