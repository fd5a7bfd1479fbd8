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
// Checkpoints: with [output] checkpoint_interval the run writes <output directory>/checkpoint.blz
// that often (the simulation, the feeders, the discharge record and the loop's counts after the
// scene's identity); with a wall-clock limit (--stop-after) it writes one past the limit and stops
// (status 3): at the next checkpoint step when there is an interval, else at the next row, frame or
// insertion. --restart continues it bitwise: the run that wrote checkpoints at the same steps, with
// timeseries.csv cut back to the checkpoint's row and the frames' list to its time (a snapshot
// rebuilds the neighbour list, so a run with checkpoints differs in rounding from one without, as
// blaze run's do; verification/test_study_hopper.cpp).
#pragma once
#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <map>
#include <memory>
#include <sstream>
#include <string>
#include <type_traits>
#include <vector>
#include "blaze/exec/device_info.hpp"
#include "blaze/io/checkpoint.hpp"
#include "blaze/io/manifest.hpp"
#include "blaze/io/vtu_writer.hpp"
#include "blaze/scene/scene_build.hpp"
#include "blaze/scene/scene_file.hpp"
#include "blaze/scene/scene_identity.hpp"
#include "blaze/shapes/polyhedron_shape.hpp"
#include "blaze/shapes/sphere_shape.hpp"
#include "blaze/sim/schedule.hpp"
#include "pipeline/feeder.hpp"
#include "pipeline/feeder_states.hpp"
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

// A checkpoint of the run: the simulation's snapshot (over ranks: a part a rank).
template <class Sim>
void write_run_checkpoint(Sim& sim, const std::string& path, const std::string& text, const std::string& feeders) {
  write_checkpoint(path, sim.snapshot(), text, feeders);
}
#if defined(BLAZE_MPI)
template <class Sim>
void write_run_checkpoint(DistributedSimulation<Sim>& sim, const std::string& path, const std::string& text, const std::string& feeders) {
  sim.write_checkpoint(path, text, feeders);
}
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
      : gate_open(s.study_value("gate_open_time", 0, s.end_time - s.dt, "s (before end_time: the discharge needs time)")),
        orifice(s.study_value_or("orifice_half_width", 1e-6, 10, "m (the flow pattern's centre column and the arch test's span)", 0.025)),
        axis_x(s.study_value_or("orifice_x", -1e3, 1e3, "m (the orifice's centre line)", 0.0)),
        arch_span(s.study_value_or("arch_time", 0, 1e3, "s without a particle leaving, with some over the orifice (0: off)", 0.0)) {
    s.check_study_used();
  }
};

// How a run starts and stops (study_hopper --restart PATH --stop-after SECONDS).
struct HopperRunOptions {
  std::string restart;      // a checkpoint of this scene's run to continue ("": from the start)
  double stop_after = -1;   // s of wall time after which the run writes a checkpoint and stops (< 0: never)
  bool phases = false;      // time each phase of the step (--phases: a synchronisation per phase)
};
constexpr int kHopperStopped = 3;  // study_hopper's status when it stopped at --stop-after

// The loop's own counts, kept in a checkpoint after the scene's identity with the discharge record.
struct HopperLoopState {
  Index count0 = 0;     // what had left the domain when the gate opened
  double mass0 = 0;     // kg, the same
  int frame = 0;        // VTU frames written
  long over_limit = 0;  // particle-samples past the penetration warning
  double worst_penetration = 0;
  std::uint64_t particle_steps = 0;
  double wall = 0;                 // s of wall time before this process
  std::uintmax_t csv_bytes = 0;    // timeseries.csv's length at the checkpoint
  std::string save(const DischargeRecord& record) const {
    char buf[256];
    std::snprintf(buf, sizeof buf, "hopper loop 1\n%lld %.17g %d %ld %.17g %llu %.17g %llu\n", static_cast<long long>(count0), mass0, frame,
                  over_limit, worst_penetration, static_cast<unsigned long long>(particle_steps), wall,
                  static_cast<unsigned long long>(csv_bytes));
    return buf + record.save();
  }
  void restore(const std::string& text, DischargeRecord& record, const std::string& path) {
    std::istringstream in(text);
    std::string a, b, c;
    long long n0 = 0;
    unsigned long long steps = 0, bytes = 0;
    if (!(in >> a >> b >> c) || a != "hopper" || b != "loop" || c != "1" ||
        !(in >> n0 >> mass0 >> frame >> over_limit >> worst_penetration >> steps >> wall >> bytes))
      throw CheckpointError(path + ": not a checkpoint of the hopper study (or a damaged one): rerun from the start");
    count0 = static_cast<Index>(n0), particle_steps = steps, csv_bytes = bytes;
    try {
      record.restore(in);
    } catch (const std::runtime_error& e) {
      throw CheckpointError(path + ": " + e.what());
    }
  }
};

