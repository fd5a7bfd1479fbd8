// Integration kernels: one stage of an integrator policy over all particles.
#pragma once
#include "blaze/integrate/integrators.hpp"

namespace blaze {

enum class Stage { prime, pre_force, post_force };

// The energy accounts' dissipation (blaze/particles/energy_ledger.hpp), booked after the step's
// last kick with its final velocities v, w: the contacts' force F and torque T (about the
// centre) did F . v dt + T . w dt on the particle over the step (exactly so between the half
// steps, for velocity Verlet); the wall classes' parts F_c, T_c are in the class sums, the pairs'
// is the rest. Each class's column gets -(F_c . v + T_c . w) dt (the world kernel has booked its
// drive power there already), the pair column -(F_pair . v + T_pair . w) dt.
template <class Features, class Real>
BLAZE_HD void book_energy(const ParticleView<Real>& p, Index i, Real dt) {
  const Vec3<Real> v = p.velocity.get(i);
  const Vec3<Real> w = Features::rotation ? p.angular_velocity.get(i) : Vec3<Real>{0, 0, 0};
  Vec3<Real> f_pair = p.force.get(i);
  Vec3<Real> t_pair = Features::rotation ? p.torque.get(i) : Vec3<Real>{0, 0, 0};
  const unsigned classes = p.ledger.class_mask[i];  // the others' sums are zero this step
  for (int c = 0; c < kContactClasses; ++c) {
    if (!(classes >> c & 1u)) continue;
    const auto& l = p.ledger;
    const Vec3<Real> f{l.sum(c, 0, i), l.sum(c, 1, i), l.sum(c, 2, i)};
    const Vec3<Real> t = Features::rotation ? Vec3<Real>{l.sum(c, 3, i), l.sum(c, 4, i), l.sum(c, 5, i)} : Vec3<Real>{0, 0, 0};
    f_pair -= f, t_pair -= t;
    l.column[ledger_column(static_cast<ContactClass>(c))][i] -= (dot(f, v) + dot(t, w)) * dt;
  }
  p.ledger.column[kLedgerPair][i] -= (dot(f_pair, v) + dot(t_pair, w)) * dt;
}

template <class Integrator, class Shape, class Features, class Real, Stage S>
struct Integrate {
  Shape shape;
  ParticleView<Real> p;
  Real dt;
  BodyForces<Real> body;
  BLAZE_HD void operator()(Index i) const {
    if constexpr (S == Stage::prime) Integrator::template prime<Features>(shape, p, i, body);
    if constexpr (S == Stage::pre_force) Integrator::template pre_force<Features>(shape, p, i, dt, body);
    if constexpr (S == Stage::post_force) {
      Integrator::template post_force<Features>(shape, p, i, dt, body);
      if (p.ledger.on()) book_energy<Features>(p, i, dt);
    }
  }
};

}  // namespace blaze
