// Internal cylinder (a drum; thesis section 3.2.1 "macro object"): particles live inside it.
// For a sphere of centre x, radius r, with s = (x - a) . u and rho = (x - a) - s u:
//   contact if 0 <= s <= length and |rho| + r > R:  overlap |rho| + r - R, normal rho/|rho|
//   (outwards, into the wall), R* = r R / (R - r) (a sphere inside a concave surface).
// The ends are not part of the cylinder: close them with planar polygons.
#pragma once
#include <cstdint>
#include <stdexcept>
#include "blaze/contact/contact_geometry.hpp"

namespace blaze {

template <class Real>
struct Cylinder {
  Vec3<Real> origin;  // m, centre of the first end
  Vec3<Real> axis;    // unit
  Real radius;        // m
  Real length;        // m
  std::uint8_t material;

  static Cylinder make(const Vec3<double>& origin, const Vec3<double>& axis, double radius, double length,
                       std::uint8_t material) {
    const double a = norm(axis);
    if (!(a > 0)) throw std::invalid_argument("cylinder: axis must be non-zero");
    if (!(radius > 0) || !(length > 0)) throw std::invalid_argument("cylinder: radius and length must be > 0 m");
    return {vec_cast<Real>(origin), vec_cast<Real>(axis * (1.0 / a)), static_cast<Real>(radius),
            static_cast<Real>(length), material};
  }
};

template <class Real>
BLAZE_HD inline ContactGeometry<Real> collide_sphere(const Vec3<Real>& x, Real r, const Cylinder<Real>& c) {
  const Vec3<Real> rel = x - c.origin;
  const Real s = dot(rel, c.axis);
  if (!(s >= Real(0) && s <= c.length)) return ContactGeometry<Real>::none();
  const Vec3<Real> rho = rel - s * c.axis;
  const Real rho2 = norm2(rho);
  const Real inner = c.radius - r;
  if (!(inner < Real(0) || rho2 > inner * inner) || rho2 == Real(0)) return ContactGeometry<Real>::none();
  const Real dist = sqrt_r(rho2);
  const Vec3<Real> n = rho * (Real(1) / dist);
  const Real delta = dist + r - c.radius;
  return {true, n, delta, x + n * (r - Real(0.5) * delta), r * c.radius / (c.radius - r)};
}

// The cylinder's wall (its points at the radius, 0 <= s <= length) lies within `reach` of x: the
// candidate test of the world lists (kernels/world_candidates.hpp), conservative like
// planar_polygon.hpp's within_reach.
template <class Real>
BLAZE_HD inline bool within_reach(const Vec3<Real>& x, Real reach, const Cylinder<Real>& c) {
  const Vec3<Real> rel = x - c.origin;
  const Real s = dot(rel, c.axis);
  if (!(s >= -reach && s <= c.length + reach)) return false;
  const Real rho = sqrt_r(norm2(rel - s * c.axis));
  return rho + reach >= c.radius;
}

}  // namespace blaze
