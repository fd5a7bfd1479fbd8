// The loads the particles put on chosen world objects (issue 20: each mesh reports its force and
// torque over time), reduced over the particles where they live (a diagnostic run at the samples,
// never inside a step). For particle i and each contact it has with object w (world_contacts.hpp,
// the very contacts the world kernel evaluates), the contact's force on i is evaluated as the
// world kernel does (contact_pair.hpp's wall_force), at the sampled positions and velocities, with
// the contact's stored state and the step dt (the law needs it: the thesis's eq. 4.3 friction is
// mu m* / dt; a spring is advanced by one step's slip), on a copy of the state (nothing is
// written); the object takes the reaction:
//   F_w = - sum F_c                                  [N]
//   T_w = - sum (p_c x F_c + M_c)                    [N m], about the origin
// (about a point q: T_q = T_w - q x F_w). Up to kLoadObjects objects per pass; reduce_in_order
// (exec/primitives.hpp) folds the particles' shares deterministically. `counted` (null: all)
// leaves out a rank's ghost particles, as in sample_tally.hpp.
#pragma once
#include "blaze/exec/launch.hpp"
#include "blaze/laws/contact_law.hpp"
#include "blaze/particles/particle_store.hpp"
#include "kernels/contact_history.hpp"
#include "kernels/contact_pair.hpp"
#include "kernels/world_contacts.hpp"

namespace blaze {

constexpr int kLoadObjects = 8;

struct LoadTally {
  double load[kLoadObjects][6] = {};  // per object: F (N), then T about the origin (N m)
  BLAZE_HD void combine(const LoadTally& o) {
    for (int k = 0; k < kLoadObjects; ++k)
      for (int c = 0; c < 6; ++c) load[k][c] += o.load[k][c];
  }
};

template <class Shape, class Law, class Kinematics, class Features>
struct WorldLoads {
  using Real = typename Law::real_type;
  static constexpr int kMinBlocks = min_blocks_v<Shape>;  // launch.hpp
  Shape shape;
  ParticleView<Real> p;
  WorldView<Real> world;
  PairTable<Law> laws;
  WallHistoryView<Real, Law::State::kReals> history;
  Real dt;                   // s, the step's
  int object[kLoadObjects];  // the objects reported; -1: none
  int count;
  const std::uint8_t* counted = nullptr;

  BLAZE_HD LoadTally operator()(Index i) const {
    LoadTally t;
    if (counted && !counted[i]) return t;
    const auto body = shape.body(p, i);
    for_each_world_contact(shape, body, world, i, [&](const auto& g, int material, int w, WallKey key, const auto*) {
      if (!g.touching) return;
      int slot = -1;
      for (int k = 0; k < count; ++k)
        if (object[k] == w) slot = k;
      if (slot < 0) return;
      auto state = Law::State::zero();
      if constexpr (Law::kHistory) {
        const int h = history.find(i, key);
        if (h >= 0) state = history.load(h, i);
      }
      (void)key;
      Vec3<Real> v_point;
      const ContactForce<Real> c = wall_force<Kinematics, Features>(laws(p.material[i], material), p, body, i, g, world.pose_of(w), state, dt, v_point);
      Vec3<double> m{0, 0, 0};
      if constexpr (has_moment_v<Law, std::decay_t<decltype(g)>>) m = vec_cast<double>(c.moment);
      const Vec3<double> f = vec_cast<double>(c.force), torque = cross(vec_cast<double>(g.point), f) + m;
      const double v[6] = {-f.x, -f.y, -f.z, -torque.x, -torque.y, -torque.z};
      for (int k = 0; k < 6; ++k) t.load[slot][k] += v[k];
    });
    return t;
  }
};

}  // namespace blaze
