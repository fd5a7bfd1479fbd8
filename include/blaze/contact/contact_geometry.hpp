// What a shape's collide() reports for a pair, in the convention every force law assumes:
//   normal  unit vector from body i towards body j (for a wall: from the particle into the wall), -
//   overlap penetration depth delta > 0 when touching, m
//   point   contact point, m (torque arm r = point - x_i)
//   r_eff   effective radius of curvature 1/(1/r_i + 1/r_j), m (walls: flat = infinite radius of j;
//           concave drum = negative curvature), used by Hertzian laws
#pragma once
#include "blaze/core/vec3.hpp"

namespace blaze {

template <class Real>
struct ContactGeometry {
  bool touching;
  Vec3<Real> normal;
  Real overlap;
  Vec3<Real> point;
  Real r_eff;

  BLAZE_HD static ContactGeometry none() { return {false, {0, 0, 0}, 0, {0, 0, 0}, 0}; }
};

}  // namespace blaze
