// Integration kernels: one stage of an integrator policy over all particles.
#pragma once
#include "blaze/integrate/integrators.hpp"

namespace blaze {

enum class Stage { prime, pre_force, post_force };

template <class Integrator, class Shape, class Features, class Real, Stage S>
struct Integrate {
  Shape shape;
  ParticleView<Real> p;
  Real dt;
  BodyForces<Real> body;
  BLAZE_HD void operator()(Index i) const {
    if constexpr (S == Stage::prime) Integrator::template prime<Features>(shape, p, i, body);
    if constexpr (S == Stage::pre_force) Integrator::template pre_force<Features>(shape, p, i, dt, body);
    if constexpr (S == Stage::post_force) Integrator::template post_force<Features>(shape, p, i, dt, body);
  }
};

}  // namespace blaze
