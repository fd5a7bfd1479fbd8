// Rolling resistance of sphere contacts (Ai, Chen, Rotter & Ooi, Powder Technol. 206 (2011) 269;
// the models of LIGGGHTS `rolling_friction cdt` and `epsd2`). w_r: the relative rolling velocity,
// w_i - w_j without its spin about the normal, rad/s; the moment acts on i (j gets its negative).
//
//   model A, constant directional torque ("cdt"):
//     M = -M_m w_r / |w_r|,  M_m = mu_r R* F_n                                        N m
//     capped at what stops w_r within the step, I_r |w_r| / dt, so that it does not reverse the
//     rotation it resists (the constant torque would otherwise chatter about w_r = 0 at rest).
//   model C, elastic-plastic spring-dashpot ("epsd"):
//     M_k <- M_k turned into the current tangent plane (its size kept);  M_k <- M_k - k_r w_r dt
//     |M_k| > M_m:  M_k <- M_m M_k / |M_k|  (full mobilisation: rolls at the constant moment)
//     M = M_k - C_r w_r, the dashpot only below full mobilisation (Ai et al.'s f = 0 there)
//     k_r = 2.25 k_n mu_r^2 R*^2 (N m/rad; k_n the normal stiffness, Hertz: dF_n/d delta)
//     C_r = eta_r 2 sqrt(I_r k_r) (N m s/rad; eta_r the damping ratio, 0.3 in Ai et al.)
//   I_r = 1 / (1/(I_i + m_i r_i^2) + 1/(I_j + m_j r_j^2)) (kg m^2), r the arm to the contact point;
//   a wall: 1/(I_j + m_j r_j^2) = 0.
// mu_r: the rolling friction coefficient (-); R*: effective radius (m); F_n: normal force (N, 0
// when it pulls). A sphere rolling on a plane under model A decelerates at (5/7) mu_r g and stops
// after v0^2 / (2 a); under model C it rests on a slope with tan(theta) <= mu_r.
// The state is the spring moment M_k (3 reals, N m, model C only); odd in (M_k, w_r, n) together,
// so the two sides of a pair stay mirrored, as the tangential spring does.
#pragma once
#include <stdexcept>
#include "blaze/core/vec3.hpp"
#include "blaze/laws/contact_state.hpp"

namespace blaze {

enum class RollingModel : int { none = 0, cdt = 1, epsd = 2 };

// What a rolling law is given.
template <class Real>
struct RollingInput {
  Vec3<Real> normal;  // -
  Real r_eff;         // m
  Vec3<Real> w_rel;   // rad/s, w_i - w_j
  Real f_n;           // N
  Real k_n;           // N/m, normal stiffness at this overlap
  Real inv_inertia;   // 1/(kg m^2), 1 / I_r
  Real dt;            // s
};

template <class Real>
struct RollingResistance {
  static constexpr int kStateReals = 3;  // M_k, N m (model C)
  RollingModel model = RollingModel::none;
  Real mu_r = 0;   // -
  Real eta_r = 0;  // -, model C damping ratio

  static RollingResistance make(RollingModel model, double mu_r, double eta_r) {
    if (!(mu_r >= 0)) throw std::invalid_argument("rolling resistance: rolling_friction must be >= 0");
    if (!(eta_r >= 0)) throw std::invalid_argument("rolling resistance: rolling_damping must be >= 0");
    return {model, static_cast<Real>(mu_r), static_cast<Real>(eta_r)};
  }
  // Reals of state in use: the spring only under model C.
  int state_reals() const { return model == RollingModel::epsd ? kStateReals : 0; }

  template <class State>
  BLAZE_HD Vec3<Real> moment(const RollingInput<Real>& in, State& state, int at) const {
    if (model == RollingModel::none) return {0, 0, 0};
    const Vec3<Real> w_r = in.w_rel - dot(in.w_rel, in.normal) * in.normal;
    const Real m_max = mu_r * in.r_eff * max_r(in.f_n, Real(0));
    if (model == RollingModel::cdt) {
      const Real speed2 = norm2(w_r);
      if (!(speed2 > Real(0))) return {0, 0, 0};
      const Real speed = sqrt_r(speed2);
      const Real m = min_r(m_max, speed / (in.inv_inertia * in.dt));
      return w_r * (-m / speed);
    }
    Vec3<Real> mk = state.vec(at);
    const Real length2 = norm2(mk);
    if (length2 > Real(0)) {
      mk -= dot(mk, in.normal) * in.normal;
      const Real turned2 = norm2(mk);
      if (turned2 > Real(0)) mk *= sqrt_r(length2 / turned2);
    }
    const Real k_r = Real(2.25) * in.k_n * mu_r * mu_r * in.r_eff * in.r_eff;
    mk -= w_r * (k_r * in.dt);
    const Real mk2 = norm2(mk);
    Vec3<Real> m = mk;
    if (mk2 > m_max * m_max) {
      mk *= m_max > Real(0) ? m_max / sqrt_r(mk2) : Real(0);
      m = mk;
    } else {
      m -= w_r * (eta_r * Real(2) * sqrt_r(k_r / in.inv_inertia));
    }
    state.set(at, mk);
    return m;
  }
};

}  // namespace blaze
