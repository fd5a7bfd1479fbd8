// Broad-phase kernels (thesis Algorithm 2.1, lines 1-3): hash, cell bounds, neighbour list, and
// the per-step test of whether the list is still valid.
#pragma once
#include <cstdint>
#include "blaze/grid/grid_spec.hpp"
#include "blaze/grid/periodic_images.hpp"
#include "blaze/particles/particle_store.hpp"

namespace blaze {

inline constexpr std::uint32_t kEmptyCell = 0xffffffffu;

// Neighbour list: entry k of particle i at index[k * stride + i] (consecutive threads read
// consecutive addresses). count[i] may exceed capacity: the list then overflowed and is rebuilt
// with more room. The list is symmetric (j lists i when i lists j: the same rounding both ways).
// With pairs evaluated once (pair_forces.hpp) it also has a reverse index: for an entry (k, i)
// whose j is below i, the position of i in j's list (other entries: unused; null otherwise).
struct NeighbourView {
  Index* index;
  Index* count;
  Index stride;
  Index capacity;
  Index* reverse = nullptr;
  // Where entry k of particle i lies, in 64 bits (capacity x N passes 2^31 above ~1e8 particles).
  BLAZE_HD std::size_t offset(Index k, Index i) const {
    return static_cast<std::size_t>(k) * static_cast<std::size_t>(stride) + static_cast<std::size_t>(i);
  }
  BLAZE_HD Index& at(Index k, Index i) const { return index[offset(k, i)]; }
  BLAZE_HD Index& reverse_at(Index k, Index i) const { return reverse[offset(k, i)]; }
};

// Before line 1 on a grid with periodic axes: each particle back into [lo, hi) along them, its
// image count moved by the periods it crossed (grid/periodic_images.hpp).
template <class Real>
struct WrapPeriodic {
  GridSpec<Real> grid;
  Vec3Field<Real> position;
  Index* image[3];
  BLAZE_HD void operator()(Index i) const {
    Vec3<Real> x = position.get(i);
    Real* c[3] = {&x.x, &x.y, &x.z};
    const Real lo[3] = {grid.lo.x, grid.lo.y, grid.lo.z}, hi[3] = {grid.hi.x, grid.hi.y, grid.hi.z};
    const Real l[3] = {grid.length.x, grid.length.y, grid.length.z};
    for (int d = 0; d < 3; ++d) {
      if (!((grid.periodic >> d) & 1u) || !(*c[d] - *c[d] == Real(0))) continue;  // NaN, Inf: left to the guard
      if (*c[d] >= lo[d] && *c[d] < hi[d]) continue;
      const Real k = floor_r((*c[d] - lo[d]) / l[d]);  // periods crossed (1 or -1 but for a very fast particle)
      *c[d] -= k * l[d];
      Index n = static_cast<Index>(k);
      if (*c[d] >= hi[d]) *c[d] -= l[d], ++n;  // rounding at the faces
      if (*c[d] < lo[d]) *c[d] += l[d], --n;
      if (!(*c[d] < hi[d])) *c[d] = lo[d];  // lo - (an ulp) + L rounded up to hi: the face itself
      image[d][i] += n;
    }
    position.set(i, x);
  }
};

// Line 1: key = cell hash (eq. 2.1), or the outside key for particles that left the domain.
template <class Real>
struct HashParticles {
  GridSpec<Real> grid;
  Vec3Field<Real> position;
  std::uint32_t* key;
  Index* order;
  BLAZE_HD void operator()(Index i) const {
    int cx, cy, cz;
    key[i] = grid.cell_of(position.get(i), cx, cy, cz) ? grid.hash(cx, cy, cz) : grid.outside_key();
    order[i] = i;
  }
};

// After sorting: first and one-past-last particle of every occupied cell.
struct CellBounds {
  const std::uint32_t* key;
  Index n;
  std::uint32_t* start;
  std::uint32_t* end;
  BLAZE_HD void operator()(Index i) const {
    const std::uint32_t k = key[i];
    if (i == 0 || key[i - 1] != k) start[k] = static_cast<std::uint32_t>(i);
    if (i == n - 1 || key[i + 1] != k) end[k] = static_cast<std::uint32_t>(i + 1);
  }
};

// Line 3: every j within r_i + r_j + skin of i, from the 27 cells around i's cell, in a fixed
// order (cells y-z-x, particles by sorted index) so that every backend builds the same list.
template <class Real>
struct BuildNeighbours {
  GridSpec<Real> grid;
  Vec3Field<Real> position;
  const Real* radius;
  const std::uint32_t* start;
  const std::uint32_t* end;
  Real skin;
  NeighbourView list;
  PeriodicImages<Real> images;  // periodic axes: each entry's image code written beside it

