// Uniform broad-phase grid (thesis section 2.2.3).
//
// Cell of a point:  GP_j = floor((P_j - W_j) / cell_j),  j = x, y, z       (thesis, section 2.2.3)
// Cell hash:        hash = GP_x + N_x (GP_z + N_z GP_y)                      (thesis eq. 2.1, corrected)
// The thesis prints GP_x + GP_z N_x + GP_y N_z N_y; that is one-to-one only when N_y >= N_x (for
// N_y < N_x two cells share a hash). We keep its ordering (y slowest, then z, then x) with the
// multiplier N_x N_z, which is one-to-one for every grid.
// Cells are at least as wide as the largest pair interaction range (2 r_max + skin), so the 27
// cells around a particle's cell hold every particle it can touch before the next rebuild. (The
// thesis says "the largest bound radius": with cells one radius wide, 27 cells miss pairs.)
// Periodic axes (grid/periodic_images.hpp): the cells wrap around there, the domain's length along
// the axis is the period, and make() asks for at least 3 cells along it, so the 27 cells around a
// cell are distinct and a particle meets at most one image of another (the period exceeds twice
// the interaction range).
#pragma once
#include <cmath>
#include <cstdint>
#include <stdexcept>
#include <string>
#include "blaze/core/vec3.hpp"

namespace blaze {

template <class Real>
struct GridSpec {
  // Cells are hashed to 32 bits and the key nx ny nz marks "outside": fewer than 2^32 - 1 cells.
  static constexpr double kMaxCells = 4294967295.0;
  Vec3<Real> lo;    // m, grid origin W
  Vec3<Real> hi;    // m, far corner; particles outside [lo, hi) leave the simulation
  Real inv_cell_x, inv_cell_y, inv_cell_z;  // 1/m
  int nx, ny, nz;
  unsigned periodic = 0;        // bit 0: x, 1: y, 2: z
  Vec3<Real> length{0, 0, 0};   // m, hi - lo along the periodic axes (the periods), 0 on the others

  // Smallest cells not narrower than min_cell (m) that tile the box exactly.
  static GridSpec make(const Vec3<Real>& lo, const Vec3<Real>& hi, Real min_cell, unsigned periodic_axes = 0) {
    if (!(min_cell > 0)) throw std::invalid_argument("grid: cell size must be > 0");
    GridSpec g{lo, hi, 0, 0, 0, 0, 0, 0, periodic_axes & 7u, {0, 0, 0}};
    const Real ext[3] = {hi.x - lo.x, hi.y - lo.y, hi.z - lo.z};
    int* dims[3] = {&g.nx, &g.ny, &g.nz};
    Real* inv[3] = {&g.inv_cell_x, &g.inv_cell_y, &g.inv_cell_z};
    // Counted in double: a domain far larger than its cells gives counts beyond int, and a cast
    // of such a count was undefined (it came out negative and bypassed the total's guard, so every
    // particle was "outside" at t = 0). The scene's validation refuses such domains first, naming
    // the key (scene_toml.cpp, check_sizes); this is the backstop for other callers.
    double cells = 1;
    for (int d = 0; d < 3; ++d) {
      if (!(ext[d] > 0)) throw std::invalid_argument("grid: domain hi must exceed lo in every axis");
      const double count = std::floor(static_cast<double>(ext[d]) / static_cast<double>(min_cell));
      if (!(count < 2147483647.0)) throw std::invalid_argument("grid: more than 2^31 cells along one axis; enlarge the cells or shrink the domain");
      *dims[d] = count < 1 ? 1 : static_cast<int>(count);
      *inv[d] = static_cast<Real>(*dims[d]) / ext[d];
      cells *= *dims[d];
    }
    if (!(cells < kMaxCells)) throw std::invalid_argument("grid: more than 4e9 cells; enlarge the cells or shrink the domain");
    for (int d = 0; d < 3; ++d)
      if ((g.periodic >> d) & 1u) {
        if (*dims[d] < 3)
          throw std::invalid_argument(std::string("grid: the periodic axis ") + "xyz"[d] + " is " + std::to_string(static_cast<double>(ext[d])) +
                                      " m long, less than 3 cells of " + std::to_string(static_cast<double>(min_cell)) +
                                      " m (twice the largest radius plus the skin): a particle would meet two images of another");
        (d == 0 ? g.length.x : d == 1 ? g.length.y : g.length.z) = ext[d];
      }
    return g;
  }

  BLAZE_HD std::uint32_t cell_count() const { return static_cast<std::uint32_t>(nx) * ny * nz; }
  // Key given to particles outside the domain: sorts after every cell.
  BLAZE_HD std::uint32_t outside_key() const { return static_cast<std::uint32_t>(nx) * ny * nz; }

  // False for points outside [lo, hi) and for NaN (every comparison with NaN is false).
  BLAZE_HD bool cell_of(const Vec3<Real>& p, int& cx, int& cy, int& cz) const {
    const Real tx = floor_r((p.x - lo.x) * inv_cell_x);
    const Real ty = floor_r((p.y - lo.y) * inv_cell_y);
    const Real tz = floor_r((p.z - lo.z) * inv_cell_z);
    if (!(tx >= 0 && tx < Real(nx) && ty >= 0 && ty < Real(ny) && tz >= 0 && tz < Real(nz))) return false;
    cx = static_cast<int>(tx);
    cy = static_cast<int>(ty);
    cz = static_cast<int>(tz);
    return true;
  }

  // Inside [lo, hi) along the axes that are not periodic (and not NaN): along the periodic ones a
  // particle may stray past the box until the next rebuild wraps it.
  BLAZE_HD bool inside_fixed_axes(const Vec3<Real>& p) const {
    return ((periodic & 1u) || (p.x >= lo.x && p.x < hi.x)) && ((periodic & 2u) || (p.y >= lo.y && p.y < hi.y)) &&
           ((periodic & 4u) || (p.z >= lo.z && p.z < hi.z)) && p.x == p.x && p.y == p.y && p.z == p.z;
  }

  BLAZE_HD std::uint32_t hash(int cx, int cy, int cz) const {
    return static_cast<std::uint32_t>(cx) +
           static_cast<std::uint32_t>(nx) * (static_cast<std::uint32_t>(cz) + static_cast<std::uint32_t>(nz) * cy);
  }
};

}  // namespace blaze
