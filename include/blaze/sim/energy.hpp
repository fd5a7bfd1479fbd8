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
  BLAZE_HD double kinetic() const { return translational + rotational; }
  BLAZE_HD double total() const { return translational + rotational + potential; }
};

// One body's share, in double from the stored reals (the host snapshot below and the device
// reduction of a time-series sample, kernels/sample_tally.hpp, both call it): m kg, v m/s, q its
// orientation, w rad/s in the world frame, I kg m^2 its principal moments, x m, g m/s^2.
template <class Real>
BLAZE_HD inline Energies body_energies(double m, const Vec3<Real>& v, const Quat<Real>& q, const Vec3<Real>& w,
                                       const Vec3<Real>& moments_of_inertia, const Vec3<Real>& x, const Vec3<Real>& g) {
  Energies e;
  e.translational = 0.5 * m * norm2(vec_cast<double>(v));
  const Vec3<double> wb = rotate(Quat<double>{q.w, -q.x, -q.y, -q.z}, vec_cast<double>(w));
  const Vec3<double> moments = vec_cast<double>(moments_of_inertia);
  e.rotational = 0.5 * (moments.x * wb.x * wb.x + moments.y * wb.y * wb.y + moments.z * wb.z * wb.z);
  e.potential = -m * dot(vec_cast<double>(g), vec_cast<double>(x));
  return e;
}

// Particle i's share.
template <class Real>
Energies particle_energies(const ParticleState<Real>& s, std::size_t i, const Vec3<Real>& gravity) {
  return body_energies(static_cast<double>(s.mass[i]), s.velocity[i], s.orientation[i], s.angular_velocity[i], s.inertia[i],
                       s.position[i], gravity);
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
