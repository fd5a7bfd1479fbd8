// Gravity packing (thesis section 2.5.2): a jittered lattice of spheres with random velocities
// above the floor of a box of five planar walls, falling under gravity. Used by the backend
// agreement test and the benchmarks.
#pragma once
#include <algorithm>
#include <cmath>
#include <random>
#include <vector>
#include "blaze/particles/particle_state.hpp"
#include "pipeline/simulation.hpp"
#include "blaze/world/world.hpp"

namespace blaze {

template <class Real>
struct Packing {
  ParticleState<Real> particles;
  World<Real> world;
  SimulationParams<Real> params;
};

enum class Lattice { cubic, fcc };

struct PackingOptions {
  Lattice lattice = Lattice::cubic;
  double pitch_in_radii = 2.1;  // nearest-neighbour spacing / nominal radius
  double radius_spread = 0.02;  // radii uniform in r (1 +- spread)
  double speed = 0.3;           // m/s, each velocity component uniform in +-speed
  bool lid = false;             // a sixth wall on top, as close as the lattice spacing allows
};

// Sites along each edge of a cube of at least n lattice cells: the integer ceiling of n^(1/3).
// (std::cbrt is not exact at run time: cbrt(216.0) = 6.0000000000000009, so ceil gave 7 rows.)
inline int lattice_side(long n) {
  int side = static_cast<int>(std::llround(std::cbrt(static_cast<double>(n))));
  while (static_cast<long>(side) * side * side < n) ++side;
  while (side > 1 && static_cast<long>(side - 1) * (side - 1) * (side - 1) >= n) --side;
  return side;
}

// Cell c of a lattice with `side` cells per row: rows along x, then z, then layers up y.
struct LatticeCell {
  int ix, iy, iz;
};
inline LatticeCell lattice_cell(int c, int side) { return {c % side, c / (side * side), (c / side) % side}; }

// Floor y = 0 and four sides up to height h over [x0, x1] x [z0, z1] (m), normals inwards, of
// world material 1.
template <class Real>
std::vector<PlanarPolygon<Real>> open_box(double x0, double x1, double z0, double z1, double h) {
  using V = Vec3<double>;
  return {PlanarPolygon<Real>::make({V{x0, 0, z1}, {x1, 0, z1}, {x1, 0, z0}, {x0, 0, z0}}, 1),
          PlanarPolygon<Real>::make({V{x0, 0, z0}, {x0, h, z0}, {x0, h, z1}, {x0, 0, z1}}, 1),
          PlanarPolygon<Real>::make({V{x1, 0, z1}, {x1, h, z1}, {x1, h, z0}, {x1, 0, z0}}, 1),
          PlanarPolygon<Real>::make({V{x1, 0, z0}, {x1, h, z0}, {x0, h, z0}, {x0, 0, z0}}, 1),
          PlanarPolygon<Real>::make({V{x0, 0, z1}, {x0, h, z1}, {x1, h, z1}, {x1, 0, z1}}, 1)};
}

// Loose bed (defaults): a cubic lattice with gaps that collapses under gravity and collisions.
// Dense bed (fcc, pitch < 2, lid): 12 neighbours each, all compressed against their neighbours and
// the six walls, so the bed stays in contact: the benchmark state.
template <class Real>
Packing<Real> gravity_packing(int n, double radius, unsigned seed, double dt, const PackingOptions& o = {}) {
  std::mt19937_64 rng(seed);
  std::uniform_real_distribution<double> u(-1, 1);
  // Sites per cubic cell and their offsets (in cells); the cell side makes neighbours `pitch` apart.
  const bool fcc = o.lattice == Lattice::fcc;
  const int per_cell = fcc ? 4 : 1;
  const double offsets[4][3] = {{0, 0, 0}, {0.5, 0.5, 0}, {0.5, 0, 0.5}, {0, 0.5, 0.5}};
  const double pitch = o.pitch_in_radii * radius, cell = fcc ? pitch * std::sqrt(2.0) : pitch;
  const int side = lattice_side((n + per_cell - 1) / per_cell);
  // Walls sit half a pitch beyond the outermost sites (fcc: the outer half-cell is partly empty).
  const double wall_gap = 0.5 * pitch;
  const double extent = (side - 1 + (fcc ? 0.5 : 0.0)) * cell;
  const double half = 0.5 * extent + wall_gap;
  Packing<Real> p;
  p.particles.reserve(static_cast<std::size_t>(n));
  double top = 0;
  for (int k = 0; k < n; ++k) {
    const int site = k % per_cell;
    const auto [ix, iy, iz] = lattice_cell(k / per_cell, side);
    const Vec3<double> x{(ix + offsets[site][0]) * cell - 0.5 * extent, wall_gap + (iy + offsets[site][1]) * cell,
                         (iz + offsets[site][2]) * cell - 0.5 * extent};
    top = std::max(top, x.y);
    const double r = radius * (1 + o.radius_spread * u(rng));
    p.particles.add_sphere(vec_cast<Real>(x), static_cast<Real>(r), Real(2500), 0,
                           vec_cast<Real>(Vec3<double>{o.speed * u(rng), o.speed * u(rng), o.speed * u(rng)}));
  }
  const double h = o.lid ? top + wall_gap : top + 4 * pitch;
  using V = Vec3<double>;
  p.world.polygons = open_box<Real>(-half, half, -half, half, h);
  if (o.lid)
    p.world.polygons.push_back(PlanarPolygon<Real>::make({V{-half, h, -half}, {half, h, -half}, {half, h, half}, {-half, h, half}}, 1));
  p.params = {static_cast<Real>(dt), Vec3<Real>{0, Real(-9.81), 0},
              vec_cast<Real>(V{-half - 4 * radius, -4 * radius, -half - 4 * radius}),
              vec_cast<Real>(V{half + 4 * radius, h + 4 * radius, half + 4 * radius}), static_cast<Real>(0.2 * radius)};
  return p;
}

}  // namespace blaze
