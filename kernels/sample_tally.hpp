// One row of the time series reduced where the particles live (Simulation::sample(), RunLog), so
// a sample costs a kernel and a few kB back to the host instead of the whole state. Per particle i:
//   translational, rotational, potential  body_energies() (blaze/sim/energy.hpp)           [J]
//   mass                                  m_i, for the energy guard's scale                 [kg]
//   pair_energy, wall_energy, wall_contacts  StoredContactEnergy's slots (contact_energy.hpp),
//                                         when that kernel ran just before                  [J]
//   vertex_face, edge_edge                the last force evaluation's counts (statistics)
//   worst, worst_id, over                 deepest overlap / radius since the last reset, its
//                                         particle's permanent id (the lowest on a tie: the
//                                         same whatever the memory order), and the count
//                                         above `threshold` (Features::monitor)
//   ledger                                the particle's energy accounts since the last reset
//                                         (drive work, dissipation by contact class;
//                                         blaze/particles/energy_ledger.hpp), when kept     [J]
//   thesis_estimate                       the thesis's sum |F_diss| |V| dt, when kept        [J]
// reduce_in_order (exec/primitives.hpp) folds them deterministically.
// `counted` (null: every particle) leaves out the particles marked 0: a rank's ghost copies of
// other ranks' particles (pipeline/parallel/distributed_simulation.hpp), which their owners count.
#pragma once
#include "blaze/exec/launch.hpp"
#include "blaze/particles/particle_store.hpp"
#include "blaze/sim/energy.hpp"

namespace blaze {

struct SampleTally {
  double translational = 0, rotational = 0, potential = 0, mass = 0;  // J, J, J, kg
  double pair_energy = 0, wall_energy = 0;                            // J
  double ledger[kLedgerColumns] = {};                                  // J
  double thesis_estimate = 0;                                          // J (EnergyLedger::thesis_estimate)
  long long wall_contacts = 0, vertex_face = 0, edge_edge = 0, over = 0;
  double worst = 0;        // overlap / radius
  Index worst_id = -1;  // permanent id of the deepest (-1: none above 0)

  BLAZE_HD void combine(const SampleTally& o) {
    translational += o.translational, rotational += o.rotational, potential += o.potential, mass += o.mass;
    pair_energy += o.pair_energy, wall_energy += o.wall_energy;
    for (int c = 0; c < kLedgerColumns; ++c) ledger[c] += o.ledger[c];
    thesis_estimate += o.thesis_estimate;
    wall_contacts += o.wall_contacts, vertex_face += o.vertex_face, edge_edge += o.edge_edge, over += o.over;
    if (o.worst > worst || (o.worst == worst && o.worst_id >= 0 && (worst_id < 0 || o.worst_id < worst_id)))
      worst = o.worst, worst_id = o.worst_id;
  }
};

// Null pointers leave their terms at zero.
template <class Shape, class Real>
struct ParticleTally {
  Shape shape;
  ParticleView<Real> p;
  Vec3<Real> gravity;
  const double* pair_energy;
  const double* wall_energy;
  const Index* wall_contacts;
  const Index* vertex_face;
  const Index* edge_edge;
  double threshold;
  const std::uint8_t* counted = nullptr;
  // Periodic axes: the image counts per axis (null: not periodic there) and the periods (m). The
  // potential energy is that of the unwrapped position x + image L: a particle that wraps along
  // gravity keeps falling, and its wrapped height would hand it m g L back at every crossing.
  const Index* image[3] = {nullptr, nullptr, nullptr};
  Vec3<double> period{0, 0, 0};

  BLAZE_HD SampleTally operator()(Index i) const {
    SampleTally t;
    if (counted && !counted[i]) return t;
    const Real m = Real(1) / p.inv_mass[i];
    const Energies e = body_energies(static_cast<double>(m), p.velocity.get(i), p.orientation.get(i),
                                     p.angular_velocity.get(i), shape.principal_inertia(p.inv_inertia[i], p.radius[i], p.type[i]),
                                     p.position.get(i), gravity);
    t.translational = e.translational, t.rotational = e.rotational, t.potential = e.potential;
    const Vec3<double> g = vec_cast<double>(gravity);
    if (image[0]) t.potential -= static_cast<double>(m) * g.x * period.x * static_cast<double>(image[0][i]);
    if (image[1]) t.potential -= static_cast<double>(m) * g.y * period.y * static_cast<double>(image[1][i]);
    if (image[2]) t.potential -= static_cast<double>(m) * g.z * period.z * static_cast<double>(image[2][i]);
    t.mass = static_cast<double>(m);
    if (pair_energy) t.pair_energy = pair_energy[i], t.wall_energy = wall_energy[i], t.wall_contacts = wall_contacts[i];
    if (vertex_face) t.vertex_face = vertex_face[i], t.edge_edge = edge_edge[i];
    if (p.ledger.on())
      for (int c = 0; c < kLedgerColumns; ++c) t.ledger[c] = static_cast<double>(p.ledger.column[c][i]);
    if (p.ledger.thesis_estimate) t.thesis_estimate = static_cast<double>(p.ledger.thesis_estimate[i]);
    if (p.penetration) {
      const double d = static_cast<double>(p.penetration[i]);
      t.over = d > threshold;
      if (d > 0) t.worst = d, t.worst_id = p.id[i];
    }
    return t;
  }
};

}  // namespace blaze
