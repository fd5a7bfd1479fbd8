// Convex polyhedron shape policy (thesis chapter 3) for the same kernels the spheres use.
//
// Polyhedron-polyhedron detection: the separating-axis theorem, exact for convex bodies. The
// candidate axes are the face normals of A and of B and the cross products of edge pairs that
// form a face of the Minkowski difference A - B (their Gauss-map arcs cross; the other edge pairs
// can never separate the bodies). Separation along an axis n (oriented from A to B):
//   face f of A:   min_{v in B} n.v - h_f            face g of B: min_{v in A} n_g.v - h_g (n = -n_g)
//   edge pair:     n.(b0 - a0),  n = (e_A x e_B)/|e_A x e_B|, pointing away from A's centre
// Any positive separation: no contact (thesis Theorem 1, the separating plane). Otherwise the
// contact normal is the axis of least penetration and the overlap is that penetration (the
// minimum translation that separates them), so the normal is continuous while bodies separate.
// Ties go to faces (checked first). No preference margin in the axis: the overlap is then a
// continuous function of the configuration, and k delta^2 / 2 a potential (see incident_point).
// But the contact point prefers faces (issue 17.10): where an edge-pair axis beats the best face
// axis by less than kFacePreference = 0.1% of the face's penetration, the normal and overlap are
// the edge pair's while the point and patch are the face's (incident_point). Two faces resting
// on each other make the axes of their edge pairs nearly the face normal, and a tilt within the
// 1% band turned the face contact into an edge-edge point contact and back every few steps: the
// patch (below) came and went, and a cube on a cube kept rocking at ~0.2 rad/s. Rigid-body codes
// prefer face contacts the same way (Gregorius, "Robust contact creation for physics
// simulations", GDC 2015; Box2D's b2CollidePolygons, a tolerance for the reference face); they
// do it in the axis, which makes the overlap jump by up to the margin (a 1% margin there failed
// the polyhedron_contact brute-force SAT check). Moving only the point moves the lever arm where
// the margin applies, which is not conservative: with a 1% margin elastic cube-cube impacts at
// random orientations changed their energy by up to 0.96% (28 of 5000 gained > 0.5%); with 0.1%
// the worst is 0.27% (test_polyhedron_dynamics), and the rocking still dies out
// (test_polyhedron_rest: as the tilt decays the edge axes fall inside the margin). The contact's
// kind (statistics) stays the axis's.
// Contact point: for a face axis, the deepest vertex of the incident body (the lever arm that
// keeps the force conservative: the overlap is its penetration), spread over the vertices within
// 1% of that depth so flat face-face contacts push through their centre (incident_point). For an
// edge axis, the midpoint of the closest points of the two edges (thesis eqs. 3.4-3.5, clamped).
// The thesis's Type 1 point is the mean of all contained vertices; it is kept with ThesisNormal.
//
// Contact patch (issue 17.10, contact_patch.hpp): the vertices of that 1% band are also the
// contact's patch, with the same weights w_k (their depth into the band, normalised): when two
// or more vertices share the deepest depth (a face or an edge lying on a face or a wall), the
// law is evaluated at each of them with its own relative velocity and the share w_k,
//   F_k = w_k law(delta, v_rel(p_k)),  F = sum_k F_k,  T_i = (p - x_i) x F + sum_k (p_k - p) x F_k,
// with one overlap delta (the deepest vertex's) for all: the elastic force and its torque are
// the one-point contact's, so are the static closed forms, while friction now acts at the
// vertices (torsional friction about the normal, Johnson 1985 chapter 7) and the normal
// dashpot damps rocking. A vertex-face contact (one vertex in the band), edge-edge contacts and
// contacts with spheres stay points and cost what they did. The patch's points are the incident
// body's vertices: a face larger than the reference face it lies on is not clipped to it, so a
// body overhanging the edge of another's face gets a patch that reaches beyond the contact.
//
// The thesis picks the normal differently (sections 2.2.4, 3.2.3): the face of the other body
// nearest to the deepest contained vertex ("the largest penetration distance"), or for edge-edge
// contact the average of the COM-to-contact vectors (read literally, (PC - x_A) and (PC - x_B)
// average to nearly zero; we take (PC - x_A) + (x_B - PC), i.e. the centre line). Its Fig 5.2
// shows that choice flipping while bodies separate. It is kept as the named option ThesisNormal.
//
// Polyhedron-sphere (a table type with no features is a sphere): the sphere's centre against the
// faces (foot points inside the body) and edges of the polyhedron: the nearest surface point p
// gives normal (c - p)/|c - p| and overlap r - |c - p|; a centre inside the body uses the face of
// largest separation. Sphere-sphere as in sphere.hpp.
//
// Polyhedron-world (Algorithm 2): the centre must be on the wall's side and within bound_R of
// the plane (lines 1-2); penetrating vertices whose foot lies inside the polygon are the contact
// (unless they came round an active rim edge: then that edge inside the body is, as the
// thesis's spheres have no rim contact and its polyhedra none either; collide_world; an edge
// under a face lying flat on the wall is part of the wall's patch instead: kFlushFace);
// overlap = the deepest; point = the deepest vertex, spread over those within 1% of its depth
// (the thesis's mean of the penetrating vertices gains energy with the deepest overlap; see
// penetrating_vertices), and those vertices are the patch as above. Cylinder (drum): vertices
// beyond the radius, the same way (the normal is the one through the weighted point).
//
// Rotation: principal moments in the body frame, I_world = R diag(I) R^T. Kick: w += I_world^-1 T h.
// Drift at constant L = I_world w: midpoint rule q' = exp(w(q_half) dt) q, w' = I_world(q')^-1 L,
// so |L| is conserved exactly in torque-free motion and the energy to second order.
#pragma once
#include "blaze/contact/contact_geometry.hpp"
#include "blaze/contact/contact_patch.hpp"
#include "blaze/shapes/sphere_shape.hpp"
#include "blaze/core/mat3.hpp"
#include "blaze/particles/particle_store.hpp"
#include "blaze/shapes/polyhedron_table.hpp"
#include "blaze/world/world.hpp"

