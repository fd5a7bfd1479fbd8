// Particle-world contact forces (thesis Algorithm 2.1, line 6), added to the particle's force and
// torque. Walls have infinite mass: m_eff = m_i. A moving object (blaze/world/motion.hpp; its
// pose placed by the move-world phase) enters the contact through its velocity at the contact
// point, v_w = omega x (x - o) + u', in the relative velocity (and omega in the rolling laws'
// relative spin). A removed object is skipped; with world lists (world_candidates.hpp) only the
// objects in the particle's list are tested. A contact with a patch (contact_patch.hpp) adds the
// patch's moment about the contact point to the torque. A law with history keeps each wall
// contact's state in a slot of the particle keyed by the object (contact_history.hpp): found or
// claimed when touching, freed when the contact opens. A triangle mesh (blaze/world/mesh_wall.hpp)
// gives one contact per point of its surface (world_contacts.hpp), each with its own slot.
// When the run keeps energy accounts (blaze/particles/energy_ledger.hpp), each contact books
// the drive's work (F . v_w(p) + M . omega) dt to the drive column and to its object's class
// column, and adds its force F and torque r x F + M to the class's sums of the particle
// (EnergyLedger::class_sums; the first contact of a class in a step writes them, and the class
// mask says which were written); the integrator's last kick then books
// -(F_c . v + T_c . w) dt with the step's final velocities (kernels/integrate.hpp, book_energy).
// With Features::thesis_power each contact also adds the thesis's estimate |F_diss| |V| dt
// (contact_pair.hpp, thesis_dissipation).
#pragma once
#include <type_traits>
#include "blaze/contact/contact_patch.hpp"
#include "blaze/contact/kinematics.hpp"
#include "blaze/exec/launch.hpp"
#include "blaze/laws/contact_law.hpp"
#include "blaze/sim/features.hpp"
#include "blaze/world/world.hpp"
#include "blaze/particles/particle_store.hpp"
#include "kernels/contact_history.hpp"
#include "kernels/contact_pair.hpp"
#include "kernels/world_contacts.hpp"

namespace blaze {

template <class Shape, class Law, class Kinematics, class Features>
struct WorldForces {
  using Real = typename Law::real_type;
  // The shape's bound, or (256, 1) for spheres: 0.22 against 0.29 ms per step without it (1e7, H200; launch.hpp).
  static constexpr int kMinBlocks =
      history_min_blocks<Law>(min_blocks_v<Shape> > 0 ? min_blocks_v<Shape> : 1, BLAZE_HISTORY_WALL_MIN_BLOCKS);
  Shape shape;
  ParticleView<Real> p;
  WorldView<Real> world;
  PairTable<Law> laws;
  WallHistoryView<Real, Law::State::kReals> history;  // per-particle slots keyed by the object (contact_history.hpp)
  Real dt;

