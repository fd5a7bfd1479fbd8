// Unit quaternion q = {w, x, y, z} for orientation (thesis section 2.3.2.1, eq. 2.8).
//
// Orientation update for a world-frame angular velocity w over a step dt (exact rotation):
//   dq = { cos(|w| dt / 2), sin(|w| dt / 2) w/|w| },   q_{t+1} = dq * q_t,  then back to |q| = 1.
// The thesis's eq. 2.9 writes cos(|w|), sin(|w|): it drops dt and the half angle, so its cube turned
// 359.944 degrees in a second that should hold one radian-per-second revolution's worth; here the
// rotation angle is |w| dt exactly. Left multiplication because w is in the world frame (the thesis's
// eq. 2.10 multiplies on the right, which is the body-frame form).
//
// Rounding. The step turns q by |w| dt / 2 ~ 3e-5 (a cube at one revolution per second, dt = 1e-5
// s), a few hundred float ulps of a component, and q is stored in working precision, so each
// step's rounding errors stay in q for good; along the rotation they add up over the 1e5 steps of
// a second. Two choices keep that sum at about one rounding per component per step:
// - dq * q is formed as q + eps * q with eps = dq - 1 = {-2 sin^2(|w| dt / 4), sin(|w| dt / 2) w/|w|}:
//   the 16 products are O(|w| dt) and carry their full precision into a single rounding per
//   component (in float, cos(3e-5) is 1.0f: forming dq outright drops its second-order part and
//   rounds products of O(1) numbers);
// - renormalized() moves q back to the unit sphere by a correction proportional to its norm error,
//   so a q whose norm is 1 to working precision is left exactly as it is (normalized() multiplies
//   every component by a rounded 1/|q|, a fresh rounding of each component every step).
// Measured in float for 1e5 steps of a 2 pi rad/s spin (dt 0.9e-5 to 1.1e-5 s, 400 random axes):
// relative angle error median 2.3e-7, worst 1.1e-6 (classic dq * q with normalized(): median
// 4.3e-6, worst 2.2e-4; the thesis's x-axis cube 6.8e-7, now 2.4e-7); axis tilt worst 2e-5 rad (was
// 1e-4). Carrying the rounding error in a second float quaternion (compensated summation) gets the
// worst to 1.6e-7 and the tilt to 1e-8 rad, at 16 more bytes per particle; not done, as the single
// rounding already meets the verification bound (1e-6 relative after one revolution in float).
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

// q / |q| for any q != 0, as q + f q with f = 1/|q| - 1 = (1 - |q|^2) / (|q| (1 + |q|)): 1 - |q|^2 is
// exact near 1 (Sterbenz), and f = 0 leaves q untouched (see the header). With e = 1 - |q|^2,
// f = e/2 + 3e^2/8 + 5e^3/16 + ...: for |e| <= 1e-6 (every step after the first: one step's
// rounding is ~1e-16 in double, ~1e-7 in float) the first two terms are f to below 4e-19, with
// no square root or division.
template <class Real>
BLAZE_HD inline Quat<Real> renormalized(const Quat<Real>& q) {
  const Real n2 = q.w * q.w + q.x * q.x + q.y * q.y + q.z * q.z;
  const Real e = Real(1) - n2;
  Real f;
  if (e <= Real(1e-6) && e >= Real(-1e-6)) {
    f = Real(0.5) * e * (Real(1) + Real(0.75) * e);
  } else {
    const Real n = sqrt_r(n2);
    f = e / (n * (Real(1) + n));
  }
  return {q.w + q.w * f, q.x + q.x * f, q.y + q.y * f, q.z + q.z * f};
}

// Exact rotation by angle |w| dt about w (world frame): q + eps * q, then renormalized (header).
// With h = |w| dt / 2: eps = {cos h - 1, (sin h / h) (dt / 2) w}. For h <= 0.05 (every DEM step:
// |w| dt ~ 1e-4) both come from their Taylor series to h^8, whose truncation (below 3e-20 of
// the result) is under double rounding: a few multiplications instead of a square root and two
// sines, which were 10% of a CPU sphere step (bench/compare/README.md). Larger angles take the
// sines, with cos h - 1 = -2 sin^2(h / 2) so that no digits cancel.
template <class Real>
BLAZE_HD inline Quat<Real> integrate_orientation(const Quat<Real>& q, const Vec3<Real>& w, Real dt) {
  const Real half_dt = Real(0.5) * dt;
  const Real h2 = norm2(w) * (half_dt * half_dt);
  if (h2 == Real(0)) return q;
  Real sinc, cos_m1;  // sin h / h, cos h - 1
  if (h2 <= Real(0.0025)) {
    sinc = Real(1) - h2 * Real(1.0 / 6) * (Real(1) - h2 * Real(1.0 / 20) * (Real(1) - h2 * Real(1.0 / 42) * (Real(1) - h2 * Real(1.0 / 72))));
    cos_m1 = -h2 * Real(0.5) * (Real(1) - h2 * Real(1.0 / 12) * (Real(1) - h2 * Real(1.0 / 30) * (Real(1) - h2 * Real(1.0 / 56))));
  } else {
    const Real h = sqrt_r(h2), quarter = sin_r(Real(0.5) * h);
    sinc = sin_r(h) / h;
    cos_m1 = Real(-2) * quarter * quarter;
  }
  const Real s = sinc * half_dt;
  const Quat<Real> eps{cos_m1, w.x * s, w.y * s, w.z * s};
  const Quat<Real> d = eps * q;
  return renormalized(Quat<Real>{q.w + d.w, q.x + d.x, q.y + d.y, q.z + d.z});
}

}  // namespace blaze
