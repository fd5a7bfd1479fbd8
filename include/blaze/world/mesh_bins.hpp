// Binned triangles of a mesh (issue 20): the world cost grows with the triangles near a particle,
// not with the mesh's size. A uniform grid over the mesh's bounding box, in the mesh's own
// (reference) frame, lists in each cell every triangle whose bounding box, widened by `reach`,
// overlaps the cell; a particle of bounding radius <= reach at x then finds every triangle it can
// touch in the one cell holding x (outside the grid: none). A mesh that moves rigidly keeps its
// bins: the particle's position is taken into the reference frame instead (x_ref = R^T (x - u)),
// so bins are built once per mesh. Cells are cubes of side `cell` (the caller's choice: about the
// larger of the mean edge length and 2 reach keeps a cell's list short); the grid is capped at
// kMaxCells cells by growing the side.
// Layout (CSR): cell c holds triangles entry[start[c] .. start[c + 1]).
#pragma once
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <stdexcept>
#include <vector>
#include "blaze/world/triangle_mesh.hpp"

namespace blaze {

struct MeshBinsHost {
  static constexpr long kMaxCells = 1L << 24;
  Vec3<double> origin{0, 0, 0};  // m, the grid's low corner (reference frame)
  double cell = 0;               // m
  int nx = 0, ny = 0, nz = 0;
  std::vector<int> start, entry;
  long longest = 0;              // the most triangles in one cell
};

inline MeshBinsHost bin_mesh(const TriangleMesh& m, double reach, double cell) {
  if (!(reach >= 0) || !(cell > 0)) throw std::invalid_argument("mesh bins: reach must be >= 0 m and cell > 0 m");
  MeshBinsHost b;
  Vec3<double> lo{HUGE_VAL, HUGE_VAL, HUGE_VAL}, hi{-HUGE_VAL, -HUGE_VAL, -HUGE_VAL};
  for (const auto& v : m.vertices) {
    lo = {std::fmin(lo.x, v.x), std::fmin(lo.y, v.y), std::fmin(lo.z, v.z)};
    hi = {std::fmax(hi.x, v.x), std::fmax(hi.y, v.y), std::fmax(hi.z, v.z)};
  }
  lo = lo - Vec3<double>{reach, reach, reach}, hi = hi + Vec3<double>{reach, reach, reach};
  const auto cells_along = [&](double span) { return std::max(1L, static_cast<long>(std::ceil(span / cell))); };
  while (static_cast<double>(cells_along(hi.x - lo.x)) * static_cast<double>(cells_along(hi.y - lo.y)) *
             static_cast<double>(cells_along(hi.z - lo.z)) >
         static_cast<double>(MeshBinsHost::kMaxCells))
    cell *= 1.25;
  b.origin = lo, b.cell = cell;
  b.nx = static_cast<int>(cells_along(hi.x - lo.x)), b.ny = static_cast<int>(cells_along(hi.y - lo.y));
  b.nz = static_cast<int>(cells_along(hi.z - lo.z));
  const std::size_t cells = static_cast<std::size_t>(b.nx) * static_cast<std::size_t>(b.ny) * static_cast<std::size_t>(b.nz);
  const auto range = [&](double a, double z, int n, int& i0, int& i1) {
    i0 = std::clamp(static_cast<int>(std::floor(a / cell)), 0, n - 1);
    i1 = std::clamp(static_cast<int>(std::floor(z / cell)), 0, n - 1);
  };
  // Two passes: count, then fill.
  std::vector<int> count(cells + 1, 0);
  for (int pass = 0; pass < 2; ++pass) {
    if (pass == 1) {
      b.start.assign(cells + 1, 0);
      for (std::size_t c = 0; c < cells; ++c) b.start[c + 1] = b.start[c] + count[c];
      b.entry.assign(static_cast<std::size_t>(b.start[cells]), 0);
      std::fill(count.begin(), count.end(), 0);
    }
    for (std::size_t t = 0; t < m.size(); ++t) {
      Vec3<double> tl{HUGE_VAL, HUGE_VAL, HUGE_VAL}, th{-HUGE_VAL, -HUGE_VAL, -HUGE_VAL};
      for (int k = 0; k < 3; ++k) {
        const Vec3<double> v = m.corner(t, k);
        tl = {std::fmin(tl.x, v.x), std::fmin(tl.y, v.y), std::fmin(tl.z, v.z)};
        th = {std::fmax(th.x, v.x), std::fmax(th.y, v.y), std::fmax(th.z, v.z)};
      }
      int x0, x1, y0, y1, z0, z1;
      range(tl.x - reach - lo.x, th.x + reach - lo.x, b.nx, x0, x1);
      range(tl.y - reach - lo.y, th.y + reach - lo.y, b.ny, y0, y1);
      range(tl.z - reach - lo.z, th.z + reach - lo.z, b.nz, z0, z1);
      for (int z = z0; z <= z1; ++z)
        for (int y = y0; y <= y1; ++y)
          for (int x = x0; x <= x1; ++x) {
            const std::size_t c = (static_cast<std::size_t>(z) * static_cast<std::size_t>(b.ny) + static_cast<std::size_t>(y)) *
                                      static_cast<std::size_t>(b.nx) + static_cast<std::size_t>(x);
            if (pass == 1) b.entry[static_cast<std::size_t>(b.start[c] + count[c])] = static_cast<int>(t);
            ++count[c];
          }
    }
  }
  for (std::size_t c = 0; c < cells; ++c) b.longest = std::max<long>(b.longest, count[c]);
  return b;
}

// What the kernels read.
template <class Real>
struct MeshBinsView {
  Vec3<Real> origin;
  Real inv_cell;
  int nx, ny, nz;
  const int* start;
  const int* entry;
  // Triangles [*first, *last) of entry for the cell holding x_ref (reference frame); none outside.
  BLAZE_HD void cell_of(const Vec3<Real>& x_ref, int& first, int& last) const {
    const Vec3<Real> r = (x_ref - origin) * inv_cell;
    first = last = 0;
    if (!(r.x >= Real(0) && r.y >= Real(0) && r.z >= Real(0))) return;
    const int i = static_cast<int>(r.x), j = static_cast<int>(r.y), k = static_cast<int>(r.z);
    if (i >= nx || j >= ny || k >= nz) return;
    const long c = (static_cast<long>(k) * ny + j) * nx + i;
    first = start[c], last = start[c + 1];
  }
};

// The view of host bins b whose cell starts and entries lie at `start` and `entry` (b's own
// vectors, or their copies on a device).
template <class Real>
MeshBinsView<Real> bins_view(const MeshBinsHost& b, const int* start, const int* entry) {
  return {vec_cast<Real>(b.origin), static_cast<Real>(1 / b.cell), b.nx, b.ny, b.nz, start, entry};
}

}  // namespace blaze
