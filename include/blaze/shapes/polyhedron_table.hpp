// Polyhedron shape data as kernels read it: fixed-capacity arrays (feature_caps.hpp), body frame,
// one entry per particle type. The thesis kept its Particle_Object in constant memory (section
// 2.2.1); so did we until the profile of issue 6 showed why not: the kernels index the table with
// registers (type, feature, the edge a lane picked), and indexed constant loads all queue on one
// unit per SM. Kernels read a copy in device memory instead (PolyhedronShape::resident), through L1.
#pragma once
#include <cstdint>
#include <stdexcept>
#include <string>
#include "blaze/core/vec3.hpp"
#include "blaze/shapes/convex_shape.hpp"

namespace blaze {

template <class Real>
struct PolyhedronData {
  Vec3<Real> vertex[kMaxVertices];  // m, body frame
  Vec3<Real> normal[kMaxFaces];     // outward unit normals
  Real offset[kMaxFaces];           // m: a point x is inside face f's half-space when normal.x <= offset
  std::uint8_t edge_vertex[kMaxEdges][2];
  std::uint8_t edge_face[kMaxEdges][2];  // faces left and right of the edge (ConvexShape::Edge)
  // Bit e set: edge e has face f as its edge_face[e][0] (edges_left_of) / [1] (edges_right_of).
  // A convex polyhedron within the caps has E = V + F - 2 <= 62 edges, so 64 bits hold them.
  std::uint64_t edges_left_of[kMaxFaces], edges_right_of[kMaxFaces];
  // normal[right] x normal[left] of each edge: the edge's Gauss-map arc, which the separating-axis
  // test's edge-pair selection tests against (polyhedron_shape.hpp, crossing_edges).
  Vec3<Real> edge_arc[kMaxEdges];
  int vertex_count, face_count, edge_count;  // all 0: a sphere of radius bounding_radius
  Real bounding_radius;    // m (bound_R)
  Real volume;             // m^3
  Real mass;               // kg, at this type's density
  Vec3<Real> inv_inertia;  // 1/(kg m^2), principal moments at this type's density

  static PolyhedronData from(const ConvexShape& s, double density) {
    if (!(density > 0)) throw std::invalid_argument("polyhedron " + s.name + ": density must be > 0 kg/m^3");
    PolyhedronData d{};
    d.vertex_count = static_cast<int>(s.vertices.size());
    d.face_count = static_cast<int>(s.faces.size());
    d.edge_count = static_cast<int>(s.edges.size());
    for (int k = 0; k < d.vertex_count; ++k) d.vertex[k] = to_vec(s.vertices[k]);
    for (int f = 0; f < d.face_count; ++f) {
      d.normal[f] = to_vec(s.normals[f]);
      d.offset[f] = static_cast<Real>(s.normals[f].dot(s.centroids[f]));
    }
    if (d.edge_count > 64)
      throw std::invalid_argument("polyhedron " + s.name + ": " + std::to_string(d.edge_count) +
                                  " edges; a convex polyhedron of <= 32 vertices and faces has <= 62");
    for (int e = 0; e < d.edge_count; ++e) {
      d.edge_vertex[e][0] = static_cast<std::uint8_t>(s.edges[e].v0);
      d.edge_vertex[e][1] = static_cast<std::uint8_t>(s.edges[e].v1);
      d.edge_face[e][0] = static_cast<std::uint8_t>(s.edges[e].left);
      d.edge_face[e][1] = static_cast<std::uint8_t>(s.edges[e].right);
      d.edges_left_of[s.edges[e].left] |= std::uint64_t(1) << e;
      d.edges_right_of[s.edges[e].right] |= std::uint64_t(1) << e;
      d.edge_arc[e] = cross(d.normal[s.edges[e].right], d.normal[s.edges[e].left]);
    }
    d.bounding_radius = static_cast<Real>(s.bounding_radius);
    d.volume = static_cast<Real>(s.volume);
    d.mass = static_cast<Real>(density * s.volume);
    const Eigen::Vector3d inv = (density * s.inertia_per_density).cwiseInverse();
    d.inv_inertia = to_vec(inv);
    return d;
  }

 private:
  static Vec3<Real> to_vec(const Eigen::Vector3d& v) {
    return {static_cast<Real>(v.x()), static_cast<Real>(v.y()), static_cast<Real>(v.z())};
  }
};

template <class Real>
struct PolyhedronTable {
  static constexpr int kMaxTypes = 4;
  PolyhedronData<Real> type[kMaxTypes];
  int count = 0;

  // A sphere type (no features): polyhedra and spheres can share one simulation.
  int add_sphere(double radius, double density) {
    if (count == kMaxTypes)
      throw std::invalid_argument("polyhedron table: more than " + std::to_string(kMaxTypes) + " particle types");
    if (!(radius > 0) || !(density > 0)) throw std::invalid_argument("sphere type: radius and density must be > 0");
    PolyhedronData<Real> d{};
    const double volume = 4.0 / 3.0 * 3.14159265358979323846 * radius * radius * radius, mass = density * volume;
    const Real inv = static_cast<Real>(1 / (0.4 * mass * radius * radius));
    d.bounding_radius = static_cast<Real>(radius);
    d.volume = static_cast<Real>(volume);
    d.mass = static_cast<Real>(mass);
    d.inv_inertia = {inv, inv, inv};
    type[count] = d;
    return count++;
  }

  int add(const ConvexShape& s, double density) {
    if (count == kMaxTypes)
      throw std::invalid_argument("polyhedron table: more than " + std::to_string(kMaxTypes) + " particle types");
    type[count] = PolyhedronData<Real>::from(s, density);
    return count++;
  }
};

}  // namespace blaze
