// 3x3 matrix for kernels: rotation matrices from quaternions (one build, many products).
#pragma once
#include "blaze/core/quat.hpp"

namespace blaze {

template <class Real>
struct Mat3 {
  Real m[3][3];

  // Rotation matrix of a unit quaternion.
  BLAZE_HD static Mat3 rotation(const Quat<Real>& q) {
    const Real w = q.w, x = q.x, y = q.y, z = q.z;
    return {{{1 - 2 * (y * y + z * z), 2 * (x * y - w * z), 2 * (x * z + w * y)},
             {2 * (x * y + w * z), 1 - 2 * (x * x + z * z), 2 * (y * z - w * x)},
             {2 * (x * z - w * y), 2 * (y * z + w * x), 1 - 2 * (x * x + y * y)}}};
  }
  BLAZE_HD Vec3<Real> operator*(const Vec3<Real>& v) const {
    return {m[0][0] * v.x + m[0][1] * v.y + m[0][2] * v.z, m[1][0] * v.x + m[1][1] * v.y + m[1][2] * v.z,
            m[2][0] * v.x + m[2][1] * v.y + m[2][2] * v.z};
  }
  // M^T v
  BLAZE_HD Vec3<Real> transpose_times(const Vec3<Real>& v) const {
    return {m[0][0] * v.x + m[1][0] * v.y + m[2][0] * v.z, m[0][1] * v.x + m[1][1] * v.y + m[2][1] * v.z,
            m[0][2] * v.x + m[1][2] * v.y + m[2][2] * v.z};
  }
  // M^T N
  BLAZE_HD Mat3 transpose_times(const Mat3& n) const {
    Mat3 r{};
    for (int i = 0; i < 3; ++i)
      for (int j = 0; j < 3; ++j) r.m[i][j] = m[0][i] * n.m[0][j] + m[1][i] * n.m[1][j] + m[2][i] * n.m[2][j];
    return r;
  }
};

}  // namespace blaze
