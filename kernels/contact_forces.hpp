// Particle-particle contact forces (thesis Algorithm 2.1, line 4), one thread per particle i:
// walk i's neighbours, collide with the shape policy, evaluate the law for the material pair, and
// write only i's force and torque (eq. 2.4: T = r x F). Each pair is evaluated from both sides, so
// no atomics are needed and the summation order is the same on every backend. Both sides call
// collide(lower index, higher index) and the higher one flips the normal, so the two see exactly
// the same geometry (Newton's third law holds to the last bit of the geometry).
// With Features::statistics each particle also counts its vertex-face and edge-edge contacts;
// with Features::monitor it keeps its deepest overlap / radius (reset by the host).
#pragma once
#include "blaze/contact/kinematics.hpp"
#include "blaze/exec/launch.hpp"
#include "blaze/laws/contact_law.hpp"
#include "blaze/sim/features.hpp"
#include "kernels/broad_phase_kernels.hpp"

namespace blaze {

// Per-particle contact counts by kind (null when statistics are off).
struct ContactStats {
  Index* vertex_face;
  Index* edge_edge;
};

template <class Shape, class Law, class Kinematics, class Features>
struct ContactForces {
  using Real = typename Law::real_type;
  static constexpr int kMinBlocks = min_blocks_v<Shape>;  // launch.hpp
  Shape shape;
  ParticleView<Real> p;
  NeighbourView list;
  PairTable<Law> laws;
  ContactStats stats;

  BLAZE_HD void operator()(Index i) const {
    const auto bi = shape.body(p, i);
    const Vec3<Real> vi = p.velocity.get(i);
    const Vec3<Real> wi = Features::rotation ? p.angular_velocity.get(i) : Vec3<Real>{0, 0, 0};
    const Real inv_mi = p.inv_mass[i];
    const int mi = p.material[i];
    Vec3<Real> f{0, 0, 0}, t{0, 0, 0};
    Index vertex_face = 0, edge_edge = 0;
    Real deepest = 0;
    const Index count = min_r(list.count[i], list.capacity);
    for (Index k = 0; k < count; ++k) {
      const Index j = list.at(k, i);
      const auto bj = shape.body(p, j);
      ContactGeometry<Real> g;
      if (i < j) {
        g = shape.collide(bi, bj);
      } else {
        g = shape.collide(bj, bi);
        g.normal = -g.normal;
      }
      if (!g.touching) continue;
      if constexpr (Features::statistics) (g.kind == ContactKind::edge_edge ? edge_edge : vertex_face) += 1;
      if constexpr (Features::monitor) deepest = max_r(deepest, g.overlap);
      const Vec3<Real> ri = g.point - bi.x;
      const Vec3<Real> wj = Features::rotation ? p.angular_velocity.get(j) : Vec3<Real>{0, 0, 0};
      const Vec3<Real> v_rel = Kinematics::relative(vi, wi, ri, p.velocity.get(j), wj, g.point - bj.x);
      const Real m_eff = Real(1) / (inv_mi + p.inv_mass[j]);
      const Vec3<Real> fij = laws(mi, p.material[j]).force(g, v_rel, m_eff);
      f += fij;
      if constexpr (Features::rotation) t += cross(ri, fij);
    }
    p.force.set(i, f);
    if constexpr (Features::rotation) p.torque.set(i, t);
    if constexpr (Features::monitor) p.penetration[i] = max_r(p.penetration[i], deepest / p.radius[i]);
    if constexpr (Features::statistics) {
      stats.vertex_face[i] = vertex_face;
      stats.edge_edge[i] = edge_edge;
    }
  }
};

}  // namespace blaze
