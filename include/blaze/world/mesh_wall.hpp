// Triangle-mesh walls as world objects (issue 20). A mesh is one object (one pose, motion,
// material and contact class) made of many triangles; its surface rules are mesh_surface.hpp's
// (one contact per point of one smooth surface) and its triangles are found through bins in its
// own reference frame (mesh_bins.hpp), so a mesh that moves rigidly never moves its vertices:
// the particle is taken into the mesh's frame, x_ref = R^T (x - u), the contact is formed there
// and its normal and point are turned back, n = R n_ref, p = R p_ref + u.
// All meshes of a world share one set of arrays (vertices, triangles, neighbours, vertex
// adjacency, bins), indices global over the meshes; each mesh keeps its bins and the range of
// its triangles (MeshObject).
// A wall contact's history key (kernels/contact_history.hpp) is its object index for polygons and
// cylinders, and mesh_key_base + the triangle's global index for a mesh (mesh_key_base = the
// world's object count), so a particle may hold several contacts with one mesh (a valley, a
// corner) and each keeps its own spring.
#pragma once
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <stdexcept>
#include <string>
#include <vector>
#include "blaze/world/mesh_bins.hpp"
#include "blaze/world/mesh_surface.hpp"
#include "blaze/world/motion.hpp"
#include "blaze/world/triangle_distance.hpp"

