// The in-block rebuild: a neighbour-list rebuild (and the world lists') run inside the batch,
// as the rebuild check's handler (phases.hpp), instead of leaving the batch for the host.
// A system small enough to be stepped by one block (phases.hpp: the 242-ball lab mill) spent a
// quarter to a half of its step time on host rebuilds when its charge tumbles (H100: ~850
// rebuilds in 20 000 steps at the default skin of 0.2 r, 0.13 ms each against ~25 us a step;
// bench/results/levers/small-mill-phases.md). In place the particles are not sorted in memory
// (for a few hundred, order does not matter) and the grid is not used: each particle tests every
// other (kernels/broad_phase_kernels.hpp, ListAllPairs: n^2 tests with no chain of dependent
// loads, where a walk of the grid's cells is one); the list holds the pairs a host rebuild's
// holds, in memory order. Trajectories agree with host rebuilds' to rounding (the order of a
// particle's sums differs, and a pair's force is formed from its lower index, which the memory
// order decides; verification/test_in_block_rebuild.cpp).
// What stays with the host (the handler then gives 1 and the step stops for it, as before):
// a particle that left the domain (its removal), a list that overflowed (its growth), contact
// history (its states carried to the new list), canonical order and periodic axes (the host's
// sort and wrap), triangle lists.
// InBlockRebuild::automatic runs it on the GPU for up to kInBlockRebuildMax particles on the
// one-block path; `on` runs it on every backend (tests compare it with `off` on the CPU, where
// a host rebuild of a few hundred particles costs less than the n^2 count).
#pragma once
#include <cstdint>
#include <type_traits>
#include "blaze/exec/phases.hpp"
#include "blaze/exec/space.hpp"
#include "pipeline/broad_phase.hpp"
#include "pipeline/world_candidates.hpp"

namespace blaze {

enum class InBlockRebuild { automatic, on, off };
// The most particles the rebuild takes in place (ListAllPairs' n^2 tests: ~1e6 here).
constexpr Index kInBlockRebuildMax = 1024;

// Whether a run of n particles rebuilds in place (the structural conditions are checked by the
// broad phase and the world lists themselves). one_block: the most the one-block path steps.
template <class Space>
bool in_block_rebuild_wanted(InBlockRebuild mode, Index n, Index one_block) {
  if (mode == InBlockRebuild::off || n > kInBlockRebuildMax) return false;
  if (mode == InBlockRebuild::on) return true;
  return !std::is_same_v<Space, Host> && n <= one_block;
}

// The handler's phases: the broad phase's parts, then the world lists (and the count).
template <class Real, class Space>
auto in_block_rebuild_phases(BroadPhase<Real, Space>& broad, WorldCandidates<Real, Space>& lists, ParticleStore<Real, Space>& store,
                             const WorldView<Real>& world, const std::uint64_t* world_step, bool enabled) {
  auto b = broad.in_block_parts(store, enabled && lists.in_place());
  return make_phases(check_phase("rebuild-list", b.list), check_phase("rebuild-reverse", b.reverse),
                     kernel_phase("rebuild-world-lists", lists.in_place(store.view(), world, world_step, b.builds)));
}

}  // namespace blaze