  // A neighbouring cell index along an axis of n cells: wrapped on a periodic axis, else -1 when
  // past the grid's edge.
  BLAZE_HD static int neighbour_cell(int c, int n, bool periodic) {
    return c >= 0 && c < n ? c : periodic ? (c < 0 ? c + n : c - n) : -1;
  }

  BLAZE_HD void operator()(Index i) const {
    const Vec3<Real> xi = position.get(i);
    const Real ri = radius[i];
    int cx = 0, cy = 0, cz = 0;
    grid.cell_of(xi, cx, cy, cz);  // inside: outsiders were removed (or wrapped) before the build
    Index count = 0;
    for (int dy = -1; dy <= 1; ++dy) {
      const int y = neighbour_cell(cy + dy, grid.ny, grid.periodic & 2u);
      if (y < 0) continue;
      for (int dz = -1; dz <= 1; ++dz) {
        const int z = neighbour_cell(cz + dz, grid.nz, grid.periodic & 4u);
        if (z < 0) continue;
        for (int dx = -1; dx <= 1; ++dx) {
          const int x = neighbour_cell(cx + dx, grid.nx, grid.periodic & 1u);
          if (x < 0) continue;
          const std::uint32_t cell = grid.hash(x, y, z);
          const std::uint32_t s = start[cell];
          if (s == kEmptyCell) continue;
          for (std::uint32_t j = s; j < end[cell]; ++j) {
            if (static_cast<Index>(j) == i) continue;
            const Real reach = (ri + radius[j]) + skin;  // same rounding for (i, j) and (j, i)
            Vec3<Real> d = position.get(static_cast<Index>(j)) - xi;
            std::uint8_t code = 0;
            if (images.code) {  // the nearest image (d -> -d from j's side: the negated code)
              code = PeriodicImages<Real>::encode(d, images.length);
              d = d + images.shift_of(code);
            }
            if (norm2(d) < reach * reach) {
              if (count < list.capacity) {
                list.at(count, i) = static_cast<Index>(j);
                if (images.code) images.code[list.offset(count, i)] = code;
              }
              ++count;
            }
          }
        }
      }
    }
    list.count[i] = count;
  }
};

// Canonical order (issue 21): particle i's entries sorted by their permanent ids (insertion sort,
// image codes carried along), so its contact forces are summed in one order however the particles
// lie in memory: a run over several ranks (each with its own memory order) or one process give
// bitwise the same forces, and so the same trajectory.
template <class Real>
struct SortNeighboursById {
  NeighbourView list;
  PeriodicImages<Real> images;
  const Index* id;
  BLAZE_HD void operator()(Index i) const {
    const Index count = min_r(list.count[i], list.capacity);
    for (Index k = 1; k < count; ++k) {
      const Index j = list.at(k, i), key = id[j];
      const std::uint8_t code = images.code ? images.code[list.offset(k, i)] : std::uint8_t{0};
      Index m = k;
      for (; m > 0 && id[list.at(m - 1, i)] > key; --m) {
        list.at(m, i) = list.at(m - 1, i);
        if (images.code) images.code[list.offset(m, i)] = images.code[list.offset(m - 1, i)];
      }
      list.at(m, i) = j;
      if (images.code) images.code[list.offset(m, i)] = code;
    }
  }
};

// The reverse index of entries (k, i) with j < i: the k' with list.at(k', j) == i (a short search
// of j's list, at each build). Run as a reduction that also checks the list's symmetry, which
// the pair kernels rely on: 1 if some j does not list i back (in either direction, a bug the
// caller reports), else 0.
struct BuildReverse {
  NeighbourView list;
  BLAZE_HD int operator()(Index i) const {
    int missing = 0;
    const Index count = min_r(list.count[i], list.capacity);
    for (Index k = 0; k < count; ++k) {
      const Index j = list.at(k, i);
      const Index count_j = min_r(list.count[j], list.capacity);
      Index m = 0;
      while (m < count_j && list.at(m, j) != i) ++m;
      if (j < i) list.reverse_at(k, i) = m;
      missing |= m == count_j ? 1 : 0;
    }
    return missing;
  }
};

// The in-block rebuild (pipeline/in_block_rebuild.hpp): the list rebuilt without the grid, for
// systems small enough to be stepped by one block (phases.hpp). Its phases:
//   ListAllPairs    particle i tests every j: n^2 tests, but no chain of dependent loads (a walk of
//                   the grid's 27 cells is one per cell, per particle, after a sort), and no
//                   sort or reorder; the same pairs as a build through the cells, in memory order;
//                   i's reference position; 1 if the rebuild may not run in place (the caller's
//                   switch), i left the grid (the host removes it) or its list overflowed (the
//                   host grows it)
//   ReverseInPlace  pairs once: the reverse index (1: the list is not symmetric, a bug the host
//                   build reports)
// and the world lists (WorldListsInPlace, kernels/world_candidates.hpp).
template <class Real>
struct ListAllPairs {
  GridSpec<Real> grid;
  Vec3Field<Real> position;
  const Real* radius;
  Real skin;
  NeighbourView list;
  Vec3Field<Real> reference;
  Index n;
  bool enabled;
  BLAZE_HD int operator()(Index i) const {
    if (!enabled) return 1;
    const Vec3<Real> xi = position.get(i);
    int cx, cy, cz;
    if (!grid.cell_of(xi, cx, cy, cz)) return 1;
    const Real ri = radius[i];
    Index count = 0;
    // kChunk partners at a time: their loads are issued together, then tested (one partner at a
    // time, the list's stores kept each partner's loads waiting on the test before; H100, the
    // turning 242-ball mill: 5.6e4 -> 5.8e4 steps/s, bench/results/levers/near-first.md).
    constexpr Index kChunk = 8;
    for (Index j0 = 0; j0 < n; j0 += kChunk) {
      Vec3<Real> xj[kChunk];
      Real rj[kChunk];
      BLAZE_UNROLL
      for (Index c = 0; c < kChunk; ++c) {
        const Index j = j0 + c < n ? j0 + c : n - 1;
        xj[c] = position.get(j), rj[c] = radius[j];
      }
      BLAZE_UNROLL
      for (Index c = 0; c < kChunk; ++c) {
        const Index j = j0 + c;
        const Real reach = (ri + rj[c]) + skin;  // same rounding for (i, j) and (j, i), as BuildNeighbours
        if (j >= n || j == i || !(norm2(xj[c] - xi) < reach * reach)) continue;
        if (count < list.capacity) list.at(count, i) = j;
        ++count;
      }
    }
    list.count[i] = count;
    reference.set(i, xi);
    return count > list.capacity ? 1 : 0;
  }
};

struct ReverseInPlace {
  BuildReverse reverse;
  bool on;  // pairs once
  BLAZE_HD int operator()(Index i) const { return on ? reverse(i) : 0; }
};

// 1 if particle i moved more than half the skin since the last build, or left the domain, or
// the world's moving objects have moved as far as the world lists allow (world_candidates.hpp).
template <class Real>
struct NeedsRebuild {
  GridSpec<Real> grid;
  Vec3Field<Real> position;
  Vec3Field<Real> reference;
  Real half_skin_squared;
  const std::uint64_t* world_step = nullptr;  // the step the world's poses are for; null: no lists to keep
  const std::uint64_t* world_valid_until = nullptr;  // the last step the lists hold for (kept where the builds write it)
  // 0: list still valid; 1: particle i moved half the skin or left the grid; 2: its position is
  // not finite (NaN or Inf). The step's one reduction thus doubles as the NaN guard at no extra
  // load: a NaN force or velocity reaches the position at the next drift, which this check follows
  // (a NaN angular velocity one or two steps later, through the contact forces). Without it a NaN
  // position would hash as "outside" and the particle be removed as if it had left the domain.
  BLAZE_HD int operator()(Index i) const {
    const Vec3<Real> x = position.get(i);
    if (!finite_r(x.x + x.y + x.z)) return 2;
    if (half_skin_squared < Real(0)) return 1;  // first build: no reference positions yet
    int cx, cy, cz;
    // (a periodic axis does not count: a particle past it is wrapped at the next build)
    if (grid.periodic ? !grid.inside_fixed_axes(x) : !grid.cell_of(x, cx, cy, cz)) return 1;
    if (world_step && *world_step > *world_valid_until) return 1;
    return norm2(x - reference.get(i)) > half_skin_squared ? 1 : 0;
  }
};

template <class T>
struct ValueOf {
  const T* v;
  BLAZE_HD int operator()(Index i) const { return static_cast<int>(v[i]); }
};

template <class Real>
struct CopyVec3 {
  Vec3Field<Real> src, dst;
  BLAZE_HD void operator()(Index i) const { dst.set(i, src.get(i)); }
};

}  // namespace blaze
