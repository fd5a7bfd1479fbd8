// The hopper study's run (studies/hopper/main.cpp: study_hopper; over ranks issue 21).
// Spheres or polyhedra, placed at the start or poured by the scene's [[feed]]s, settle behind the
// wall named "gate"; at [study] gate_open_time the gate is removed (a timed event of the one run:
// the contacts keep their history across it) and the bed drains through the orifice. Particles
// that fall below the hopper leave the domain: they are removed and counted, and that count is the
// discharge. Times are reported from the opening (negative while settling). With [study]
// arch_time > 0, a run whose flow stops (no exit for that long) with particles over the orifice has
// arched (discharge_record.hpp): it ends there and says so. Writes <output
// directory>/{timeseries.csv, discharge.csv (each particle's place at the opening and exit time),
// manifest.txt (with the flow rate, residual and flow pattern: discharge_record.hpp),
// vtu/*.vtu, particles.pvd, walls.vtu}. The scene chooses the law (linear or Hertz, history-free or
// with a tangential spring, rolling resistance for spheres); the study runs in double.
// Over ranks (build/mpi/study_hopper under mpirun): every rank runs the loop; a row's energies,
// stored energy and penetration are the ranks' sums (Simulation::sample, reduced); the bed's
// particles come to rank 0 at each row and frame (the discharge record and the VTU files), which
// writes, and which decides for all whether an arch holds.
#pragma once
#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <map>
#include <string>
#include <type_traits>
#include <vector>
#include "blaze/exec/device_info.hpp"
#include "blaze/io/manifest.hpp"
#include "blaze/io/vtu_writer.hpp"
#include "blaze/scene/scene_build.hpp"
#include "blaze/scene/scene_file.hpp"
#include "blaze/shapes/polyhedron_shape.hpp"
#include "blaze/shapes/sphere_shape.hpp"
#include "blaze/sim/schedule.hpp"
#include "pipeline/feeder.hpp"
#include "pipeline/parallel/communicator.hpp"
#include "pipeline/scene_law.hpp"
#include "pipeline/scene_params.hpp"
#include "pipeline/simulation.hpp"
#include "studies/hopper/discharge_record.hpp"
#if defined(BLAZE_MPI)
#include "pipeline/parallel/distributed_simulation.hpp"
#endif