namespace blaze {

struct SeparatingAxisNormal {
  static constexpr const char* name = "separating-axis";
};
struct ThesisNormal {
  static constexpr const char* name = "thesis";
};

namespace polyhedron_detail {

// Which edge pairs are faces of the Minkowski difference A - B? Edge ea of A (normals a, b beside
// it) and edge eb of B (negated normals c, d beside it) qualify when their Gauss-map arcs cross:
//   (c.(b x a)) (d.(b x a)) < 0,  (a.(d x c)) (b.(d x c)) < 0,  (c.(b x a)) (b.(d x c)) > 0.
// Only signs matter, and each depends on one edge and one face. With s_L, s_R = n_B.(b x a) for
// the faces left and right of eb (c.(b x a) = -s_L) and arc_B = d x c = n_R x n_L (a table
// constant, PolyhedronData::edge_arc), the test reads
//   opposite(s_L, s_R) and opposite(a.arc_B, b.arc_B) and opposite(s_L, b.arc_B).
// It is taken for all of B's edges at once, as 64-bit sets (issue 6):
//   for each face g of A: the edges eb with n_A[g].arc_B[eb] > 0 (pos[g]) or < 0 (neg[g]);
//   for edge ea: the signs s_f = n_B[f].(b x a) for each face f of B, turned into edge sets
//     through the table's edges_left_of / edges_right_of;
// then the candidates of ea are one AND-OR expression: F_A E_B + E_A F_B dot products instead of
// 4 E_A E_B. Measured on the H200 at 1e6 bodies against testing the pairs one by one: packed
// dodecahedra 12.2 ms per step for the contacts instead of 17.8 (the first version, which held
// B's vertices per thread); with the table read in B's axes, falling cubes 2.27 ms instead of
// 2.71, packed cubes 25.7 instead of 28.2, octahedra level (bench/results/levers/).
// verification/test_polyhedron_contact.cpp checks the sets against the pairwise test.
struct ArcSets {
  std::uint64_t pos[kMaxFaces], neg[kMaxFaces];  // over B's edges, per face of A
};
// The sets of every face of A; r turns A's body frame into B's axes.
template <class Real>
BLAZE_HD inline void arc_sets(const PolyhedronData<Real>& A, const PolyhedronData<Real>& B, const Mat3<Real>& r,
                              ArcSets& sets) {
  for (int g = 0; g < A.face_count; ++g) {
    const Vec3<Real> m = r * A.normal[g];
    std::uint64_t pos = 0, neg = 0;
    for (int eb = 0; eb < B.edge_count; ++eb) {
      const Real s = dot(m, B.edge_arc[eb]);
      if (s > Real(0)) pos |= std::uint64_t(1) << eb;
      if (s < Real(0)) neg |= std::uint64_t(1) << eb;
    }
    sets.pos[g] = pos, sets.neg[g] = neg;
  }
}
// B's edges whose arcs cross that of A's edge ea (faces fa0 = a, fa1 = b; axis = b x a, in B's axes).
template <class Real>
BLAZE_HD inline std::uint64_t crossing_edges(const PolyhedronData<Real>& B, const Vec3<Real>& axis, const ArcSets& sets,
                                            int fa0, int fa1) {
  std::uint64_t left_pos = 0, left_neg = 0, right_pos = 0, right_neg = 0;
  for (int f = 0; f < B.face_count; ++f) {
    const Real s = dot(B.normal[f], axis);
    if (s > Real(0)) left_pos |= B.edges_left_of[f], right_pos |= B.edges_right_of[f];
    if (s < Real(0)) left_neg |= B.edges_left_of[f], right_neg |= B.edges_right_of[f];
  }
  const std::uint64_t opposite_b = (left_pos & right_neg) | (left_neg & right_pos);
  const std::uint64_t opposite_a = (sets.pos[fa0] & sets.neg[fa1]) | (sets.neg[fa0] & sets.pos[fa1]);
  const std::uint64_t left_against_b = (left_pos & sets.neg[fa1]) | (left_neg & sets.pos[fa1]);
  return opposite_b & opposite_a & left_against_b;
}
// Edge ea's axis b x a in B's axes.
template <class Real>
BLAZE_HD inline Vec3<Real> edge_axis_of(const PolyhedronData<Real>& A, const Mat3<Real>& r, int ea) {
  return cross(r * A.normal[A.edge_face[ea][1]], r * A.normal[A.edge_face[ea][0]]);
}

// Midpoint of the closest points of segments p0 + s u and q0 + t w, s, t in [0, 1].
template <class Real>
BLAZE_HD inline Vec3<Real> segment_midpoint(const Vec3<Real>& p0, const Vec3<Real>& u, const Vec3<Real>& q0,
                                           const Vec3<Real>& w) {
  const Vec3<Real> r = p0 - q0;
  const Real a = dot(u, u), b = dot(u, w), c = dot(w, w), d = dot(u, r), e = dot(w, r);
  const Real den = a * c - b * b;
  Real s = den > Real(0) ? clamp_r((b * e - c * d) / den, Real(0), Real(1)) : Real(0);
  Real t = clamp_r((b * s + e) / c, Real(0), Real(1));
  s = clamp_r((b * t - d) / a, Real(0), Real(1));
  return Real(0.5) * ((p0 + s * u) + (q0 + t * w));
}

}  // namespace polyhedron_detail

template <class Real, class NormalChoice = SeparatingAxisNormal>
struct PolyhedronShape {
  static constexpr const char* name = "polyhedron";
  // An edge-pair axis that separates by at most this share of the best face axis's penetration
  // more than that face keeps the face's contact point and patch (header comment).
  static constexpr double kFacePreference = 1e-3;
  // A wall's rim edge under a face of the body that lies within 1 degree of flat on one of the
  // edge's planes is no contact of its own: its ends join that plane's patch (collide_world for a
  // planar wall, collide_mesh): cos(1 degree).
  static constexpr double kFlushFace = 0.99984769515639127;
  static constexpr int kFlushPoints = 4;  // such edges' ends one plane's patch takes (two edges)
  // The most particles a step takes in one block on the GPU (phases.hpp's one-block path: 256
  // threads on one SM): one a thread. A polyhedron's contacts are a long serial chain (SAT over
  // faces and edge pairs): a thread taking ten of them made a step of 2 679 corn kernels cost 6 ms
  // on an H100 (make fig-2.17's pour), where the whole GPU takes them at once.
  static constexpr int kOneBlockParticles = 256;
  // Contact kernels: at least this many blocks of 256 per SM (launch.hpp): 4 caps them at 64
  // registers. BLAZE_POLYHEDRON_MIN_BLOCKS sets it for lever measurements (bench/results/levers/).
#ifdef BLAZE_POLYHEDRON_MIN_BLOCKS
  static constexpr int kMinBlocks = BLAZE_POLYHEDRON_MIN_BLOCKS;
#else
  static constexpr int kMinBlocks = 4;
#endif
  // The shape table. The host reads `table`; kernels read `resident`, a copy of it in the
  // space's memory that the Simulation makes (using Resident below), through L1. Read from
  // the kernel arguments instead (CUDA's constant bank), every table read whose index is a
  // register (the type, a loop's feature, the lane's chosen edge) is an indexed constant load,
  // served by the SM's address-divergence unit: Nsight Compute found that unit 91% busy in the
  // packed-cube pair kernel (87% for dodecahedra) while the FP32 pipe stood at 18%
  // (bench/results/ncu/, issue 6). BLAZE_POLYHEDRON_TABLE_IN_CONSTANT restores the constant-bank
  // reads for lever measurements (bench/results/levers/).
  using Resident = PolyhedronTable<Real>;
  PolyhedronTable<Real> table;
  const PolyhedronTable<Real>* resident = nullptr;

  BLAZE_HD const PolyhedronData<Real>& data(int type) const {
#if defined(__CUDA_ARCH__) && !defined(BLAZE_POLYHEDRON_TABLE_IN_CONSTANT)
    return resident->type[type];
#else
    return table.type[type];
#endif
  }

  // A body is its type's shape scaled by `scale` about its centre (a feed's size distribution,
  // scene.hpp's FeedSpec): the particle's radius over the type's bounding radius, exactly 1 for a
  // particle of the type's own size (the products with it are then exact: an unscaled scene
  // computes bit for bit what it did before scales existed). Lengths scale by s, mass by s^3 and
  // the principal moments by s^5 (same density); normals, edges' Gauss-map arcs and the feature
  // topology do not change, so the table holds one entry per shape, not per size.
  struct Body {
    Vec3<Real> x;
    Quat<Real> q;
    int type;
    Index index;
    Real scale = 1;
  };

  BLAZE_HD Real scale_of(const ParticleView<Real>& p, Index i) const { return p.radius[i] / data(p.type[i]).bounding_radius; }
  BLAZE_HD Body body(const ParticleView<Real>& p, Index i) const {
    return {p.position.get(i), p.orientation.get(i), p.type[i], i, scale_of(p, i)};
  }
  // The body's bounding radius (m).
  BLAZE_HD Real radius_of(const Body& b) const { return data(b.type).bounding_radius * b.scale; }

