// Test-only reference for polyhedron contact: a brute-force separating-axis test in Eigen double,
// written independently of the kernel's (every face normal and every edge-pair cross product, every
// vertex projected; no Gauss-map pruning). Exact for convex polyhedra: the bodies overlap iff no
// axis separates them, and the least-penetration axis is the minimum translation direction.
#pragma once
#include <Eigen/Dense>
#include <limits>
#include <vector>
#include "blaze/shapes/convex_shape.hpp"

namespace blaze::test {

struct ReferenceContact {
  bool touching;
  double separation;   // > 0: the largest gap along any axis (m); <= 0: minus the least penetration
  Eigen::Vector3d normal;  // least-penetration axis, from A to B
  double second;       // least penetration along an axis more than 1 degree from `normal` (m)
};

inline ReferenceContact reference_contact(const ConvexShape& a, const Eigen::Vector3d& xa, const Eigen::Matrix3d& ra,
                                          const ConvexShape& b, const Eigen::Vector3d& xb, const Eigen::Matrix3d& rb) {
  std::vector<Eigen::Vector3d> va, vb, axes;
  for (const auto& v : a.vertices) va.push_back(xa + ra * v);
  for (const auto& v : b.vertices) vb.push_back(xb + rb * v);
  for (const auto& n : a.normals) axes.push_back(ra * n);
  for (const auto& n : b.normals) axes.push_back(rb * n);
  for (const auto& ea : a.edges)
    for (const auto& eb : b.edges) {
      const Eigen::Vector3d da = va[ea.v1] - va[ea.v0], db = vb[eb.v1] - vb[eb.v0];
      const Eigen::Vector3d n = da.cross(db);
      if (n.norm() > 1e-9 * da.norm() * db.norm()) axes.push_back(n.normalized());
    }
  ReferenceContact r{true, -std::numeric_limits<double>::infinity(), Eigen::Vector3d::Zero(),
                     std::numeric_limits<double>::infinity()};
  std::vector<std::pair<double, Eigen::Vector3d>> pen;
  for (const auto& n : axes) {
    double a_min = 1e300, a_max = -1e300, b_min = 1e300, b_max = -1e300;
    for (const auto& v : va) a_min = std::min(a_min, n.dot(v)), a_max = std::max(a_max, n.dot(v));
    for (const auto& v : vb) b_min = std::min(b_min, n.dot(v)), b_max = std::max(b_max, n.dot(v));
    const double up = b_min - a_max, down = a_min - b_max;  // gap with B on the +n or -n side
    const double sep = std::max(up, down);
    if (sep > r.separation) r.separation = sep, r.normal = up >= down ? n : Eigen::Vector3d(-n);
    pen.push_back({-sep, up >= down ? n : Eigen::Vector3d(-n)});
  }
  r.touching = r.separation <= 0;
  for (const auto& [p, n] : pen)
    if (n.dot(r.normal) < std::cos(3.14159265358979323846 / 180)) r.second = std::min(r.second, p);
  return r;
}

}  // namespace blaze::test