namespace blaze::hopper {

// The bed's particles: the simulation's; over ranks all of them on rank 0 (none elsewhere).
template <class Sim>
auto bed_state(Sim& sim) { return sim.state(); }
// A decision rank 0 takes for all (over ranks: the largest of the ranks' flags, only rank 0's set).
template <class Sim>
bool on_every_rank(Sim&, bool flag) { return flag; }
#if defined(BLAZE_MPI)
template <class Sim>
auto bed_state(DistributedSimulation<Sim>& sim) { return sim.gathered_state(); }
template <class Sim>
bool on_every_rank(DistributedSimulation<Sim>& sim, bool flag) { return sim.communicator().max(static_cast<long>(flag)) != 0; }
#endif

// The scene's world without the wall named "gate" (which must exist).
template <class Real>
World<Real> without_gate(Scene s) {
  const auto n = s.walls.size();
  s.walls.erase(std::remove_if(s.walls.begin(), s.walls.end(), [](const WallSpec& w) { return w.name == "gate"; }),
                s.walls.end());
  if (s.walls.size() + 1 != n) throw SceneError(s.path + ": the hopper study needs exactly one [[wall]] with name = \"gate\"");
  return build_world<Real>(s);
}

// The [study] keys of the hopper.
struct HopperKeys {
  double gate_open = 0;  // s
  double orifice = 0;    // m, the orifice's half-width (the flow pattern's centre column)
  double axis_x = 0;     // m, the orifice's centre line
  double arch_span = 0;  // s without an exit, particles over the orifice: an arch (0: off)
  explicit HopperKeys(const Scene& s)
      : gate_open(s.study_value("gate_open_time", 0, s.end_time, "s (at most end_time)")),
        orifice(s.study_value_or("orifice_half_width", 0, 10, "m (the flow pattern's centre column)", 0.025)),
        axis_x(s.study_value_or("orifice_x", -1e3, 1e3, "m (the orifice's centre line)", 0.0)),
        arch_span(s.study_value_or("arch_time", 0, 1e3, "s without a particle leaving, with some over the orifice (0: off)", 0.0)) {
    s.check_study_used();
  }
};

// The study's loop on a Simulation, or over ranks on a DistributedSimulation (`root`: the rank
// that writes; every rank runs the same loop, whose samples and counts are collective).
template <class Real, class Shape, class Run>
int drive_hopper(Run& sim, const Scene& s, const HopperKeys& h, std::vector<Feeder<Real>>& feeders,
                 const std::vector<ConvexShape>& shapes, const std::vector<std::string>& overrides, bool root) {
  constexpr bool polyhedra = !std::is_same_v<Shape, SphereShape>;
  const std::string dir = s.output.directory;
  if (root) std::filesystem::create_directories(dir + "/vtu");
  std::ofstream csv(root ? dir + "/timeseries.csv" : std::string("/dev/null"));  // (every rank runs the loop)
  csv << "t_s,discharged_mass_kg,discharged_count,particles_in_hopper,kinetic_translational_J,kinetic_rotational_J,"
         "potential_J,max_penetration_ratio,elastic_J,contacts_wall\n";
  PvdCollection pvd(dir + "/particles.pvd");  // (written by rank 0 alone)
  if (root) write_world_vtu(dir + "/walls.vtu", without_gate<Real>(s));
  int frame = 0;
  long over_limit = 0;
  double worst_penetration = 0;
  std::uint64_t particle_steps = 0;
  const auto every = [&](double interval) {
    return std::max<std::uint64_t>(1, static_cast<std::uint64_t>(std::llround(interval / s.dt)));
  };
  const std::uint64_t csv_every = every(s.output.csv_interval > 0 ? s.output.csv_interval : s.end_time / 100);
  const std::uint64_t vtu_every = every(s.output.vtu_interval > 0 ? s.output.vtu_interval : s.end_time / 10);
  const auto k_open = static_cast<std::uint64_t>(std::llround(h.gate_open / s.dt));
  const auto k_end = static_cast<std::uint64_t>(std::llround(s.end_time / s.dt));
  const auto wall_start = std::chrono::steady_clock::now();
  DischargeRecord record;
  double arched_at = -1;  // s from the opening, when an arch was seen (-1: none)
  Index count0 = 0;  // what had left the domain when the gate opened (the discharge counts from there)
  double mass0 = 0;
  for (std::uint64_t k = 0;;) {
    const double t = static_cast<double>(k) * s.dt - h.gate_open;
    if (k == k_open) {
      count0 = sim.removed_count(), mass0 = sim.removed_mass();
      if (count0 > 0 && root) std::printf("WARNING: %d particles left the domain while the gate was closed\n", static_cast<int>(count0));
      for (const auto& f : feeders)
        if (f.next_insertion(k) != ~std::uint64_t{0} && root) std::printf("WARNING: feed %s still feeds after the gate opens\n", f.spec().name.c_str());
      record.open(bed_state(sim), h.axis_x, h.orifice);
    }
    const bool end = k == k_end, csv_due = k % csv_every == 0 || end, vtu_due = k % vtu_every == 0 || end;
    if (csv_due || vtu_due) {
      const auto st = bed_state(sim);
      const Index present = sim.size();
      const Index removed = sim.removed_count() - count0;
      const double removed_mass = sim.removed_mass() - mass0;
      if (csv_due) {
        const auto smp = sim.sample(s.output.penetration_warning);
        over_limit += smp.penetration.over;
        worst_penetration = std::max(worst_penetration, static_cast<double>(smp.penetration.worst));
        csv << t << ',' << removed_mass << ',' << removed << ',' << present << ',' << smp.energies.translational << ','
            << smp.energies.rotational << ',' << smp.energies.potential << ',' << smp.penetration.worst << ',' << smp.stored.total() << ','
            << smp.stored.wall_contacts << '\n';
        if (k >= k_open) record.sample(t, st);
        if (on_every_rank(sim, root && k >= k_open && record.arch(t, h.arch_span))) {
          if (root)
            std::printf("  t = %6.3f s  an arch holds: none has left since t = %.3f s, %zu particles over the orifice; the run ends\n", t,
                      record.last_exit(), record.over_orifice());
          arched_at = t;
        }
      }
      if (vtu_due) {
        char name[64];
        std::snprintf(name, sizeof name, "vtu/particles_%04d.vtu", frame++);
        if (root) {
          if constexpr (polyhedra) write_polyhedra_vtu(dir + "/" + name, st, shapes);
          else write_particles_vtu(dir + "/" + name, st);
          pvd.add(t, name);
        }
        if (root)
          std::printf("  t = %6.3f s  in hopper %6zu  discharged %6d (%.3f kg)\n", t, static_cast<std::size_t>(present), static_cast<int>(removed),
                    removed_mass);
      }
    }
    if (end || arched_at >= 0) break;
    for (auto& f : feeders)
      if (f.inserts_at(k)) f.feed(sim);
    // Up to the next row, frame, insertion or the opening in one stretch (the GPU batches it).
    std::uint64_t next = next_event(k, k_end, {csv_every, vtu_every});
    if (k < k_open) next = std::min(next, k_open);
    for (const auto& f : feeders) next = std::min(next, f.next_insertion(k + 1));
    sim.run(next - k);
    particle_steps += static_cast<std::uint64_t>(sim.size()) * (next - k);
    k = next;
  }
  csv.close();

  const double wall = std::chrono::duration<double>(std::chrono::steady_clock::now() - wall_start).count();
  const DischargeSummary d = record.summary(h.orifice, h.arch_span);
  const double t_run = arched_at >= 0 ? arched_at : s.end_time - h.gate_open;  // s of discharge run
  const double discharged_mass = sim.removed_mass() - mass0;
  if (!root) return 0;  // (rank 0 holds the record and writes)
  record.write_csv(dir + "/discharge.csv");
  std::printf("discharged %zu of %zu particles (%s; %.3f kg) in %.2f s; %.1f%% remain in the hopper\n", d.discharged, d.particles, Shape::name,
              discharged_mass, t_run, 100 * d.residual);
  if (h.arch_span > 0)
    std::printf("%s\n", d.arched ? ("arched: the flow stopped at t = " + std::to_string(d.last_exit) + " s with " +
                                    std::to_string(record.over_orifice()) + " particles over the orifice").c_str()
                                 : "no arch: the flow did not stop with particles over the orifice");
  std::printf("steady mass flow rate %.4g kg/s (R^2 %.4f); median exit: top centre %.3g s, bottom sides %.3g s (%s)\n", d.flow_rate,
              d.flow_r2, d.t_top_centre, d.t_bottom_side, d.funnel() ? "funnel flow" : "not funnel flow");
  for (const auto& f : feeders)
    std::printf("feed %s: %ld inserted, %ld due not placed\n", f.spec().name.c_str(), f.inserted(), f.undelivered());
  std::printf("deepest penetration %.3g%% of the radius; %ld particle-samples over %.3g%%\n", 100 * worst_penetration,
              over_limit, 100 * s.output.penetration_warning);
  std::printf("wall time %.1f s, %.3g particle-steps/s\n", wall, static_cast<double>(particle_steps) / wall);
  std::map<std::string, std::string> manifest;
  manifest["scene"] = s.path;
  std::string set;
  for (const auto& o : overrides) set += (set.empty() ? "" : " ") + o;
  manifest["overrides"] = set.empty() ? "(none)" : set;
  manifest["commit"] = git_commit();
  manifest["date"] = utc_date();
  manifest["backend"] = DefaultSpace::name;
  manifest["device"] = device_name(DefaultSpace{});
  manifest["shape"] = Shape::name;
  manifest["law"] = scene_law_name(s);
  auto put = [&](const char* key, double v) {
    char buf[64];
    std::snprintf(buf, sizeof buf, "%.17g", v);
    manifest[key] = buf;
  };
  put("dt_s", s.dt);
  put("wall_time_s", wall);
  manifest["particles_at_opening"] = std::to_string(d.particles);
  manifest["discharged_count"] = std::to_string(d.discharged);
  put("residual_fraction", d.residual);
  put("flow_rate_kg_s", d.flow_rate);
  put("flow_fit_r2", d.flow_r2);
  put("exit_top_centre_s", d.t_top_centre);
  put("exit_bottom_sides_s", d.t_bottom_side);
  manifest["funnel_flow"] = d.funnel() ? "yes" : "no";
  if (h.arch_span > 0) {
    manifest["arched"] = d.arched ? "yes" : "no";
    put("last_exit_s", d.last_exit);
    put("arch_time_s", h.arch_span);
    manifest["over_orifice_at_end"] = std::to_string(record.over_orifice());
  }
  write_manifest(dir + "/manifest.txt", manifest);
  std::printf("wrote %s/timeseries.csv, %s/discharge.csv, %s/particles.pvd (%d frames)\n", dir.c_str(), dir.c_str(), dir.c_str(), frame);
  return 0;
}

// The hopper study of one law and shape: over the ranks of `comm` when it has more than one (an MPI
// build), else one Simulation; in an MPI build (comm given) pairs from both sides in canonical order,
// so one rank and many give the same run (pipeline/parallel/distributed_simulation.hpp).
template <class Law, class Shape>
int run_hopper(const Scene& s, const std::vector<std::string>& overrides, const Communicator* comm = nullptr) {
  using Real = double;
  constexpr bool polyhedra = !std::is_same_v<Shape, SphereShape>;
  using Sim = Simulation<DefaultSpace, Shape, Law, VelocityVerlet, ContactPointVelocity, MonitoredFeatures>;
  const HopperKeys h(s);
  SimulationParams<Real> sp = simulation_params<Real>(s, polyhedra);
  if (comm) sp.pairs = PairEvaluation::both_sides, sp.canonical_order = true;
  Shape shape;
  std::vector<ConvexShape> shapes;
  const PolyhedronTable<Real>* table = nullptr;
  if constexpr (polyhedra) shapes = build_shapes(s), shape.table = build_shape_table<Real>(s, shapes), table = &shape.table;
  const ParticleState<Real> initial = build_particles<Real>(s, table);
  std::printf("hopper: %zu particles (%s) placed, %zu feeds, dt = %.3g s (%.3f of the critical step %.3g s), impact overlap %.3g%% of the "
              "radius\n", initial.size(), Shape::name, s.feeds.size(), s.dt, s.dt / s.dt_critical, s.dt_critical, 100 * s.impact_overlap);
  std::printf("backend: %s, %s\n", DefaultSpace::name, device_name(DefaultSpace{}).c_str());
  std::printf("law: %s\n", scene_law_name(s).c_str());
  std::vector<Feeder<Real>> feeders;
  for (std::size_t k = 0; k < s.feeds.size(); ++k) feeders.emplace_back(s, k, table);
  // One run: the gate is removed at gate_open_time (a timed event), the contacts keep their state.
  const World<Real> world = build_world<Real>(with_wall_removed_at(s, "gate", h.gate_open));
#if defined(BLAZE_MPI)
  if (comm && comm->size() > 1) {
    DistributedSimulation<Sim> run(*comm, sp, build_laws<Law>(s), world, initial, shape);
    return drive_hopper<Real, Shape>(run, s, h, feeders, shapes, overrides, comm->rank() == 0);
  }
#endif
  Sim sim(sp, build_laws<Law>(s), world, initial, shape);
  return drive_hopper<Real, Shape>(sim, s, h, feeders, shapes, overrides, true);
}

}  // namespace blaze::hopper
