// Gravity packing (thesis section 2.5.2): a jittered lattice of spheres with random velocities
// above the floor of a box of five planar walls, falling under gravity. Used by the backend
// agreement test and the benchmarks.
#pragma once
#include <cmath>
#include <random>
#include "blaze/particles/particle_state.hpp"
#include "blaze/sim/simulation.hpp"
#include "blaze/world/world.hpp"

namespace blaze {

template <class Real>
struct Packing {
  ParticleState<Real> particles;
  World<Real> world;
  SimulationParams<Real> params;
};

template <class Real>
// pitch: lattice spacing in radii; 2.1 leaves gaps, 2.0 starts the bed in contact (radii vary by
// +-2%, so about half the lattice neighbours overlap by up to 2% of a radius).
Packing<Real> gravity_packing(int n, double radius, unsigned seed, double dt, double pitch_in_radii = 2.1) {
  std::mt19937_64 rng(seed);
  std::uniform_real_distribution<double> u(-1, 1);
  const int side = static_cast<int>(std::ceil(std::cbrt(static_cast<double>(n))));
  const double pitch = pitch_in_radii * radius;
  const double half = 0.5 * side * pitch + radius;
  Packing<Real> p;
  for (int k = 0; k < n; ++k) {
    const int ix = k % side, iz = (k / side) % side, iy = k / (side * side);
    const Vec3<double> x{(ix - 0.5 * (side - 1)) * pitch, radius * 1.05 + iy * pitch, (iz - 0.5 * (side - 1)) * pitch};
    const double r = radius * (1 + 0.02 * u(rng));
    p.particles.add_sphere(vec_cast<Real>(x), static_cast<Real>(r), Real(2500), 0,
                           vec_cast<Real>(Vec3<double>{0.3 * u(rng), 0.3 * u(rng), 0.3 * u(rng)}));
  }
  const double h = 2 * radius * 1.05 + (n / (side * side) + 2) * pitch;
  using V = Vec3<double>;
  p.world.polygons = {
      PlanarPolygon<Real>::make({{-half, 0, half}, {half, 0, half}, {half, 0, -half}, {-half, 0, -half}}, 1),
      PlanarPolygon<Real>::make({V{-half, 0, -half}, {-half, h, -half}, {-half, h, half}, {-half, 0, half}}, 1),
      PlanarPolygon<Real>::make({V{half, 0, half}, {half, h, half}, {half, h, -half}, {half, 0, -half}}, 1),
      PlanarPolygon<Real>::make({V{half, 0, -half}, {half, h, -half}, {-half, h, -half}, {-half, 0, -half}}, 1),
      PlanarPolygon<Real>::make({V{-half, 0, half}, {-half, h, half}, {half, h, half}, {half, 0, half}}, 1)};
  p.params = {static_cast<Real>(dt), Vec3<Real>{0, Real(-9.81), 0},
              vec_cast<Real>(V{-half - 4 * radius, -4 * radius, -half - 4 * radius}),
              vec_cast<Real>(V{half + 4 * radius, h + 4 * radius, half + 4 * radius}), static_cast<Real>(0.2 * radius)};
  return p;
}

}  // namespace blaze
