// A triangle mesh as a contact surface (issue 20): a sphere touching one smooth surface gets one
// contact, wherever the tessellation puts its edges and vertices.
// Each triangle T offers the contact at the point p of T nearest the sphere's centre x (Voronoi
// regions of its face, edges and vertices), but only where p is the surface's nearest point near
// there:
//   face    x projects inside T (all three in-plane edge tests s_k = (x - a_k) . (n x e_k) >= 0)
//           and lies in front (d = (x - a) . n > 0): overlap r - d, normal -n;
//   edge e  p inside edge e, and x projects outside T across e (s_e <= 0) and outside the
//           neighbour T' across e (T'`s own test, recomputed): then neither face has x over its
//           interior, and the nearest point of the pair is on e (a convex ridge's wedge);
//   vertex  p = v, and x projects onto no edge at v: (x - v) . (w - v) <= 0 for every neighbour w
//           of v (then x's nearest point on every triangle at v is v).
// In exact arithmetic these regions tile space around a convex ridge or corner, so one triangle
// offers the contact; in a valley two faces do (two points of the surface touch the sphere). At
// the regions' shared boundaries (x exactly over an edge or a vertex of a flat tessellation, where
// the triangles' normals differ in the last bits) rounding could let two triangles offer it or
// none; so every test is inclusive by a rounding margin, and the offers a particle receives are
// merged (MeshContacts): offers at the same point with the same normal (within 1e-9 of the
// radius, 1e-9 rad) are one contact, the deepest kept. A surface seen over a vertex of a flat
// fan thus pushes as one polygon. An edge of three or more triangles (non-manifold) is treated as
// open for each of them. Faces act on their front, as planar walls do; edges and vertices push
// from wherever x is.
// Sources: the closest-point regions of a triangle (Ericson, Real-Time Collision Detection, 5.1.5);
// one contact per surface point (Su et al. 2011; Kremmer & Favier 2001).
#pragma once
#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <unordered_map>
#include <vector>
#include "blaze/contact/contact_geometry.hpp"
#include "blaze/core/math.hpp"
#include "blaze/world/triangle_mesh.hpp"

