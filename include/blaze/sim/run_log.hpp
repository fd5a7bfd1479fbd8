// The time series of a run (timeseries.csv) and its warnings on stdout: energies (J), the energy
// dissipated so far, contacts by kind, particles removed, penetration. One row per sample:
//   t_s, particles, removed, kinetic_translational_J, kinetic_rotational_J, potential_J, total_J,
//   dissipated_J, contacts_vertex_face, contacts_edge_edge, max_penetration_ratio,
//   penetration_over_limit, worst_penetration_id
// dissipated_J = E(0) - E(t) - E_removed: what contacts and drag took out. E_removed sums each
// removed particle's energy at the last sample that still held it, so it is exact when nothing
// left the domain and an estimate (one sample interval late) otherwise.
// Penetration (overlap / radius) is the deepest over all steps since the previous sample, not
// only at the sample: a particle over `limit` is counted and the worst named (the thesis warns
// at 5%). Particles leaving the domain are reported the sample after they left.
#pragma once
#include <cstdio>
#include <fstream>
#include <string>
#include <vector>
#include "blaze/sim/energy.hpp"
#include "blaze/sim/simulation.hpp"

namespace blaze {

template <class Real>
class RunLog {
 public:
  // keep_until >= 0 (a restarted run): the existing file's rows up to that time stay.
  RunLog(const std::string& path, double penetration_limit, const Vec3<Real>& gravity, std::size_t particles,
         double keep_until = -1)
      : path_(path), limit_(penetration_limit), gravity_(gravity), energy_(particles, 0), present_(particles, 0) {
    std::string kept = "t_s,particles,removed,kinetic_translational_J,kinetic_rotational_J,potential_J,total_J,dissipated_J,"
                       "contacts_vertex_face,contacts_edge_edge,max_penetration_ratio,penetration_over_limit,"
                       "worst_penetration_id\n";
    if (keep_until >= 0) {
      std::ifstream in(path);
      std::string line;
      for (bool header = true; std::getline(in, line); header = false)
        if (!header && !line.empty() && std::stod(line.substr(0, line.find(','))) <= keep_until) kept += line + "\n";
    }
    out_.open(path, std::ios::trunc);
    if (!out_) throw std::runtime_error("cannot write " + path);
    out_ << kept;
    out_.precision(10);
  }

  // A restarted run continues with the energy bookkeeping its checkpoint saved (save()).
  void resume(const std::string& saved, const ParticleState<Real>& st) {
    if (std::sscanf(saved.c_str(), "e0=%lf removed_energy=%lf", &e0_, &removed_energy_) != 2)
      throw std::runtime_error("checkpoint: no energy bookkeeping in its run text");
    started_ = true;
    for (std::size_t k = 0; k < st.size(); ++k) {
      energy_[static_cast<std::size_t>(st.id[k])] = particle_energies(st, k, gravity_).total();
      present_[static_cast<std::size_t>(st.id[k])] = 1;
    }
  }
  std::string save() const {
    char buf[96];
    std::snprintf(buf, sizeof buf, "e0=%.17g removed_energy=%.17g", e0_, removed_energy_);
    return buf;
  }

  // One row: the state `st` at time t, the simulation's counters since the last sample.
  template <class Sim>
  void sample(Sim& sim, const ParticleState<Real>& st) {
    Energies e;
    // Each particle's energy, by id, for the removed-energy estimate.
    std::vector<char> now(present_.size(), 0);
    for (std::size_t k = 0; k < st.size(); ++k) {
      const Energies p = particle_energies(st, k, gravity_);
      e.translational += p.translational, e.rotational += p.rotational, e.potential += p.potential;
      const auto id = static_cast<std::size_t>(st.id[k]);
      energy_[id] = p.total();
      now[id] = 1;
    }
    for (std::size_t id = 0; id < present_.size(); ++id)
      if (present_[id] && !now[id]) removed_energy_ += energy_[id];
    if (!started_) e0_ = e.total(), started_ = true;
    present_.swap(now);

    const auto [vf, ee] = sim.contact_counts();
    const PenetrationReport pen = sim.take_penetration(limit_);
    out_ << sim.time() << ',' << st.size() << ',' << sim.removed_count() << ',' << e.translational << ','
         << e.rotational << ',' << e.potential << ',' << e.total() << ',' << e0_ - e.total() - removed_energy_ << ','
         << vf << ',' << ee << ',' << pen.worst << ',' << pen.over << ',' << pen.worst_id << '\n';
    if (pen.over > 0 && warnings_++ < kMaxWarnings)
      std::printf("warning: t = %.6g s: %ld particles exceeded %.3g%% penetration since the last sample; deepest "
                  "%.3g%% (particle id %d)%s\n",
                  sim.time(), pen.over, 100 * limit_, 100 * pen.worst, static_cast<int>(pen.worst_id),
                  warnings_ == kMaxWarnings ? " [further penetration warnings only in the CSV]" : "");
    if (sim.removed_count() > reported_removed_) {
      std::printf("note: t = %.6g s: %d particles left the domain (total %d, %.4g kg)\n", sim.time(),
                  static_cast<int>(sim.removed_count() - reported_removed_), static_cast<int>(sim.removed_count()),
                  sim.removed_mass());
      reported_removed_ = sim.removed_count();
    }
    worst_ = std::max(worst_, pen.worst);
    over_samples_ += pen.over > 0;
  }

  double worst_penetration() const { return worst_; }
  long samples_over_limit() const { return over_samples_; }

 private:
  static constexpr long kMaxWarnings = 10;
  std::ofstream out_;
  std::string path_;
  double limit_;
  Vec3<Real> gravity_;
  std::vector<double> energy_;
  std::vector<char> present_;
  double e0_ = 0, removed_energy_ = 0, worst_ = 0;
  bool started_ = false;
  long warnings_ = 0, over_samples_ = 0;
  Index reported_removed_ = 0;
};

}  // namespace blaze
