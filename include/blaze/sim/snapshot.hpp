// What a run needs to continue bit for bit: a SimulationSnapshot (pipeline/simulation.hpp takes
// and restores it; io/checkpoint.hpp writes it to disk).
#pragma once
#include <cstdint>
#include <vector>
#include "blaze/laws/contact_state.hpp"
#include "blaze/particles/particle_store.hpp"

namespace blaze {

// Everything a run needs to continue bit for bit (with the same params, laws, world and shape):
// the store's raw arrays and the counters. Taken right after a neighbour-list rebuild, so the
// restarted run rebuilds the same list (Simulation::snapshot()).
// The contact store's contents on the host (pipeline/contact_store.hpp), keyed by permanent ids.
template <class Real>
struct ContactSnapshot {
  int used = 0;                       // reals per contact
  std::vector<Index> pair_ids;        // (id_i, id_j) per pair state, i's copy
  std::vector<Real> pair_values;      // `used` per pair state
  std::vector<Index> wall_ids;        // particle id per wall state
  std::vector<WallKey> wall_objects;  // the contacts' keys (object, or mesh triangle)
  std::vector<Real> wall_values;
};

template <class Real>
struct SimulationSnapshot {
  StoreSnapshot<Real> store;
  ContactSnapshot<Real> contacts;  // the contact store (laws with history; empty otherwise)
  std::uint64_t steps = 0;
  Index initial_count = 0, removed_count = 0;
  double removed_mass = 0, removed_energy = 0;
  Index inserted_count = 0;  // particles inserted after the start (feeders)
  double inserted_mass = 0, inserted_energy = 0, inserted_kinetic = 0;  // kg; J when inserted (all, kinetic)
  Index next_id = 0;  // the next inserted particle's permanent id
};

}  // namespace blaze
