// Particle-world contact forces (thesis Algorithm 2.1, line 6), added to the particle's force and
// torque. Walls are immovable here (infinite mass, zero velocity): m_eff = m_i.
#pragma once
#include "blaze/contact/kinematics.hpp"
#include "blaze/exec/launch.hpp"
#include "blaze/laws/contact_law.hpp"
#include "blaze/sim/features.hpp"
#include "blaze/world/world.hpp"
#include "blaze/particles/particle_store.hpp"

namespace blaze {

template <class Shape, class Law, class Kinematics, class Features>
struct WorldForces {
  using Real = typename Law::real_type;
  static constexpr int kMinBlocks = min_blocks_v<Shape>;  // launch.hpp
  Shape shape;
  ParticleView<Real> p;
  WorldView<Real> world;
  PairTable<Law> laws;

  BLAZE_HD void operator()(Index i) const {
    const auto body = shape.body(p, i);
    const Vec3<Real> v = p.velocity.get(i);
    const Vec3<Real> w = Features::rotation ? p.angular_velocity.get(i) : Vec3<Real>{0, 0, 0};
    const Real m = Real(1) / p.inv_mass[i];
    const int mi = p.material[i];
    Vec3<Real> f = p.force.get(i), t{0, 0, 0};
    Real deepest = 0;
    const auto apply = [&](const ContactGeometry<Real>& g, int material) {
      if (!g.touching) return;
      if constexpr (Features::monitor) deepest = max_r(deepest, g.overlap);
      const Vec3<Real> ri = g.point - body.x;
      const Vec3<Real> zero{0, 0, 0};
      const Vec3<Real> v_rel = Kinematics::relative(v, w, ri, zero, zero, zero);
      const Vec3<Real> fw = laws(mi, material).force(g, v_rel, m);
      f += fw;
      if constexpr (Features::rotation) t += cross(ri, fw);
    };
    for (int k = 0; k < world.polygon_count; ++k)
      apply(shape.collide_world(body, world.polygons[k]), world.polygons[k].material);
    for (int k = 0; k < world.cylinder_count; ++k)
      apply(shape.collide_world(body, world.cylinders[k]), world.cylinders[k].material);
    p.force.set(i, f);
    if constexpr (Features::rotation) p.torque.set(i, p.torque.get(i) + t);
    if constexpr (Features::monitor) p.penetration[i] = max_r(p.penetration[i], deepest / p.radius[i]);
  }
};

}  // namespace blaze
