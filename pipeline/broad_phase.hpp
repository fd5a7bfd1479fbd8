// Broad phase on one memory space: the uniform grid, the sort by cell hash with the particle
// arrays reordered (thesis section 2.2.3: sorting gave it 32x), cell start/end, and a Verlet
// neighbour list with a skin, rebuilt when any particle has moved more than half the skin since
// the last build or has left the domain. Particles outside the domain at a rebuild are sorted to
// the end, counted, their mass summed, and dropped. Along periodic axes particles are wrapped back
// into the box first (grid/periodic_images.hpp), and the list keeps each entry's image.
#pragma once
#include <algorithm>
#include <cstdint>
#include <stdexcept>
#include "blaze/exec/primitives.hpp"
#include "blaze/sim/phase_timer.hpp"
#include "kernels/broad_phase_kernels.hpp"

namespace blaze {

template <class Real, class Space>
class BroadPhase {
 public:
  struct Removed {
    Index count = 0;
    double mass = 0;  // kg
    // Translational kinetic + potential energy (J, potential in `gravity`) at the moment of
    // removal, for the run's energy balance (rotational energy is left out: a particle leaving
    // the domain carries little of it).
    double energy = 0;
  };

  BroadPhase(const GridSpec<Real>& grid, Real skin) : grid_(grid), skin_(skin) {
    cell_start_.resize(grid_.cell_count() + 1);
    cell_end_.resize(grid_.cell_count() + 1);
    end_bit_ = 1;
    while (end_bit_ < 32 && (std::uint64_t{1} << end_bit_) <= grid_.outside_key()) ++end_bit_;
  }

  const GridSpec<Real>& grid() const { return grid_; }
  Real skin() const { return skin_; }
  Index capacity() const { return capacity_; }
  std::uint64_t builds() const { return builds_; }

  // 0: the neighbour list is valid; 1: it must be rebuilt; 2: some particle's position is not finite.
  // `fresh`: the store was replaced since the last build (Simulation::reload), so the reference
  // positions are not its particles' (nor as many): only finiteness is checked (1 or 2).
  int rebuild_check(ParticleStore<Real, Space>& store, bool fresh = false) {
    auto p = store.view();
    const Real h = Real(0.5) * skin_, h2 = builds_ == 0 || fresh ? Real(-1) : h * h;
    const int code = reduce_max(Space{}, p.n,
                                NeedsRebuild<Real>{grid_, p.position, field(reference_), h2}, 0);
    return builds_ == 0 && code == 0 ? 1 : code;
  }

  // The same check as a functor (fused steps), after the first build only; it also trips when
  // *world_step passes *world_valid_until (world lists: pipeline/world_candidates.hpp; both or
  // neither given).
  NeedsRebuild<Real> rebuild_check_functor(ParticleStore<Real, Space>& store, const std::uint64_t* world_step = nullptr,
                                           const std::uint64_t* world_valid_until = nullptr) {
    if (builds_ == 0) throw std::logic_error("broad phase: the rebuild check needs a first build");
    const Real h = Real(0.5) * skin_;
    return {grid_, store.view().position, field(reference_), h * h, world_step, world_valid_until};
  }

