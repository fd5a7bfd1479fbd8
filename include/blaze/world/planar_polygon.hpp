// A finite planar convex polygon wall (thesis section 3.2.1: S(n, c)), and its contact with a
// sphere (section 3.2.4, Algorithm 2 lines 1-2 plus the containment test).
//
// The wall acts on the side its normal n points to. For a sphere of centre x, radius r:
//   d = (x - c) . n                        signed distance of the centre (m)
//   face contact  if 0 < d < r and the foot point q = x - d n lies inside the polygon:
//                 overlap r - d, contact normal -n
//   rim contact   if |d| < r, q lies outside, and the nearest boundary point p lies on an edge
//                 marked active: overlap r - |x - p|, normal (p - x)/|x - p|
// The thesis tests containment by summing the areas of the triangles q makes with the edges
// (equal to the polygon's area iff q is inside); for convex polygons that is the same as q lying
// on the inner side of every edge, which is what we test (cheaper, and exact at the boundary).
// The thesis has no rim contact: a sphere rolling over the edge of an orifice would pass through
// the plate's rim. Edges shared with a coplanar neighbour must be left inactive, or a sphere near
// the seam would be pushed twice.
#pragma once
#include <cmath>
#include <cstdint>
#include <stdexcept>
#include <string>
#include <vector>
#include "blaze/contact/contact_geometry.hpp"

namespace blaze {

template <class Real>
struct PlanarPolygon {
  static constexpr int kMaxVertices = 8;
  Vec3<Real> vertex[kMaxVertices];  // m, counter-clockwise seen from the side n points to
  int vertex_count;
  Vec3<Real> normal;    // unit, derived from the vertices
  Vec3<Real> centroid;  // m, derived
  Real bound;           // m, derived: every point lies within this of the centroid (the farthest
                        // vertex's distance, 0.1% more for the rounding of a moved polygon)
  std::uint32_t active_edges;  // bit k: edge vertex[k] -> vertex[k+1] has rim contact
  std::uint8_t material;

  // Builds and validates a polygon; all edges active unless a mask is given.
  static PlanarPolygon make(const std::vector<Vec3<double>>& v, std::uint8_t material,
                            std::uint32_t active_edges = 0xffffffffu) {
    const int n = static_cast<int>(v.size());
    if (n < 3 || n > kMaxVertices)
      throw std::invalid_argument("planar polygon: needs 3 to " + std::to_string(kMaxVertices) +
                                  " vertices, got " + std::to_string(n));
    Vec3<double> c{0, 0, 0}, area_vec{0, 0, 0};
    for (const auto& p : v) c += p;
    c *= 1.0 / n;
    for (int k = 0; k < n; ++k) area_vec += cross(v[k] - c, v[(k + 1) % n] - c);
    const double twice_area = norm(area_vec);
    double size = 0;
    for (const auto& p : v) size = std::fmax(size, norm(p - c));
    if (!(twice_area > 1e-12 * size * size)) throw std::invalid_argument("planar polygon: zero area");
    const Vec3<double> nrm = area_vec * (1.0 / twice_area);
    for (int k = 0; k < n; ++k) {
      if (std::fabs(dot(v[k] - c, nrm)) > 1e-9 * size)
        throw std::invalid_argument("planar polygon: vertex " + std::to_string(k) + " is off the plane");
      const Vec3<double> e0 = v[(k + 1) % n] - v[k], e1 = v[(k + 2) % n] - v[(k + 1) % n];
      if (dot(cross(e0, e1), nrm) < -1e-12 * size * size)
        throw std::invalid_argument("planar polygon: not convex at vertex " + std::to_string((k + 1) % n));
    }
    PlanarPolygon p{};
    for (int k = 0; k < n; ++k) p.vertex[k] = vec_cast<Real>(v[k]);
    p.vertex_count = n;
    p.normal = vec_cast<Real>(nrm);
    p.centroid = vec_cast<Real>(c);
    p.bound = static_cast<Real>(1.001 * size);
    p.active_edges = active_edges;
    p.material = material;
    return p;
  }

