// Relative velocity of body i with respect to body j at the contact point (thesis section 2.3.1):
//   v_rel = (v_i + w_i x r_i) - (v_j + w_j x r_j),   r = contact point - centre of mass,  m/s
// The normal approach speed is v_n = v_rel . n (positive when closing, n from i to j) and the
// tangential slip v_t = v_rel - v_n n.
//
// The thesis replaces w_i, w_j by their mean w_R = (w_i + w_j)/2 to save a memory read, and its
// eq. 2.3 writes r_1 x w_R - r_2 x w_R, the opposite sign of w x r. That shortcut is kept only as
// the explicitly named policy ThesisMeanOmegaVelocity (with the sign of w x r); ContactPointVelocity,
// which uses both angular velocities, is what every law uses unless a study asks otherwise.
#pragma once
#include "blaze/core/vec3.hpp"

namespace blaze {

struct ContactPointVelocity {
  template <class Real>
  BLAZE_HD static Vec3<Real> relative(const Vec3<Real>& v_i, const Vec3<Real>& w_i, const Vec3<Real>& r_i,
                                      const Vec3<Real>& v_j, const Vec3<Real>& w_j, const Vec3<Real>& r_j) {
    return (v_i + cross(w_i, r_i)) - (v_j + cross(w_j, r_j));
  }
};

struct ThesisMeanOmegaVelocity {
  template <class Real>
  BLAZE_HD static Vec3<Real> relative(const Vec3<Real>& v_i, const Vec3<Real>& w_i, const Vec3<Real>& r_i,
                                      const Vec3<Real>& v_j, const Vec3<Real>& w_j, const Vec3<Real>& r_j) {
    const Vec3<Real> w_mean = Real(0.5) * (w_i + w_j);
    return (v_i + cross(w_mean, r_i)) - (v_j + cross(w_mean, r_j));
  }
};

}  // namespace blaze