  // with_forces: also move force and torque (a rebuild between steps, for a checkpoint).
  Removed rebuild(ParticleStore<Real, Space>& store, PhaseTimer<Space>& timer, const Vec3<Real>& gravity,
                  bool with_forces = false) {
    const Index n = store.size();
    keys_.ensure(n);
    order_.ensure(n);
    timer.time("hash", [&] {
      if (grid_.periodic)  // back into the box along the periodic axes, counting the images
        for_each(Space{}, n, WrapPeriodic<Real>{grid_, store.view().position, {store.image(0), store.image(1), store.image(2)}});
      for_each(Space{}, n, HashParticles<Real>{grid_, store.view().position, keys_.data(), order_.data()});
    });
    timer.time("sort", [&] { sorter_.sort_pairs(keys_.data(), order_.data(), n, end_bit_); });
    timer.time("reorder", [&] { store.permute(order_.data(), with_forces); });
    Removed removed;
    timer.time("neighbours", [&] {
      const Index cells = static_cast<Index>(grid_.cell_count()) + 1;
      for_each(Space{}, cells, Fill<std::uint32_t>{cell_start_.data(), kEmptyCell});
      for_each(Space{}, n, CellBounds{keys_.data(), n, cell_start_.data(), cell_end_.data()});
      const std::uint32_t first_outside = read_one(cell_start_.data() + grid_.outside_key(), Space{});
      if (first_outside != kEmptyCell) {
        removed.count = n - static_cast<Index>(first_outside);
        const auto p = store.view();
        std::vector<Real> inv_m(removed.count), x[3], v[3];
        copy_n(p.inv_mass + first_outside, inv_m.size(), inv_m.data(), Space{}, Host{});
        const Real* xs[3] = {p.position.x, p.position.y, p.position.z};
        const Real* vs[3] = {p.velocity.x, p.velocity.y, p.velocity.z};
        for (int d = 0; d < 3; ++d) {
          x[d].resize(removed.count), v[d].resize(removed.count);
          copy_n(xs[d] + first_outside, x[d].size(), x[d].data(), Space{}, Host{});
          copy_n(vs[d] + first_outside, v[d].size(), v[d].data(), Space{}, Host{});
        }
        for (std::size_t k = 0; k < inv_m.size(); ++k) {
          const double m = 1.0 / static_cast<double>(inv_m[k]);
          removed.mass += m;
          double v2 = 0, gx = 0;
          for (int d = 0; d < 3; ++d) v2 += static_cast<double>(v[d][k]) * static_cast<double>(v[d][k]);
          gx = static_cast<double>(gravity.x) * x[0][k] + static_cast<double>(gravity.y) * x[1][k] +
               static_cast<double>(gravity.z) * x[2][k];
          removed.energy += 0.5 * m * v2 - m * gx;
        }
        store.truncate(static_cast<Index>(first_outside));
      }
      build_list(store);
    });
    return removed;
  }

  // The in-block rebuild's phases (kernels/broad_phase_kernels.hpp; run by a check's handler,
  // phases.hpp): the list rebuilt where the particles lie, for the one-block path's small systems
  // (pipeline/in_block_rebuild.hpp says when). `enabled` false: its first check gives 1, and the
  // host rebuilds. Not with the previous list kept (contact history), canonical order or
  // periodic axes (a host rebuild does those).
  struct InBlockParts {
    ListAllPairs<Real> list;
    ReverseInPlace reverse;
    std::uint64_t* builds;  // [0]: the lists built in place
  };
  InBlockParts in_block_parts(ParticleStore<Real, Space>& store, bool enabled) {
    auto p = store.view();
    enabled = enabled && builds_ > 0 && !with_previous_ && !by_id_ && !grid_.periodic && stride_ == p.n;
    if (in_block_builds_.size() == 0) from_host(in_block_builds_, std::vector<std::uint64_t>{0});
    return {ListAllPairs<Real>{grid_, p.position, p.radius, skin_, neighbours(), field(reference_), p.n, enabled},
            ReverseInPlace{BuildReverse{neighbours()}, with_reverse_}, in_block_builds_.data()};
  }
  // Lists built in place (the in-block rebuild) since the start.
  std::uint64_t in_block_builds() const { return in_block_builds_.size() ? read_one(in_block_builds_.data(), Space{}) : 0; }

  // Device memory held by the broad phase (grid cells, sort buffers, neighbour list), bytes.
  std::size_t bytes() const {
    std::size_t b = (keys_.size() + cell_start_.size() + cell_end_.size()) * sizeof(std::uint32_t);
    b += images_.size();
    b += (order_.size() + list_.size() + count_.size() + reverse_.size() + previous_list_.size() + previous_count_.size()) *
         sizeof(Index);
    for (const auto& c : reference_) b += c.size() * sizeof(Real);
    return b;
  }

