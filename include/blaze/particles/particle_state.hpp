// Host-side particle description: what scenes build and what output reads. Plain vectors, one
// entry per particle, in SI units. The simulation uploads it into its SoA store.
#pragma once
#include <cstdint>
#include <stdexcept>
#include <string>
#include <vector>
#include "blaze/core/quat.hpp"

namespace blaze {

template <class Real>
struct ParticleState {
  std::vector<Vec3<Real>> position;         // m, centre of mass
  std::vector<Vec3<Real>> velocity;         // m/s
  std::vector<Vec3<Real>> angular_velocity; // rad/s, world frame
  std::vector<Quat<Real>> orientation;      // unit quaternion, body to world
  std::vector<Real> radius;                 // m (bounding radius for non-spheres)
  std::vector<Real> mass;                   // kg
  std::vector<Vec3<Real>> inertia;          // kg m^2, principal moments in the body frame (sphere: 2/5 m r^2)
  std::vector<std::uint8_t> material;       // index into the material-pair table
  std::vector<std::uint8_t> type;           // index into the shape table (polyhedra; 0 for spheres)
  std::vector<Index> id;                    // stable identity, survives re-sorting

  std::size_t size() const { return position.size(); }
  void reserve(std::size_t n) {  // large scenes: no regrowth copies
    position.reserve(n), velocity.reserve(n), angular_velocity.reserve(n), orientation.reserve(n), radius.reserve(n);
    mass.reserve(n), inertia.reserve(n), material.reserve(n), type.reserve(n), id.reserve(n);
  }

  void resize(std::size_t n) {
    position.resize(n), velocity.resize(n), angular_velocity.resize(n), orientation.resize(n), radius.resize(n);
    mass.resize(n), inertia.resize(n), material.resize(n), type.resize(n), id.resize(n);
  }

  // Particle i (below size()) becomes a solid sphere of uniform density (kg/m^3), id i, at rest
  // in rotation; distinct i may be set from many threads at once.
  void set_sphere(std::size_t i, const Vec3<Real>& x, Real r, Real density, std::uint8_t mat, const Vec3<Real>& v = {0, 0, 0}) {
    const Real m = density * Real(4.0 / 3.0 * 3.14159265358979323846) * r * r * r;
    const Real moment = Real(0.4) * m * r * r;
    position[i] = x, velocity[i] = v, angular_velocity[i] = {0, 0, 0}, orientation[i] = Quat<Real>::identity();
    radius[i] = r, mass[i] = m, inertia[i] = {moment, moment, moment}, material[i] = mat, type[i] = 0;
    id[i] = static_cast<Index>(i);
  }

  // A solid sphere of uniform density (kg/m^3).
  void add_sphere(const Vec3<Real>& x, Real r, Real density, std::uint8_t mat, const Vec3<Real>& v = {0, 0, 0}) {
    resize(size() + 1);
    set_sphere(size() - 1, x, r, density, mat, v);
  }

  // A rigid body of given mass, principal moments, bounding radius and shape-table type, with its
  // centre of mass at x and body axes rotated by q.
  void add_body(const Vec3<Real>& x, const Quat<Real>& q, Real bound_radius, Real m, const Vec3<Real>& principal,
                std::uint8_t shape_type, std::uint8_t mat, const Vec3<Real>& v = {0, 0, 0},
                const Vec3<Real>& w = {0, 0, 0}) {
    position.push_back(x);
    velocity.push_back(v);
    angular_velocity.push_back(w);
    orientation.push_back(q);
    radius.push_back(bound_radius);
    mass.push_back(m);
    inertia.push_back(principal);
    material.push_back(mat);
    type.push_back(shape_type);
    id.push_back(static_cast<Index>(id.size()));
  }

  void check_consistent() const {
    const std::size_t n = size();
    if (velocity.size() != n || angular_velocity.size() != n || orientation.size() != n ||
        radius.size() != n || mass.size() != n || inertia.size() != n || material.size() != n ||
        type.size() != n || id.size() != n)
      throw std::invalid_argument("ParticleState: field lengths differ");
    for (std::size_t i = 0; i < n; ++i)
      if (!(radius[i] > 0) || !(mass[i] > 0) || !(inertia[i].x > 0 && inertia[i].y > 0 && inertia[i].z > 0))
        throw std::invalid_argument("ParticleState: particle " + std::to_string(i) +
                                    " needs radius, mass and inertia > 0");
  }
};

}  // namespace blaze
