// The arithmetic of one particle-particle contact and of a particle's sums over its contacts,
// shared by the kernel that evaluates each pair from both sides (contact_forces.hpp) and by the
// pair and gather kernels that evaluate it once (pair_forces.hpp), so that the two paths cannot
// drift apart (they agree bitwise on the host: verification/test_pair_evaluation.cpp).
//   F_ij = law(m_i, m_j).evaluate(geometry, {v_rel, w_i - w_j, m_eff}, state, dt).force  [N]
//   v_rel = Kinematics::relative(v_i, w_i, p - x_i, v_j, w_j, p - x_j)  at the contact point p [m/s]
//   m_eff = 1 / (1/m_i + 1/m_j)                                   [kg]
//   T_i  += (p - x_i) x F_ij (thesis eq. 2.4)                     [N m]
// A contact with a patch (PatchGeometry, contact_patch.hpp: polyhedron face contacts) evaluates the
// law at each of its points and adds the patch's moment about p:
//   T_i  += (p - x_i) x F_ij + M_ij,   M_ij = sum_k (p_k - p) x F_k     [N m]
#pragma once
#include <type_traits>
#include "blaze/contact/contact_patch.hpp"
#include "blaze/contact/kinematics.hpp"
#include "blaze/laws/contact_law.hpp"
#include "blaze/particles/particle_store.hpp"
#include "blaze/sim/features.hpp"
#include "blaze/world/motion.hpp"

