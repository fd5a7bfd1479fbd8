// Particle-particle contact forces with each pair evaluated once (PairEvaluation::once), in two
// kernels:
//   PairForces:       for every list entry (k, i) whose neighbour j = list.at(k, i) is above i,
//                     collide(i, j), evaluate the law, and keep F_ij and the contact point in the
//                     entry's slot (k * stride + i);
//   GatherPairForces: for every particle i, walk its list in order and add F_ij and
//                     (point - x_i) x F_ij from its own slots (j > i) or, with F_ij = -F_ji, from
//                     j's slot for i (j < i; the slot comes from the list's reverse index).
// The arithmetic is ContactForces's (contact_forces.hpp) for the lower index: the higher one's
// force there is the exact negation (v_rel = a - b against b - a, the normal negated, and every
// product and the friction branch unchanged by the two signs), its torque the same expression,
// and both kernels add in list order. So the result is bitwise that of ContactForces, for half
// its collisions and law evaluations, at the cost of a slot per list entry: 6 reals (3 without
// rotation), a state byte, the overlap with Features::monitor, and the 4-byte reverse index,
// 29 B per entry in float. It pays where a pair costs more than those bytes: polyhedra (1.8x on
// the CPU), not spheres in double on the CPU (1.5x slower; bench/compare/README.md).
#pragma once
#include <cstdint>
#include "blaze/contact/kinematics.hpp"
#include "blaze/exec/launch.hpp"
#include "blaze/laws/contact_law.hpp"
#include "blaze/sim/features.hpp"
#include "kernels/broad_phase_kernels.hpp"
#include "kernels/contact_forces.hpp"

namespace blaze {

// One slot per neighbour-list entry, same layout as the list (entry k of particle i at
// k * stride + i); only the slots of entries with j > i are written.
template <class Real>
struct PairSlots {
  Real* force[3];       // N, F_ij on i
  Real* point[3];       // m, the contact point (Features::rotation; null otherwise)
  std::uint8_t* state;  // 0: not touching; 1: vertex-face; 2: edge-edge
  Real* overlap;        // m (Features::monitor; null otherwise)

  BLAZE_HD Vec3<Real> get(Real* const (&f)[3], std::size_t s) const { return {f[0][s], f[1][s], f[2][s]}; }
  BLAZE_HD void set(Real* const (&f)[3], std::size_t s, const Vec3<Real>& v) const { f[0][s] = v.x, f[1][s] = v.y, f[2][s] = v.z; }
};

BLAZE_HD inline std::size_t slot_of(const NeighbourView& list, Index k, Index i) {
  return static_cast<std::size_t>(k) * static_cast<std::size_t>(list.stride) + static_cast<std::size_t>(i);
}

template <class Shape, class Law, class Kinematics, class Features>
struct PairForces {
  using Real = typename Law::real_type;
  static constexpr int kMinBlocks = min_blocks_v<Shape>;  // launch.hpp
  Shape shape;
  ParticleView<Real> p;
  NeighbourView list;
  PairTable<Law> laws;
  PairSlots<Real> slots;

  BLAZE_HD void operator()(Index i) const {
    const auto bi = shape.body(p, i);
    const Vec3<Real> vi = p.velocity.get(i);
    const Vec3<Real> wi = Features::rotation ? p.angular_velocity.get(i) : Vec3<Real>{0, 0, 0};
    const Real inv_mi = p.inv_mass[i];
    const int mi = p.material[i];
    const Index count = min_r(list.count[i], list.capacity);
    for (Index k = 0; k < count; ++k) {
      const Index j = list.at(k, i);
      if (j < i) continue;  // j's kernel thread evaluates this pair
      const std::size_t s = slot_of(list, k, i);
      const auto bj = shape.body(p, j);
      const ContactGeometry<Real> g = shape.collide(bi, bj);
      if (!g.touching) {
        slots.state[s] = 0;
        continue;
      }
      slots.state[s] = g.kind == ContactKind::edge_edge ? 2 : 1;
      if constexpr (Features::monitor) slots.overlap[s] = g.overlap;
      const Vec3<Real> ri = g.point - bi.x;
      const Vec3<Real> wj = Features::rotation ? p.angular_velocity.get(j) : Vec3<Real>{0, 0, 0};
      const Vec3<Real> v_rel = Kinematics::relative(vi, wi, ri, p.velocity.get(j), wj, g.point - bj.x);
      const Real m_eff = Real(1) / (inv_mi + p.inv_mass[j]);
      const Vec3<Real> fij = laws(mi, p.material[j]).force(g, v_rel, m_eff);
      slots.set(slots.force, s, fij);
      if constexpr (Features::rotation) slots.set(slots.point, s, g.point);
    }
  }
};

template <class Real, class Features>
struct GatherPairForces {
  ParticleView<Real> p;
  NeighbourView list;
  PairSlots<Real> slots;
  ContactStats stats;

  BLAZE_HD void operator()(Index i) const {
    const Vec3<Real> xi = p.position.get(i);
    Vec3<Real> f{0, 0, 0}, t{0, 0, 0};
    Index vertex_face = 0, edge_edge = 0;
    Real deepest = 0;
    const Index count = min_r(list.count[i], list.capacity);
    for (Index k = 0; k < count; ++k) {
      const Index j = list.at(k, i);
      const bool own = i < j;
      const std::size_t s = own ? slot_of(list, k, i) : slot_of(list, list.reverse_at(k, i), j);
      const std::uint8_t state = slots.state[s];
      if (state == 0) continue;
      if constexpr (Features::statistics) (state == 2 ? edge_edge : vertex_face) += 1;
      if constexpr (Features::monitor) deepest = max_r(deepest, slots.overlap[s]);
      const Vec3<Real> fs = slots.get(slots.force, s);
      const Vec3<Real> fij = own ? fs : -fs;
      f += fij;
      if constexpr (Features::rotation) t += cross(slots.get(slots.point, s) - xi, fij);
    }
    p.force.set(i, f);
    if constexpr (Features::rotation) p.torque.set(i, t);
    if constexpr (Features::monitor) p.penetration[i] = max_r(p.penetration[i], deepest / p.radius[i]);
    if constexpr (Features::statistics) {
      stats.vertex_face[i] = vertex_face;
      stats.edge_edge[i] = edge_edge;
    }
  }
};

}  // namespace blaze