  BLAZE_HD void operator()(Index i) const {
    const auto body = shape.body(p, i);
    // A particle that touches no wall (most of them) reads its position and nothing else, and
    // writes nothing: the force and the rest are read at the first wall contact. The sums are
    // formed in the same order as when they were read up front, so the result is the same.
    bool touched = false;
    Vec3<Real> f{0, 0, 0}, t{0, 0, 0};
    Real deepest = 0;
    unsigned seen = 0;  // slots of objects touched this step
    Real work = 0;      // J, done this step by moving objects on i (energy accounts)
    Real thesis = 0;    // J, the thesis's estimate over i's wall contacts (Features::thesis_power)
    unsigned classes = 0;  // the classes whose sums this step has written (EnergyLedger::class_mask)
    // Per class, its drive column and its sums as booked so far, written once after the contacts
    // (the same additions in the same order as booking each contact in memory, without a load
    // and a store per contact that held up the next contact's loads).
    Real class_drive[kContactClasses] = {}, class_sum[kContactClasses][6] = {};
    // A contact with object w (world_contacts.hpp: key, and for a mesh the group of its contacts).
    const auto apply = [&](const auto& g, int material, int w, WallKey key, const auto* group) {
      if (!g.touching) return;
      if (!touched) f = p.force.get(i), touched = true;
      if constexpr (Features::monitor) deepest = max_r(deepest, g.overlap);
      const Vec3<Real> ri = g.point - body.x;
      const Vec3<Real> zero{0, 0, 0};
      const Pose<Real>* pose = world.pose_of(w);  // a still object: the identity
      const Vec3<Real> w_wall = pose ? pose->omega : zero;
      const Law& law = laws(p.material[i], material);
      int h = -1;  // the contact's slot (laws with history)
      (void)h, (void)key, (void)group;
      auto state = typename Law::State{};
      if constexpr (Law::kHistory) {
        h = group ? mesh_contact_slot(history, i, key, seen, *group, world, w) : history.slot(i, key);
        state = h >= 0 ? history.load(h, i) : Law::State::zero();
        if (h < 0) history.overflow[i] = 1;  // ran without its state: the store grows at the next rebuild
        else seen |= 1u << h;
      }
      Vec3<Real> v_point;
      const ContactForce<Real> c = wall_force<Kinematics, Features>(law, p, body, i, g, pose, state, dt, v_point);
      if constexpr (Features::thesis_power) thesis += thesis_dissipation(law, static_cast<const ContactGeometry<Real>&>(g), c.force, v_point, dt);
      if constexpr (Law::kHistory)
        if (h >= 0) history.store(h, i, state);
      f += c.force;
      constexpr bool kMoment = has_moment_v<Law, std::decay_t<decltype(g)>>;
      if constexpr (Features::rotation) {
        if constexpr (kMoment) t += cross(ri, c.force) + c.moment;
        else t += cross(ri, c.force);
      }
      if (p.ledger.on()) {
        const Vec3<Real> mc = kMoment && Features::rotation ? c.moment : zero;
        const Real drive = (pose ? dot(c.force, pose->velocity_at(g.point)) + dot(mc, w_wall) : Real(0)) * dt;
        const int cls = static_cast<int>(world.class_of(w));
        work += drive;
        const Vec3<Real> tc = Features::rotation ? cross(ri, c.force) + mc : zero;
        const Real add[6] = {c.force.x, c.force.y, c.force.z, tc.x, tc.y, tc.z};
        BLAZE_UNROLL
        for (int k = 0; k < kContactClasses; ++k) {  // (constant indices: the books stay in registers)
          if (k != cls) continue;
          const bool first = !(classes >> k & 1u);  // the class's first contact this step
          class_drive[k] = (first ? p.ledger.column[kLedgerWalls + k][i] : class_drive[k]) + drive;
          for (int j = 0; j < 6; ++j) class_sum[k][j] = first ? add[j] : class_sum[k][j] + add[j];
        }
        classes |= 1u << cls;
      }
    };
    for_each_world_contact(shape, body, world, i, apply);
    if constexpr (Law::kHistory) history.release_unseen(i, seen);
    if (p.ledger.on()) {
      BLAZE_UNROLL
      for (int k = 0; k < kContactClasses; ++k) {
        if (!(classes >> k & 1u)) continue;
        p.ledger.column[kLedgerWalls + k][i] = class_drive[k];
        for (int j = 0; j < 6; ++j) p.ledger.sum(k, j, i) = class_sum[k][j];
      }
      p.ledger.class_mask[i] = static_cast<std::uint8_t>(classes);
    }
    if (!touched) return;
    if (p.ledger.on()) p.ledger.column[kLedgerDrive][i] += work;
    if constexpr (Features::thesis_power)
      if (p.ledger.thesis_estimate) p.ledger.thesis_estimate[i] += thesis;
    p.force.set(i, f);
    if constexpr (Features::rotation) p.torque.set(i, p.torque.get(i) + t);
    if constexpr (Features::monitor) p.penetration[i] = max_r(p.penetration[i], deepest / p.radius[i]);
  }
};

}  // namespace blaze
