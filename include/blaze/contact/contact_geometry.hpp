// What a shape's collide() reports for a pair, in the convention every force law assumes:
//   normal  unit vector from body i towards body j (for a wall: from the particle into the wall), -
//   overlap penetration depth delta > 0 when touching, m
//   point   contact point, m (torque arm r = point - x_i)
//   r_eff   effective radius of curvature 1/(1/r_i + 1/r_j), m (walls: flat = infinite radius of j;
//           concave drum = negative curvature), used by Hertzian laws
//   kind    vertex-face (also sphere and wall contacts) or edge-edge, for collision statistics
//           (thesis Fig 3.27)
#pragma once
#include <cstdint>
#include "blaze/core/vec3.hpp"

namespace blaze {

enum class ContactKind : std::uint8_t { vertex_face = 0, edge_edge = 1 };

template <class Real>
struct ContactGeometry {
  bool touching;
  Vec3<Real> normal;
  Real overlap;
  Vec3<Real> point;
  Real r_eff;
  ContactKind kind = ContactKind::vertex_face;

  BLAZE_HD static ContactGeometry none() { return {false, {0, 0, 0}, 0, {0, 0, 0}, 0, ContactKind::vertex_face}; }
};

}  // namespace blaze