  BLAZE_HD bool is_sphere(const Body& b) const { return data(b.type).vertex_count == 0; }

  // A polyhedron face, edge-face or face-wall contact comes with its patch (contact_patch.hpp);
  // contacts with spheres, edge-edge and vertex-face contacts are points (patch.count <= 1).
  using Geometry = PatchGeometry<Real>;

  BLAZE_HD Geometry collide(const Body& a, const Body& b) const {
    if (is_sphere(a) || is_sphere(b)) {
      if (is_sphere(a) && is_sphere(b))
        return Geometry::of(SphereShape{}.collide(SphereShape::Body<Real>{a.x, radius_of(a), a.index},
                                                  SphereShape::Body<Real>{b.x, radius_of(b), b.index}));
      if (is_sphere(b)) return Geometry::of(polyhedron_sphere(a, b.x, radius_of(b)));
      ContactGeometry<Real> g = polyhedron_sphere(b, a.x, radius_of(a));
      g.normal = -g.normal;
      return Geometry::of(g);
    }
    return polyhedron_polyhedron(a, b);
  }

  // Normal from the polyhedron towards the sphere of centre c, radius r_world. The test runs in
  // A's body frame at A's table size (lengths over a.scale: the sphere's centre and radius), and
  // its lengths are scaled back at the end.
  BLAZE_HD ContactGeometry<Real> polyhedron_sphere(const Body& a, const Vec3<Real>& c, Real r_world) const {
    using namespace polyhedron_detail;
    const PolyhedronData<Real>& A = data(a.type);
    const Vec3<Real> d = c - a.x;
    if (!(norm2(d) < (radius_of(a) + r_world) * (radius_of(a) + r_world))) return ContactGeometry<Real>::none();
    const Real unscale = Real(1) / a.scale;
    const Real r = r_world * unscale, reach = A.bounding_radius + r;
    const Mat3<Real> ra = Mat3<Real>::rotation(a.q);
    const Vec3<Real> cl = ra.transpose_times(d) * unscale;
    const Real tol = Real(1e-9) * reach;
    int f_max = 0;
    Real s_max = dot(A.normal[0], cl) - A.offset[0];
    for (int f = 1; f < A.face_count; ++f) {
      const Real s = dot(A.normal[f], cl) - A.offset[f];
      if (s > s_max) s_max = s, f_max = f;
    }
    Vec3<Real> n;
    Real gap;  // signed distance from the surface to the centre
    if (s_max <= Real(0)) {
      n = A.normal[f_max];
      gap = s_max;
    } else {
      if (s_max >= r) return ContactGeometry<Real>::none();
      Real best = reach;
      Vec3<Real> nearest{0, 0, 0};
      for (int f = 0; f < A.face_count; ++f) {
        const Real s = dot(A.normal[f], cl) - A.offset[f];
        if (!(s > Real(0)) || s >= best) continue;
        const Vec3<Real> foot = cl - s * A.normal[f];
        bool inside = true;
        for (int g = 0; g < A.face_count && inside; ++g) inside = dot(A.normal[g], foot) - A.offset[g] <= tol;
        if (inside) best = s, nearest = foot;
      }
      for (int e = 0; e < A.edge_count; ++e) {
        const Vec3<Real> p0 = A.vertex[A.edge_vertex[e][0]], u = A.vertex[A.edge_vertex[e][1]] - p0;
        const Vec3<Real> q = p0 + clamp_r(dot(cl - p0, u) / norm2(u), Real(0), Real(1)) * u;
        const Real dist = norm(cl - q);
        if (dist < best) best = dist, nearest = q;
      }
      if (!(best < r) || best == Real(0)) return ContactGeometry<Real>::none();
      n = (cl - nearest) * (Real(1) / best);
      gap = best;
    }
    const Real overlap = (r - gap) * a.scale;
    const Vec3<Real> point = (cl - n * (Real(0.5) * (r + gap))) * a.scale;  // middle of the overlap
    return {true, ra * n, overlap, a.x + ra * point, r * A.bounding_radius / reach * a.scale, ContactKind::vertex_face};
  }

