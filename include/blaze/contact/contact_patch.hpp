// A contact patch: a contact that carries its load over an area, as a few points with weights
// (issue 17, item 10). Polyhedron face, edge-face and face-wall contacts report one (polyhedron_shape.hpp);
// spheres and point contacts do not, and their code is unchanged.
//
//   one overlap delta, one normal n, one law;  points p_k, weights w_k > 0, sum_k w_k = 1:
//   F_k = w_k law.force(delta, v_rel(p_k), m_eff)                          [N]
//   F   = sum_k F_k,   M = sum_k (p_k - p) x F_k  (moment about the contact point p)  [N, N m]
//   torque on i: (p - x_i) x F + M                                          [N m]
//
// The law is evaluated at every point with that point's relative velocity (v + w x r at p_k) and
// its share w_k of the contact: the normal force and the friction cap mu w_k F_n, the viscous
// friction w_k K_T. So a patch in pure translation gives exactly the one-point force; what it adds
// is what a distributed contact has (Johnson, Contact Mechanics, 1985, chapter 7; Lubkin 1951 for a twisted Hertz contact): a
// torsional friction M_t = sum_k |r_k| mu w_k F_n (|r_k| from the patch centre) against turning
// about the normal, bounded as Johnson's Coulomb torsion of a patch, M_t <= mu F_n max |r|, and
// a normal dashpot spread over the patch that damps rocking (sum_k w_k c (r_k x n)(r_k x n)^T).
// A one-point contact at the patch centre has neither: a resting cube kept turning and rocking.
// Several points per contact with one penetration are the contact manifolds of rigid-body
// engines (e.g. Catto, "Contact manifolds", GDC 2007; Bullet's persistent manifold) and of
// polyhedral DEM (Nassauer & Kuna, Comput. Part. Mech. 2013; Feng & Owen, Eng. Comput. 2004,
// spread the force over the contact region). Keeping one overlap, with the elastic part
// sum_k w_k F(delta) = F(delta), keeps every static closed form of the one-point contact (e.g.
// Hertz delta_s = (m g / K_n)^(2/3)) and, with the weights the shape already used for the point
// p = sum_k w_k p_k, its (conservative) elastic torque (sum_k w_k r_k) x F(delta) n.
// Each F_k is exactly negated when i and j swap (v_rel and n both change sign), so a pair
// evaluated once and from both sides agree bitwise (kernels/pair_forces.hpp).
#pragma once
#include <type_traits>
#include "blaze/config.hpp"
#include "blaze/contact/contact_geometry.hpp"
#include "blaze/laws/contact_law.hpp"

namespace blaze {

template <class Real>
struct ContactPatch {
  // A face of a shipped shape has at most 6 vertices (corn); 8 covers any face within the
  // 1% band (polyhedron_shape.hpp). More: the shape reports a point contact at the weighted centre.
  static constexpr int kMaxPoints = 8;
  int count = 0;  // 0 or 1: a point contact at geometry.point
  Vec3<Real> point[kMaxPoints];
  Real weight[kMaxPoints];  // -, sum 1
};

// A ContactGeometry with its patch; reads as a ContactGeometry everywhere one is expected.
template <class Real>
struct PatchGeometry : ContactGeometry<Real> {
  ContactPatch<Real> patch;

  BLAZE_HD static PatchGeometry none() {
    PatchGeometry g;
    static_cast<ContactGeometry<Real>&>(g) = ContactGeometry<Real>::none();
    return g;
  }
  BLAZE_HD static PatchGeometry of(const ContactGeometry<Real>& c) {
    PatchGeometry g;
    static_cast<ContactGeometry<Real>&>(g) = c;
    return g;
  }
};

template <class G>
struct is_patch_geometry : std::false_type {};
template <class Real>
struct is_patch_geometry<PatchGeometry<Real>> : std::true_type {};
template <class G>
inline constexpr bool is_patch_geometry_v = is_patch_geometry<G>::value;

// The force system of a contact: the resultant and its moment about the contact point.
template <class Real>
struct ContactWrench {
  Vec3<Real> force;   // N, on body i
  Vec3<Real> moment;  // N m, about geometry.point (0 for a point contact)
};

// The law over the patch (header comment); v_rel(x) is the relative velocity at the point x.
template <class Law, class Real, class RelativeVelocity>
BLAZE_HD_INLINE ContactWrench<Real> patch_force(const Law& law, const PatchGeometry<Real>& g, const RelativeVelocity& v_rel,
                                                Real m_eff) {
  if (g.patch.count <= 1) return {law.force(g, v_rel(g.point), m_eff), {0, 0, 0}};
  ContactWrench<Real> w{{0, 0, 0}, {0, 0, 0}};
  for (int k = 0; k < g.patch.count; ++k) {
    const Vec3<Real> f = law.force(g, v_rel(g.patch.point[k]), m_eff) * g.patch.weight[k];
    w.force += f;
    w.moment += cross(g.patch.point[k] - g.point, f);
  }
  return w;
}

// A patch under a law with history (a tangential spring, one state per contact, keyed by the
// pair): the normal force at each point as above, the spring once at the patch centre p with the
// total normal force and the centre's slip (its force acts at p: no moment about p), and the
// tangential damping of each point's slip relative to the centre's, w_k c_t (v_t,k - v_t,p),
// which sums to zero force and damps turning about the normal (torsion) and rocking:
//   F = sum_k -w_k F_n(delta, v_n,k) n + F_t(spring; sum_k w_k F_n,k, v_t,p) - sum_k w_k c_t (v_t,k - v_t,p)
//   M = sum_k (p_k - p) x (-w_k F_n,k n - w_k c_t (v_t,k - v_t,p))
// A twist is thus resisted viscously (a steady torque about n turns the body slowly), not by a
// torsional spring: a contact turning about its normal keeps no twist in its state.
template <class Law, class Real, class RelativeVelocity>
BLAZE_HD_INLINE ContactForce<Real> contact_patch_force(const Law& law, const PatchGeometry<Real>& g, const RelativeVelocity& v_rel,
                                                      const Vec3<Real>& w_rel, Real m_eff, typename Law::State& state, Real dt) {
  if constexpr (!Law::kHistory) {
    const ContactWrench<Real> w = patch_force(law, g, v_rel, m_eff);
    return {w.force, w.moment, false};
  } else {
    const Vec3<Real> v_c = v_rel(g.point);
    if (g.patch.count <= 1) return law.evaluate(g, {v_c, w_rel, m_eff}, state, dt);
    const Vec3<Real> n = g.normal;
    const Vec3<Real> slip_c = v_c - dot(v_c, n) * n;
    const Real c_t = law.tangential.damping(g.overlap, g.r_eff, m_eff);
    Real f_n = 0;
    Vec3<Real> force{0, 0, 0}, moment{0, 0, 0};
    for (int k = 0; k < g.patch.count; ++k) {
      const Vec3<Real> v = v_rel(g.patch.point[k]);
      const Real v_n = dot(v, n);
      const Real w = g.patch.weight[k];
      const Real f_nk = w * law.normal.normal_force(g.overlap, v_n, m_eff, g.r_eff);
      const Vec3<Real> f = n * (-f_nk) - ((v - v_n * n) - slip_c) * (w * c_t);
      f_n += f_nk;
      force += f;
      moment += cross(g.patch.point[k] - g.point, f);
    }
    const TangentialInput<Real> in{n, g.overlap, g.r_eff, slip_c, dot(v_c, n), f_n, m_eff, dt};
    const TangentialForce<Real> t = law.tangential.force(in, state, 0);
    return {force + t.force, moment, t.sliding};
  }
}

}  // namespace blaze
