// Spheres placed so far, for overlap tests while particles are placed: a scene's lattices, lists
// and fills (scene_build.hpp). Host only (a feeder's rounds run where the particles live, in the
// hashed cells of kernels/placement.hpp).
//
// Cells at least `cell` wide over a box [lo, hi], each the head of a chain of its spheres (newest
// first, through next_): an array over the box while it needs no more than max(4 per expected
// sphere, 2^22) cells; cells beyond the box, or every cell of a box too large for the array (tiny
// particles in a huge domain), sit in a hash map. A query of (x, r) reads the cells within
// r + r_max of x: 8 at most with cells 4 r_max wide, 27 with 2 r_max. (A hash map of vectors for
// every cell, 27 cells a query, took half of a 4e6-ball fill's 100 s; an unordered_map of cells
// cost ~1 us per placement, 10% of a 1e6-particle feed, when feeds used this grid.)
//
// Entries are numbered in the order they are added; a query names the entry it found.
#pragma once
#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <stdexcept>
#include <unordered_map>
#include <vector>
#include "blaze/core/vec3.hpp"

namespace blaze {

class SphereGrid {
 public:
  // r_max (m): no sphere put is larger; expected: about how many will be (sizes the array's cap).
  SphereGrid(const Vec3<double>& lo, const Vec3<double>& hi, double cell, double r_max, double expected = 0)
      : lo_(lo), hi_(hi), cell_(cell), r_max_(r_max) {
    if (!(cell > 0) || !(r_max >= 0)) throw std::invalid_argument("sphere grid: the cell must be > 0 m and r_max >= 0 m");
    const double e[3] = {hi.x - lo.x, hi.y - lo.y, hi.z - lo.z};
    double cells = 1;
    for (int d = 0; d < 3; ++d) {
      dims_[d] = e[d] > 0 ? static_cast<long>(std::floor(e[d] / cell_)) + 1 : 1;
      cells *= static_cast<double>(dims_[d]);
    }
    if (cells <= std::fmax(4 * expected, 4194304.0)) head_.assign(static_cast<std::size_t>(cells), -1);
    else dims_[0] = dims_[1] = dims_[2] = 0;
  }
  // Was it made for this box, cell and largest radius?
  bool covers(const Vec3<double>& lo, const Vec3<double>& hi, double cell, double r_max) const {
    return lo.x == lo_.x && lo.y == lo_.y && lo.z == lo_.z && hi.x == hi_.x && hi.y == hi_.y && hi.z == hi_.z && cell == cell_ &&
           r_max == r_max_;
  }
  // Some entry that (x, r) overlaps by more than `slack` (m), or -1.
  long overlapping(const Vec3<double>& x, double r, double slack = 0) const {
    const double reach = r + r_max_;
    const auto lo = cell_of(x - Vec3<double>{reach, reach, reach}), hi = cell_of(x + Vec3<double>{reach, reach, reach});
    for (long cx = lo[0]; cx <= hi[0]; ++cx)
      for (long cy = lo[1]; cy <= hi[1]; ++cy)
        for (long cz = lo[2]; cz <= hi[2]; ++cz)
          for (std::int64_t j = first(cx, cy, cz); j >= 0; j = next_[static_cast<std::size_t>(j)]) {
            const Entry& q = entry_[static_cast<std::size_t>(j)];
            const double touch = r + q.r - slack, dx = x.x - q.x, dy = x.y - q.y, dz = x.z - q.z;
            if (dx * dx + dy * dy + dz * dz < touch * touch) return static_cast<long>(j);
          }
    return -1;
  }

  std::size_t size() const { return entry_.size(); }
  // A sphere (x, r), r <= r_max, as the next entry.
  void add(const Vec3<double>& x, double r) {
    if (!(r <= r_max_)) throw std::logic_error("sphere grid: a sphere larger than its r_max");
    const auto c = cell_of(x);
    std::int64_t* h = dense(c[0], c[1], c[2]);
    std::int64_t& head = h ? *h : far_.try_emplace(key(c[0], c[1], c[2]), -1).first->second;
    entry_.push_back(Entry{x.x, x.y, x.z, r});
    next_.push_back(head);
    head = static_cast<std::int64_t>(entry_.size() - 1);
  }

 private:
  struct Entry {
    double x, y, z, r;  // m: an entry's centre and radius, in one cache line's half
  };
  std::array<long, 3> cell_of(const Vec3<double>& x) const {
    return {static_cast<long>(std::floor((x.x - lo_.x) / cell_)), static_cast<long>(std::floor((x.y - lo_.y) / cell_)),
            static_cast<long>(std::floor((x.z - lo_.z) / cell_))};
  }
  std::int64_t* dense(long i, long j, long k) {
    if (i < 0 || j < 0 || k < 0 || i >= dims_[0] || j >= dims_[1] || k >= dims_[2]) return nullptr;
    return &head_[static_cast<std::size_t>((k * dims_[1] + j) * dims_[0] + i)];
  }
  std::int64_t first(long i, long j, long k) const {
    if (i >= 0 && j >= 0 && k >= 0 && i < dims_[0] && j < dims_[1] && k < dims_[2])
      return head_[static_cast<std::size_t>((k * dims_[1] + j) * dims_[0] + i)];
    if (far_.empty()) return -1;
    const auto it = far_.find(key(i, j, k));
    return it == far_.end() ? -1 : it->second;
  }
  static std::uint64_t key(long i, long j, long k) {
    return (static_cast<std::uint64_t>(i & 0x1fffff) << 42) | (static_cast<std::uint64_t>(j & 0x1fffff) << 21) |
           static_cast<std::uint64_t>(k & 0x1fffff);
  }

  Vec3<double> lo_, hi_;
  double cell_, r_max_;
  long dims_[3] = {0, 0, 0};
  std::vector<std::int64_t> head_;                       // the box's cells: newest entry, or -1
  std::unordered_map<std::uint64_t, std::int64_t> far_;  // cells beyond the box (21 bits an axis, wrapped)
  std::vector<std::int64_t> next_;                       // the next entry of the same cell, or -1
  std::vector<Entry> entry_;
};

}  // namespace blaze