namespace blaze {

// Per-particle contact counts by kind (null when statistics are off).
struct ContactStats {
  Index* vertex_face;
  Index* edge_edge;
};

// What every pair of particle i needs of i, read once per thread.
template <class Real, class Body>
struct PairSide {
  Body body;
  Vec3<Real> v, w;  // w = 0 without Features::rotation
  Real inv_mass;
  int material;
};

template <class Features, class Shape, class Real>
BLAZE_HD_INLINE auto pair_side(const Shape& shape, const ParticleView<Real>& p, Index i) {
  using Body = decltype(shape.body(p, i));
  return PairSide<Real, Body>{shape.body(p, i), p.velocity.get(i),
                              Features::rotation ? p.angular_velocity.get(i) : Vec3<Real>{0, 0, 0}, p.inv_mass[i],
                              p.material[i]};
}

// 1 / (I + m r^2) of sphere i about its contact point at arm r (rolling resistance), 1/(kg m^2).
template <class Real>
BLAZE_HD_INLINE Real rolling_term(const ParticleView<Real>& p, Index i, const Vec3<Real>& r) {
  return Real(1) / (Real(1) / p.inv_inertia[i] + norm2(r) / p.inv_mass[i]);
}

// F_ij on i (and a moment on i: a patch's about the contact point, a rolling resistance) for the
// geometry g of i and j (normal from i towards j, contact_geometry.hpp), with the contact's state
// (updated; laws without history have none).
template <class Kinematics, class Features, class Law, class Real, class Body, class Geometry>
BLAZE_HD_INLINE ContactForce<Real> pair_force(const PairTable<Law>& laws, const ParticleView<Real>& p,
                                              const PairSide<Real, Body>& a, Index j, const Body& bj, const Geometry& g,
                                              typename Law::State& state, Real dt) {
  // The loads in this order (j's spin, its velocity inside v_rel, its mass, then the material
  // pair's law): the register count of the sphere kernels depends on it (54 against 48 for the
  // linear law in float, 4 blocks of 256 threads per SM against 5: 8% of the step).
  const Vec3<Real> wj = Features::rotation ? p.angular_velocity.get(j) : Vec3<Real>{0, 0, 0};
  if constexpr (is_patch_geometry_v<Geometry>) {
    const Vec3<Real> vj = p.velocity.get(j);
    const auto v_rel = [&](const Vec3<Real>& x) { return Kinematics::relative(a.v, a.w, x - a.body.x, vj, wj, x - bj.x); };
    const Real m_eff = Real(1) / (a.inv_mass + p.inv_mass[j]);
    return contact_patch_force(laws(a.material, p.material[j]), g, v_rel, a.w - wj, m_eff, state, dt);
  } else {
    const Vec3<Real> v_rel = Kinematics::relative(a.v, a.w, g.point - a.body.x, p.velocity.get(j), wj, g.point - bj.x);
    const Real m_eff = Real(1) / (a.inv_mass + p.inv_mass[j]);
    ContactMotion<Real> m{v_rel, a.w - wj, m_eff};
    if constexpr (Law::kRolling)  // spheres (isotropic inertia): 1/I_r = sum 1 / (I + m r^2)
      m.inv_rolling_inertia = rolling_term(p, a.body.index, g.point - a.body.x) + rolling_term(p, j, g.point - bj.x);
    return laws(a.material, p.material[j]).evaluate(g, m, state, dt);
  }
}

// The same with j's side read up front (PairSide, with its body: other_side<true>), so that j's
// velocity, spin, mass and material are loaded beside its position rather than after the
// collision (contact_forces.hpp, BLAZE_PAIR_EARLY_SIDE). The arithmetic is the other overload's.
template <class Kinematics, class Features, class Law, class Real, class Body, class Geometry>
BLAZE_HD_INLINE ContactForce<Real> pair_force(const PairTable<Law>& laws, const ParticleView<Real>& p,
                                              const PairSide<Real, Body>& a, Index, const PairSide<Real, Body>& b,
                                              const Geometry& g, typename Law::State& state, Real dt) {
  const Real m_eff = Real(1) / (a.inv_mass + b.inv_mass);
  if constexpr (is_patch_geometry_v<Geometry>) {
    const auto v_rel = [&](const Vec3<Real>& x) { return Kinematics::relative(a.v, a.w, x - a.body.x, b.v, b.w, x - b.body.x); };
    return contact_patch_force(laws(a.material, b.material), g, v_rel, a.w - b.w, m_eff, state, dt);
  } else {
    const Vec3<Real> v_rel = Kinematics::relative(a.v, a.w, g.point - a.body.x, b.v, b.w, g.point - b.body.x);
    ContactMotion<Real> m{v_rel, a.w - b.w, m_eff};
    if constexpr (Law::kRolling)
      m.inv_rolling_inertia = rolling_term(p, a.body.index, g.point - a.body.x) + rolling_term(p, b.body.index, g.point - b.body.x);
    return laws(a.material, b.material).evaluate(g, m, state, dt);
  }
}

// Does a shape ask for its partner's whole side before the collision (Shape::kEarlySide)?
template <class Shape, class = void>
struct EarlySide : std::false_type {};
template <class Shape>
struct EarlySide<Shape, std::void_t<decltype(Shape::kEarlySide)>> : std::bool_constant<Shape::kEarlySide> {};
template <class Shape>
inline constexpr bool early_side_v = EarlySide<Shape>::value;

// j as a pair's other side: its whole side (Side), or its body alone; body_of gives the body.
template <bool Side, class Features, class Shape, class Real>
BLAZE_HD_INLINE auto other_side(const Shape& shape, const ParticleView<Real>& p, Index j) {
  if constexpr (Side) return pair_side<Features>(shape, p, j);
  else return shape.body(p, j);
}
template <class Real, class Body>
BLAZE_HD_INLINE Body& body_of(PairSide<Real, Body>& s) { return s.body; }
template <class Body>
BLAZE_HD_INLINE Body& body_of(Body& b) { return b; }

// F on particle i (and a moment on i) from its contact g with a world object standing at `pose`
// (null: still; blaze/world/motion.hpp), whose material law is `law`: the wall's velocity at the
// point enters v_rel and its spin the relative spin; the wall's mass is infinite (m_eff = m_i, and
// the rolling inertia is i's alone). v_point: v_rel at the contact point (for the thesis's estimate).
template <class Kinematics, class Features, class Law, class Real, class Body, class Geometry>
BLAZE_HD_INLINE ContactForce<Real> wall_force(const Law& law, const ParticleView<Real>& p, const Body& body, Index i,
                                              const Geometry& g, const Pose<Real>* pose, typename Law::State& state, Real dt,
                                              Vec3<Real>& v_point) {
  const Vec3<Real> zero{0, 0, 0};
  const Vec3<Real> wi = Features::rotation ? p.angular_velocity.get(i) : zero;
  const Vec3<Real> vi = p.velocity.get(i);
  const Vec3<Real> w_wall = pose ? pose->omega : zero;
  const Real m_eff = Real(1) / p.inv_mass[i];
  const auto v_rel = [&](const Vec3<Real>& x) { return Kinematics::relative(vi, wi, x - body.x, pose ? pose->velocity_at(x) : zero, zero, zero); };
  v_point = v_rel(g.point);
  if constexpr (is_patch_geometry_v<Geometry>) {  // contact_patch.hpp
    return contact_patch_force(law, g, v_rel, wi - w_wall, m_eff, state, dt);
  } else {
    ContactMotion<Real> m{v_point, wi - w_wall, m_eff};
    if constexpr (Law::kRolling) m.inv_rolling_inertia = rolling_term(p, i, g.point - body.x);  // the wall: I_j infinite
    return law.evaluate(g, m, state, dt);
  }
}

// The thesis's power estimate of one contact over one step (section 4.1.4.1; energy_ledger.hpp):
//   |F_diss| |V| dt,  F_diss = -(F_n - F_el(delta)) n + F_t   [J]
// from the contact's force c on i (F = -F_n n + F_t, contact_law.hpp), its geometry and the
// relative velocity V at the contact point. An upper bound of the work F_diss . V dt.
template <class Law, class Real>
BLAZE_HD_INLINE Real thesis_dissipation(const Law& law, const ContactGeometry<Real>& g, const Vec3<Real>& force,
                                        const Vec3<Real>& v_rel, Real dt) {
  const Real f_n = -dot(force, g.normal);
  const Vec3<Real> f_t = force + g.normal * f_n;
  const Real damping = f_n - law.normal.elastic_force(g.overlap, g.r_eff);
  return sqrt_r(damping * damping + norm2(f_t)) * sqrt_r(norm2(v_rel)) * dt;
}

// The same for a pair of particles (point contacts; a patch is taken at its contact point).
template <class Kinematics, class Features, class Law, class Real, class Body, class Geometry>
BLAZE_HD_INLINE Real pair_thesis_dissipation(const PairTable<Law>& laws, const ParticleView<Real>& p, const PairSide<Real, Body>& a,
                                             Index j, const Body& bj, const Geometry& g, const ContactForce<Real>& c, Real dt) {
  const Vec3<Real> wj = Features::rotation ? p.angular_velocity.get(j) : Vec3<Real>{0, 0, 0};
  const Vec3<Real> v_rel = Kinematics::relative(a.v, a.w, g.point - a.body.x, p.velocity.get(j), wj, g.point - bj.x);
  return thesis_dissipation(laws(a.material, p.material[j]), static_cast<const ContactGeometry<Real>&>(g), c.force, v_rel, dt);
}

// Does a contact's force come with a moment (a patch, or a law with rolling resistance)?
template <class Law, class Geometry>
inline constexpr bool has_moment_v = is_patch_geometry_v<Geometry> || Law::kRolling;

// Particle i's sums over its contacts, added in list order and stored once: force, torque
// (Features::rotation), deepest overlap / radius (Features::monitor, kept as the maximum with
// what the host reset), and contact counts by kind (Features::statistics).
template <class Real, class Features>
struct ContactSums {
  Vec3<Real> f{0, 0, 0}, t{0, 0, 0};
  Index vertex_face = 0, edge_edge = 0;
  Real deepest = 0;
  Real thesis = 0;  // J, the thesis's estimate over i's contacts this step (Features::thesis_power)

