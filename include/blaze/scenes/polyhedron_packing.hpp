// Gravity packing of polyhedra: the sphere packing's lattice and walls (gravity_packing.hpp) with a
// polyhedron of one table type at each site, its bounding sphere where the sphere was, at a
// random orientation.
#pragma once
#include "blaze/contact/polyhedron.hpp"
#include "blaze/scenes/gravity_packing.hpp"

namespace blaze {

template <class Real>
Packing<Real> polyhedron_packing(const PolyhedronTable<Real>& table, int type, int n, unsigned seed, double dt,
                                 const PackingOptions& o = {}) {
  PackingOptions spheres = o;
  spheres.radius_spread = 0;
  Packing<Real> p = gravity_packing<Real>(n, table.type[type].bounding_radius, seed, dt, spheres);
  std::mt19937_64 rng(seed + 1);
  std::normal_distribution<double> g;
  ParticleState<Real> poly;
  for (std::size_t i = 0; i < p.particles.size(); ++i) {
    const Quat<double> q = normalized(Quat<double>{g(rng), g(rng), g(rng), g(rng)});
    add_polyhedron(poly, table, type, p.particles.position[i], Quat<Real>{Real(q.w), Real(q.x), Real(q.y), Real(q.z)},
                   p.particles.material[i], p.particles.velocity[i]);
  }
  p.particles = poly;
  return p;
}

}  // namespace blaze
