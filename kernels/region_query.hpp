// The particles whose centre lies in an axis-aligned box, found on the particles' memory space
// (a feeder's neighbourhood, Simulation::particles_in_box): a flag per particle (InBox), read back
// (1 B per particle), then the flagged particles' centre and radius gathered into a compact array
// (GatherCentres) and read back: 1 + 16 B per flagged particle (float) instead of 16 B per
// particle.
#pragma once
#include <cstdint>
#include "blaze/config.hpp"
#include "blaze/particles/particle_store.hpp"

namespace blaze {

template <class Real>
struct InBox {
  Vec3Field<Real> x;
  Vec3<Real> lo, hi;
  std::uint8_t* flag;
  BLAZE_HD void operator()(Index i) const {
    const Vec3<Real> p = x.get(i);
    flag[i] = p.x >= lo.x && p.x <= hi.x && p.y >= lo.y && p.y <= hi.y && p.z >= lo.z && p.z <= hi.z;
  }
};

// out[4k .. 4k+3] = x, y, z, r of particle which[k].
template <class Real>
struct GatherCentres {
  Vec3Field<Real> x;
  const Real* radius;
  const Index* which;
  Real* out;
  BLAZE_HD void operator()(Index k) const {
    const Index i = which[k];
    const Vec3<Real> p = x.get(i);
    out[4 * k] = p.x, out[4 * k + 1] = p.y, out[4 * k + 2] = p.z, out[4 * k + 3] = radius[i];
  }
};

}  // namespace blaze
