// The body of `blaze run` (apps/blaze/main.cpp): one scene run with a given precision, law and
// shape (run_scene), and the law families by which the program is split into translation units
// (run_history_free, run_spring, run_rolling: apps/blaze/run_*.cpp instantiate them, so that a
// parallel build compiles them side by side; one unit holding them all took ~10 minutes of nvcc).
// Over several ranks (an MPI build, build/mpi/blaze under mpirun; issue 21) the same loop drives a
// DistributedSimulation: rank 0 writes the time series, the .pvd and the world; every rank writes
// its own particles as a piece of each frame (vtu/particles_NNNN_rK.vtu) and rank 0 the frame's
// .pvtu naming the pieces; checkpoints are one part a rank (checkpoint.blz.part<k>of<n>), read back
// by any number of ranks.
#pragma once
#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <memory>
#include "blaze/shapes/sphere_shape.hpp"
#include "blaze/exec/device_info.hpp"
#include "blaze/io/background_writer.hpp"
#include "blaze/io/checkpoint.hpp"
#include "blaze/io/vtu_writer.hpp"
#include "blaze/scene/scene_build.hpp"
#include "blaze/scene/scene_file.hpp"
#include "blaze/scene/run_size.hpp"
#include "blaze/scene/scene_identity.hpp"
#include "pipeline/scene_law.hpp"
#include "pipeline/feeder.hpp"
#include "pipeline/feeder_states.hpp"
#include "pipeline/run_log.hpp"
#include "blaze/sim/schedule.hpp"
#include "pipeline/scene_params.hpp"
#include "pipeline/simulation.hpp"
#include "blaze/io/console.hpp"
#include "apps/blaze/run_families.hpp"
#if defined(BLAZE_MPI)
#include "pipeline/parallel/distributed_simulation.hpp"
#endif

namespace blaze::app {

// "t = 0.25 / 1 s (25%)  3.1e+06 particle-steps/s  ETA 12 s": on a terminal one line redrawn
// twice a second; into a file or a pipe (a batch job) a line every minute, so that a long run is
// never silent. --quiet turns both off.
class Progress {
 public:
  Progress(bool on, double end_time)
      : on_(on), tty_(isatty(2)), end_(end_time), start_(clock::now()), last_(start_) {}
  void update(double t, double particle_steps, bool force = false) {
    if (!on_) return;
    const auto now = clock::now();
    if (!force && std::chrono::duration<double>(now - last_).count() < (tty_ ? 0.5 : 60.0)) return;
    if (force && !tty_) return;  // the summary line follows
    last_ = now;
    const double wall = std::chrono::duration<double>(now - start_).count(), frac = t / end_;
    const double eta = frac > 0 ? wall * (1 - frac) / frac : 0;
    std::fprintf(stderr, "%s  t = %.4g / %.4g s (%3.0f%%)  %.3g particle-steps/s  ETA %.0f s   %s", tty_ ? "\r" : "", t, end_,
                 100 * frac, wall > 0 ? particle_steps / wall : 0.0, eta, tty_ && !force ? "" : "\n");
  }