  // The test runs in A's centre with B's axes: B's vertices (+ u), normals and edge arcs are read
  // from the table as stored (uniform reads, one broadcast per warp), and A's features are turned
  // by r = R_B^T R_A one at a time. Only the edge sets (ArcSets) stay per thread: B's vertices and
  // planes, once held in per-thread arrays (896 B), lived in local memory and were most of the
  // kernel's DRAM traffic (issue 6, Nsight Compute: 13-15 GB per launch at 1e6 bodies, now 2-4).
  // Scales (Body): the table's vertices and offsets times sa or sb where they are read (a minimum
  // over a body's vertices once, after the minimum); directions need none.
  BLAZE_HD Geometry polyhedron_polyhedron(const Body& a, const Body& b) const {
    using namespace polyhedron_detail;
    const PolyhedronData<Real>& A = data(a.type);
    const PolyhedronData<Real>& B = data(b.type);
    const Real sa = a.scale, sb = b.scale;
    const Vec3<Real> d = b.x - a.x;
    const Real reach = A.bounding_radius * sa + B.bounding_radius * sb;
    if (!(norm2(d) < reach * reach)) return Geometry::none();
    const Mat3<Real> rb = Mat3<Real>::rotation(b.q);
    const Mat3<Real> r = rb.transpose_times(Mat3<Real>::rotation(a.q));  // A's body frame -> B's axes
    const Vec3<Real> u = rb.transpose_times(d);                          // B's centre
    const auto vertex_b = [&](int k) { return B.vertex[k] * sb + u; };
    const auto offset_b = [&](int f) { return B.offset[f] * sb + dot(B.normal[f], u); };
    // Face axes of A: min over B's vertices of (r n).(v + u) - h; then of B: min over A's
    // vertices of n.(r v) - h_B = (r^T n).v - h_B.
    Real best = -reach;
    int kind = -1, index = -1;  // kind 0: face of A, 1: face of B, 2: edge pair
    for (int f = 0; f < A.face_count; ++f) {
      const Vec3<Real> m = r * A.normal[f];
      Real s = dot(m, B.vertex[0]);
      for (int k = 1; k < B.vertex_count; ++k) s = min_r(s, dot(m, B.vertex[k]));
      s = s * sb + (dot(m, u) - A.offset[f] * sa);
      if (s > Real(0)) return Geometry::none();
      if (s > best) best = s, kind = 0, index = f;
    }
    for (int f = 0; f < B.face_count; ++f) {
      const Vec3<Real> m = r.transpose_times(B.normal[f]);
      Real s = dot(m, A.vertex[0]);
      for (int k = 1; k < A.vertex_count; ++k) s = min_r(s, dot(m, A.vertex[k]));
      s = s * sa - offset_b(f);
      if (s > Real(0)) return Geometry::none();
      if (s > best) best = s, kind = 1, index = f;
    }
    // Edge pairs that are faces of the Minkowski difference.
    Real edge_best = -reach;
    int edge_a = -1, edge_b = -1;
    Vec3<Real> edge_axis{0, 0, 0};
    // The separation along the axis of edges ea, eb (if they are not parallel); false: separated.
    const auto edge_axis_test = [&](int ea, int eb, const Vec3<Real>& a0, const Vec3<Real>& da) {
      const Vec3<Real> b0 = vertex_b(B.edge_vertex[eb][0]);
      // (B's edge direction at table size: only its direction counts, the parallel test is relative)
      const Vec3<Real> db = B.vertex[B.edge_vertex[eb][1]] - B.vertex[B.edge_vertex[eb][0]];
      Vec3<Real> n = cross(da, db);
      const Real len2 = norm2(n);
      if (!(len2 > Real(1e-12) * norm2(da) * norm2(db))) return true;  // parallel edges: a face axis covers them
      n *= Real(1) / sqrt_r(len2);
      if (dot(n, a0) < Real(0)) n = -n;
      const Real s = dot(n, b0 - a0);
      if (s > Real(0)) return false;
      if (s > edge_best) edge_best = s, edge_a = ea, edge_b = eb, edge_axis = n;
      return true;
    };
    // A's edge ea turned into B's axes: first vertex and direction.
    const auto edge_of_a = [&](int ea, Vec3<Real>& a0, Vec3<Real>& da) {
      a0 = (r * A.vertex[A.edge_vertex[ea][0]]) * sa;
      da = (r * (A.vertex[A.edge_vertex[ea][1]] - A.vertex[A.edge_vertex[ea][0]])) * sa;
    };
    ArcSets sets;
    arc_sets(A, B, r, sets);
    for (int ea = 0; ea < A.edge_count; ++ea) {
      Vec3<Real> a0, da;
      edge_of_a(ea, a0, da);
      for (std::uint64_t todo = crossing_edges(B, edge_axis_of(A, r, ea), sets, A.edge_face[ea][0], A.edge_face[ea][1]);
           todo != 0; todo &= todo - 1)
        if (!edge_axis_test(ea, lowest_bit(todo), a0, da)) return Geometry::none();
    }
    // An edge pair within kFacePreference of the best face axis: the face's point and patch
    // (header comment).
    const bool face_point = !(edge_best > best + Real(kFacePreference) * abs_r(best));
    const int face_kind = kind;
    if (edge_a >= 0 && edge_best > best) best = edge_best, kind = 2;

    const auto vertex_a = [&](int k) { return (r * A.vertex[k]) * sa; };
    Vec3<Real> n{0, 0, 0}, point{0, 0, 0};
    ContactPatch<Real> patch;
    Real overlap = -best;
    ContactKind contact_kind = ContactKind::vertex_face;
    if (kind == 2) {
      n = edge_axis;
      contact_kind = ContactKind::edge_edge;
    }
    if (kind == 2 && !face_point) {
      Vec3<Real> a0, da;
      edge_of_a(edge_a, a0, da);
      const Vec3<Real> b0 = vertex_b(B.edge_vertex[edge_b][0]);
      point = segment_midpoint(a0, da, b0, vertex_b(B.edge_vertex[edge_b][1]) - b0);
    } else if (face_kind == 0) {
      const Vec3<Real> m = r * A.normal[index];
      if (kind != 2) n = m;
      point = incident_point(m, A.offset[index] * sa, vertex_b, B.vertex_count, patch);
    } else {
      if (kind != 2) n = -B.normal[index];
      point = incident_point(B.normal[index], offset_b(index), vertex_a, A.vertex_count, patch);
    }
    if constexpr (std::is_same_v<NormalChoice, ThesisNormal>) {
      // Type 1: contained vertices of either body; the deepest one's nearest face gives the normal.
      const Real tol = Real(1e-6) * reach;
      int inside = 0;
      Real deepest = -1;
      Vec3<Real> sum{0, 0, 0}, thesis_normal{0, 0, 0};
      for (int side = 0; side < 2; ++side) {
        const int count = side == 0 ? B.vertex_count : A.vertex_count;
        for (int k = 0; k < count; ++k) {
          const Vec3<Real> v = side == 0 ? vertex_b(k) : vertex_a(k);
          Real nearest = reach;
          int face = -1;
          bool in = true;
          const int faces = side == 0 ? A.face_count : B.face_count;
          for (int g = 0; g < faces && in; ++g) {
            const Real pen = side == 0 ? A.offset[g] * sa - dot(r * A.normal[g], v) : offset_b(g) - dot(B.normal[g], v);
            in = pen >= -tol;
            if (pen < nearest) nearest = pen, face = g;
          }
          if (!in) continue;
          sum += v;
          ++inside;
          if (nearest > deepest) deepest = nearest, thesis_normal = side == 0 ? r * A.normal[face] : -B.normal[face];
        }
      }
      if (inside > 0) {
        n = thesis_normal;
        overlap = deepest;
        point = sum * (Real(1) / static_cast<Real>(inside));
        contact_kind = ContactKind::vertex_face;
        patch.count = 0;  // the thesis's contact is one point
      } else {
        n = point + (u - point);  // (PC - x_A) + (x_B - PC), x_A = 0 here
        n *= Real(1) / norm(n);
        contact_kind = ContactKind::edge_edge;
        patch.count = 0;
      }
    }
    const Real r_eff = (A.bounding_radius * sa) * (B.bounding_radius * sb) / reach;
    Geometry g;
    static_cast<ContactGeometry<Real>&>(g) = {true, rb * n, overlap, a.x + rb * point, r_eff, contact_kind};
    for (int k = 0; k < patch.count; ++k) patch.point[k] = a.x + rb * patch.point[k];
    g.patch = patch;
    return g;
  }

  BLAZE_HD Geometry collide_world(const Body& a, const PlanarPolygon<Real>& w) const {
    const PolyhedronData<Real>& A = data(a.type);
    const Real bound = radius_of(a);
    if (A.vertex_count == 0) return Geometry::of(collide_sphere(a.x, bound, w));
    const Real d_com = dot(a.x - w.centroid, w.normal);
    if (!(d_com > -bound && d_com < bound)) return Geometry::none();
    const Mat3<Real> ra = Mat3<Real>::rotation(a.q);
    // The active rim edges inside the body: the deepest is an edge-face contact (deeper than the
    // vertices' wins); one under a face flush on the plate (kFlushFace) is part of the plate's
    // contact instead, its ends inside the body points of the vertices' patch (as a mesh's rim
    // edges, collide_mesh: a face overhanging an orifice's lip rests on the lip too).
    Vec3<Real> extra_point[kFlushPoints];
    Real extra_depth[kFlushPoints];
    int extra = 0;
    Real rim_depth = 0;
    Vec3<Real> rim_normal{0, 0, 0}, rim_point{0, 0, 0};
    for (int k = 0; k < w.vertex_count && w.active_edges; ++k) {
      if (!((w.active_edges >> k) & 1u)) continue;
      const Vec3<Real> e0 = w.vertex[k], e1 = w.vertex[k + 1 < w.vertex_count ? k + 1 : 0];
      Real depth = 0;
      Vec3<Real> normal{0, 0, 0}, point{0, 0, 0};
      if (!rim_in_body(a, A, ra, e0, e1, depth, normal, point)) continue;
      if (d_com > Real(0) && dot(normal, w.normal) < -Real(kFlushFace)) flush_ends(a, A, ra, e0, e1, normal, extra_point, extra_depth, extra);
      else if (depth > rim_depth) rim_depth = depth, rim_normal = normal, rim_point = point;
    }
    Geometry g;
    Real deepest = 0;
    if (d_com > Real(0)) {
      Vec3<Real> point;
      // A vertex below the plane counts when its foot lies inside and it came through the plate,
      // not round one of its active rim edges: the line from the centre to it crosses the plane
      // inside, or outside only past inactive edges (a seam with a coplanar neighbour, which the
      // floor continues). Round an active edge the rim contact holds it, at the true depth
      // (the vertex's depth below the plane there is no overlap: a dodecahedron tipping into an
      // orifice read up to 65% of its radius).
      const auto below_inside = [&](const Vec3<Real>& v) {
        const Real dk = dot(v - w.centroid, w.normal);
        if (!(dk < Real(0)) || !w.contains(v - dk * w.normal)) return Real(0);
        const Vec3<Real> cross_at = a.x + (v - a.x) * (d_com / (d_com - dk));
        return past_active_edge(w, cross_at) ? Real(0) : -dk;
      };
      const int nv = A.vertex_count;
      const auto at = [&](int k) { return k < nv ? a.x + ra * (A.vertex[k] * a.scale) : extra_point[k - nv]; };
      const auto depth = [&](int k) { return k < nv ? below_inside(at(k)) : extra_depth[k - nv]; };
      if (patch_of_points(nv + extra, at, depth, point, deepest, g.patch))
        static_cast<ContactGeometry<Real>&>(g) = {true, -w.normal, deepest, point, bound, ContactKind::vertex_face};
    }
    if (rim_depth > deepest) {
      deepest = rim_depth;
      g = Geometry::of(ContactGeometry<Real>{true, rim_normal, rim_depth, rim_point, bound, ContactKind::edge_edge});
    }
    return deepest > Real(0) ? g : Geometry::none();
  }

