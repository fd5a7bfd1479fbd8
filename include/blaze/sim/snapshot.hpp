// What a run needs to continue bit for bit: a SimulationSnapshot (pipeline/simulation.hpp takes
// and restores it; io/checkpoint.hpp writes it to disk).
#pragma once
#include <cstdint>
#include "blaze/particles/particle_store.hpp"

namespace blaze {

// Everything a run needs to continue bit for bit (with the same params, laws, world and shape):
// the store's raw arrays and the counters. Taken right after a neighbour-list rebuild, so the
// restarted run rebuilds the same list (Simulation::snapshot()).
template <class Real>
struct SimulationSnapshot {
  StoreSnapshot<Real> store;
  std::uint64_t steps = 0;
  Index initial_count = 0, removed_count = 0;
  double removed_mass = 0, removed_energy = 0;
};

}  // namespace blaze
