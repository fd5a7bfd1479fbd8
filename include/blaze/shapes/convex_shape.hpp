// A convex polyhedron on the host: validated geometry, exact mass properties, body frame.
//
// Mass properties (per unit density, so any density can be applied): the solid is split into
// tetrahedra (origin, a, b, c), one per triangle of a fan over each face. For each,
//   V = a.(b x c)/6,  first moment V (a+b+c)/4,
//   second moment  S = int x x^T dV = V/20 (a a^T + b b^T + c c^T + s s^T),  s = a + b + c
// (exact for a linear map of the unit tetrahedron). Inertia about the origin I = tr(S) 1 - S,
// moved to the centre of mass by the parallel-axis theorem, then diagonalised (Eigen): the body
// frame has its origin at the centre of mass and its axes on the principal axes, so the inertia
// tensor is diag(I1, I2, I3) there (thesis section 2.2.1 stores the vertex list and bound_R).
#pragma once
#include <Eigen/Dense>
#include <algorithm>
#include <cmath>
#include <map>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>
#include "blaze/shapes/feature_caps.hpp"

namespace blaze {

struct ShapeError : std::runtime_error {
  using std::runtime_error::runtime_error;
};

struct ConvexShape {
  struct Edge {
    int v0, v1;       // vertices
    int left, right;  // faces: `left` runs v0 -> v1 in its counter-clockwise loop, `right` v1 -> v0
  };
  std::string name;
  std::vector<Eigen::Vector3d> vertices;  // m, body frame
  std::vector<std::vector<int>> faces;    // counter-clockwise seen from outside
  std::vector<Eigen::Vector3d> normals;   // outward unit normals, body frame
  std::vector<Eigen::Vector3d> centroids; // face centroids (vertex mean), m
  std::vector<Edge> edges;
  double volume = 0;                      // m^3
  Eigen::Vector3d inertia_per_density;    // principal moments / density, m^5
  double bounding_radius = 0;             // m, largest vertex distance from the centre of mass
  Eigen::Vector3d com_in_input;           // where the centre of mass was in the input frame, m
  Eigen::Matrix3d axes_in_input;          // columns: principal axes in the input frame
  std::vector<std::string> repairs;       // what loading fixed, in words
};

namespace shape_detail {

inline Eigen::Vector3d face_area_vector(const std::vector<Eigen::Vector3d>& v, const std::vector<int>& f) {
  Eigen::Vector3d a = Eigen::Vector3d::Zero();
  for (std::size_t k = 0; k < f.size(); ++k) a += v[f[k]].cross(v[f[(k + 1) % f.size()]]);
  return 0.5 * a;
}

inline Eigen::Vector3d mean_of(const std::vector<Eigen::Vector3d>& v, const std::vector<int>& f) {
  Eigen::Vector3d c = Eigen::Vector3d::Zero();
  for (int i : f) c += v[i];
  return c / static_cast<double>(f.size());
}

}  // namespace shape_detail

// Validates, repairs winding, computes mass properties and moves the shape to its body frame.
// `source` names the file in error messages. Relative tolerance for planarity and convexity:
// 1e-9 of the shape's size (far above rounding of coordinates given to 17 digits, far below any
// intended feature).
inline ConvexShape make_convex_shape(const std::string& name, std::vector<Eigen::Vector3d> v,
                                     std::vector<std::vector<int>> faces, const std::string& source) {
  using namespace shape_detail;
  auto fail = [&](const std::string& what) -> void { throw ShapeError(source + ": " + what); };
  const int nv = static_cast<int>(v.size()), nf = static_cast<int>(faces.size());
  if (nv > kMaxVertices) fail(std::to_string(nv) + " vertices: more than the cap of " + std::to_string(kMaxVertices));
  if (nf > kMaxFaces) fail(std::to_string(nf) + " faces: more than the cap of " + std::to_string(kMaxFaces));
  if (nv < 4 || nf < 4) fail("a closed polyhedron needs at least 4 vertices and 4 faces");
  Eigen::Vector3d centre = Eigen::Vector3d::Zero();
  for (const auto& p : v) centre += p;
  centre /= nv;
  double size = 0;
  for (const auto& p : v) size = std::max(size, (p - centre).norm());
  if (!(size > 0)) fail("all vertices coincide");
  const double tol = 1e-9 * size;

  ConvexShape s;
  s.name = name;
  std::vector<bool> used(nv, false);
  for (int f = 0; f < nf; ++f) {
    auto& loop = faces[f];
    const std::string face = "face " + std::to_string(f);
    if (loop.size() < 3) fail(face + " has fewer than 3 vertices (degenerate)");
    for (int i : loop) {
      if (i < 0 || i >= nv) fail(face + " refers to vertex " + std::to_string(i) + ", which does not exist");
      used[i] = true;
    }
    for (std::size_t a = 0; a < loop.size(); ++a)
      for (std::size_t b = a + 1; b < loop.size(); ++b)
        if (loop[a] == loop[b]) fail(face + " uses vertex " + std::to_string(loop[a]) + " twice (degenerate)");
    Eigen::Vector3d area = face_area_vector(v, loop);
    if (area.norm() < 1e-12 * size * size) fail(face + " has zero area (degenerate)");
    const Eigen::Vector3d n = area.normalized(), c = mean_of(v, loop);
    for (int i : loop)
      if (std::fabs(n.dot(v[i] - c)) > tol) fail(face + " is not planar (vertex " + std::to_string(i) + " is off its plane)");
    // Winding: outward means away from the vertex centre (inside a convex body).
    if (n.dot(c - centre) < 0) {
      std::reverse(loop.begin(), loop.end());
      s.repairs.push_back(face + " was wound clockwise; reversed");
    }
  }
  for (int i = 0; i < nv; ++i)
    if (!used[i]) fail("vertex " + std::to_string(i) + " belongs to no face");
  // Closed and consistently wound: every directed edge once, and its reverse once.
  std::map<std::pair<int, int>, int> directed;
  for (int f = 0; f < nf; ++f)
    for (std::size_t k = 0; k < faces[f].size(); ++k) {
      const std::pair<int, int> e{faces[f][k], faces[f][(k + 1) % faces[f].size()]};
      if (directed.count(e)) fail("edge " + std::to_string(e.first) + "-" + std::to_string(e.second) +
                                  " is used twice in the same direction (faces overlap or wind inconsistently)");
      directed[e] = f;
    }
  for (const auto& [e, f] : directed) {
    const auto back = directed.find({e.second, e.first});
    if (back == directed.end())
      fail("not closed: edge " + std::to_string(e.first) + "-" + std::to_string(e.second) + " of face " +
           std::to_string(f) + " has no neighbouring face");
    if (e.first < e.second) s.edges.push_back({e.first, e.second, f, back->second});
  }
  if (static_cast<int>(s.edges.size()) > kMaxEdges)
    fail(std::to_string(s.edges.size()) + " edges: more than the cap of " + std::to_string(kMaxEdges));
  if (nv - static_cast<int>(s.edges.size()) + nf != 2) fail("not a closed surface of genus 0 (V - E + F != 2)");
  // Convex: every vertex on the inner side of every face plane.
  for (int f = 0; f < nf; ++f) {
    const Eigen::Vector3d n = face_area_vector(v, faces[f]).normalized(), c = mean_of(v, faces[f]);
    for (int i = 0; i < nv; ++i) {
      const double d = n.dot(v[i] - c);
      if (d > tol)
        fail("not convex: vertex " + std::to_string(i) + " lies " + std::to_string(d) + " m outside the plane of face " +
             std::to_string(f));
    }
  }

  // Mass properties per unit density, about the input origin.
  double vol = 0;
  Eigen::Vector3d first = Eigen::Vector3d::Zero();
  Eigen::Matrix3d second = Eigen::Matrix3d::Zero();
  for (const auto& loop : faces)
    for (std::size_t k = 1; k + 1 < loop.size(); ++k) {
      const Eigen::Vector3d& a = v[loop[0]];
      const Eigen::Vector3d& b = v[loop[k]];
      const Eigen::Vector3d& c = v[loop[k + 1]];
      const double tv = a.dot(b.cross(c)) / 6;
      const Eigen::Vector3d sum = a + b + c;
      vol += tv;
      first += tv * sum / 4;
      second += tv / 20 * (a * a.transpose() + b * b.transpose() + c * c.transpose() + sum * sum.transpose());
    }
  if (!(vol > 0)) fail("non-positive volume");
  const Eigen::Vector3d com = first / vol;
  const Eigen::Matrix3d s_com = second - vol * com * com.transpose();
  const Eigen::Matrix3d inertia = s_com.trace() * Eigen::Matrix3d::Identity() - s_com;
  Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> eig(inertia);
  Eigen::Matrix3d axes = eig.eigenvectors();
  if (axes.determinant() < 0) axes.col(2) = -axes.col(2);  // a rotation, not a reflection

  s.volume = vol;
  s.inertia_per_density = eig.eigenvalues();
  s.com_in_input = com;
  s.axes_in_input = axes;
  for (const auto& p : v) s.vertices.push_back(axes.transpose() * (p - com));
  s.faces = faces;
  for (const auto& loop : faces) {
    s.normals.push_back(face_area_vector(s.vertices, loop).normalized());
    s.centroids.push_back(mean_of(s.vertices, loop));
  }
  for (const auto& p : s.vertices) s.bounding_radius = std::max(s.bounding_radius, p.norm());
  return s;
}

}  // namespace blaze