  // The ends inside the body of a wall's edge e0 -> e1 under the body's face whose outward normal
  // is `normal` (world axes), with their depths below that face: points of a flush contact's patch,
  // appended to point[] and depth[] while count < kFlushPoints.
  BLAZE_HD static void flush_ends(const Body& a, const PolyhedronData<Real>& A, const Mat3<Real>& ra, const Vec3<Real>& e0,
                                  const Vec3<Real>& e1, const Vec3<Real>& normal, Vec3<Real>* point, Real* depth, int& count) {
    const Vec3<Real> p0 = ra.transpose_times(e0 - a.x), dl = ra.transpose_times(e1 - e0), nb = ra.transpose_times(normal);
    Real t0 = 0, t1 = 1;
    clip_to_body(a, A, p0, dl, t0, t1);
    int face = 0;  // the flush face: the one whose normal the contact took
    for (int f = 1; f < A.face_count; ++f)
      if (dot(A.normal[f], nb) > dot(A.normal[face], nb)) face = f;
    for (int j = 0; j < 2 && count < kFlushPoints; ++j) {
      const Real t = j == 0 ? t0 : t1;
      point[count] = e0 + (e1 - e0) * t;
      depth[count++] = A.offset[face] * a.scale - dot(A.normal[face], p0 + dl * t);
    }
  }

  // Is q (a point of w's plane) outside w past one of its active rim edges?
  BLAZE_HD static bool past_active_edge(const PlanarPolygon<Real>& w, const Vec3<Real>& q) {
    for (int k = 0; k < w.vertex_count; ++k) {
      const Vec3<Real> e0 = w.vertex[k];
      const Vec3<Real> e = w.vertex[k + 1 < w.vertex_count ? k + 1 : 0] - e0;
      if (((w.active_edges >> k) & 1u) && dot(cross(e, q - e0), w.normal) < Real(0)) return true;
    }
    return false;
  }
  // The part [t0, t1] of the segment p0 + t d (t in [0, 1], the body's frame from its centre)
  // inside the body: clipped by the face planes (Cyrus & Beck 1978). False: it misses the body.
  BLAZE_HD static bool clip_to_body(const Body& a, const PolyhedronData<Real>& A, const Vec3<Real>& p0, const Vec3<Real>& d, Real& t0,
                                    Real& t1) {
    t0 = 0, t1 = 1;
    for (int f = 0; f < A.face_count && t0 < t1; ++f) {  // inside face f: n.(p0 + t d) <= offset
      const Real num = A.offset[f] * a.scale - dot(A.normal[f], p0), den = dot(A.normal[f], d);
      if (den == Real(0)) {
        if (num < Real(0)) return false;
      } else if (den > Real(0)) {
        t1 = min_r(t1, num / den);
      } else {
        t0 = max_r(t0, num / den);
      }
    }
    return t0 < t1;
  }
  // A wall's edge e0 -> e1 against the body: its part inside (clipped by the face planes,
  // Cyrus & Beck 1978), and at that part's ends and middle the least depth below a face; the
  // deepest of the three gives the overlap, the point and the normal (that face's, outward: from
  // the body towards the wall; faces tied within rounding: their normals' sum). False when the
  // edge misses the body.
  BLAZE_HD static bool rim_in_body(const Body& a, const PolyhedronData<Real>& A, const Mat3<Real>& ra, const Vec3<Real>& e0,
                                   const Vec3<Real>& e1, Real& depth, Vec3<Real>& normal, Vec3<Real>& point) {
    {  // the edge beyond the bounding sphere: no clipping to do (most edges of a wall)
      const Vec3<Real> e = e1 - e0;
      const Real t = clamp_r(dot(a.x - e0, e) / norm2(e), Real(0), Real(1));
      const Real bound = A.bounding_radius * a.scale;
      if (!(norm2(a.x - (e0 + t * e)) < bound * bound)) return false;
    }
    const Vec3<Real> p0 = ra.transpose_times(e0 - a.x), d = ra.transpose_times(e1 - e0);
    Real t0 = 0, t1 = 1;
    if (!clip_to_body(a, A, p0, d, t0, t1)) return false;
    depth = 0;
    const Real tie = Real(sizeof(Real) == 4 ? 1e-5 : 1e-9) * A.bounding_radius * a.scale;
    for (const Real t : {t0, Real(0.5) * (t0 + t1), t1}) {
      const Vec3<Real> p = p0 + t * d;
      Real least = Real(0);
      int face = -1;
      for (int f = 0; f < A.face_count; ++f) {
        const Real df = A.offset[f] * a.scale - dot(A.normal[f], p);
        if (face < 0 || df < least) least = df, face = f;
      }
      if (!(face >= 0 && least > depth)) continue;
      // Faces within rounding of the least depth share the normal (their sum): the middle of a
      // chord through a slab (a corn kernel's two flat faces) is exactly as deep below both, and
      // picking one by rounding turned the normal by the angle between mirror-image faces.
      Vec3<Real> sum{0, 0, 0};
      for (int f = 0; f < A.face_count; ++f)
        if (A.offset[f] * a.scale - dot(A.normal[f], p) <= least + tie) sum += A.normal[f];
      depth = least, normal = ra * (sum * (Real(1) / norm(sum))), point = a.x + ra * p;
    }
    return depth > Real(0);
  }

  BLAZE_HD Geometry collide_world(const Body& a, const Cylinder<Real>& c) const {
    const PolyhedronData<Real>& A = data(a.type);
    const Real bound = radius_of(a);
    if (A.vertex_count == 0) return Geometry::of(collide_sphere(a.x, bound, c));
    const Vec3<Real> rel = a.x - c.origin;
    const Vec3<Real> rho = rel - dot(rel, c.axis) * c.axis;
    if (!(norm(rho) + bound > c.radius)) return Geometry::none();
    Vec3<Real> point;
    Real deepest;
    const auto beyond_radius = [&](const Vec3<Real>& v) {
      const Vec3<Real> vr = v - c.origin;
      const Real s = dot(vr, c.axis);
      return s >= Real(0) && s <= c.length ? norm(vr - s * c.axis) - c.radius : Real(0);
    };
    Geometry g;
    if (!penetrating_vertices(a, A, beyond_radius, point, deepest, g.patch)) return Geometry::none();
    const Vec3<Real> mr = point - c.origin;
    Vec3<Real> n = mr - dot(mr, c.axis) * c.axis;
    n *= Real(1) / norm(n);
    static_cast<ContactGeometry<Real>&>(g) = {true, n, deepest, point, bound, ContactKind::vertex_face};
    return g;
  }

