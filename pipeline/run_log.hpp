// The time series of a run (timeseries.csv) and its warnings on stdout: energies (J), the energy
// dissipated so far, contacts by kind, particles removed, penetration. One row per sample:
//   t_s, particles, removed, kinetic_translational_J, kinetic_rotational_J, potential_J, elastic_J,
//   total_J, dissipated_J, contacts_vertex_face, contacts_edge_edge, contacts_wall,
//   max_penetration_ratio, penetration_over_limit, worst_penetration_id, drive_work_J
// elastic_J: the energy stored in the open contacts, particle-particle and particle-wall
// (Simulation::contact_energy(): the laws' stored_energy, 1/2 K_n delta^2 or (2/5) K_n delta^(5/2)).
// total_J = kinetic_translational_J + kinetic_rotational_J + potential_J + elastic_J = E(t).
// drive_work_J = W(t): the work moving world objects did on the particles so far (F . v_wall dt
//   per contact and step, kernels/world_forces.hpp; zero in a static world).
// When the run keeps energy accounts (a world that moves, or [output] energy_by_class; the log is
// made with `ledger`), five more columns follow: the energy taken out so far by particle-particle
// contacts and by the contacts with each class of world object (blaze/particles/energy_ledger.hpp):
//   dissipated_pair_J, dissipated_wall_J, dissipated_shell_J, dissipated_lifter_J, dissipated_end_plate_J
// Then, for each reported world object (LoadColumns: `blaze run` reports every [[mesh]] and every
// named [[wall]]), the load the particles put on it (Simulation::world_loads):
//   load_<name>_Fx_N, _Fy_N, _Fz_N, _Tx_Nm, _Ty_Nm, _Tz_Nm   (torque about the origin)
// Their sum is the energy method's dissipation, measured contact by contact; it differs from
// dissipated_J (the balance's residual) by the elastic energy the contacts hold and the
// integrator's error in the work (verification/test_energy_ledger.cpp).
// With feeders (the log made with `feeding`), two columns close the row: inserted, inserted_kg
// (particles and mass inserted since the start).
// dissipated_J = E(0) + W(t) + E_inserted - E(t) - E_removed: what the dashpots, friction and drag
//   took out, so that E(0) + W(t) + E_inserted = E(t) + dissipated_J + E_removed (energy in =
//   energy out + stored); E_inserted: the kinetic and potential energy particles inserted by
//   feeders had when they were inserted (Simulation::inserted_energy)
// holds in every row; an elastic, frictionless run keeps dissipated_J at zero up to the
// integrator's O((omega dt)^2) wobble (verification/test_energy_balance.cpp). E_removed is the
// kinetic and potential energy the removed particles had when they were removed
// (Simulation::removed_energy; their rotational energy, and the elastic energy of contacts
// they left, are left out: they leave the domain in flight).
// contacts_vertex_face, contacts_edge_edge: particle-particle contacts by kind (spheres are
// vertex-face), each pair once; contacts_wall: particle-world contacts, planar polygons and
// cylinders together (a particle touching two walls counts 2).
// Penetration (overlap / radius) is the deepest over all steps since the previous sample, not
// only at the sample: a particle over `limit` is counted and the worst named (the thesis warns
// at 5%). Particles leaving the domain are reported the sample after they left.
//
// Energy guard: nothing but the moving walls feeds energy in, so E(t) + E_removed <= E(0) + W(t) up to the
// integrator's O(dt^2) wobble, with E(t) including the elastic energy (so the guard is not
// loosened by energy hidden in the contacts). A gain above `energy_gain_limit` x scale, scale =
// initial kinetic + initial elastic energy + sum m |g| h (h: the domain's extent along g, so the
// most energy the bed can exchange) + |W(t)| (the walls' work is summed once per step, so its
// error grows with it), is an unstable step: sample() throws EnergyGain before it
// writes that row, so no row with created energy reaches the file.
// Checkpoints keep E(0) and the scale (save(), resume()); the text names the energy's parts, and a
// checkpoint whose E(0) left out the elastic energy is refused (its dissipated_J would jump).
#pragma once
#include <cctype>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <string>
#include <vector>
#include "blaze/sim/energy.hpp"
#include "pipeline/simulation.hpp"

