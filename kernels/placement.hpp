// A feeder's rounds of random sequential addition (pipeline/feeder.hpp), where the particles live:
// spheres in hashed cells (SphereCellsView), the draws and tests of the particles due
// (DrawCandidates), the round's candidates put into cells (PutCandidates) and tested against the
// earlier ones (TestAgainstEarlier), the kept added to what is there (KeepCandidates). Particles
// are numbered by their place among those due, so no round needs a scan: a kernel runs over all of
// them and those placed before skip. One code on the host (OpenMP) and the GPU; every answer a
// kernel reads from the cells is a yes or no, so the order in which threads link spheres into a
// cell changes nothing, and a round gives the same centres on any number of threads.
//
// Cells: cubes of side `cell` (>= 2 r_max) from `lo`, each hashed into a table of a power of two
// heads (cells beyond a box need no room; two cells may share a head, which only lengthens a
// chain). A query of a sphere (x, r <= r_max) reads the cells within r + r_max of x: 27 at most.
// Spheres are numbered in the order they are put (entries [0, size)); a query may see only those
// below `before` (a round's candidates see the earlier ones).
#pragma once
#include <cstdint>
#include "blaze/config.hpp"
#include "blaze/core/counter_random.hpp"
#include "blaze/core/vec3.hpp"
#include "blaze/exec/launch.hpp"
#include "blaze/scene/insertion_region.hpp"
#include "blaze/scene/world_block.hpp"

namespace blaze {

struct SphereCellsView {
  Vec3<double> lo;     // m
  double inv_cell;     // 1/m
  double r_max;        // m: no sphere put is larger
  std::uint32_t mask;  // heads - 1 (a power of two less one)
  int* head;           // per hash: the newest entry, or -1
  int* next;           // per entry: the next of its chain, or -1
  double* sphere;      // per entry: x, y, z, r (m)

  BLAZE_HD long cell_along(double v, double origin) const { return static_cast<long>(::floor((v - origin) * inv_cell)); }
  BLAZE_HD std::uint32_t hash(long i, long j, long k) const {
    return (static_cast<std::uint32_t>(i) * 73856093u ^ static_cast<std::uint32_t>(j) * 19349663u ^ static_cast<std::uint32_t>(k) * 83492791u) & mask;
  }
  // Entry e is the sphere (x, r) (from one thread per entry; many at once).
  BLAZE_HD void put(int e, const Vec3<double>& x, double r) const {
    sphere[4 * e] = x.x, sphere[4 * e + 1] = x.y, sphere[4 * e + 2] = x.z, sphere[4 * e + 3] = r;
    next[e] = atomic_exchange(&head[hash(cell_along(x.x, lo.x), cell_along(x.y, lo.y), cell_along(x.z, lo.z))], e);
  }
  // Does (x, r) overlap an entry below `before` by more than `slack` (m)?
  BLAZE_HD bool overlapping(const Vec3<double>& x, double r, double slack, int before) const {
    const double reach = r + r_max;
    const long i0 = cell_along(x.x - reach, lo.x), i1 = cell_along(x.x + reach, lo.x);
    const long j0 = cell_along(x.y - reach, lo.y), j1 = cell_along(x.y + reach, lo.y);
    const long k0 = cell_along(x.z - reach, lo.z), k1 = cell_along(x.z + reach, lo.z);
    for (long i = i0; i <= i1; ++i)
      for (long j = j0; j <= j1; ++j)
        for (long k = k0; k <= k1; ++k)
          for (int e = head[hash(i, j, k)]; e >= 0; e = next[e]) {
            if (e >= before) continue;
            const double* q = sphere + 4 * e;
            const double touch = r + q[3] - slack, dx = x.x - q[0], dy = x.y - q[1], dz = x.z - q[2];
            if (dx * dx + dy * dy + dz * dz < touch * touch) return true;
          }
    return false;
  }
};

// Entries [base, base + n) from spheres found where the particles live (x, y, z, r in Real).
template <class Real>
struct PutFound {
  SphereCellsView cells;
  const Real* found;
  int base;
  BLAZE_HD void operator()(Index k) const {
    const Real* f = found + 4 * k;
    cells.put(base + k, {static_cast<double>(f[0]), static_cast<double>(f[1]), static_cast<double>(f[2])}, static_cast<double>(f[3]));
  }
};

// A round over the particles due [0, want): each particle k not yet placed draws centres from its
// own stream (seed, first + k), up to `draws`, until one lies in the domain, clear of the entries
// of `occupied` and of the world: centre[3k..], and ok[k] = 1 when one did (0 for the placed).
struct DrawCandidates {
  SphereCellsView occupied;
  WorldBlockView world;
  InsertionRegion region;
  Vec3<double> domain_lo, domain_hi;  // m
  std::uint64_t seed, first;
  int draws;
  const double* radius;         // m, per particle due
  const std::uint8_t* placed;   // per particle due: placed in an earlier round
  double* centre;               // m, 3 per particle due
  std::uint8_t* ok;