  // Contacts with a triangle mesh (blaze/world/mesh_wall.hpp). A sphere type: its bounding
  // sphere's, merged per surface point. A polyhedron: as against a planar wall, with the mesh's
  // triangles grouped by plane, each plane a wall (a tessellated floor pushes as one polygon; a
  // valley gives two contacts):
  //   vertices  below the plane whose foot lies in one of its triangles, counted once however many
  //             hold it, and only if they came through the surface: the line from the centre
  //             crosses the plane in one of its triangles, or outside them only across edges that
  //             are not rims (a vertex that came round a rim edge is that edge's contact); the
  //             patch of the deepest and those within 1% of it;
  //   rim edges a triangle's open edges and its convex ones (the neighbour's far vertex below the
  //             plane: a ridge, an orifice's lip) inside the body (rim_in_body: clipped by the
  //             faces, its deepest point below one, that face's normal), each edge taken once (from
  //             the triangle whose plane the centre is in front of; both: the lower index; an open
  //             edge also from behind its plane: a lip met from below or beyond), each
  //             its own contact (edge-face: a ridge pushing into a face of the body), unless that
  //             face lies within 1 degree of flat on a plane of the edge (kFlushFace): then the
  //             edge is part of that plane's contact, its two ends inside the body points of the
  //             plane's patch at their depth below the face (a face overhanging a table's edge or
  //             a ridge rests on the edge too; left out, it sank round the edge until it turned
  //             past the 1 degree, 91 static overlaps deep on a 15-degree ridge).
  // Flat seams and valleys are not rims. A mesh's vertices pushing into a face of the body meet it
  // through the edges at them. In the mesh's frame (pose), turned back. (A planar wall keeps the
  // deeper of its vertex and rim contacts instead: one contact per polygon.)
  template <int K>
  BLAZE_HD void collide_mesh(const Body& a, const MeshSurfaceView<Real>& s, const MeshObject<Real>& m, const Pose<Real>* pose,
                             MeshContacts<Real, K, Geometry>& out, const TriangleList& near = {}) const {
    using mesh_detail::edge_side;
    const PolyhedronData<Real>& A = data(a.type);
    const Real bound = radius_of(a);
    if (A.vertex_count == 0) {
      MeshContacts<Real, K> points;
      collide_sphere_mesh(a.x, bound, s, m, pose, points, near);
      for (int k = 0; k < points.count; ++k) out.add(Geometry::of(points.contact[k]), points.owner[k], bound);
      return;
    }
    const Vec3<Real> xr = pose ? pose->to_reference(a.x) : a.x;
    const Mat3<Real> ra = pose ? pose->rotation.transpose_times(Mat3<Real>::rotation(a.q)) : Mat3<Real>::rotation(a.q);
    Body in_frame = a;
    in_frame.x = xr;
    Vec3<Real> placed[kMaxVertices];  // the vertices in the mesh's frame, once (not per triangle)
    for (int k = 0; k < A.vertex_count; ++k) placed[k] = xr + ra * (A.vertex[k] * a.scale);
    const auto vertex = [&](int k) { return placed[k]; };
    const TriangleRange tested = near_triangles(m, xr, near);
    struct Plane {
      Vec3<Real> n;
      Real offset;
      std::uint32_t below;    // vertices below the plane with their foot in one of its triangles
      std::uint32_t through;  // vertices below it whose line from the centre crosses it in one of them
      std::uint32_t rounded;  // ... crosses it outside one of them, across a rim edge
      int owner;              // the first such triangle
      int extra;              // rim edges' points under a face flush on it (kFlushFace), and their depths
      Vec3<Real> extra_point[kFlushPoints];
      Real extra_depth[kFlushPoints];
    } plane[K];
    struct Edge {
      ContactGeometry<Real> g;  // in the mesh's frame
      int t, o;                 // the triangle that took it and its neighbour across it (-1: open)
      bool flush;               // under a face flush on plane (n, offset): that plane's patch gets its ends
      Vec3<Real> n, end[2];
      Real offset, end_depth[2];
    } edge[K];
    int planes = 0, edges = 0;
    const Real angle = sizeof(Real) == 4 ? Real(1e-4) : Real(1e-9);
    // The plane (n, offset)'s group, made if new (owner t); -1: all K taken. (Through a pointer:
    // nvcc takes a lambda's reference to the array, not yet written, for a use before it is set.)
    Plane* const groups = plane;
    const auto group = [&](const Vec3<Real>& n, Real offset, Real reach, int t) {
      int q = 0;
      while (q < planes && !(norm2(groups[q].n - n) <= angle * angle && abs_r(groups[q].offset - offset) <= angle * reach)) ++q;
      if (q < planes) return q;
      if (planes == K) return -1;
      groups[planes] = {n, offset, 0u, 0u, 0u, t, 0, {}, {}};
      return planes++;
    };
    for (int e = 0; e < tested.count; ++e) {
      const int t = tested[e];
      if (!m.owns(t)) continue;
      const int* tri = s.triangle + 3 * t;
      const Vec3<Real> v[3] = {s.vertex[tri[0]], s.vertex[tri[1]], s.vertex[tri[2]]};
      const Vec3<Real> n = s.normal[t];
      const Real offset = dot(n, v[0]);
      const Real d_com = dot(xr, n) - offset;
      if (!(d_com > -bound && d_com < bound)) continue;
      // Beyond the bounding sphere no point of the body lies in it or over it: what a triangle
      // farther off would add is nothing, or the `rounded` mark of a vertex that came round one
      // of its rim edges far away (which made the result depend on the bins' cells); so the
      // triangle list's extra triangles and the cell's give the same contacts.
      if (!triangle_within(xr, v[0], v[1], v[2], bound)) continue;
      const bool in_front = d_com > Real(0);  // behind the plane: only its open edges (a lip met from below)
      const Real reach = sqrt_r(max_r(norm2(v[1] - v[0]), norm2(v[2] - v[0]))) + bound + sqrt_r(norm2(xr - v[0]));
      const Real margin = Real(64) * epsilon_r<Real>() * reach * reach;
      // Edge k (corner k -> k + 1) is a rim: open, or convex (the neighbour's far vertex below this plane).
      const auto rim = [&](int k) {
        const int o = s.neighbour[3 * t + k];
        if (o < 0) return true;
        const int* other = s.triangle + 3 * o;
        int far = other[0];
        for (int j = 1; j < 3; ++j)
          if (far == tri[k] || far == tri[k + 1 < 3 ? k + 1 : 0]) far = other[j];
        const Vec3<Real> w = s.vertex[far] - v[k];
        return dot(n, w) < -angle * sqrt_r(norm2(w));
      };
      std::uint32_t below = 0, through = 0, rounded = 0;
      int rims = -1;  // bit k: edge k is a rim (found when first needed)
      for (int k = 0; k < A.vertex_count && in_front; ++k) {
        const Vec3<Real> p = vertex(k);
        const Real dk = dot(n, p) - offset;
        if (!(dk < Real(0))) continue;
        bool inside = true;
        for (int j = 0; j < 3 && inside; ++j) inside = edge_side(p, v[j], v[j + 1 < 3 ? j + 1 : 0], n) >= -margin;
        if (inside) below |= 1u << k;
        // where the line from the centre crosses the plane
        const Vec3<Real> c = xr + (p - xr) * (d_com / (d_com - dk));
        bool in = true, round = false;
        for (int j = 0; j < 3; ++j) {
          if (edge_side(c, v[j], v[j + 1 < 3 ? j + 1 : 0], n) >= -margin) continue;
          in = false;
          if (rims < 0) rims = int(rim(0)) | int(rim(1)) << 1 | int(rim(2)) << 2;
          round = round || ((rims >> j) & 1);
        }
        if (in) through |= 1u << k;
        if (round) rounded |= 1u << k;
      }
      // the rim edges inside the body, each once, each a contact
      for (int k = 0; k < 3; ++k) {
        const Vec3<Real> e0 = v[k], e1 = v[k + 1 < 3 ? k + 1 : 0], ed = e1 - e0;
        {  // beyond the bounding sphere: most edges (rim_in_body tests it too, after more reads)
          const Real u = clamp_r(dot(xr - e0, ed) / norm2(ed), Real(0), Real(1));
          if (!(norm2(xr - (e0 + u * ed)) < bound * bound)) continue;
        }
        if (rims < 0) rims = int(rim(0)) | int(rim(1)) << 1 | int(rim(2)) << 2;
        if (!((rims >> k) & 1)) continue;
        const int o = s.neighbour[3 * t + k];
        if (o >= 0 && !in_front) continue;  // a convex edge is met from in front of one of its planes
        if (o >= 0 && o < t) {  // the neighbour takes it when the centre is in front of it too
          const Real d_o = dot(xr - s.vertex[s.triangle[3 * o]], s.normal[o]);
          if (d_o > Real(0) && d_o < bound) continue;
        }
        Real depth = 0;
        Vec3<Real> normal{0, 0, 0}, point{0, 0, 0};
        if (!rim_in_body(in_frame, A, ra, e0, e1, depth, normal, point)) continue;
        if (edges == K) {
          ++out.dropped;
          continue;
        }
        Edge& ed_k = edge[edges++];
        ed_k.g = {true, normal, depth, point, bound, ContactKind::edge_edge}, ed_k.t = t, ed_k.o = o, ed_k.flush = false;
        // Under a face flush on this plane or the neighbour's, the edge is part of that plane's
        // contact: its ends inside the body join the plane's patch, at their depth below that face
        // (the face overhangs the plane's triangles there: without them it would sink round the edge).
        const bool on_t = dot(normal, n) < -Real(kFlushFace), on_o = !on_t && o >= 0 && dot(normal, s.normal[o]) < -Real(kFlushFace);
        if (!on_t && !on_o) continue;
        ed_k.flush = true;
        ed_k.n = on_t ? n : s.normal[o];
        ed_k.offset = on_t ? offset : dot(s.normal[o], s.vertex[s.triangle[3 * o]]);
        int ends = 0;
        flush_ends(in_frame, A, ra, e0, e1, normal, ed_k.end, ed_k.end_depth, ends);
      }
      if (!below && !through && !rounded) continue;
      const int q = group(n, offset, reach, t);
      if (q < 0) {
        ++out.dropped;
        continue;
      }
      plane[q].below |= below, plane[q].through |= through, plane[q].rounded |= rounded;
    }
    // the flush edges' ends join their planes' patches
    for (int k = 0; k < edges; ++k) {
      if (!edge[k].flush) continue;
      const int q = group(edge[k].n, edge[k].offset, bound, edge[k].t);
      if (q < 0) {
        ++out.dropped;
        continue;
      }
      for (int j = 0; j < 2 && plane[q].extra < kFlushPoints; ++j)
        plane[q].extra_point[plane[q].extra] = edge[k].end[j], plane[q].extra_depth[plane[q].extra++] = edge[k].end_depth[j];
    }
    for (int q = 0; q < planes; ++q) {
      const Plane& pl = plane[q];
      const std::uint32_t counted = pl.below & (pl.through | ~pl.rounded);
      if (!counted && !pl.extra) continue;
      Geometry g;
      Vec3<Real> point;
      Real deepest;
      const int nv = A.vertex_count;
      const auto at = [&](int k) { return k < nv ? vertex(k) : pl.extra_point[k - nv]; };
      const auto depth = [&](int k) {
        if (k >= nv) return pl.extra_depth[k - nv];
        return (counted >> k) & 1u ? pl.offset - dot(pl.n, vertex(k)) : Real(0);
      };
      if (!patch_of_points(nv + pl.extra, at, depth, point, deepest, g.patch)) continue;
      Vec3<Real> n = -pl.n;
      if (pose) {
        n = pose->turn(n), point = pose->place(point);
        for (int k = 0; k < g.patch.count && k < ContactPatch<Real>::kMaxPoints; ++k) g.patch.point[k] = pose->place(g.patch.point[k]);
      }
      static_cast<ContactGeometry<Real>&>(g) = {true, n, deepest, point, bound, ContactKind::vertex_face};
      out.add(g, pl.owner, bound);
    }
    // The edges' contacts, keyed (the history's key: the owner triangle) by a triangle no contact
    // of the group holds: the one that took the edge, its neighbour across it, or one across
    // another edge of either (by the mesh alone: the same whichever triangles were tested).
    for (int k = 0; k < edges; ++k) {
      if (edge[k].flush) continue;
      const auto taken = [&](int u) {
        for (int j = 0; j < out.count; ++j)
          if (out.owner[j] == u) return true;
        return false;
      };
      const int t = edge[k].t, o = edge[k].o;
      int owner = t;
      if (taken(owner) && o >= 0) owner = o;
      for (int j = 0; j < 6 && taken(owner); ++j) {
        const int u = j < 3 ? s.neighbour[3 * t + j] : o >= 0 ? s.neighbour[3 * o + j - 3] : -1;
        if (u >= 0) owner = u;
      }
      ContactGeometry<Real> c = edge[k].g;
      if (pose) c.normal = pose->turn(c.normal), c.point = pose->place(c.point);
      out.add(Geometry::of(c), owner, bound);
    }
  }