namespace blaze {

// The host description: the mesh in its reference frame (m; the scene's scale and placement
// already applied), repaired (triangle_mesh.hpp).
struct MeshWall {
  std::string name;
  TriangleMesh mesh;
  std::uint8_t material = 0;
};

// What the kernels read of one mesh.
template <class Real>
struct MeshObject {
  MeshBinsView<Real> bins;  // entries are global triangle indices
  int first_triangle;       // its triangles are [first_triangle, first_triangle + triangle_count)
  int triangle_count;
  std::uint8_t material;
  BLAZE_HD bool owns(int triangle) const { return triangle >= first_triangle && triangle < first_triangle + triangle_count; }
};

// The meshes' arrays, concatenated, on the host (WorldStore uploads them and points each
// object's bins at its part: bin_start_offset, bin_entry_offset).
template <class Real>
struct MeshArrays {
  std::vector<Vec3<Real>> vertex;
  std::vector<Vec3<Real>> normal;
  std::vector<Vec3<Real>> corner;  // per triangle its three vertices (MeshSurfaceView::corner)
  std::vector<int> triangle, neighbour, adjacency_start, adjacency, bin_start, bin_entry;
  std::vector<int> patch;  // per triangle its flat patch (flat_patches), numbered over all meshes
  std::vector<MeshObject<Real>> objects;
  std::vector<std::size_t> bin_start_offset, bin_entry_offset;
  std::vector<long> longest_cell;  // per mesh: the most triangles one cell lists
};

// The bins' cell: the reach (a particle's cell then lists the triangles within about two reaches
// of it, however large the triangles: cells as large as the mean edge listed ~14 per cell for
// large triangles, and the dense bed's world phase took 2x the six polygons' at 1e3 triangles),
// at least 1e-6 of the mesh's size; bin_mesh grows it to keep the grid within kMaxCells.
inline double mesh_cell_size(const TriangleMesh& m, double reach) { return std::fmax(reach, 1e-6 * std::fmax(m.extent(), 1e-300)); }

// `reach` (m): the largest bounding radius a particle has plus the neighbour-list skin (the world
// lists test every mesh whose bins list triangles in the particle's cell; the contact finds every
// triangle within a particle's radius there).
template <class Real>
MeshArrays<Real> mesh_arrays(const std::vector<MeshWall>& meshes, double reach) {
  if (!(reach > 0)) throw std::invalid_argument("mesh walls: the bins' reach must be > 0 m");
  MeshArrays<Real> a;
  long triangles = 0, vertices = 0;
  for (const auto& w : meshes) triangles += static_cast<long>(w.mesh.size()), vertices += static_cast<long>(w.mesh.vertices.size());
  if (triangles > 100000000L || vertices > 300000000L)
    throw std::invalid_argument("mesh walls: at most 1e8 triangles in all, got " + std::to_string(triangles));
  a.adjacency_start.push_back(0);
  int patches = 0;
  for (const auto& w : meshes) {
    if (w.mesh.size() == 0) throw std::invalid_argument("mesh wall '" + w.name + "': no triangles");
    const int v0 = static_cast<int>(a.vertex.size()), t0 = static_cast<int>(a.triangle.size() / 3);
    const MeshTopology topo = mesh_topology(w.mesh);
    for (const auto& v : w.mesh.vertices) a.vertex.push_back(vec_cast<Real>(v));
    for (const auto& n : triangle_normals(w.mesh)) a.normal.push_back(vec_cast<Real>(n));
    for (const auto& tri : w.mesh.triangles)
      for (int k = 0; k < 3; ++k) a.corner.push_back(vec_cast<Real>(w.mesh.vertices[static_cast<std::size_t>(tri[static_cast<std::size_t>(k)])]));
    for (std::size_t t = 0; t < w.mesh.size(); ++t)
      for (int k = 0; k < 3; ++k) {
        a.triangle.push_back(v0 + w.mesh.triangles[t][static_cast<std::size_t>(k)]);
        const int o = topo.neighbour[t][static_cast<std::size_t>(k)];
        a.neighbour.push_back(o < 0 ? -1 : t0 + o);
      }
    const int adjacency0 = static_cast<int>(a.adjacency.size());
    for (std::size_t v = 0; v + 1 < topo.adjacency_start.size(); ++v) a.adjacency_start.push_back(adjacency0 + topo.adjacency_start[v + 1]);
    for (int u : topo.adjacency) a.adjacency.push_back(v0 + u);
    int most = -1;
    for (int code : flat_patches(w.mesh, topo)) {
      const int p = code >= 0 ? code : -1 - code;
      most = std::max(most, p);
      a.patch.push_back(code >= 0 ? patches + p : -1 - (patches + p));
    }
    patches += most + 1;
    const MeshBinsHost b = bin_mesh(w.mesh, reach, mesh_cell_size(w.mesh, reach));
    MeshObject<Real> o{};
    o.bins = bins_view<Real>(b, nullptr, nullptr);  // pointed at their part of the arrays by WorldStore
    o.first_triangle = t0;
    o.triangle_count = static_cast<int>(w.mesh.size());
    o.material = w.material;
    a.bin_start_offset.push_back(a.bin_start.size());
    a.bin_entry_offset.push_back(a.bin_entry.size());
    a.bin_start.insert(a.bin_start.end(), b.start.begin(), b.start.end());
    for (int t : b.entry) a.bin_entry.push_back(t0 + t);
    a.objects.push_back(o);
    a.longest_cell.push_back(b.longest);
  }
  return a;
}

// A particle's triangle list (kernels/world_candidates.hpp): the triangles of every mesh that lay
// within its reach at the last rebuild, in ascending index (global over the meshes), or none
// (count < 0: the list overflowed or there is none), when the triangles of its bins' cell are
// tested instead. Either holds every triangle the particle can touch until the next rebuild.
struct TriangleList {
  const int* triangle = nullptr;  // triangle[k * stride], k < count
  Index stride = 0;
  int count = -1;
};

// Some point of triangle t of surface s lies within `reach` of x (up to rounding, triangle_distance.hpp).
template <class Real>
BLAZE_HD bool triangle_near(const MeshSurfaceView<Real>& s, int t, const Vec3<Real>& x, Real reach) {
  return triangle_within(x, s.corner_of(t, 0), s.corner_of(t, 1), s.corner_of(t, 2), reach);
}

// The triangles to test for a particle at x_ref (its mesh's reference frame): its list's
// (of every mesh: a user keeps those m owns) or its cell's in mesh m's bins; ascending either way.
struct TriangleRange {
  const int* first;
  std::size_t step;
  int count;
  BLAZE_HD int operator[](int k) const { return first[static_cast<std::size_t>(k) * step]; }
};
template <class Real>
BLAZE_HD TriangleRange near_triangles(const MeshObject<Real>& m, const Vec3<Real>& x_ref, const TriangleList& list) {
  if (list.count >= 0) return {list.triangle, static_cast<std::size_t>(list.stride), list.count};
  int first = 0, last = 0;
  m.bins.cell_of(x_ref, first, last);
  return {m.bins.entry + first, 1, last - first};
}

// f(t) for each triangle t of mesh m in near_triangles.
template <class Real, class F>
BLAZE_HD void for_each_near_triangle(const MeshObject<Real>& m, const Vec3<Real>& x_ref, const TriangleList& list, F&& f) {
  const TriangleRange r = near_triangles(m, x_ref, list);
  for (int k = 0; k < r.count; ++k)
    if (m.owns(r[k])) f(r[k]);
}

// The contacts sphere (x, r) has with mesh m (pose: where it stands; null: as built), merged per
// point of the surface (mesh_surface.hpp), in the world frame; added to `out`. A triangle farther
// than r offers nothing, so the list's extra triangles change nothing.
template <class Real, int K>
BLAZE_HD void collide_sphere_mesh(const Vec3<Real>& x, Real r, const MeshSurfaceView<Real>& s, const MeshObject<Real>& m,
                                  const Pose<Real>* pose, MeshContacts<Real, K>& out, const TriangleList& list = {}) {
  const Vec3<Real> xr = pose ? pose->to_reference(x) : x;
  for_each_near_triangle(m, xr, list, [&](int t) { out.add(collide_sphere_mesh_triangle(xr, r, s, t), t, r); });
  if (pose)
    for (int k = 0; k < out.count; ++k) {
      out.contact[k].normal = pose->turn(out.contact[k].normal);
      out.contact[k].point = pose->place(out.contact[k].point);
    }
}

// Flat patches and triangle lists (kernels/world_candidates.hpp). A sphere at x (the mesh's
// frame) that stays within `move` of x until its list is rebuilt, and lies over the face of a
// triangle T deeper inside each of T's edges than `move` plus a rounding allowance, stays over T:
// every other flat-interior triangle T' of T's patch (flat_patches) then offers it nothing
// (mesh_surface.hpp: its face does not lie under x, its edges' neighbours in the plane have x on
// their inner side, its corners' fans close around them in the plane), so T' leaves the list and
// the contacts are bitwise those of the full list (test_flat_patches.cpp). The allowance keeps
// the regions' rounding margin (64 ulps of (|x - a| + L)^2 over an edge of length L, L' the
// longest edge of T') 64 times over: depth >= move + 4096 eps (r + move + 2 L')^2 / L', with the
// depth x's distance inside T's nearest edge line; in double it is nil, in float ~5e-3 r for
// triangles as large as the sphere.
// list[k * stride], k < count: the listed triangles of one mesh, ascending; kept in order, the
// new count returned. Patches over which x lies that deep: the first kFlatCovers of the list.
constexpr int kFlatCovers = 2;
template <class Real>
BLAZE_HD int patch_of(const MeshSurfaceView<Real>& s, int t) {
  return s.patch[t] >= 0 ? s.patch[t] : -1 - s.patch[t];
}
// How far x's projection lies inside triangle t's nearest edge line (m; < 0: outside).
template <class Real>
BLAZE_HD Real depth_over_face(const MeshSurfaceView<Real>& s, int t, const Vec3<Real>& x) {
  const Vec3<Real> n = s.normal[t];
  Real depth = Real(0);
  for (int k = 0; k < 3; ++k) {
    const Vec3<Real> a = s.corner_of(t, k), b = s.corner_of(t, k + 1 < 3 ? k + 1 : 0);
    const Real side = mesh_detail::edge_side(x, a, b, n) / sqrt_r(norm2(b - a));  // m, inside the edge's line
    if (k == 0 || side < depth) depth = side;
  }
  return depth;
}
template <class Real>
BLAZE_HD int drop_flat_neighbours(const MeshSurfaceView<Real>& s, const Vec3<Real>& x, Real r, Real move, int* list,
                                  std::size_t stride, int count) {
  if (!s.patch) return count;
  int cover[kFlatCovers], covers = 0;  // the triangles x lies deep over, one per patch
  Real depth[kFlatCovers];
  for (int k = 0; k < count && covers < kFlatCovers; ++k) {
    const int t = list[static_cast<std::size_t>(k) * stride];
    const Real d = depth_over_face(s, t, x);
    if (!(d > move)) continue;
    bool seen = false;
    for (int c = 0; c < covers; ++c) seen = seen || patch_of(s, cover[c]) == patch_of(s, t);
    if (!seen) cover[covers] = t, depth[covers] = d, ++covers;
  }
  if (covers == 0) return count;
  int kept = 0;
  for (int k = 0; k < count; ++k) {
    const int t = list[static_cast<std::size_t>(k) * stride];
    bool drop = false;
    for (int c = 0; c < covers && !drop; ++c) {
      // flat-interior (its code is its patch) and in the cover's patch
      if (t == cover[c] || s.patch[t] != patch_of(s, cover[c])) continue;
      const Vec3<Real> v0 = s.corner_of(t, 0), v1 = s.corner_of(t, 1), v2 = s.corner_of(t, 2);
      const Real longest = sqrt_r(max_r(norm2(v1 - v0), max_r(norm2(v2 - v1), norm2(v0 - v2))));
      const Real span = r + move + Real(2) * longest;
      drop = depth[c] >= move + Real(4096) * epsilon_r<Real>() * span * span / longest;
    }
    if (!drop) list[static_cast<std::size_t>(kept++) * stride] = t;
  }
  return kept;
}

// Mesh m may hold a contact of any body within the bins' reach of x (the world lists' test:
// its bins list triangles in x's cell).
template <class Real>
BLAZE_HD bool mesh_near(const Vec3<Real>& x, const MeshObject<Real>& m, const Pose<Real>* pose) {
  int first = 0, last = 0;
  m.bins.cell_of(pose ? pose->to_reference(x) : x, first, last);
  return last > first;
}

// Triangles a and b lie in one plane (normals within 1e-6 rad, planes within 1e-9 of a's size):
// a contact moving from one to the other on a flat tessellation keeps its history.
template <class Real>
BLAZE_HD bool coplanar(const MeshSurfaceView<Real>& s, int a, int b) {
  const int *ta = s.triangle + 3 * a, *tb = s.triangle + 3 * b;
  const Vec3<Real> na = s.normal[a], nb = s.normal[b];
  const Real size = sqrt_r(max_r(norm2(s.vertex[ta[1]] - s.vertex[ta[0]]), norm2(s.vertex[ta[2]] - s.vertex[ta[0]])));
  const Real angle = sizeof(Real) == 4 ? Real(1e-4) : Real(1e-6), gap = sizeof(Real) == 4 ? Real(1e-5) : Real(1e-9);
  return norm2(na - nb) <= angle * angle && abs_r(dot(s.vertex[tb[0]] - s.vertex[ta[0]], na)) <= gap * size;
}

// Triangles a and b share a vertex (a contact rolling from one to the other keeps its history).
BLAZE_HD inline bool share_vertex(const int* triangle, int a, int b) {
  for (int p = 0; p < 3; ++p)
    for (int q = 0; q < 3; ++q)
      if (triangle[3 * a + p] == triangle[3 * b + q]) return true;
  return false;
}

}  // namespace blaze