 private:
  using clock = std::chrono::steady_clock;
  bool on_, tty_;
  double end_;
  clock::time_point start_, last_;
};

// What the loop needs to know of what it drives (a Simulation, or over ranks a
// DistributedSimulation of one): the local simulation's type, whether its particles are polyhedra.
template <class Run>
struct RunTraits;
template <class Space, class Shape, class Law, class Integrator, class Kinematics, class Features>
struct RunTraits<Simulation<Space, Shape, Law, Integrator, Kinematics, Features>> {
  using Local = Simulation<Space, Shape, Law, Integrator, Kinematics, Features>;
  static constexpr bool polyhedra = !std::is_same_v<Shape, SphereShape>;
};
// A frame's particles and (periodic axes) their unwrapped positions: all of them, or over ranks
// the rank's own (its piece).
template <class Sim>
ParticleState<typename Sim::Real> frame_state(Sim& sim, std::vector<Vec3<double>>& unwrapped) {
  ParticleState<typename Sim::Real> st = sim.state();
  unwrapped = sim.unwrapped_positions(st);
  return st;
}
#if defined(BLAZE_MPI)
template <class Sim>
struct RunTraits<DistributedSimulation<Sim>> {
  using Local = Sim;
  static constexpr bool polyhedra = RunTraits<Sim>::polyhedra;
};
template <class Sim>
ParticleState<typename Sim::Real> frame_state(DistributedSimulation<Sim>& sim, std::vector<Vec3<double>>& unwrapped) {
  return sim.piece(unwrapped);
}
#endif
template <class Real, class Shape>
const PolyhedronTable<Real>* table_of(const Shape& shape) {
  if constexpr (std::is_same_v<Shape, SphereShape>) return nullptr;
  else return &shape.table;
}

// The run's loop (the output, the feeders, the guards) over a Simulation or, over ranks, a
// DistributedSimulation (then every call on `sim` that the loop makes is collective).
template <class Real, class Run>
int drive(Run& sim, const Scene& s, const Options& o, const World<Real>& world, const std::vector<ConvexShape>& shapes,
          const std::string& identity, const std::string& restart_log, const std::string& feeder_bytes,
          const PolyhedronTable<Real>* table) {
  constexpr bool kRanks = !std::is_same_v<Run, typename RunTraits<Run>::Local>;
  constexpr bool polyhedra = RunTraits<Run>::polyhedra;
  int rank = 0, pieces = 1;
  if constexpr (kRanks) rank = sim.communicator().rank(), pieces = sim.communicator().size();
  const bool root = rank == 0;
  // The [[feed]]s (pipeline/feeder.hpp), their state restored with the run's.
  std::vector<Feeder<Real>> feeders;
  for (std::size_t k = 0; k < s.feeds.size(); ++k) feeders.emplace_back(s, k, table);
  if (!o.restart.empty()) restore_feeders(feeders, feeder_bytes, o.restart);
  // A restart at the end steps nothing and loses nothing; past it, it is a mistake, refused before
  // any output (the time series, the collections) is trimmed to the checkpoint.
  if (!o.restart.empty() && sim.steps() > static_cast<std::uint64_t>(std::llround(s.end_time / s.dt)))
    throw CheckpointError(o.restart + ": the checkpoint is at t = " + Scene::shortest(sim.time()) + " s (step " +
                          std::to_string(sim.steps()) + "), past this run's end_time = " + Scene::shortest(s.end_time) +
                          " s: give an end_time after the checkpoint's time (--set end_time=...)");

  const std::string& dir = s.output.directory;
  make_output_directory(s, "vtu");
  const auto steps = static_cast<std::uint64_t>(std::llround(s.end_time / s.dt));  // <= kMaxSteps (validated)
  const auto every = [&](double interval) { return interval_steps(interval, s.dt, steps); };
  const std::uint64_t csv_every = every(s.output.csv_interval), vtu_every = every(s.output.vtu_interval);
  // Without a CSV the guards (energy, penetration, removals) still sample, kGuardSamples times a
  // run, with no row: a blown-up run stops with status 3 as one with a CSV does.
  constexpr std::uint64_t kGuardSamples = 100;
  const std::uint64_t guard_every = csv_every ? csv_every : std::max<std::uint64_t>(1, steps / kGuardSamples);
  // On restart, the rows and frames that the stopped run wrote up to its checkpoint stay: those of
  // the checkpoint's own step only where this run writes one there too (on its schedule, or its
  // end), not the stopped run's last row or frame off the schedule (its end), which the run that
  // never stopped does not have.
  const auto kept_until = [&](std::uint64_t every_k) {
    if (o.restart.empty()) return -1.0;
    const bool written_here = sim.steps() == steps || (every_k > 0 && sim.steps() % every_k == 0);
    return sim.time() + (written_here ? 0.5 : -0.5) * s.dt;
  };
  const double g = norm(s.gravity), height = g > 0 ? std::abs(dot(s.gravity, s.domain_hi - s.domain_lo)) / g : 0;
  // Over ranks every rank samples (the samples are collective) and rank 0 writes.
  RunLog<Real> log(root ? dir + "/timeseries.csv" : std::string("/dev/null"), s.output.penetration_warning, s.output.energy_gain_limit,
                   vec_cast<Real>(s.gravity), height, kept_until(csv_every), sim.keeps_energy_ledger(), reported_loads(s), !feeders.empty());
  // The last sampled state that passed the guards stays on the device (Simulation::keep_state());
  // it is downloaded only if a guard stops the run.
  sim.keep_state();
  if (!world.empty() && root) write_world_vtu(dir + "/walls.vtu", world);
  PvdCollection pvd(dir + "/particles.pvd"), pvd_faces(dir + "/polyhedra.pvd");
  // A world that moves gets a walls frame with every particles frame (walls.vtu: where it started).
  std::unique_ptr<PvdCollection> pvd_walls = sim.world_moves() ? std::make_unique<PvdCollection>(dir + "/walls.pvd") : nullptr;
  // One frame's file (stem: vtu/name): whole, or over ranks this rank's piece (stem_rK.vtu) and
  // on rank 0 the .pvtu naming every rank's; the collection names the frame.
  const auto write_frame = [&](const VtuFile& file, const std::string& stem, PvdCollection& collection, double t) {
    file.write(dir + "/" + stem + (pieces > 1 ? "_r" + std::to_string(rank) : std::string()) + ".vtu");
    if (pieces > 1 && root) {
      std::vector<std::string> names;
      for (int r = 0; r < pieces; ++r) names.push_back(stem.substr(stem.find('/') + 1) + "_r" + std::to_string(r) + ".vtu");
      file.write_parallel(dir + "/" + stem + ".pvtu", names);
    }
    if (root) collection.add(t, stem + (pieces > 1 ? ".pvtu" : ".vtu"));
  };
  int frame = 0;
  constexpr long kMaxFeedNotes = 10;
  long feed_notes = 0;
  BackgroundWriter frames;  // VTU frames written while the steps go on (after pvd: it goes first)
  if (!o.restart.empty()) {
    log.resume(restart_log);
    frame = static_cast<int>(root ? pvd.resume(kept_until(vtu_every)) : 0);
    if constexpr (kRanks) frame = static_cast<int>(sim.communicator().max(static_cast<long>(frame)));
    pvd_faces.resume(kept_until(vtu_every));
    if (pvd_walls) pvd_walls->resume(kept_until(vtu_every));
    std::printf("restarted from %s at step %llu (t = %.6g s)\n", o.restart.c_str(),
                static_cast<unsigned long long>(sim.steps()), sim.time());
  }

  const std::uint64_t checkpoint_every = every(s.output.checkpoint_interval);
  Progress progress(!o.quiet && root, s.end_time);  // over ranks rank 0's line
  double particle_steps = 0;
  const std::uint64_t first = sim.steps();
  Index sim_size = sim.size();
  const std::uint64_t builds_before = sim.neighbour_builds();
  sim.timer().enabled = o.phases;
  double output_seconds = 0;  // samples, frame downloads and checkpoints (the GPU idle meanwhile)
  double feed_seconds = 0;    // the feeders' insertions (placement, insertion, rebuild)
  const auto loop_start = std::chrono::steady_clock::now();
  // A guard that trips (NaN/Inf, energy created) stops the run; the last sampled state is kept.
  const auto stop = [&](const std::exception& e) {
    progress.update(sim.time(), particle_steps, true);
    try {
      frames.wait();
    } catch (const std::exception& w) {  // the guard's report and last_good.vtu come first
      std::fprintf(stderr, "blaze: a frame could not be written: %s\n", w.what());
    }
    const ParticleState<Real> last_good = sim.kept_state();  // over ranks: all of it on rank 0
    if (root) write_particles_vtu(dir + "/last_good.vtu", last_good);
    std::fprintf(stderr, "blaze: run stopped: %s\nthe last good state (%zu particles) is in %s/last_good.vtu; "
                 "lower dt or check the contact parameters\n", e.what(), last_good.size(), dir.c_str());
    return 3;
  };
  // The steps between two events (a row, a frame, a checkpoint, the end) run as one stretch, so
  // the GPU can batch them (Simulation::run).
  const auto next_event = [&](std::uint64_t k) {
    std::uint64_t next = blaze::next_event(k, steps, {guard_every, vtu_every, checkpoint_every});
    for (const auto& f : feeders) next = std::min(next, f.next_insertion(k + 1));
    // and the progress line now and then: about 1e7 particle-steps apart (~3 s on 2 CPU cores)
    const std::uint64_t chunk = std::clamp<std::uint64_t>(10000000 / std::max<std::uint64_t>(1, static_cast<std::uint64_t>(sim_size)), 1, 10000);
    return std::min(next, k + chunk);
  };
  for (std::uint64_t k = first;;) try {
    const bool resumed = k == first && first > 0;  // that sample is in the files already
    const bool write_csv = !resumed && csv_every && (k % csv_every == 0 || k == steps);
    const bool write_vtu = !resumed && vtu_every && (k % vtu_every == 0 || k == steps);
    const bool guard_only = !resumed && !csv_every && (k % guard_every == 0 || k == steps);
    const auto output_start = std::chrono::steady_clock::now();
    if (write_csv || write_vtu || guard_only) {
      if (write_csv || guard_only) log.sample(sim, write_csv);  // the guards: a state that trips one is not a good one
      sim.keep_state();
    }
    if (write_vtu) {  // in the background; the .pvd names a frame once it is written
      auto unwrapped = std::make_shared<std::vector<Vec3<double>>>();
      const auto st = std::make_shared<const ParticleState<Real>>(frame_state(sim, *unwrapped));
      const auto walls = pvd_walls && root ? std::make_shared<const World<Real>>(placed(world, sim.world_poses())) : nullptr;
      frames.start([&, st, unwrapped, walls, f = frame++, t = sim.time()] {
        char name[64];
        std::snprintf(name, sizeof name, "vtu/particles_%04d", f);
        write_frame(particles_vtu(*st, *unwrapped), name, pvd, t);
        if (walls) {
          std::snprintf(name, sizeof name, "vtu/walls_%04d.vtu", f);
          write_world_vtu(dir + "/" + name, *walls);
          pvd_walls->add(t, name);
        }
        if constexpr (polyhedra) {
          std::snprintf(name, sizeof name, "vtu/polyhedra_%04d", f);
          write_frame(polyhedra_vtu(*st, shapes), name, pvd_faces, t);
        }
      });
    }
    // The checkpoint after the sample: of a state the guards passed, with this row in its log's
    // sums; it rebuilds the lists (both kinds of run alike, so they stay bitwise one another), and
    // the sample read the last force evaluation's statistics in the order they were counted.
    if (checkpoint_every && k > first && k % checkpoint_every == 0) {
      if constexpr (kRanks) sim.write_checkpoint(dir + "/checkpoint.blz", identity + log.save(), save_feeders(feeders));
      else write_checkpoint(dir + "/checkpoint.blz", sim.snapshot(), identity + log.save(), save_feeders(feeders));
    }
    output_seconds += std::chrono::duration<double>(std::chrono::steady_clock::now() - output_start).count();
    if (k >= steps) break;  // (a restart may begin at or past the end)
    for (auto& f : feeders)  // after the step's sample: its energy enters the balance from the next
      if (f.inserts_at(k)) {
        const auto feed_start = std::chrono::steady_clock::now();
        f.feed(sim);
        feed_seconds += std::chrono::duration<double>(std::chrono::steady_clock::now() - feed_start).count();
        if (f.shortfall() > 0 && feed_notes++ < kMaxFeedNotes)
          std::printf("note: t = %.6g s: %s: %ld particles could not be placed (%s); they stay due%s\n", sim.time(),
                      f.spec().name.c_str(), f.shortfall(),
                      f.inserted() > 0 ? "the region is full"
                                       : "none placed yet: no place in the region is clear of walls and particles; is it inside "
                                         "or against a wall?",
                      feed_notes == kMaxFeedNotes ? " [further such notes omitted]" : "");
      }
    sim_size = sim.size();  // over ranks a collective count: once a stretch
    const std::uint64_t next = next_event(k);
    sim.run(next - k);
    particle_steps += static_cast<double>(sim_size) * static_cast<double>(next - k);
    k = next;
    progress.update(sim.time(), particle_steps);
  } catch (const NonFiniteState& e) {
    return stop(e);
  } catch (const EnergyGain& e) {
    return stop(e);
  }
  const auto drain_start = std::chrono::steady_clock::now();
  frames.wait();  // the last frame on disk before the run reports
  output_seconds += std::chrono::duration<double>(std::chrono::steady_clock::now() - drain_start).count();
  progress.update(sim.time(), particle_steps, true);
  const Index left = sim.size(), removed = sim.removed_count();  // collective over ranks
  std::printf("done: %llu steps, %u particles left, %u removed (left the domain)", static_cast<unsigned long long>(steps),
              static_cast<unsigned>(left), static_cast<unsigned>(removed));
  // the guards' figures come from the samples (without csv_interval: the guards' own, no rows)
  std::printf("; deepest penetration %.3g%% of the radius, over %.3g%% in %ld samples%s; ", 100 * log.worst_penetration(),
              100 * s.output.penetration_warning, log.samples_over_limit(),
              csv_every ? "" : " (no csv_interval: the guards sampled without rows)");
  if (log.energy_compared()) std::printf("largest energy gain %.3g of the scale", log.max_energy_gain());
  else std::printf("no energy to compare (no sample had particles, motion or gravity)");
  std::printf("\n");
  for (const auto& f : feeders) {
    std::printf("feed %s: %ld particles inserted (%.4g kg)", f.spec().name.c_str(), f.inserted(), f.inserted_mass());
    if (f.undelivered() > 0 && sim.time() >= f.spec().end - 0.5 * s.dt)
      std::printf(", %ld due by its end could NOT be placed (%ld insertions fell short)", f.undelivered(), f.short_insertions());
    if (f.spec().size.kind != SizeKind::constant && f.inserted() > 0)
      std::printf("; sizes: Kolmogorov-Smirnov distance %.3g from the requested %s distribution (by %s; %.3g expected at this "
                  "count)", f.ks_distance(), to_string(f.spec().size.kind), f.spec().size.by_mass ? "mass" : "number",
                  1.36 / std::sqrt(static_cast<double>(f.inserted())));
    std::printf("\n");
  }
  const double wall = std::chrono::duration<double>(std::chrono::steady_clock::now() - loop_start).count();
  std::printf("wall time %.3f s for the steps and output, %.4g particle-steps/s\n", wall, wall > 0 ? particle_steps / wall : 0.0);
  const double stepping = wall - output_seconds - feed_seconds;
  const std::uint64_t taken = sim.steps() - first, builds = sim.neighbour_builds() - builds_before;
  std::printf("  steps %.3f s (%.4g particle-steps/s), output %.3f s (%.0f%%); %llu neighbour-list builds (every %.3g steps)\n",
              stepping, stepping > 0 ? particle_steps / stepping : 0.0, output_seconds, wall > 0 ? 100 * output_seconds / wall : 0.0,
              static_cast<unsigned long long>(builds), builds ? static_cast<double>(taken) / static_cast<double>(builds) : 0.0);
  if (!feeders.empty()) {
    double place = 0, insert = 0, find = 0;
    long insertions = 0, rounds = 0;
    for (const auto& f : feeders)
      place += f.place_seconds(), insert += f.insert_seconds(), find += f.find_seconds(), insertions += f.insertions(), rounds += f.rounds();
    std::printf("  feeding %.3f s (%.2g%% of the steps' time) in %ld insertions: placing %.3f s (finding the particles present "
                "%.3f s; drawing and testing centres %.3f s, %.3g rounds an insertion), inserting %.3f s (appending and re-sorting)\n",
                feed_seconds, stepping > 0 ? 100 * feed_seconds / stepping : 0.0, insertions, place, find, place - find,
                insertions ? static_cast<double>(rounds) / static_cast<double>(insertions) : 0.0, insert);
  }
  if (o.phases && taken > 0) {  // per step, GPU time on the GPU (phase_timer.hpp)
    std::printf("  phases, ms per step:");
    for (const auto& [phase, seconds] : sim.timer().seconds())
      std::printf(" %s %.4g", phase.c_str(), 1e3 * seconds / static_cast<double>(taken));
    std::printf("\n");
  }
  std::printf("wrote %s/timeseries.csv, %s/particles.pvd (%d frames%s)%s\n", dir.c_str(), dir.c_str(), frame,
              pieces > 1 ? (", a piece a rank on " + std::to_string(pieces) + " ranks").c_str() : "",
              pvd_walls ? " and walls.pvd (the moving world)" : "");
  return 0;
}


template <class Real, class Law, class Shape>
int run_scene(const Scene& s, const Options& o) {
  constexpr bool polyhedra = !std::is_same_v<Shape, SphereShape>;
  Shape shape;
  ParticleState<Real> particles;
  std::vector<ConvexShape> shapes;
  // A restart takes its particles from the checkpoint, whose identity holds the placements: they
  // are not placed again (a 4e6-ball random fill takes a minute).
  if constexpr (polyhedra) {
    shapes = build_shapes(s);
    shape.table = build_shape_table<Real>(s, shapes);
    if (o.restart.empty()) particles = build_particles<Real>(s, &shape.table);
  } else {
    if (o.restart.empty()) particles = build_particles<Real>(s, nullptr);
  }
  // Unless the scene says: polyhedra evaluate each pair once (their pairs are dear: 1.8x on the
  // CPU), spheres from both sides (a sphere pair costs less than its slot's memory traffic).
  const bool once = s.pair_evaluation == PairsKind::automatic ? std::string(Shape::name) != "sphere"
                                                              : s.pair_evaluation == PairsKind::once;
  const SimulationParams<Real> prm = simulation_params<Real>(s, once);
  const World<Real> world = build_world<Real>(s);
  using Sim = Simulation<DefaultSpace, Shape, Law, VelocityVerlet, ContactPointVelocity, MonitoredFeatures>;
  // The run's identity, checked on restart: a checkpoint continues only the run that wrote it,
  // and every physical input of the scene must be as it was (scene_identity.hpp).
  const SceneIdentity scene_id = scene_identity(s);
  const std::string identity = identity_text(scene_id);
  // An MPI build runs over its ranks with a DistributedSimulation; on one rank, unless it continues
  // a checkpoint written in parts, with the plain Simulation in canonical order: bitwise the run
  // over any number of ranks, without the distributed step's collective checks every step and with
  // the batched steps of small systems (one rank costs the plain build's time, MPI's start and
  // canonical order's ~10%: bench/README.md, issue 21).
#if defined(BLAZE_MPI)
  std::error_code no_file;
  const bool over_ranks = o.comm && (o.comm->size() > 1 || (!o.restart.empty() && !std::filesystem::is_regular_file(o.restart, no_file)));
#else
  constexpr bool over_ranks = false;
#endif
  SimulationParams<Real> p = prm;
  if (o.comm) {
    if (s.pair_evaluation == PairsKind::once)
      throw SceneError(s.place("simulation.pair_evaluation") + " = \"once\": a run over ranks evaluates pairs from both sides "
                       "(\"both_sides\" or \"automatic\")");
    p.pairs = PairEvaluation::both_sides, p.canonical_order = true;
  }
  Checkpoint<Real> restart;
  std::string restart_log;  // the run's own bookkeeping saved after the identity
  if (!o.restart.empty() && !over_ranks) {  // over ranks: the parts are read below
    restart = read_checkpoint<Real>(o.restart);
    const std::string why = identity_difference(restart.text, scene_id, s, restart_log);
    if (!why.empty()) throw CheckpointError(o.restart + ": cannot continue this scene: " + why);
  }
#if defined(BLAZE_MPI)
  if (over_ranks) {  // the same run on any number of ranks (canonical order)
    using Run = DistributedSimulation<Sim>;
    std::unique_ptr<Run> run;
    if (o.restart.empty()) run = std::make_unique<Run>(*o.comm, p, build_laws<Law>(s), world, particles, shape);
    else {
      run = std::make_unique<Run>(*o.comm, p, build_laws<Law>(s), world, o.restart, shape);
      const std::string why = identity_difference(run->restart_text(), scene_id, s, restart_log);
      if (!why.empty()) throw CheckpointError(o.restart + ": cannot continue this scene: " + why);
      restart.feeders = run->restart_feeders();
    }
    return drive<Real>(*run, s, o, world, shapes, identity, restart_log, restart.feeders, table_of<Real>(shape));
  }
#endif
  Sim sim = o.restart.empty() ? Sim(p, build_laws<Law>(s), world, particles, shape)
                              : Sim(p, build_laws<Law>(s), world, restart.snapshot, shape);
  return drive<Real>(sim, s, o, world, shapes, identity, restart_log, restart.feeders, table_of<Real>(shape));
}

template <class Real, class Law>
int run_law(const Scene& s, const Options& o) {
  return s.all_spheres() ? run_scene<Real, Law, SphereShape>(s, o) : run_scene<Real, Law, PolyhedronShape<Real>>(s, o);
}

// The scene's law families (pipeline/scene_law.hpp; rolling resistance for spheres only).
template <class Real>
int run_history_free(const Scene& s, const Options& o) {
  return with_history_free_law<Real>(s, [&](auto law) { return run_law<Real, typename decltype(law)::type>(s, o); });
}
template <class Real>
int run_spring(const Scene& s, const Options& o) {
  return with_spring_law<Real>(s, [&](auto law) { return run_law<Real, typename decltype(law)::type>(s, o); });
}
template <class Real>
int run_rolling(const Scene& s, const Options& o) {
  return with_rolling_law<Real>(s, [&](auto law) { return run_scene<Real, typename decltype(law)::type, SphereShape>(s, o); });
}

}  // namespace blaze::app