  // Rotation steps (see the header comment).
  BLAZE_HD Vec3<Real> kick_rotation(const ParticleView<Real>& p, Index i, const Quat<Real>& q, const Vec3<Real>& w,
                                    const Vec3<Real>& torque, Real h) const {
    return w + inverse_inertia_times(inverse_inertia(p.type[i], scale_of(p, i)), Mat3<Real>::rotation(q), torque * h);
  }
  BLAZE_HD void drift_rotation(const ParticleView<Real>& p, Index i, Quat<Real>& q, Vec3<Real>& w, Real dt) const {
    const Vec3<Real> inv = inverse_inertia(p.type[i], scale_of(p, i));
    const Vec3<Real> l = inertia_times(inv, Mat3<Real>::rotation(q), w);
    const Quat<Real> q_half = integrate_orientation(q, w, Real(0.5) * dt);
    const Vec3<Real> w_half = inverse_inertia_times(inv, Mat3<Real>::rotation(q_half), l);
    q = integrate_orientation(q, w_half, dt);
    w = inverse_inertia_times(inv, Mat3<Real>::rotation(q), l);
  }
  // Principal moments of a body of bounding radius `radius` (host snapshots, the time series' energies).
  BLAZE_HD Vec3<Real> principal_inertia(Real, Real radius, std::uint8_t type) const {
    const Vec3<Real> inv = inverse_inertia(type, radius / data(type).bounding_radius);
    return {Real(1) / inv.x, Real(1) / inv.y, Real(1) / inv.z};
  }
  // Inverse principal moments (1/(kg m^2)) of the type scaled by s: the table's over s^5.
  BLAZE_HD Vec3<Real> inverse_inertia(int type, Real s) const {
    const Real s2 = s * s;
    return data(type).inv_inertia * (Real(1) / (s2 * s2 * s));
  }