// The study's loop on a Simulation, or over ranks on a DistributedSimulation (`root`: the rank
// that writes; every rank runs the same loop, whose samples and counts are collective). `saved`:
// the loop's state from a checkpoint the simulation and feeders continue ("": a fresh run);
// `identity`: the scene's, written first into checkpoints.
template <class Real, class Shape, class Run>
int drive_hopper(Run& sim, const Scene& s, const HopperKeys& h, std::vector<Feeder<Real>>& feeders,
                 const std::vector<ConvexShape>& shapes, const std::vector<std::string>& overrides, bool root,
                 const HopperRunOptions& opt = {}, const std::string& identity = "", const std::string& saved = "") {
  constexpr bool polyhedra = !std::is_same_v<Shape, SphereShape>;
  const std::string dir = s.output.directory;
  if (root) make_output_directory(s, "vtu");
  DischargeRecord record;
  HopperLoopState loop;
  const bool resumed = !saved.empty();
  if (resumed) loop.restore(saved, record, opt.restart);
  const std::string csv_path = root ? dir + "/timeseries.csv" : std::string("/dev/null");  // (every rank runs the loop)
  if (resumed && root) {  // the rows past the checkpoint's are the stopped run's: cut them
    std::error_code ec;
    if (std::filesystem::file_size(csv_path, ec) < loop.csv_bytes || ec)
      throw CheckpointError(opt.restart + ": " + csv_path + " is shorter than when the checkpoint was written (or gone)");
    std::filesystem::resize_file(csv_path, loop.csv_bytes);
  }
  std::ofstream csv(csv_path, resumed ? std::ios::app : std::ios::trunc);
  if (!resumed)
    csv << "t_s,discharged_mass_kg,discharged_count,particles_in_hopper,kinetic_translational_J,kinetic_rotational_J,"
           "potential_J,max_penetration_ratio,elastic_J,contacts_wall\n";
  PvdCollection pvd(dir + "/particles.pvd");  // (written by rank 0 alone)
  if (resumed) {
    const Index present = sim.size(), removed = sim.removed_count();  // (collective over ranks)
    if (root) {
      pvd.resume(sim.time() - h.gate_open + 0.5 * s.dt);
      std::printf("restarted from %s at t = %.6g s (step %llu): %d particles, %d left the domain\n", opt.restart.c_str(),
                  sim.time() - h.gate_open, static_cast<unsigned long long>(sim.steps()), static_cast<int>(present), static_cast<int>(removed));
    }
  }
  if (root) write_world_vtu(dir + "/walls.vtu", without_gate<Real>(s));
  int& frame = loop.frame;
  long& over_limit = loop.over_limit;
  double& worst_penetration = loop.worst_penetration;
  std::uint64_t& particle_steps = loop.particle_steps;
  const auto every = [&](double interval) {
    return std::max<std::uint64_t>(1, static_cast<std::uint64_t>(std::llround(interval / s.dt)));
  };
  const std::uint64_t csv_every = every(s.output.csv_interval > 0 ? s.output.csv_interval : s.end_time / 100);
  const std::uint64_t vtu_every = every(s.output.vtu_interval > 0 ? s.output.vtu_interval : s.end_time / 10);
  const std::uint64_t checkpoint_every = s.output.checkpoint_interval > 0 ? every(s.output.checkpoint_interval) : 0;
  const auto k_open = static_cast<std::uint64_t>(std::llround(h.gate_open / s.dt));
  const auto k_end = static_cast<std::uint64_t>(std::llround(s.end_time / s.dt));
  const auto wall_start = std::chrono::steady_clock::now();
  const auto wall_now = [&] { return std::chrono::duration<double>(std::chrono::steady_clock::now() - wall_start).count(); };
  double arched_at = -1;  // s from the opening, when an arch was seen (-1: none)
  Index& count0 = loop.count0;  // what had left the domain when the gate opened (the discharge counts from there)
  double& mass0 = loop.mass0;
  const std::uint64_t k_first = resumed ? sim.steps() : 0;
  if (k_first > k_end) throw CheckpointError(opt.restart + ": the checkpoint lies past end_time");
  // This process's pace: steps, neighbour-list builds, feeding and (--phases) each phase's share.
  sim.timer().enabled = opt.phases;
  const std::uint64_t builds_before = sim.neighbour_builds();
  const auto report_pace = [&](std::uint64_t k) {
    const double w = wall_now();
    const std::uint64_t taken = k - k_first, builds = sim.neighbour_builds() - builds_before;
    double feeding = 0;
    for (const auto& f : feeders) feeding += f.place_seconds() + f.insert_seconds();
    if (!root || taken == 0) return;
    std::printf("pace: %llu steps in %.1f s (%.4g steps/s), a neighbour-list build every %.3g steps, feeding %.3g s\n",
                static_cast<unsigned long long>(taken), w, static_cast<double>(taken) / w,
                builds ? static_cast<double>(taken) / static_cast<double>(builds) : 0.0, feeding);
    if (opt.phases) {
      std::printf("  phases, ms per step:");
      for (const auto& [phase, seconds] : sim.timer().seconds()) std::printf(" %s %.4g", phase.c_str(), 1e3 * seconds / static_cast<double>(taken));
      std::printf("\n");
    }
  };
  for (std::uint64_t k = k_first;;) {
    const double t = static_cast<double>(k) * s.dt - h.gate_open;
    const bool again = resumed && k == k_first;  // the checkpoint's step: its rows, frames and insertions are done
    if (k == k_open && !again) {
      count0 = sim.removed_count(), mass0 = sim.removed_mass();
      if (count0 > 0 && root) std::printf("WARNING: %d particles left the domain while the gate was closed\n", static_cast<int>(count0));
      for (const auto& f : feeders)
        if (f.next_insertion(k) != ~std::uint64_t{0} && root) std::printf("WARNING: feed %s still feeds after the gate opens\n", f.spec().name.c_str());
      record.open(bed_state(sim), h.axis_x, h.orifice);
    }
    const bool end = k == k_end, csv_due = !again && (k % csv_every == 0 || end), vtu_due = !again && (k % vtu_every == 0 || end);
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
    if (!again)
      for (auto& f : feeders)
        if (f.inserts_at(k)) f.feed(sim);
    // A checkpoint after the step's rows, frames and insertions: at the interval, or to stop (past
    // the wall-clock limit: at the next checkpoint step when there is an interval, so that the
    // stopped and restarted run is bitwise the uninterrupted one; else at the next event).
    const bool at_interval = checkpoint_every && k % checkpoint_every == 0 && k > 0;
    const bool stop = opt.stop_after >= 0 && (at_interval || !checkpoint_every) &&
                      on_every_rank(sim, wall_now() >= opt.stop_after);  // (over ranks: when one has reached it, all stop)
    if (!again && (at_interval || stop)) {
      csv.flush();
      HopperLoopState now = loop;
      now.wall = loop.wall + wall_now();
      now.csv_bytes = root ? std::filesystem::file_size(csv_path) : 0;
      write_run_checkpoint(sim, dir + "/checkpoint.blz", identity + now.save(record), save_feeders(feeders));
      if (stop) {
        report_pace(k);
        if (root)
          std::printf("stopped at t = %.6g s (wall-clock limit %.6g s): continue with --restart %s/checkpoint.blz\n", t, opt.stop_after,
                      dir.c_str());
        return kHopperStopped;
      }
    }
    // Up to the next row, frame, insertion, checkpoint or the opening in one stretch (the GPU batches it).
    std::uint64_t next = next_event(k, k_end, {csv_every, vtu_every, checkpoint_every});
    if (k < k_open) next = std::min(next, k_open);
    for (const auto& f : feeders) next = std::min(next, f.next_insertion(k + 1));
    sim.run(next - k);
    particle_steps += static_cast<std::uint64_t>(sim.size()) * (next - k);
    k = next;
  }
  csv.close();
  report_pace(sim.steps());

  const double wall = loop.wall + wall_now();
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
int run_hopper(const Scene& s, const std::vector<std::string>& overrides, const Communicator* comm = nullptr,
               const HopperRunOptions& opt = {}) {
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
  // a restart takes its particles from the checkpoint
  const ParticleState<Real> initial = opt.restart.empty() ? build_particles<Real>(s, table) : ParticleState<Real>{};
  const std::string placed = opt.restart.empty() ? std::to_string(initial.size()) + " particles (" + Shape::name + ") placed"
                                                  : std::string(Shape::name) + " particles from " + opt.restart;
  std::printf("hopper: %s, %zu feeds, dt = %.3g s (%.3f of the critical step %.3g s), impact overlap %.3g%% of the radius\n", placed.c_str(),
              s.feeds.size(), s.dt, s.dt / s.dt_critical, s.dt_critical, 100 * s.impact_overlap);
  std::printf("backend: %s, %s\n", DefaultSpace::name, device_name(DefaultSpace{}).c_str());
  std::printf("law: %s\n", scene_law_name(s).c_str());
  std::vector<Feeder<Real>> feeders;
  for (std::size_t k = 0; k < s.feeds.size(); ++k) feeders.emplace_back(s, k, table);
  // One run: the gate is removed at gate_open_time (a timed event), the contacts keep their state.
  const World<Real> world = build_world<Real>(with_wall_removed_at(s, "gate", h.gate_open));
  // A checkpoint continues only the run that wrote it (the scene's identity, scene_identity.hpp).
  const SceneIdentity scene_id = scene_identity(s);
  const std::string identity = identity_text(scene_id);
  std::string saved;  // the loop's state after the identity
  const auto check = [&](const std::string& text) {
    const std::string why = identity_difference(text, scene_id, s, saved);
    if (!why.empty()) throw CheckpointError(opt.restart + ": cannot continue this scene: " + why);
    if (saved.empty()) throw CheckpointError(opt.restart + ": not a checkpoint of the hopper study: rerun from the start");
  };
#if defined(BLAZE_MPI)
  std::error_code no_file;
  if (comm && (comm->size() > 1 || (!opt.restart.empty() && !std::filesystem::is_regular_file(opt.restart, no_file)))) {
    using Run = DistributedSimulation<Sim>;
    std::unique_ptr<Run> run;
    if (opt.restart.empty()) run = std::make_unique<Run>(*comm, sp, build_laws<Law>(s), world, initial, shape);
    else {
      run = std::make_unique<Run>(*comm, sp, build_laws<Law>(s), world, opt.restart, shape);
      check(run->restart_text());
      restore_feeders(feeders, run->restart_feeders(), opt.restart);
    }
    return drive_hopper<Real, Shape>(*run, s, h, feeders, shapes, overrides, comm->rank() == 0, opt, identity, saved);
  }
#endif
  if (opt.restart.empty()) {
    Sim sim(sp, build_laws<Law>(s), world, initial, shape);
    return drive_hopper<Real, Shape>(sim, s, h, feeders, shapes, overrides, true, opt, identity);
  }
  const Checkpoint<Real> restart = read_checkpoint<Real>(opt.restart);
  check(restart.text);
  restore_feeders(feeders, restart.feeders, opt.restart);
  Sim sim(sp, build_laws<Law>(s), world, restart.snapshot, shape);
  return drive_hopper<Real, Shape>(sim, s, h, feeders, shapes, overrides, true, opt, identity, saved);
}

}  // namespace blaze::hopper
