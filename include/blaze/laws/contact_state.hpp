// What a contact remembers from one step to the next (its history): N reals, held by the contact
// store (pipeline/contact_store.hpp; list-aligned for particle pairs, per-particle slots for world
// objects), loaded before the law is evaluated and stored after. A contact that opens is
// forgotten (all zero); one that closes again starts from zero, so "no history" and "a fresh
// contact" are the same state. Laws without history have N = 0: nothing is stored or loaded.
//
// Layout of a law's state (ContactLaw): the tangential law's reals first, then the rolling law's.
// Each sub-law reads its part at its offset as Vec3s (a tangential spring: 3 reals, m or N; a
// rolling spring: 3 reals, N m).
#pragma once
#include <cstdint>
#include "blaze/core/vec3.hpp"

namespace blaze {

// A wall contact's key in the store: its world object's index, or for a triangle mesh
// mesh_key_base + the triangle (blaze/world/mesh_wall.hpp); -1: a free slot.
using WallKey = std::int32_t;

template <class Real, int N>
struct ContactState {
  static constexpr int kReals = N;
  Real value[N > 0 ? N : 1];  // one unused real when N = 0 (never loaded or stored)

  BLAZE_HD Vec3<Real> vec(int at) const { return {value[at], value[at + 1], value[at + 2]}; }
  BLAZE_HD void set(int at, const Vec3<Real>& v) {
    value[at] = v.x, value[at + 1] = v.y, value[at + 2] = v.z;
  }
  BLAZE_HD static ContactState zero() {
    ContactState s{};
    for (int k = 0; k < (N > 0 ? N : 1); ++k) s.value[k] = Real(0);
    return s;
  }
};

}  // namespace blaze
