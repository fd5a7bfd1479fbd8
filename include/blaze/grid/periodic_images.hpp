// Periodic boundaries (minimum image; Allen & Tildesley, Computer Simulation of Liquids, 2nd ed.
// 2017, section 1.6.2), as a neighbour list carries them:
//   image of j nearest i:  x_j + s_ij,   s_ij,d = -L_d if x_j,d - x_i,d > L_d / 2,
//                                                 +L_d if x_j,d - x_i,d < -L_d / 2, else 0   [m]
// along each periodic axis d of period L_d (the domain's length). Positions are wrapped into the
// box only at neighbour-list builds (kernels/broad_phase_kernels.hpp: WrapPeriodic, which counts
// each particle's image), and each list entry keeps its shift as a code (2 bits per axis), so
// between builds particles move continuously and the shifts stay right (as LAMMPS re-maps atoms
// only when it re-neighbours).
// Both sides of a pair compute it in the frame of its lower index (contact_forces.hpp: the higher
// one is moved to its image beside the lower), the same rounding from either side, so the two
// forces are still exact negations. The period exceeds twice the interaction range (GridSpec::make
// asks for 3 cells), so a particle meets at most one image of another.
#pragma once
#include <cstddef>
#include <cstdint>
#include "blaze/config.hpp"
#include "blaze/core/vec3.hpp"

namespace blaze {

template <class Real>
struct PeriodicImages {
  std::uint8_t* code = nullptr;  // per list entry, at the list's offsets; null: no periodic axis
  Vec3<Real> length{0, 0, 0};    // m, the periods (0 on other axes)

  BLAZE_HD bool on() const { return code != nullptr; }
  // Bits per axis d: 1 << 2d: +L_d, 2 << 2d: -L_d.
  BLAZE_HD static Real part(unsigned c, int d, Real l) { return (c >> (2 * d)) & 1u ? l : (c >> (2 * d)) & 2u ? -l : Real(0); }
  BLAZE_HD Vec3<Real> shift_of(unsigned c) const { return {part(c, 0, length.x), part(c, 1, length.y), part(c, 2, length.z)}; }
  BLAZE_HD Vec3<Real> shift(std::size_t entry) const { return shift_of(code[entry]); }
  // The code of s_ij for d = x_j - x_i (periodic axes: those with length > 0).
  BLAZE_HD static std::uint8_t encode(const Vec3<Real>& d, const Vec3<Real>& length) {
    const Real dd[3] = {d.x, d.y, d.z}, l[3] = {length.x, length.y, length.z};
    unsigned c = 0;
    for (int k = 0; k < 3; ++k)
      if (l[k] > Real(0)) c |= dd[k] > Real(0.5) * l[k] ? 2u << (2 * k) : dd[k] < Real(-0.5) * l[k] ? 1u << (2 * k) : 0u;
    return static_cast<std::uint8_t>(c);
  }
  // Pair (i, j) of list entry `entry`: the higher index's body moves to its image beside the lower.
  BLAZE_HD void place(std::size_t entry, Index i, Index j, Vec3<Real>& xi, Vec3<Real>& xj) const {
    if (!code) return;
    const Vec3<Real> s = shift(entry);
    if (i < j) xj = xj + s;
    else xi = xi - s;
  }
};

}  // namespace blaze
