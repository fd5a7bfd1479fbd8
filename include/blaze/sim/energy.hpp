// System energies from a host snapshot (J), for output and conservation checks:
//   translational  sum 1/2 m v.v      rotational  sum 1/2 w_b . diag(I) w_b,  w_b = R^T w (body frame)
//   potential      sum -m g.x         (zero at the origin)
// The elastic energy stored in the contacts needs the contacts, not only the state: it is
// Simulation::contact_energy() (kernels/contact_energy.hpp); RunLog adds the two.
#pragma once
#include "blaze/particles/particle_state.hpp"

namespace blaze {

struct Energies {
  double translational = 0, rotational = 0, potential = 0;
  double kinetic() const { return translational + rotational; }
  double total() const { return translational + rotational + potential; }
};

// Particle i's share.
template <class Real>
Energies particle_energies(const ParticleState<Real>& s, std::size_t i, const Vec3<Real>& gravity) {
  Energies e;
  const double m = s.mass[i];
  e.translational = 0.5 * m * norm2(vec_cast<double>(s.velocity[i]));
  const Quat<double> q{s.orientation[i].w, s.orientation[i].x, s.orientation[i].y, s.orientation[i].z};
  const Vec3<double> wb = rotate(Quat<double>{q.w, -q.x, -q.y, -q.z}, vec_cast<double>(s.angular_velocity[i]));
  const Vec3<double> moments = vec_cast<double>(s.inertia[i]);
  e.rotational = 0.5 * (moments.x * wb.x * wb.x + moments.y * wb.y * wb.y + moments.z * wb.z * wb.z);
  e.potential = -m * dot(vec_cast<double>(gravity), vec_cast<double>(s.position[i]));
  return e;
}

template <class Real>
Energies energies(const ParticleState<Real>& s, const Vec3<Real>& gravity) {
  Energies e;
  for (std::size_t i = 0; i < s.size(); ++i) {
    const Energies p = particle_energies(s, i, gravity);
    e.translational += p.translational;
    e.rotational += p.rotational;
    e.potential += p.potential;
  }
  return e;
}

}  // namespace blaze
