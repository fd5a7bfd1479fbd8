// Particle-particle contact forces with each pair evaluated once (PairEvaluation::once), in two
// kernels:
//   PairForces:       for every list entry (k, i) whose neighbour j = list.at(k, i) is above i,
//                     collide(i, j), evaluate the law, and keep F_ij and the contact point in the
//                     entry's slot (k * stride + i);
//   GatherPairForces: for every particle i, walk its list in order and add F_ij and
//                     (point - x_i) x F_ij from its own slots (j > i) or, with F_ij = -F_ji, from
//                     j's slot for i (j < i; the slot comes from the list's reverse index).
// The arithmetic is ContactForces's (both through contact_pair.hpp) for the lower index: the
// higher one's force there is the exact negation (v_rel = a - b against b - a, the normal
// negated, and every product and the friction branch unchanged by the two signs), its torque the
// same expression, and both kernels add in list order. So the result is bitwise that of ContactForces, for half
// its collisions and law evaluations, at the cost of a slot per list entry: 6 reals (3 without
// rotation), a state byte, the overlap with Features::monitor, and the 4-byte reverse index,
// 29 B per entry in float; shapes with contact patches (polyhedra) keep the patch's moment too,
// 3 reals more (41 B in float, 77 B in double). It pays where a pair costs more than those bytes: polyhedra (1.8x on
// the CPU), not spheres in double on the CPU (1.5x slower; bench/compare/README.md).
#pragma once
#include <cstdint>
#include <type_traits>
#include "blaze/exec/launch.hpp"
#include "kernels/broad_phase_kernels.hpp"
#include "kernels/contact_history.hpp"
#include "kernels/contact_pair.hpp"

namespace blaze {

// One slot per neighbour-list entry, same layout as the list (entry k of particle i at
// k * stride + i); only the slots of entries with j > i are written.
template <class Real>
struct PairSlots {
  Real* force[3];       // N, F_ij on i
  Real* point[3];       // m, the contact point (Features::rotation; null otherwise)
  std::uint8_t* state;  // 0: not touching; 1: vertex-face; 2: edge-edge
  Real* overlap;        // m (Features::monitor; null otherwise)
  Real* moment[3];      // N m, a contact patch's moment about the point (shapes with patches and
                        // Features::rotation; null otherwise)

  BLAZE_HD Vec3<Real> get(Real* const (&f)[3], std::size_t s) const { return {f[0][s], f[1][s], f[2][s]}; }
  BLAZE_HD void set(Real* const (&f)[3], std::size_t s, const Vec3<Real>& v) const { f[0][s] = v.x, f[1][s] = v.y, f[2][s] = v.z; }
};

template <class Shape, class Law, class Kinematics, class Features>
struct PairForces {
  using Real = typename Law::real_type;
  static constexpr int kMinBlocks = min_blocks_v<Shape>;  // launch.hpp
  Shape shape;
  ParticleView<Real> p;
  NeighbourView list;
  PairTable<Law> laws;
  PairSlots<Real> slots;
  PairHistoryView<Real, Law::State::kReals> history;  // the lower index's copy (contact_history.hpp)
  Real dt;
  PeriodicImages<Real> images;  // periodic axes: j's image beside i (grid/periodic_images.hpp)
  // 0: a thread a particle, walking its list; n (the particles): a thread a list entry, t = k n + i
  // (items(n) of them, phases.hpp), each evaluating at most one pair. A polyhedron pair is a long
  // serial chain (SAT): a few thousand particles give the GPU too few threads a particle each
  // (make fig-2.17's pour), an entry each gives it capacity times more. The same arithmetic for
  // every pair: bitwise the same slots. Not with Features::thesis_power (a particle's sum).
  Index entry_rows = 0;

  BLAZE_HD Index items(Index n) const { return entry_rows > 0 ? n * list.capacity : n; }

