// Small wall scenes shared by the mesh cases (test_mesh_walls.cpp, test_mesh_rims.cpp): a mesh from
// its corners, and the turn that lays a polyhedron's face on a wall.
#pragma once
#include <array>
#include <cmath>
#include <vector>
#include "blaze/core/quat.hpp"
#include "blaze/shapes/polyhedron_table.hpp"
#include "blaze/world/triangle_mesh.hpp"

namespace blaze::test {

inline TriangleMesh mesh_of(std::vector<Vec3<double>> v, std::vector<std::array<int, 3>> t) {
  TriangleMesh m;
  m.vertices = std::move(v), m.triangles = std::move(t);
  return m;
}

// The turn that takes the shape's face normal a = normal[0] to `down` and a face normal b
// perpendicular to a to `side` (then a x b to down x side): Q = down a^T + side b^T + (down x side)
// (a x b)^T, as a quaternion.
inline Quat<double> face_turn(const PolyhedronData<double>& d, const Vec3<double>& down, const Vec3<double>& side) {
  const Vec3<double> a = d.normal[0];
  Vec3<double> b = d.normal[1];
  for (int f = 1; f < d.face_count; ++f)
    if (std::fabs(dot(a, d.normal[f])) < 0.5) b = d.normal[f];
  const Vec3<double> c = cross(a, b), u2 = cross(down, side);
  double q[3][3];
  const double av[3] = {a.x, a.y, a.z}, bv[3] = {b.x, b.y, b.z}, cv[3] = {c.x, c.y, c.z};
  const double t1[3] = {down.x, down.y, down.z}, t2[3] = {side.x, side.y, side.z}, t3[3] = {u2.x, u2.y, u2.z};
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) q[i][j] = t1[i] * av[j] + t2[i] * bv[j] + t3[i] * cv[j];
  const double w = 0.5 * std::sqrt(std::fmax(0.0, 1 + q[0][0] + q[1][1] + q[2][2]));
  return {w, (q[2][1] - q[1][2]) / (4 * w), (q[0][2] - q[2][0]) / (4 * w), (q[1][0] - q[0][1]) / (4 * w)};
}

}  // namespace blaze::test