namespace blaze {

struct MeshTopology {
  std::vector<std::array<int, 3>> neighbour;  // per triangle and edge k (corner k -> k + 1): the triangle across it, -1 open
  std::vector<int> adjacency_start;           // per vertex (+1): where its neighbours start in adjacency
  std::vector<int> adjacency;                 // vertices joined to it by an edge
};

inline MeshTopology mesh_topology(const TriangleMesh& m) {
  MeshTopology t;
  const std::size_t n = m.size();
  t.neighbour.assign(n, {-1, -1, -1});
  std::unordered_map<std::uint64_t, std::vector<std::pair<int, int>>> edges;  // (triangle, edge k)
  const auto key = [](int a, int b) {
    return static_cast<std::uint64_t>(std::min(a, b)) << 32 | static_cast<std::uint64_t>(std::max(a, b));
  };
  for (std::size_t f = 0; f < n; ++f)
    for (std::size_t k = 0; k < 3; ++k) edges[key(m.triangles[f][k], m.triangles[f][(k + 1) % 3])].push_back({static_cast<int>(f), static_cast<int>(k)});
  for (const auto& e : edges) {
    const auto& users = e.second;
    if (users.size() != 2) continue;  // open or non-manifold: no neighbour
    t.neighbour[static_cast<std::size_t>(users[0].first)][static_cast<std::size_t>(users[0].second)] = users[1].first;
    t.neighbour[static_cast<std::size_t>(users[1].first)][static_cast<std::size_t>(users[1].second)] = users[0].first;
  }
  std::vector<std::vector<int>> around(m.vertices.size());
  for (const auto& tri : m.triangles)
    for (std::size_t k = 0; k < 3; ++k)
      for (std::size_t j = 1; j < 3; ++j) around[static_cast<std::size_t>(tri[k])].push_back(tri[(k + j) % 3]);
  t.adjacency_start.push_back(0);
  for (auto& a : around) {
    std::sort(a.begin(), a.end());
    a.erase(std::unique(a.begin(), a.end()), a.end());
    t.adjacency.insert(t.adjacency.end(), a.begin(), a.end());
    t.adjacency_start.push_back(static_cast<int>(t.adjacency.size()));
  }
  return t;
}

// Each triangle's unit normal, formed in double from the mesh's double vertices (kernels read it
// rounded once: a flat mesh in an axis plane has exactly the axis as its normal, as a planar
// polygon has; forming it per contact in float or from rounded vertices differed in the last bits).
inline std::vector<Vec3<double>> triangle_normals(const TriangleMesh& m) {
  std::vector<Vec3<double>> n(m.size());
  for (std::size_t t = 0; t < m.size(); ++t) {
    const Vec3<double> a = m.area_vector(t);
    const double l = std::sqrt(norm2(a));  // divided, not multiplied by 1 / l: an axis normal comes out exact
    n[t] = {a.x / l, a.y / l, a.z / l};
  }
  return n;
}

// Flat patches: the triangles joined across manifold edges into one plane (normals within 1e-9
// rad of the first one's, corners within 1e-9 of the mesh's extent of its plane). A triangle is
// flat-interior when the whole fan of each of its corners lies in its patch and closes once around
// the corner (every edge at it manifold, the fan's angles summing to 2 pi within 1e-9, none over
// 170 degrees): around such a triangle the surface is the patch's plane, tiled without overlap,
// and of the regions above only its face offers contacts, to spheres over it (a triangle list
// drops a sphere's far triangles of a flat patch with this: mesh_wall.hpp, drop_flat_neighbours).
// A flat patch is assumed not to overlap itself away from its corners (a sheet folded flat onto
// itself, which no repair here detects).
// Each triangle's plane patch (numbered from 0).
inline std::vector<int> plane_patches(const TriangleMesh& m, const MeshTopology& topo) {
  const std::size_t n = m.size();
  const std::vector<Vec3<double>> normal = triangle_normals(m);
  const double size = std::fmax(m.extent(), 1e-300);
  std::vector<int> patch(n, -1);
  int patches = 0;
  std::vector<int> queue;
  for (std::size_t seed = 0; seed < n; ++seed) {
    if (patch[seed] >= 0) continue;
    const Vec3<double> ns = normal[seed], ps = m.corner(seed, 0);
    const auto in_plane = [&](std::size_t t) {
      if (norm(normal[t] - ns) > 1e-9) return false;
      for (int k = 0; k < 3; ++k)
        if (std::fabs(dot(m.corner(t, k) - ps, ns)) > 1e-9 * size) return false;
      return true;
    };
    patch[seed] = patches;
    queue.assign(1, static_cast<int>(seed));
    while (!queue.empty()) {
      const int t = queue.back();
      queue.pop_back();
      for (int o : topo.neighbour[static_cast<std::size_t>(t)])
        if (o >= 0 && patch[static_cast<std::size_t>(o)] < 0 && in_plane(static_cast<std::size_t>(o)))
          patch[static_cast<std::size_t>(o)] = patches, queue.push_back(o);
    }
    ++patches;
  }
  return patch;
}

// Per vertex: 1 when its fan lies in one patch, closes (both edges of each of its triangles at it
// manifold) with no angle over 170 degrees, and its angles make one turn (2 pi within 1e-9).
inline std::vector<char> flat_corners(const TriangleMesh& m, const MeshTopology& topo, const std::vector<int>& patch) {
  const double pi = 3.14159265358979323846;
  const std::size_t nv = m.vertices.size();
  std::vector<int> fan_patch(nv, -2);  // -2: no triangle yet; -1: not flat
  std::vector<double> angle_sum(nv, 0);
  for (std::size_t t = 0; t < m.size(); ++t)
    for (int c = 0; c < 3; ++c) {
      const auto v = static_cast<std::size_t>(m.triangles[t][static_cast<std::size_t>(c)]);
      const Vec3<double> a = m.corner(t, (c + 1) % 3) - m.corner(t, c), b = m.corner(t, (c + 2) % 3) - m.corner(t, c);
      const double angle = std::atan2(norm(cross(a, b)), dot(a, b));
      // the fan's two edges at v: edge c (v to the next corner) and edge c + 2 (the previous to v)
      const bool closed = topo.neighbour[t][static_cast<std::size_t>(c)] >= 0 && topo.neighbour[t][static_cast<std::size_t>((c + 2) % 3)] >= 0;
      if (fan_patch[v] == -2) fan_patch[v] = patch[t];
      if (fan_patch[v] != patch[t] || !closed || angle > 170.0 / 180.0 * pi) fan_patch[v] = -1;
      angle_sum[v] += angle;
    }
  std::vector<char> flat(nv);
  for (std::size_t v = 0; v < nv; ++v) flat[v] = fan_patch[v] >= 0 && std::fabs(angle_sum[v] - 2 * pi) <= 1e-9 * 2 * pi;
  return flat;
}

// Per triangle: its patch when flat-interior, else -1 - its patch.
inline std::vector<int> flat_patches(const TriangleMesh& m, const MeshTopology& topo) {
  const std::vector<int> patch = plane_patches(m, topo);
  const std::vector<char> corner = flat_corners(m, topo, patch);
  std::vector<int> code(m.size());
  for (std::size_t t = 0; t < m.size(); ++t) {
    bool flat = true;
    for (int c = 0; c < 3; ++c) flat = flat && corner[static_cast<std::size_t>(m.triangles[t][static_cast<std::size_t>(c)])];
    code[t] = flat ? patch[t] : -1 - patch[t];
  }
  return code;
}

// What the contact kernels read (device-copyable pointers; the arrays are kept elsewhere;
// std::array<int, 3> is stored as three ints, so its vectors' data() serve as the int arrays).
template <class Real>
struct MeshSurfaceView {
  const Vec3<Real>* vertex;  // m, current positions
  const int* triangle;       // 3 vertex indices per triangle (TriangleMesh::triangles' storage)
  const int* neighbour;      // 3 per triangle (MeshTopology::neighbour's storage)
  const int* adjacency_start;
  const int* adjacency;
  const Vec3<Real>* normal;  // per triangle, unit (triangle_normals)
  // Per triangle its three vertices, vertex[triangle[3 t + k]] copied (null: read through
  // `triangle`): the contact reads them in one step instead of two dependent ones.
  const Vec3<Real>* corner = nullptr;
  // Per triangle its flat patch (flat_patches; null: none known, nothing dropped).
  const int* patch = nullptr;
  BLAZE_HD Vec3<Real> corner_of(int t, int k) const { return corner ? corner[3 * t + k] : vertex[triangle[3 * t + k]]; }
};

namespace mesh_detail {
// (x - a) . (n x (b - a)): >= 0 when x projects onto the inner side of edge a -> b of a
// counter-clockwise triangle with unit normal n (m^2).
template <class Real>
BLAZE_HD Real edge_side(const Vec3<Real>& x, const Vec3<Real>& a, const Vec3<Real>& b, const Vec3<Real>& n) {
  return dot(x - a, cross(n, b - a));
}
}  // namespace mesh_detail

// The contact triangle t offers sphere (x, r) (above); none when p is not its to offer.
// early_out: a triangle whose edge line alone keeps x's projection farther than the sphere reaches
// is left before the boundary's nearest point is formed (most of a triangle list: the triangles
// within r + skin of a ball resting on a finely meshed wall; issue 20's 1e5-triangle world
// phase). With x's projection outside edge k (s_k < 0), the in-plane distance to T is at least
// -s_k / |e_k|, so |x - p|^2 >= d^2 + s_k^2 / |e_k|^2; the test asks that bound, with s_k less its
// rounding margin, to pass r^2 by 1e-3, so the full test's best2 >= r^2 too and the result is
// the same (test_mesh_surface.cpp compares the two over random spheres and triangles).
template <class Real, bool early_out = true>
BLAZE_HD ContactGeometry<Real> collide_sphere_mesh_triangle(const Vec3<Real>& x, Real r, const MeshSurfaceView<Real>& m, int t) {
  using mesh_detail::edge_side;
  const int* tri = m.triangle + 3 * t;
  const Vec3<Real> v[3] = {m.corner_of(t, 0), m.corner_of(t, 1), m.corner_of(t, 2)};
  const Vec3<Real> n = m.normal[t];
  const Real d = dot(x - v[0], n);
  if (!(d < r && d > -r)) return ContactGeometry<Real>::none();
  // The rounding margin of the region tests (m^2): 64 ulps of the terms' size.
  const Real reach = sqrt_r(norm2(x - v[0])) + sqrt_r(max_r(norm2(v[1] - v[0]), norm2(v[2] - v[0])));
  const Real margin = Real(64) * epsilon_r<Real>() * reach * reach;
  Real s[3];
  for (int k = 0; k < 3; ++k) s[k] = edge_side(x, v[k], v[k + 1 < 3 ? k + 1 : 0], n);
  if (s[0] >= -margin && s[1] >= -margin && s[2] >= -margin) {  // face
    if (!(d > Real(0))) return ContactGeometry<Real>::none();
    const Real delta = r - d;
    return {true, -n, delta, x - n * (r - Real(0.5) * delta), r};
  }
  if (early_out) {
    const Real room = r * r * Real(1.001) - d * d;  // > 0: |d| < r
    for (int k = 0; k < 3; ++k) {
      const Real out = -s[k] - margin;
      if (out > Real(0) && out * out > room * norm2(v[k + 1 < 3 ? k + 1 : 0] - v[k])) return ContactGeometry<Real>::none();
    }
  }
  // The nearest point on the boundary: inside an edge, or a vertex.
  Real best2 = Real(-1);
  int edge = -1, corner = -1;
  Vec3<Real> p{0, 0, 0};
  for (int k = 0; k < 3; ++k) {
    const Vec3<Real> a = v[k], b = v[k + 1 < 3 ? k + 1 : 0], e = b - a;
    const Real u = clamp_r(dot(x - a, e) / norm2(e), Real(0), Real(1));
    const Vec3<Real> q = a + e * u;
    const Real dist2 = norm2(x - q);
    if (best2 < Real(0) || dist2 < best2) {
      best2 = dist2, p = q;
      edge = u > Real(0) && u < Real(1) ? k : -1;
      corner = u <= Real(0) ? k : u >= Real(1) ? (k + 1 < 3 ? k + 1 : 0) : -1;
    }
  }
  if (!(best2 < r * r) || best2 == Real(0)) return ContactGeometry<Real>::none();
  if (edge >= 0) {
    // x over the other face of the edge: that face offers the contact.
    const int o = m.neighbour[3 * t + edge];
    if (o >= 0) {
      const Vec3<Real> no = m.normal[o];
      const Vec3<Real> a = v[edge + 1 < 3 ? edge + 1 : 0], b = v[edge];  // the neighbour runs it b <- a
      if (edge_side(x, a, b, no) > margin) return ContactGeometry<Real>::none();
    }
  } else {
    const int vi = tri[corner];
    for (int k = m.adjacency_start[vi]; k < m.adjacency_start[vi + 1]; ++k)
      if (dot(x - v[corner], m.vertex[m.adjacency[k]] - v[corner]) > margin) return ContactGeometry<Real>::none();
  }
  const Real dist = sqrt_r(best2);
  const Vec3<Real> nrm = (p - x) * (Real(1) / dist);
  const Real delta = r - dist;
  return {true, nrm, delta, x + nrm * (r - Real(0.5) * delta), r};
}

// The offers one particle receives from the triangles of a mesh, merged: an offer at the same
// point with the same normal as one kept (1e-9 of the radius, 1e-9 rad; float: 1e-4) is the same
// contact, and the deeper of the two is kept. Holds up to K contacts; more are counted in
// `dropped` (the deepest K kept). Geometry: ContactGeometry, or a polyhedron's patch geometry.
template <class Real, int K = 8, class Geometry = ContactGeometry<Real>>
struct MeshContacts {
  Geometry contact[K];
  int owner[K];  // the triangle that offered the kept one
  int count = 0;
  int dropped = 0;

  BLAZE_HD void add(const Geometry& g, int triangle, Real r) {
    if (!g.touching) return;
    const Real same = (sizeof(Real) == 4 ? Real(1e-4) : Real(1e-9));
    for (int k = 0; k < count; ++k) {
      if (norm2(contact[k].normal - g.normal) <= same * same && norm2(contact[k].point - g.point) <= same * same * r * r) {
        if (g.overlap > contact[k].overlap) contact[k] = g, owner[k] = triangle;
        return;
      }
    }
    if (count < K) {
      contact[count] = g, owner[count] = triangle, ++count;
      return;
    }
    ++dropped;
    int shallowest = 0;
    for (int k = 1; k < K; ++k)
      if (contact[k].overlap < contact[shallowest].overlap) shallowest = k;
    if (g.overlap > contact[shallowest].overlap) contact[shallowest] = g, owner[shallowest] = triangle;
  }
};

}  // namespace blaze