namespace blaze {

// A run whose energy rose above its initial value: what() names the time, the gain and the scale.
struct EnergyGain : std::runtime_error {
  using std::runtime_error::runtime_error;
};

// The world objects whose loads a log reports, and their names in the column headers.
struct LoadColumns {
  std::vector<std::string> names;
  std::vector<int> objects;
};

template <class Real>
class RunLog {
 public:
  // keep_until >= 0 (a restarted run): the existing file's rows up to that time stay.
  // `height`: the domain's extent along gravity (m), for the energy guard's scale.
  RunLog(const std::string& path, double penetration_limit, double energy_gain_limit, const Vec3<Real>& gravity,
         double height, double keep_until = -1, bool ledger = false, LoadColumns loads = {}, bool feeding = false)
      : path_(path), limit_(penetration_limit), gain_limit_(energy_gain_limit), gravity_(gravity), height_(height), ledger_(ledger),
        loads_(std::move(loads)), feeding_(feeding) {
    std::string kept = "t_s,particles,removed,kinetic_translational_J,kinetic_rotational_J,potential_J,elastic_J,total_J,"
                       "dissipated_J,contacts_vertex_face,contacts_edge_edge,contacts_wall,max_penetration_ratio,"
                       "penetration_over_limit,worst_penetration_id,drive_work_J";
    if (ledger_) {
      kept += ",dissipated_pair_J";
      for (int c = 0; c < kContactClasses; ++c) kept += std::string(",dissipated_") + contact_class_name(c) + "_J";
    }
    for (const auto& name : loads_.names) {
      std::string n;
      for (char ch : name) n += std::isalnum(static_cast<unsigned char>(ch)) ? ch : '_';
      for (const char* q : {"Fx_N", "Fy_N", "Fz_N", "Tx_Nm", "Ty_Nm", "Tz_Nm"}) kept += ",load_" + n + "_" + q;
    }
    if (feeding_) kept += ",inserted,inserted_kg";
    kept += "\n";
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
  void resume(const std::string& saved) {
    if (std::sscanf(saved.c_str(), "e0=%lf scale=%lf", &e0_, &scale_) != 2)
      throw std::runtime_error("checkpoint: no energy bookkeeping in its run text");
    const auto w = saved.find(" work=");  // absent before moving walls: none was done
    work_ = w == std::string::npos ? 0.0 : std::stod(saved.substr(w + 6));
    const auto d = saved.find(" dissipated=");  // absent before the accounts: none kept
    if (d != std::string::npos) {
      std::size_t at = d + 12;
      for (double& x : dissipated_) {
        std::size_t used = 0;
        x = std::stod(saved.substr(at), &used);
        at += used + 1;  // past the comma
      }
    }
    // the run so far's guard summary (absent before it was saved: the restarted part only)
    const auto g = saved.find(" gain=");
    if (g != std::string::npos) {
      int compared = 0;
      if (std::sscanf(saved.c_str() + g, " gain=%lf compared=%d worst=%lf over=%ld", &max_gain_, &compared, &worst_, &over_samples_) != 4)
        throw std::runtime_error("checkpoint: its run text's guard summary is malformed");
      compared_ = compared != 0;
    }
    if (saved.find(kEnergyParts) == std::string::npos)
      throw std::runtime_error("checkpoint: its E(0) leaves out the elastic energy of the contacts (written before "
                               "elastic_J was part of total_J); rerun from the start");
    started_ = true;
  }
  std::string save() const {
    char buf[600];
    std::snprintf(buf, sizeof buf,
                  "e0=%.17g scale=%.17g work=%.17g %s dissipated=%.17g,%.17g,%.17g,%.17g,%.17g gain=%.17g compared=%d "
                  "worst=%.17g over=%ld",
                  e0_, scale_, work_, kEnergyParts, dissipated_[0], dissipated_[1], dissipated_[2], dissipated_[3], dissipated_[4],
                  max_gain_, compared_ ? 1 : 0, worst_, over_samples_);
    return buf;
  }

  // One row: the simulation now, reduced where its particles live (Simulation::sample()), and
  // the counters since the last sample.
  // write = false: the guards and the sums only, no row (a run without csv_interval still checks).
  template <class Sim>
  void sample(Sim& sim, bool write = true) {
    const auto smp = sim.sample(limit_);
    const Energies& e = smp.energies;
    const ContactEnergy& stored = smp.stored;
    const double total = e.total() + stored.total();
    if (!started_) {  // the scale: initial kinetic + elastic energy + sum m |g| h
      const double exchange = smp.mass * static_cast<double>(norm(gravity_)) * height_;
      e0_ = total, scale_ = e.translational + e.rotational + stored.total() + exchange, started_ = true;
    }
    const double removed_energy = sim.removed_energy();
    // particles inserted since the start (feeders) brought their kinetic and potential energy
    const double inserted_energy = sim.inserted_energy();
    work_ += smp.drive_work;
    dissipated_[0] += smp.dissipated_pair;
    for (int c = 0; c < kContactClasses; ++c) dissipated_[1 + c] += smp.dissipated_walls[c];
    const double gain = total + removed_energy - work_ - inserted_energy - e0_;
    // the balance's error grows with the energy that went through it: moving walls add |W|,
    // inserted particles their kinetic energy and what they can exchange with gravity
    const double scale = scale_ + std::abs(work_) + sim.inserted_kinetic() + sim.inserted_mass() * static_cast<double>(norm(gravity_)) * height_;
    if (scale > 0 && gain > gain_limit_ * scale) {
      char msg[360];
      std::snprintf(msg, sizeof msg, "t = %.6g s (step %llu): the energy rose %.3g J above its initial value plus the "
                    "moving walls' work (%.3g J), %.3g of the scale %.3g J (limit %.3g, [output] energy_gain_limit); "
                    "nothing else feeds energy in, so the time step is unstable",
                    sim.time(), static_cast<unsigned long long>(sim.steps()), gain, work_, gain / scale, scale, gain_limit_);
      throw EnergyGain(msg);
    }
    if (scale > 0) max_gain_ = std::max(max_gain_, gain / scale), compared_ = true;

    const PenetrationReport& pen = smp.penetration;
    if (write) row(sim, smp, total, inserted_energy, removed_energy);
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

  // The sample's row (its columns: the header above).
  template <class Sim, class Sample>
  void row(Sim& sim, const Sample& smp, double total, double inserted_energy, double removed_energy) {
    const Energies& e = smp.energies;
    const ContactEnergy& stored = smp.stored;
    const long vf = smp.vertex_face, ee = smp.edge_edge;
    const PenetrationReport& pen = smp.penetration;
    out_ << sim.time() << ',' << sim.size() << ',' << sim.removed_count() << ',' << e.translational << ','
         << e.rotational << ',' << e.potential << ',' << stored.total() << ',' << total << ','
         << e0_ + work_ + inserted_energy - total - removed_energy << ',' << vf << ',' << ee << ',' << stored.wall_contacts << ',' << pen.worst
         << ',' << pen.over << ',' << pen.worst_id << ',' << work_;
    if (ledger_)
      for (double d : dissipated_) out_ << ',' << d;
    if (!loads_.objects.empty())
      for (const auto& l : sim.world_loads(loads_.objects))
        out_ << ',' << l.force.x << ',' << l.force.y << ',' << l.force.z << ',' << l.torque.x << ',' << l.torque.y << ',' << l.torque.z;
    if (feeding_) out_ << ',' << sim.inserted_count() << ',' << sim.inserted_mass();
    out_ << '\n';
  }

  double worst_penetration() const { return worst_; }
  // Largest (E(t) + E_removed - E(0)) / scale over the samples written (<= 0: never above E(0)).
  double max_energy_gain() const { return max_gain_; }
  bool energy_compared() const { return compared_; }  // a sample had a scale to compare the gain with
  long samples_over_limit() const { return over_samples_; }

 private:
  static constexpr long kMaxWarnings = 10;
  static constexpr const char* kEnergyParts = "energy=kinetic+potential+elastic";
  std::ofstream out_;
  std::string path_;
  double limit_, gain_limit_;
  Vec3<Real> gravity_;
  double height_;
  double e0_ = 0, scale_ = 0, worst_ = 0, max_gain_ = -1e300;
  bool compared_ = false;
  double work_ = 0;  // J, W(t)
  bool ledger_;
  LoadColumns loads_;
  bool feeding_;
  double dissipated_[1 + kContactClasses] = {};  // J so far: pairs, then each world contact class
  static_assert(1 + kContactClasses == 5, "save() writes five accounts");
  bool started_ = false;
  long warnings_ = 0, over_samples_ = 0;
  Index reported_removed_ = 0;
};

}  // namespace blaze