  NeighbourView neighbours() {
    return {list_.data(), count_.data(), stride_, capacity_, with_reverse_ ? reverse_.data() : nullptr};
  }
  // The list entries' image codes (grid/periodic_images.hpp); off without periodic axes.
  PeriodicImages<Real> images() {
    return grid_.periodic ? PeriodicImages<Real>{images_.data(), grid_.length} : PeriodicImages<Real>{};
  }

  // Keep the list's reverse index from the next build on (pairs evaluated once).
  void keep_reverse_index() { with_reverse_ = true; }
  // Sort each particle's list by permanent id at every build (SortNeighboursById: canonical order).
  void order_by_id() { by_id_ = true; }
  // Keep the previous list through each build (a contact store carries its states over by it).
  void keep_previous_list() { with_previous_ = true; }
  // The list before the last build, in the order before its sort (keep_previous_list()).
  NeighbourView previous_neighbours() {
    return {previous_list_.data(), previous_count_.data(), previous_stride_, previous_capacity_, nullptr};
  }
  // The last rebuild's sort: particle i now was particle order()[i] before it.
  const Index* order() const { return order_.data(); }

 private:
  static Vec3Field<Real> field(Buffer<Real, Space> (&f)[3]) { return {f[0].data(), f[1].data(), f[2].data()}; }

  void build_list(ParticleStore<Real, Space>& store) {
    auto p = store.view();
    if (with_previous_) {
      list_.swap(previous_list_);
      count_.swap(previous_count_);
      previous_stride_ = stride_, previous_capacity_ = capacity_;
    }
    stride_ = p.n;
    count_.ensure(p.n);
    for (;;) {
      list_.ensure(static_cast<std::size_t>(capacity_) * p.n);
      if (grid_.periodic) images_.ensure(list_.size());
      for_each(Space{}, p.n,
               BuildNeighbours<Real>{grid_, p.position, p.radius, cell_start_.data(), cell_end_.data(), skin_,
                                     neighbours(), images()});
      const Index most = reduce_max(Space{}, p.n, ValueOf<Index>{count_.data()}, 0);
      if (most <= capacity_) break;
      capacity_ = most + most / 4 + 1;  // grow with headroom, rebuild
      // exact (ensure's headroom is for a growing count)
      if (list_.size() < static_cast<std::size_t>(capacity_) * p.n) list_.resize(static_cast<std::size_t>(capacity_) * p.n);
    }
    if (by_id_) for_each(Space{}, p.n, SortNeighboursById<Real>{neighbours(), images(), p.id});
    if (with_reverse_) {
      reverse_.ensure(list_.size());
      if (reduce_max(Space{}, p.n, BuildReverse{neighbours()}, 0) > 0)
        throw std::logic_error("blaze broad phase: the neighbour list is not symmetric (some j does not list i back), "
                               "so pairs cannot be evaluated once; this is a bug, please report it");
    }
    for (auto& c : reference_) c.ensure(p.n);
    for_each(Space{}, p.n, CopyVec3<Real>{p.position, field(reference_)});
    ++builds_;
  }

  GridSpec<Real> grid_;
  Real skin_;
  int end_bit_;
  Buffer<std::uint32_t, Space> keys_;
  Buffer<Index, Space> order_;
  Buffer<std::uint32_t, Space> cell_start_, cell_end_;
  Buffer<Index, Space> list_, count_, reverse_, previous_list_, previous_count_;
  Buffer<std::uint8_t, Space> images_;  // periodic axes: each list entry's image code
  bool with_reverse_ = false, with_previous_ = false, by_id_ = false;
  Index previous_stride_ = 0, previous_capacity_ = 0;
  Buffer<Real, Space> reference_[3];
  Buffer<std::uint64_t, Space> in_block_builds_;  // lists built in place
  Index stride_ = 0;
  Index capacity_ = 16;
  std::uint64_t builds_ = 0;
  RadixSorter<Space> sorter_;
};

}  // namespace blaze
