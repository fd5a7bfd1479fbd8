// Elastic energy stored in the open contacts, and the contacts with world objects, per particle
// (a diagnostic: Simulation::contact_energy() runs it only when a sample is taken, never inside
// the step). One thread per particle i:
//   pairs  sum over i's neighbours j > i of Law(m_i, m_j).stored_energy(collide(i, j))   [J]
//          (each pair once, from its lower index, with the very call ContactForces and
//          PairForces make for that pair: collide(lower, higher) on the same list);
//   walls  sum over the planar polygons and cylinders w of Law(m_i, m_w).stored_energy(
//          collide_world(i, w))                                                          [J]
//   wall_contacts  the number of those world objects i touches (polygons and cylinders alike).
// The energies are formed in double (the law's stored_energy returns double) and written per
// particle; the host sums them in index order, so the total is deterministic and the same on
// every backend up to the geometry's rounding (no atomics, no reduction order to vary).
#pragma once
#include "blaze/exec/launch.hpp"
#include "blaze/laws/contact_law.hpp"
#include "blaze/particles/particle_store.hpp"
#include "blaze/world/world.hpp"
#include "kernels/broad_phase_kernels.hpp"

namespace blaze {

// Per-particle outputs of StoredContactEnergy.
struct ContactEnergySlots {
  double* pairs;         // J, contacts with neighbours of higher index
  double* walls;         // J, contacts with world objects
  Index* wall_contacts;  // world objects touched
};

template <class Shape, class Law>
struct StoredContactEnergy {
  using Real = typename Law::real_type;
  static constexpr int kMinBlocks = min_blocks_v<Shape>;  // launch.hpp
  Shape shape;
  ParticleView<Real> p;
  NeighbourView list;
  WorldView<Real> world;
  PairTable<Law> laws;
  ContactEnergySlots out;

  BLAZE_HD void operator()(Index i) const {
    const auto bi = shape.body(p, i);
    const int mi = p.material[i];
    double pairs = 0, walls = 0;
    Index touched = 0;
    const Index count = min_r(list.count[i], list.capacity);
    for (Index k = 0; k < count; ++k) {
      const Index j = list.at(k, i);
      if (j < i) continue;  // j's thread holds this pair
      const ContactGeometry<Real> g = shape.collide(bi, shape.body(p, j));
      if (g.touching) pairs += laws(mi, p.material[j]).stored_energy(g);
    }
    const auto wall = [&](const ContactGeometry<Real>& g, int material) {
      if (!g.touching) return;
      walls += laws(mi, material).stored_energy(g);
      ++touched;
    };
    for (int k = 0; k < world.polygon_count; ++k) wall(shape.collide_world(bi, world.polygons[k]), world.polygons[k].material);
    for (int k = 0; k < world.cylinder_count; ++k) wall(shape.collide_world(bi, world.cylinders[k]), world.cylinders[k].material);
    out.pairs[i] = pairs;
    out.walls[i] = walls;
    out.wall_contacts[i] = touched;
  }
};

}  // namespace blaze
