// Unit quaternion q = {w, x, y, z} for orientation (thesis section 2.3.2.1, eq. 2.8).
//
// Orientation update for a world-frame angular velocity w over a step dt (exact rotation):
//   dq = { cos(|w| dt / 2), sin(|w| dt / 2) w/|w| },   q_{t+1} = normalize(dq * q_t).
// The thesis's eq. 2.9 writes cos(|w|), sin(|w|): it drops dt and the half angle, so its cube turned
// 359.944 degrees in a second that should hold one radian-per-second revolution's worth; here the
// rotation angle is |w| dt exactly. Left multiplication because w is in the world frame (the thesis's
// eq. 2.10 multiplies on the right, which is the body-frame form).
#pragma once
#include "blaze/core/vec3.hpp"

namespace blaze {

template <class Real>
struct Quat {
  Real w, x, y, z;
  BLAZE_HD static Quat identity() { return {Real(1), Real(0), Real(0), Real(0)}; }
};

template <class Real>
BLAZE_HD inline Quat<Real> operator*(const Quat<Real>& a, const Quat<Real>& b) {
  return {a.w * b.w - a.x * b.x - a.y * b.y - a.z * b.z,
          a.w * b.x + a.x * b.w + a.y * b.z - a.z * b.y,
          a.w * b.y - a.x * b.z + a.y * b.w + a.z * b.x,
          a.w * b.z + a.x * b.y - a.y * b.x + a.z * b.w};
}

template <class Real>
BLAZE_HD inline Quat<Real> normalized(const Quat<Real>& q) {
  const Real s = Real(1) / sqrt_r(q.w * q.w + q.x * q.x + q.y * q.y + q.z * q.z);
  return {q.w * s, q.x * s, q.y * s, q.z * s};
}

// Rotate v by q (v' = q v q*), expanded to avoid building the matrix.
template <class Real>
BLAZE_HD inline Vec3<Real> rotate(const Quat<Real>& q, const Vec3<Real>& v) {
  const Vec3<Real> u{q.x, q.y, q.z};
  const Vec3<Real> t = Real(2) * cross(u, v);
  return v + q.w * t + cross(u, t);
}

// Exact rotation by angle |w| dt about w (world frame), then renormalized against drift.
template <class Real>
BLAZE_HD inline Quat<Real> integrate_orientation(const Quat<Real>& q, const Vec3<Real>& w, Real dt) {
  const Real wn = norm(w);
  if (wn * dt == Real(0)) return q;
  const Real half = Real(0.5) * wn * dt;
  const Real s = sin_r(half) / wn;
  const Quat<Real> dq{cos_r(half), w.x * s, w.y * s, w.z * s};
  return normalized(dq * q);
}

}  // namespace blaze
