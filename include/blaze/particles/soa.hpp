// Structure-of-arrays accessors: a vector or quaternion field is stored as one array per component,
// so neighbouring threads read neighbouring addresses (thesis section 2.2.2: AoS was 3x slower).
#pragma once
#include "blaze/core/quat.hpp"

namespace blaze {

template <class Real>
struct Vec3Field {
  Real* x;
  Real* y;
  Real* z;
  BLAZE_HD Vec3<Real> get(Index i) const { return {x[i], y[i], z[i]}; }
  BLAZE_HD void set(Index i, const Vec3<Real>& v) const { x[i] = v.x; y[i] = v.y; z[i] = v.z; }
};

template <class Real>
struct QuatField {
  Real* w;
  Real* x;
  Real* y;
  Real* z;
  BLAZE_HD Quat<Real> get(Index i) const { return {w[i], x[i], y[i], z[i]}; }
  BLAZE_HD void set(Index i, const Quat<Real>& q) const { w[i] = q.w; x[i] = q.x; y[i] = q.y; z[i] = q.z; }
};

}  // namespace blaze