  BLAZE_HD void operator()(Index t) const {
    if constexpr (!Features::thesis_power)
      if (entry_rows > 0) {
        const Index i = t % entry_rows, k = t / entry_rows;
        if (k >= min_r(list.count[i], list.capacity) || list.at(k, i) < i) return;  // j's entry evaluates it
        const auto a = pair_side<Features>(shape, p, i);
        Real unused = 0;
        evaluate(a, i, k, unused);
        return;
      }
    const Index i = t;
    const auto a = pair_side<Features>(shape, p, i);
    const Index count = min_r(list.count[i], list.capacity);
    Real thesis = 0;  // J (Features::thesis_power): the pairs evaluated here, booked whole to i
    for (Index k = 0; k < count; ++k) {
      if (list.at(k, i) < i) continue;  // j's kernel thread evaluates this pair
      evaluate(a, i, k, thesis);
    }
    if constexpr (Features::thesis_power)
      if (p.ledger.thesis_estimate) p.ledger.thesis_estimate[i] += thesis;
  }

 private:
  // Entry k of particle i (its neighbour above i): collide, evaluate the law, fill the slot.
  template <class Side>
  BLAZE_HD void evaluate(const Side& a, Index i, Index k, Real& thesis) const {
    const Index j = list.at(k, i);
    const std::size_t s = list.offset(k, i);
    constexpr bool kEarly = Law::kHistory && BLAZE_HISTORY_EARLY_LOAD;  // contact_history.hpp
    auto state = kEarly ? history.load(s) : typename Law::State{};
    auto bj = shape.body(p, j);
    if (images.on()) bj.x = bj.x + images.shift(s);
    const auto g = shape.collide(a.body, bj);
    if (!g.touching) {
      slots.state[s] = 0;
      if constexpr (kEarly) history.forget(s, state);
      else if constexpr (Law::kHistory) history.forget(s);
      return;
    }
    slots.state[s] = g.kind == ContactKind::edge_edge ? 2 : 1;
    if constexpr (Features::monitor) slots.overlap[s] = g.overlap;
    if constexpr (Law::kHistory && !kEarly) state = history.load(s);
    const ContactForce<Real> c = pair_force<Kinematics, Features>(laws, p, a, j, bj, g, state, dt);
    if constexpr (Law::kHistory) history.store(s, state);
    slots.set(slots.force, s, c.force);
    if constexpr (has_moment_v<Law, std::decay_t<decltype(g)>> && Features::rotation) slots.set(slots.moment, s, c.moment);
    if constexpr (Features::rotation) slots.set(slots.point, s, g.point);
    if constexpr (Features::thesis_power) thesis += pair_thesis_dissipation<Kinematics, Features>(laws, p, a, j, bj, g, c, dt);
    else (void)thesis;
  }
};

// Patches: the shape's contacts carry patches, so the slots hold their moments.
template <class Real, class Features, bool Patches = false>
struct GatherPairForces {
  ParticleView<Real> p;
  NeighbourView list;
  PairSlots<Real> slots;
  ContactStats stats;
  PeriodicImages<Real> images;  // periodic axes: a slot of j's holds the point beside j's image of i

  BLAZE_HD void operator()(Index i) const {
    const Vec3<Real> xi = p.position.get(i);
    ContactSums<Real, Features> sums;
    const Index count = min_r(list.count[i], list.capacity);
    for (Index k = 0; k < count; ++k) {
      const Index j = list.at(k, i);
      const bool own = i < j;
      const std::size_t s = own ? list.offset(k, i) : list.offset(list.reverse_at(k, i), j);
      const std::uint8_t state = slots.state[s];
      if (state == 0) continue;
      sums.touch(state == 2, Features::monitor ? slots.overlap[s] : Real(0));
      const Vec3<Real> fs = slots.get(slots.force, s);
      // the point of a slot of j's lies beside j: i's arm from its image there, x_i - s (s: entry (k, i)'s
      // shift of j), rounded as ContactForces rounds it
      const Vec3<Real> at = !own && images.on() ? xi - images.shift(list.offset(k, i)) : xi;
      const Vec3<Real> r = Features::rotation ? slots.get(slots.point, s) - at : Vec3<Real>{0, 0, 0};
      if constexpr (Patches && Features::rotation) {
        const Vec3<Real> ms = slots.get(slots.moment, s);
        sums.add(own ? fs : -fs, r, own ? ms : -ms);
      } else {
        sums.add(own ? fs : -fs, r);
      }
    }
    sums.store(p, stats, i);
  }
};

}  // namespace blaze
