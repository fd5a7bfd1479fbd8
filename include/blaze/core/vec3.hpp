// A plain 3-vector for kernels (Eigen stays on the host: shape set-up and references).
#pragma once
#include "blaze/core/math.hpp"

namespace blaze {

template <class Real>
struct Vec3 {
  Real x, y, z;

  BLAZE_HD Vec3& operator+=(const Vec3& o) { x += o.x; y += o.y; z += o.z; return *this; }
  BLAZE_HD Vec3& operator-=(const Vec3& o) { x -= o.x; y -= o.y; z -= o.z; return *this; }
  BLAZE_HD Vec3& operator*=(Real s) { x *= s; y *= s; z *= s; return *this; }
};

template <class Real> BLAZE_HD inline Vec3<Real> operator+(Vec3<Real> a, const Vec3<Real>& b) { return a += b; }
template <class Real> BLAZE_HD inline Vec3<Real> operator-(Vec3<Real> a, const Vec3<Real>& b) { return a -= b; }
template <class Real> BLAZE_HD inline Vec3<Real> operator-(const Vec3<Real>& a) { return {-a.x, -a.y, -a.z}; }
template <class Real> BLAZE_HD inline Vec3<Real> operator*(Vec3<Real> a, Real s) { return a *= s; }
template <class Real> BLAZE_HD inline Vec3<Real> operator*(Real s, Vec3<Real> a) { return a *= s; }

template <class Real> BLAZE_HD inline Real dot(const Vec3<Real>& a, const Vec3<Real>& b) {
  return a.x * b.x + a.y * b.y + a.z * b.z;
}
template <class Real> BLAZE_HD inline Vec3<Real> cross(const Vec3<Real>& a, const Vec3<Real>& b) {
  return {a.y * b.z - a.z * b.y, a.z * b.x - a.x * b.z, a.x * b.y - a.y * b.x};
}
template <class Real> BLAZE_HD inline Real norm2(const Vec3<Real>& a) { return dot(a, a); }
template <class Real> BLAZE_HD inline Real norm(const Vec3<Real>& a) { return sqrt_r(dot(a, a)); }

template <class To, class From>
BLAZE_HD inline Vec3<To> vec_cast(const Vec3<From>& v) {
  return {static_cast<To>(v.x), static_cast<To>(v.y), static_cast<To>(v.z)};
}

}  // namespace blaze