  // The contact's kind and overlap (before its force is known).
  BLAZE_HD_INLINE void touch(bool edge, Real overlap) {
    if constexpr (Features::statistics) (edge ? edge_edge : vertex_face) += 1;
    if constexpr (Features::monitor) deepest = max_r(deepest, overlap);
  }
  // F_ij acting at the contact point, r = point - x_i.
  BLAZE_HD_INLINE void add(const Vec3<Real>& fij, const Vec3<Real>& r) {
    f += fij;
    if constexpr (Features::rotation) t += cross(r, fij);
  }
  // A patch's F_ij with its moment m about the contact point.
  BLAZE_HD_INLINE void add(const Vec3<Real>& fij, const Vec3<Real>& r, const Vec3<Real>& m) {
    f += fij;
    if constexpr (Features::rotation) t += cross(r, fij) + m;
  }
  // A law's force and, when it has one (Moment), its moment.
  template <bool Moment>
  BLAZE_HD_INLINE void add(const ContactForce<Real>& c, const Vec3<Real>& r) {
    if constexpr (Moment) add(c.force, r, c.moment);
    else add(c.force, r);
  }
  BLAZE_HD_INLINE void store(const ParticleView<Real>& p, const ContactStats& stats, Index i) const {
    p.force.set(i, f);
    if constexpr (Features::rotation) p.torque.set(i, t);
    if constexpr (Features::monitor) p.penetration[i] = max_r(p.penetration[i], deepest / p.radius[i]);
    if constexpr (Features::statistics) {
      stats.vertex_face[i] = vertex_face;
      stats.edge_edge[i] = edge_edge;
    }
    if constexpr (Features::thesis_power)
      if (p.ledger.thesis_estimate) p.ledger.thesis_estimate[i] += thesis;
  }
};

}  // namespace blaze
