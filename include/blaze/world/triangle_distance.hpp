// The squared distance from a point p to a triangle (a, b, c) (m^2), and the test that decides
// which triangles of a mesh a particle may touch (its triangle list, kernels/world_candidates.hpp;
// a polyhedron's mesh contact, polyhedron_shape.hpp).
// The nearest point of the triangle lies in one of its seven Voronoi regions (three vertices,
// three edges, the face), told apart by the signs of d1 = ab.ap, d2 = ac.ap (and the same from b
// and c) and of the barycentric products va, vb, vc (Ericson, Real-Time Collision Detection,
// 2005, section 5.1.5); the distance is then |p - q| for that nearest point q.
// Rounding: q is formed from vectors of the triangle's size L, so the squared distance carries an
// error of order eps L |p - q| + (eps L)^2; `within` allows 16 eps (|ab|^2 + |ac|^2 + |ap|^2) more
// (in double 6e-8 L on the distance, in float 1.4e-3 L): a test that errs only towards keeping.
#pragma once
#include "blaze/core/math.hpp"
#include "blaze/core/vec3.hpp"

namespace blaze {

template <class Real>
BLAZE_HD Real distance2_to_triangle(const Vec3<Real>& p, const Vec3<Real>& a, const Vec3<Real>& b, const Vec3<Real>& c) {
  const Vec3<Real> ab = b - a, ac = c - a, ap = p - a;
  const Real d1 = dot(ab, ap), d2 = dot(ac, ap);
  if (d1 <= Real(0) && d2 <= Real(0)) return norm2(ap);  // vertex a
  const Vec3<Real> bp = p - b;
  const Real d3 = dot(ab, bp), d4 = dot(ac, bp);
  if (d3 >= Real(0) && d4 <= d3) return norm2(bp);  // vertex b
  const Real vc = d1 * d4 - d3 * d2;
  if (vc <= Real(0) && d1 >= Real(0) && d3 <= Real(0)) return norm2(ap - ab * (d1 / (d1 - d3)));  // edge ab
  const Vec3<Real> cp = p - c;
  const Real d5 = dot(ab, cp), d6 = dot(ac, cp);
  if (d6 >= Real(0) && d5 <= d6) return norm2(cp);  // vertex c
  const Real vb = d5 * d2 - d1 * d6;
  if (vb <= Real(0) && d2 >= Real(0) && d6 <= Real(0)) return norm2(ap - ac * (d2 / (d2 - d6)));  // edge ac
  const Real va = d3 * d6 - d5 * d4;
  if (va <= Real(0) && d4 - d3 >= Real(0) && d5 - d6 >= Real(0))  // edge bc
    return norm2(bp - (c - b) * ((d4 - d3) / ((d4 - d3) + (d5 - d6))));
  const Real inv = Real(1) / (va + vb + vc);  // the face
  return norm2(ap - ab * (vb * inv) - ac * (vc * inv));
}

// Some point of triangle (a, b, c) lies within `reach` of p, or within the rounding allowance of it.
template <class Real>
BLAZE_HD bool triangle_within(const Vec3<Real>& p, const Vec3<Real>& a, const Vec3<Real>& b, const Vec3<Real>& c, Real reach) {
  const Real size2 = norm2(b - a) + norm2(c - a) + norm2(p - a);
  return distance2_to_triangle(p, a, b, c) <= reach * reach + Real(16) * epsilon_r<Real>() * size2;
}

}  // namespace blaze
