// Particle-particle contact forces (thesis Algorithm 2.1, line 4), one thread per particle i:
// walk i's neighbours, collide with the shape policy, evaluate the law for the material pair, and
// write only i's force and torque (eq. 2.4: T = r x F). Each pair is evaluated from both sides, so
// no atomics are needed and the summation order is the same on every backend. Both sides call
// collide(lower index, higher index) and the higher one flips the normal, so the two see exactly
// the same geometry (Newton's third law holds to the last bit of the geometry). With `by_id`
// (SimulationParams::canonical_order) "lower" is by permanent id instead of memory index, so the
// pair is formed the same way wherever the two lie in memory (runs over ranks, issue 21).
// A law with history (contact_state.hpp) loads each touching pair's state from i's own copy
// (contact_history.hpp), updates it and stores it back; an open pair's state is forgotten.
// Across a periodic boundary the pair is taken beside its lower index (grid/periodic_images.hpp).
// With Features::statistics each particle also counts its vertex-face and edge-edge contacts;
// with Features::monitor it keeps its deepest overlap / radius (reset by the host).
#pragma once
#include "blaze/exec/launch.hpp"
#include "kernels/broad_phase_kernels.hpp"
#include "kernels/contact_history.hpp"
#include "kernels/contact_pair.hpp"

// j's side (velocity, spin, mass, material) read with its position, before the collision
// (pair_side; contact_pair.hpp): one memory latency fewer per list entry for 6-10 more registers.
// 1 (default): for the laws with history of shapes that ask for it (SphereShape::kEarlySide);
// 2: for every law of those shapes; 0: never. H100, 1e7 spheres in float, dense bed, contacts per
// step (bench/results/levers/early-loads.md): Mindlin 3.44 -> 3.26 ms, Mindlin + EPSD 5.93 ->
// 5.82, linear 1.58 -> 1.38, linear double 3.32 -> 2.75, but Hertz 1.66 -> 1.86 (68 registers: a
// block fewer per SM), so history-free laws keep the late loads until each is measured.
#ifndef BLAZE_PAIR_EARLY_SIDE
#define BLAZE_PAIR_EARLY_SIDE 1
#endif

namespace blaze {

template <class Shape, class Law, class Kinematics, class Features>
struct ContactForces {
  using Real = typename Law::real_type;
  static constexpr int kMinBlocks = history_min_blocks<Law>(min_blocks_v<Shape>, BLAZE_HISTORY_CONTACT_MIN_BLOCKS);  // launch.hpp
  Shape shape;
  ParticleView<Real> p;
  NeighbourView list;
  PairTable<Law> laws;
  ContactStats stats;
  PairHistoryView<Real, Law::State::kReals> history;  // i's own copy of each pair's state (contact_history.hpp)
  Real dt;
  PeriodicImages<Real> images;  // periodic axes: the pair in its lower index's frame (periodic_images.hpp)
  bool by_id = false;           // the lower of a pair by permanent id, not by index
  static constexpr bool kSide = early_side_v<Shape> && (BLAZE_PAIR_EARLY_SIDE == 2 || (BLAZE_PAIR_EARLY_SIDE == 1 && Law::kHistory));

  BLAZE_HD void operator()(Index i) const {
    const auto side = pair_side<Features>(shape, p, i);
    ContactSums<Real, Features> sums;
    const Index count = min_r(list.count[i], list.capacity);
    for (Index k = 0; k < count; ++k) {
      const Index j = list.at(k, i);
      const std::size_t s = list.offset(k, i);
      constexpr bool kEarly = Law::kHistory && BLAZE_HISTORY_EARLY_LOAD;  // contact_history.hpp
      auto state = kEarly ? history.load(s) : typename Law::State{};
      auto sj = other_side<kSide, Features>(shape, p, j);  // j's body, or its whole side (contact_pair.hpp)
      auto& bj = body_of(sj);
      auto a = side;
      images.place(s, i, j, a.body.x, bj.x);
      decltype(shape.collide(a.body, bj)) g;  // ContactGeometry, or PatchGeometry (contact_patch.hpp)
      if (by_id ? p.id[i] < p.id[j] : i < j) {
        g = shape.collide(a.body, bj);
      } else {
        g = shape.collide(bj, a.body);
        g.normal = -g.normal;
      }
      if (!g.touching) {
        if constexpr (kEarly) history.forget(s, state);
        else if constexpr (Law::kHistory) history.forget(s);
        continue;
      }
      sums.touch(g.kind == ContactKind::edge_edge, g.overlap);
      if constexpr (Law::kHistory && !kEarly) state = history.load(s);
      const ContactForce<Real> c = pair_force<Kinematics, Features>(laws, p, a, j, sj, g, state, dt);
      if constexpr (Law::kHistory) history.store(s, state);
      sums.template add<has_moment_v<Law, decltype(g)>>(c, g.point - a.body.x);
      if constexpr (Features::thesis_power)  // the pair is booked from both sides: half each
        sums.thesis += Real(0.5) * pair_thesis_dissipation<Kinematics, Features>(laws, p, a, j, bj, g, c, dt);
    }
    sums.store(p, stats, i);
  }
};

}  // namespace blaze