  // True when q (a point of the plane) lies inside the polygon or on its boundary.
  BLAZE_HD bool contains(const Vec3<Real>& q) const {
    for (int k = 0; k < vertex_count; ++k) {
      const Vec3<Real> a = vertex[k];
      const Vec3<Real> e = vertex[k + 1 < vertex_count ? k + 1 : 0] - a;
      if (dot(cross(e, q - a), normal) < Real(0)) return false;
    }
    return true;
  }
};

template <class Real>
BLAZE_HD inline ContactGeometry<Real> collide_sphere(const Vec3<Real>& x, Real r, const PlanarPolygon<Real>& w) {
  const Real d = dot(x - w.centroid, w.normal);
  if (!(d < r && d > -r)) return ContactGeometry<Real>::none();  // bounding-sphere test (line 2)
  // Beyond the polygon's own bounding sphere (a lifter face whose plane crosses the particle far
  // from the face): no vertex read.
  const Real reach = r + w.bound;
  if (norm2(x - w.centroid) > reach * reach) return ContactGeometry<Real>::none();
  const Vec3<Real> q = x - d * w.normal;
  bool inside = true;
  Real best2 = Real(0);
  Vec3<Real> best{0, 0, 0};
  int best_edge = -1;
  for (int k = 0; k < w.vertex_count; ++k) {
    const Vec3<Real> a = w.vertex[k];
    const Vec3<Real> e = w.vertex[k + 1 < w.vertex_count ? k + 1 : 0] - a;
    if (dot(cross(e, q - a), w.normal) >= Real(0)) continue;
    inside = false;
    // Nearest point of this edge to x.
    const Real t = clamp_r(dot(x - a, e) / norm2(e), Real(0), Real(1));
    const Vec3<Real> p = a + t * e;
    const Real dist2 = norm2(x - p);
    if (best_edge < 0 || dist2 < best2) {
      best2 = dist2;
      best = p;
      best_edge = k;
    }
  }
  if (inside) {
    if (!(d > Real(0))) return ContactGeometry<Real>::none();  // centre behind the wall (line 1)
    const Real delta = r - d;
    const Vec3<Real> n = -w.normal;
    return {true, n, delta, x + n * (r - Real(0.5) * delta), r};
  }
  if (!((w.active_edges >> best_edge) & 1u) || !(best2 < r * r) || best2 == Real(0))
    return ContactGeometry<Real>::none();
  const Real dist = sqrt_r(best2);
  const Vec3<Real> n = (best - x) * (Real(1) / dist);
  const Real delta = r - dist;
  return {true, n, delta, x + n * (r - Real(0.5) * delta), r};
}

// Some point of the polygon (a closed set) lies within `reach` of x: the candidate test of the
// world lists (kernels/world_candidates.hpp). Any body inside the sphere (x, r) that touches the
// wall after x and the wall have each moved at most m passes it with reach = r + 2 m.
template <class Real>
BLAZE_HD inline bool within_reach(const Vec3<Real>& x, Real reach, const PlanarPolygon<Real>& w) {
  // Beyond the bounding sphere: no point is in reach (most of a mill's faces for most particles:
  // the rest of the test reads every vertex).
  const Real far = reach + w.bound;
  if (norm2(x - w.centroid) > far * far) return false;
  const Real d = dot(x - w.centroid, w.normal);
  if (!(d <= reach && d >= -reach)) return false;
  const Vec3<Real> q = x - d * w.normal;
  if (w.contains(q)) return true;
  for (int k = 0; k < w.vertex_count; ++k) {
    const Vec3<Real> a = w.vertex[k];
    const Vec3<Real> e = w.vertex[k + 1 < w.vertex_count ? k + 1 : 0] - a;
    const Real t = clamp_r(dot(x - a, e) / norm2(e), Real(0), Real(1));
    if (norm2(x - (a + t * e)) <= reach * reach) return true;
  }
  return false;
}

}  // namespace blaze
