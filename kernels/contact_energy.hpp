// Elastic energy stored in the open contacts, and the contacts with world objects, per particle
// (a diagnostic: Simulation::contact_energy() runs it only when a sample is taken, never inside
// the step). One thread per particle i:
//   pairs  sum over i's neighbours j > i of Law(m_i, m_j).stored_energy(collide(i, j), state)  [J]
//          (the state: i's copy of the pair's, for a tangential spring's |F_e|^2 / (2 k_t))
//          (each pair once, from its lower index, with the very call ContactForces and
//          PairForces make for that pair: collide(lower, higher) on the same list);
//   walls  sum over i's contacts with world objects (world_contacts.hpp: a mesh's merged ones) of
//          Law(m_i, m_w).stored_energy(contact, state)                                   [J]
//   wall_contacts  the number of those contacts.
// With `counted` (a rank's own particles flagged, its ghosts not: kernels/sample_tally.hpp) a pair
// with a ghost is held by the lower permanent id, so over all ranks each pair counts once.
// The energies are formed in double (the law's stored_energy returns double) and written per
// particle; reduce_in_order (exec/primitives.hpp, through kernels/sample_tally.hpp) adds them in
// a fixed order per backend, so the total is deterministic (no atomics) and the backends agree up
// to the geometry's rounding and their two summation orders.
// The two sums are two kernels (Part: pairs, then walls), each writing its own slots: in one kernel
// nvcc gave a polyhedron with a mesh a 30 KB stack frame a thread (1.2 KB for the pairs alone,
// 7.2 KB for the walls), and a CUDA context reserves a kernel's frame for every thread the GPU can
// hold: 8.3 GB on an H100, which ran twelve corn hoppers side by side out of memory (make fig-2.17).
#pragma once
#include "blaze/exec/launch.hpp"
#include "blaze/laws/contact_law.hpp"
#include "blaze/particles/particle_store.hpp"
#include "blaze/world/world.hpp"
#include "kernels/broad_phase_kernels.hpp"
#include "kernels/contact_history.hpp"
#include "kernels/world_contacts.hpp"

namespace blaze {

// Per-particle outputs of StoredContactEnergy.
struct ContactEnergySlots {
  double* pairs;         // J, contacts with neighbours of higher index
  double* walls;         // J, contacts with world objects
  Index* wall_contacts;  // world objects touched
};

enum class ContactEnergyPart { pairs, walls };

template <class Shape, class Law, ContactEnergyPart Part>
struct StoredContactEnergy {
  using Real = typename Law::real_type;
  static constexpr int kMinBlocks = min_blocks_v<Shape>;  // launch.hpp
  Shape shape;
  ParticleView<Real> p;
  NeighbourView list;
  WorldView<Real> world;
  PairTable<Law> laws;
  ContactEnergySlots out;
  PairHistoryView<Real, Law::State::kReals> history;  // a tangential spring's energy is in the state
  WallHistoryView<Real, Law::State::kReals> wall_history;
  PeriodicImages<Real> images;  // periodic axes (grid/periodic_images.hpp)
  const std::uint8_t* counted = nullptr;

  BLAZE_HD void operator()(Index i) const {
    if constexpr (Part == ContactEnergyPart::pairs) out.pairs[i] = pair_sum(i);
    else wall_sum(i);
  }

 private:
  BLAZE_HD double pair_sum(Index i) const {
    const auto bi = shape.body(p, i);
    const int mi = p.material[i];
    double pairs = 0;
    const Index count = min_r(list.count[i], list.capacity);
    for (Index k = 0; k < count; ++k) {
      const Index j = list.at(k, i);
      const bool j_counts = !counted || counted[j];
      if (j_counts ? j < i : p.id[j] < p.id[i]) continue;  // j's thread (or j's rank) holds this pair
      auto bj = shape.body(p, j);
      if (images.on()) bj.x = bj.x + images.shift(list.offset(k, i));  // j's image beside i
      const ContactGeometry<Real> g = shape.collide(bi, bj);
      if (!g.touching) continue;
      const auto state = Law::kHistory ? history.load(list.offset(k, i)) : Law::State::zero();
      pairs += laws(mi, p.material[j]).stored_energy(g, state);
    }
    return pairs;
  }
  BLAZE_HD void wall_sum(Index i) const {
    const auto bi = shape.body(p, i);
    const int mi = p.material[i];
    double walls = 0;
    Index touched = 0;
    for_each_world_contact(shape, bi, world, i, [&](const auto& g, int material, int, WallKey key, const auto*) {
      if (!g.touching) return;
      auto state = Law::State::zero();
      if constexpr (Law::kHistory) {
        const int h = wall_history.find(i, key);
        if (h >= 0) state = wall_history.load(h, i);
      }
      walls += laws(mi, material).stored_energy(g, state);
      ++touched;
    });
    out.walls[i] = walls;
    out.wall_contacts[i] = touched;
  }
};

}  // namespace blaze
