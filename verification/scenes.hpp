// Small scenes shared by the verification cases: laws, materials and the simulation type.
#pragma once
#include <random>
#include "blaze/shapes/sphere_shape.hpp"
#include "blaze/laws/standard_laws.hpp"
#include "blaze/sim/energy.hpp"
#include "pipeline/simulation.hpp"
#include "pipeline/gravity_packing.hpp"
#include "verification/tolerances.hpp"

namespace blaze::test {

constexpr double kPi = 3.14159265358979323846;

template <class Law, class Integrator = VelocityVerlet, class Space = DefaultSpace>
using SphereSim = Simulation<Space, SphereShape, Law, Integrator>;

template <class Law>
PairTable<Law> one_law(const Law& law, int materials = 2) {
  PairTable<Law> t;
  for (int a = 0; a < materials; ++a)
    for (int b = a; b < materials; ++b) t.set(a, b, law);
  return t;
}

template <class Real>
SimulationParams<Real> params(double dt, Vec3<double> g = {0, 0, 0}, double box = 1.0, double skin = 1e-3) {
  return {static_cast<Real>(dt), vec_cast<Real>(g), vec_cast<Real>(Vec3<double>{-box, -box, -box}),
          vec_cast<Real>(Vec3<double>{box, box, box}), static_cast<Real>(skin)};
}

// A square floor polygon in the plane y = height, normal +y, half-width a.
template <class Real>
PlanarPolygon<Real> floor_square(double height, double a, std::uint8_t material = 1) {
  return PlanarPolygon<Real>::make({{-a, height, a}, {a, height, a}, {a, height, -a}, {-a, height, -a}}, material);
}

// Crossing times of a sampled signal through zero, linearly interpolated.
inline std::vector<double> zero_crossings(const std::vector<double>& t, const std::vector<double>& f) {
  std::vector<double> out;
  for (std::size_t k = 1; k < f.size(); ++k)
    if ((f[k - 1] < 0) != (f[k] < 0)) out.push_back(t[k - 1] + (t[k] - t[k - 1]) * f[k - 1] / (f[k - 1] - f[k]));
  return out;
}

// Random polydisperse spheres (radius r_min..r_max, uniform) in a cube of side L centred at 0,
// overlaps allowed: a stress test for the broad phase, not a physical state.
template <class Real>
ParticleState<Real> random_spheres(int n, double r_min, double r_max, double side, unsigned seed) {
  std::mt19937_64 rng(seed);
  std::uniform_real_distribution<double> u(0, 1);
  ParticleState<Real> s;
  for (int i = 0; i < n; ++i) {
    const Vec3<double> x{(u(rng) - 0.5) * side, (u(rng) - 0.5) * side, (u(rng) - 0.5) * side};
    s.add_sphere(vec_cast<Real>(x), static_cast<Real>(r_min + (r_max - r_min) * u(rng)), Real(2500), 0);
  }
  return s;
}

}  // namespace blaze::test