  BLAZE_HD bool inside_domain(const Vec3<double>& x, double r) const {
    return x.x - r >= domain_lo.x && x.x + r <= domain_hi.x && x.y - r >= domain_lo.y && x.y + r <= domain_hi.y &&
           x.z - r >= domain_lo.z && x.z + r <= domain_hi.z;
  }
  BLAZE_HD void operator()(Index k) const {
    ok[k] = 0;
    if (placed[k]) return;
    CounterEngine e(seed, first + static_cast<std::uint64_t>(k));
    const double r = radius[k];
    bool clear = false;
    Vec3<double> x{0, 0, 0};
    for (int t = 0; t < draws && !clear; ++t) {
      x = region.draw(e, r);
      clear = inside_domain(x, r) && !occupied.overlapping(x, r, 0, 0x7fffffff) && !world.blocked(x, r);
    }
    centre[3 * k] = x.x, centre[3 * k + 1] = x.y, centre[3 * k + 2] = x.z;
    ok[k] = clear ? 1 : 0;
  }
};

// The round's candidates that passed (ok[k]) into `cells` as entry k, so that each can be tested
// against the earlier ones (TestAgainstEarlier).
struct PutCandidates {
  SphereCellsView cells;
  const double* radius;
  const double* centre;
  const std::uint8_t* ok;
  BLAZE_HD void operator()(Index k) const {
    if (ok[k]) cells.put(k, {centre[3 * k], centre[3 * k + 1], centre[3 * k + 2]}, radius[k]);
  }
};

// A candidate that overlaps a candidate of its round before it (in `cells` below its own entry;
// passed itself, whether or not it is kept) is not kept: ok[k] = 0.
struct TestAgainstEarlier {
  SphereCellsView cells;
  const double* radius;
  const double* centre;
  std::uint8_t* ok;
  BLAZE_HD void operator()(Index k) const {
    if (ok[k] && cells.overlapping({centre[3 * k], centre[3 * k + 1], centre[3 * k + 2]}, radius[k], 0, k)) ok[k] = 0;
  }
};

// The kept (ok[k]) join `occupied` as entry base + k, and are placed at their centre.
struct KeepCandidates {
  SphereCellsView occupied;
  const double* radius;
  const double* centre;
  const std::uint8_t* ok;
  int base;
  std::uint8_t* placed;
  BLAZE_HD void operator()(Index k) const {
    if (!ok[k]) return;
    occupied.put(base + k, {centre[3 * k], centre[3 * k + 1], centre[3 * k + 2]}, radius[k]);
    placed[k] = 1;
  }
};

// 1 while particle k is not placed (reduce_max over the particles due: is any left?).
struct StillOpen {
  const std::uint8_t* placed;
  BLAZE_HD int operator()(Index k) const { return placed[k] ? 0 : 1; }
};

}  // namespace blaze