 private:
  // Thesis Algorithm 2 for any world object: the vertices with a positive penetration(v) (m) are
  // the contact; `deepest`, the largest penetration, is the overlap. The force is conservative
  // only if it acts through the deepest vertex (it is then the gradient of the law's potential in
  // that overlap). The thesis's point, the mean of the penetrating vertices, is not: an elastic
  // cube dropped nearly flat left the floor with up to 2.2 times its kinetic energy
  // (verification/test_cube_at_rest.cpp); the thesis's mean depth with the mean point did worse.
  // So `point` is the deepest vertex, spread over the vertices within 1% of its depth as in
  // incident_point: a flat face still pushes through its centre. Two consequences: rocking on a
  // flat face is stiff (~10x the normal contact frequency), damped only because the band's
  // vertices are the contact patch (the dashpot acts at each of them); and a tensile
  // (dashpot-pulled) normal force makes the rocking unstable, so damped flat contacts want the
  // no-tension clamp (a linear-law tetrahedron rocked at 0.08 rad/s without it:
  // verification/test_polyhedron_rest.cpp).
  template <class Penetration>
  BLAZE_HD static bool penetrating_vertices(const Body& a, const PolyhedronData<Real>& A, const Penetration& penetration,
                                            Vec3<Real>& point, Real& deepest, ContactPatch<Real>& patch) {
    const Mat3<Real> ra = Mat3<Real>::rotation(a.q);
    const auto vertex = [&](int k) { return a.x + ra * (A.vertex[k] * a.scale); };
    return patch_of_depths(A, vertex, [&](int k) { return penetration(vertex(k)); }, point, deepest, patch);
  }
  // The same from vertex k's position vertex(k) and depth depth(k) (> 0: penetrating).
  template <class Vertex, class Depth>
  BLAZE_HD static bool patch_of_depths(const PolyhedronData<Real>& A, const Vertex& vertex, const Depth& depth, Vec3<Real>& point,
                                       Real& deepest, ContactPatch<Real>& patch) {
    return patch_of_points(A.vertex_count, vertex, depth, point, deepest, patch);
  }
  // The same over `points` points (a polyhedron's vertices, and more: collide_mesh).
  template <class Vertex, class Depth>
  BLAZE_HD static bool patch_of_points(int points, const Vertex& vertex, const Depth& depth, Vec3<Real>& point, Real& deepest,
                                       ContactPatch<Real>& patch) {
    deepest = 0;
    for (int k = 0; k < points; ++k) deepest = max_r(deepest, depth(k));
    if (!(deepest > Real(0))) return false;
    const Real floor = Real(0.99) * deepest;
    Vec3<Real> sum{0, 0, 0};
    Real weight = 0;
    int count = 0;
    for (int k = 0; k < points; ++k) {
      const Real w = depth(k) - floor;
      if (w > Real(0)) {
        const Vec3<Real> v = vertex(k);
        sum += v * w, weight += w;
        if (count < ContactPatch<Real>::kMaxPoints) patch.point[count] = v, patch.weight[count] = w;
        ++count;
      }
    }
    point = sum * (Real(1) / weight);
    finish_patch(patch, count, weight);
    return true;
  }

  // Contact point for a face axis of the reference body (the face's plane: normal.x = offset): the
  // incident body's vertices v(k), in the same frame, that penetrate the face plane to within 1%
  // of the deepest, weighted by how far they reach into that band. The overlap is the deepest vertex's
  // penetration, so that vertex is the lever arm that keeps the contact force conservative; the
  // band only spreads the arm over (nearly) flat contacts, which it centres, and its weights
  // vary continuously as vertices enter it.
  template <class Vertex>
  BLAZE_HD static Vec3<Real> incident_point(const Vec3<Real>& normal, Real offset, const Vertex& v, int count,
                                            ContactPatch<Real>& patch) {
    Real deepest = offset - dot(normal, v(0));
    for (int k = 1; k < count; ++k) deepest = max_r(deepest, offset - dot(normal, v(k)));
    const Real floor = deepest - (Real(0.01) * abs_r(deepest) + Real(1e-12) * abs_r(offset));
    Vec3<Real> sum{0, 0, 0};
    Real weight = 0;
    int points = 0;
    for (int k = 0; k < count; ++k) {
      const Vec3<Real> vk = v(k);
      const Real w = offset - dot(normal, vk) - floor;
      if (w > Real(0)) {
        sum += vk * w, weight += w;
        if (points < ContactPatch<Real>::kMaxPoints) patch.point[points] = vk, patch.weight[points] = w;
        ++points;
      }
    }
    finish_patch(patch, points, weight);
    return sum * (Real(1) / weight);
  }

  // The band's vertices as the contact patch, weights normalised; one vertex, or more than the
  // patch holds: a point contact at the weighted centre.
  BLAZE_HD static void finish_patch(ContactPatch<Real>& patch, int count, Real weight) {
    patch.count = count > ContactPatch<Real>::kMaxPoints ? 0 : count;
    const Real inv = Real(1) / weight;
    for (int k = 0; k < patch.count; ++k) patch.weight[k] *= inv;
  }

  // R diag(I^-1) R^T v and R diag(I) R^T v, from the inverse principal moments inv.
  BLAZE_HD static Vec3<Real> inverse_inertia_times(const Vec3<Real>& inv, const Mat3<Real>& r, const Vec3<Real>& v) {
    const Vec3<Real> b = r.transpose_times(v);
    return r * Vec3<Real>{b.x * inv.x, b.y * inv.y, b.z * inv.z};
  }
  BLAZE_HD static Vec3<Real> inertia_times(const Vec3<Real>& inv, const Mat3<Real>& r, const Vec3<Real>& v) {
    const Vec3<Real> b = r.transpose_times(v);
    return r * Vec3<Real>{b.x / inv.x, b.y / inv.y, b.z / inv.z};
  }
};

// Adds a polyhedron of table type `type` to a particle state, of bounding radius `radius` (m; 0:
// the type's own), scaled from the type's: mass s^3, principal moments s^5 (PolyhedronShape::Body).
template <class Real>
void add_polyhedron(ParticleState<Real>& s, const PolyhedronTable<Real>& table, int type, const Vec3<Real>& x,
                    const Quat<Real>& q, std::uint8_t material, const Vec3<Real>& v = {0, 0, 0},
                    const Vec3<Real>& w = {0, 0, 0}, Real radius = 0) {
  const PolyhedronData<Real>& d = table.type[type];
  if (radius == Real(0)) radius = d.bounding_radius;
  const Real k = radius / d.bounding_radius, k3 = k * k * k, k5 = k3 * k * k;
  const Vec3<Real> inertia{k5 / d.inv_inertia.x, k5 / d.inv_inertia.y, k5 / d.inv_inertia.z};
  s.add_body(x, q, radius, d.mass * k3, inertia, static_cast<std::uint8_t>(type), material, v, w);
}

}  // namespace blaze
