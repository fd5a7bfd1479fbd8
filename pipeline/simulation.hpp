// One simulation on one memory space: the time step as a list of named phases over views
// (step_phases(); blaze/exec/phases.hpp runs it, one launch per phase or many steps per launch)
//   integrate (pre-force) -> rebuild-check [-> rebuild: hash, sort, reorder, cells, neighbours]
//   -> contacts -> walls -> integrate (post-force)
// (thesis Algorithm 2.1). Shape, law, integrator, contact kinematics and features are policies.
#pragma once
#include <algorithm>
#include <cstdint>
#include <stdexcept>
#include <string>
#include <type_traits>
#include <utility>
#include <vector>
#include "blaze/contact/kinematics.hpp"
#include "blaze/exec/phases.hpp"
#include "pipeline/broad_phase.hpp"
#include "pipeline/contact_store.hpp"
#include "pipeline/in_block_rebuild.hpp"
#include "pipeline/world_candidates.hpp"
#include "blaze/sim/features.hpp"
#include "blaze/sim/snapshot.hpp"
#include "blaze/world/world.hpp"
#include "kernels/contact_energy.hpp"
#include "kernels/sample_tally.hpp"
#include "kernels/contact_forces.hpp"
#include "kernels/pair_forces.hpp"
#include "kernels/region_query.hpp"
#include "kernels/integrate.hpp"
#include "kernels/move_world.hpp"
#include "kernels/world_forces.hpp"
#include "kernels/world_loads.hpp"

namespace blaze {

// How particle-particle contacts are evaluated (the results are bitwise the same):
//   both_sides: one kernel; each particle walks its list and evaluates every pair itself
//               (contact_forces.hpp): no storage beyond the list;
//   once:       each pair evaluated once into a slot per list entry, then gathered per particle
//               (pair_forces.hpp): half the collisions and law evaluations, 29 B (float) or
//               53 B (double) more per list entry. A scene's choice: it pays for polyhedra,
//               whose pairs are dear, not for spheres (bench/README.md).
enum class PairEvaluation { both_sides, once };
// With pairs once, the threads of the pair phase (the slots are bitwise the same either way):
//   particle:  a thread a particle, walking its list;
//   entry:     a thread a list entry (kernels/pair_forces.hpp PairForces::entry_rows): capacity
//              times the threads, for systems too small to fill the GPU a particle a thread;
//   automatic: entries on the GPU below kEntryThreadsBelow particles, particles otherwise.
enum class PairThreads { automatic, particle, entry };
constexpr Index kEntryThreadsBelow = Index(1) << 17;  // ~half the threads an H100/H200 holds at once

template <class Real>
struct SimulationParams {
  Real dt;              // s
  Vec3<Real> gravity;   // m/s^2
  Vec3<Real> domain_lo; // m; particles leaving [lo, hi) are removed and counted
  Vec3<Real> domain_hi; // m
  Real skin;            // m, neighbour-list margin; 0 rebuilds whenever anything moves
  Real drag = 0;        // kg/m, quadratic air drag F = -drag |v| v on every particle (0: none)
  PairEvaluation pairs = PairEvaluation::both_sides;  // see PairEvaluation
  // Keep the energy accounts (blaze/particles/energy_ledger.hpp: the drive's work and the
  // dissipation by contact class) even in a still world; a world that moves keeps them anyway.
  bool energy_ledger = false;
  // Per-particle lists of the world objects in reach (pipeline/world_candidates.hpp).
  WorldLists world_lists = WorldLists::automatic;
  // m, the largest bounding radius the run will ever hold: particles inserted later (feeders,
  // pipeline/feeder.hpp) may be larger than the first ones, and the grid's cell is sized for it.
  // 0: the initial particles' largest (a run that starts empty must give it).
  Real max_radius = 0;
  // Periodic axes (bit 0: x, 1: y, 2: z; grid/periodic_images.hpp): the domain wraps around there,
  // its length the period (at least 3 cells of 2 max_radius + skin).
  unsigned periodic = 0;
  // Sum each particle's contact forces in the order of its neighbours' permanent ids (the broad
  // phase sorts each list at a build) and form each pair from its lower id (ContactForces::by_id):
  // a trajectory with pairs from both sides then does not depend on where particles lie in memory,
  // so a run over any number of ranks (pipeline/parallel/) is bitwise one process's with this on.
  // Off: the list's cell order and the lower index (cheaper by a sort per list at each rebuild).
  bool canonical_order = false;
  PairThreads pair_threads = PairThreads::automatic;  // with pairs once: see PairThreads
  // Rebuild small systems' neighbour lists inside the batch (pipeline/in_block_rebuild.hpp).
  InBlockRebuild in_block_rebuild = InBlockRebuild::automatic;
};

// A state that is no longer finite (NaN or Inf), found by the per-step rebuild check: the run
// cannot continue. Names the step and one particle whose state is not finite.
struct NonFiniteState : std::runtime_error {
  NonFiniteState(const std::string& what, std::uint64_t step_, Index id_) : std::runtime_error(what), step(step_), id(id_) {}
  std::uint64_t step;
  Index id;
};

// Deepest overlap / radius since the last take_penetration() (Features::monitor).
struct PenetrationReport {
  double worst = 0;   // overlap / radius of the deepest contact
  Index worst_id = -1;
  long over = 0;      // particles whose deepest contact exceeded the threshold
};

// The elastic energy held in the open contacts now, and the contacts with world objects
// (Simulation::contact_energy(); kernels/contact_energy.hpp).
struct ContactEnergy {
  double pairs = 0;        // J, particle-particle contacts, each pair once
  double walls = 0;        // J, particle-world contacts (planar polygons and cylinders)
  long wall_contacts = 0;  // particle-world contacts (a particle touching two walls counts 2)
  double total() const { return pairs + walls; }
};

// A shape policy with a table that its kernels read from the space's memory names it Resident
// and has members `table` and `resident` (polyhedron_shape.hpp); the Simulation keeps that copy.
template <class Shape, class = void>
struct ResidentTable {
  static constexpr bool value = false;
  using type = char;
};
template <class Shape>
struct ResidentTable<Shape, std::void_t<typename Shape::Resident>> {
  static constexpr bool value = true;
  using type = typename Shape::Resident;
};

template <class Space, class Shape, class Law, class Integrator, class Kinematics = ContactPointVelocity,
          class Features = FullFeatures>
class Simulation {
 public:
  using Real = typename Law::real_type;
  using space_type = Space;
  // Does the shape report contact patches (contact_patch.hpp)? Then pairs once keep their moments.
  using ShapeBody = decltype(std::declval<const Shape&>().body(std::declval<const ParticleView<Real>&>(), Index{}));
  using PairGeometry = std::decay_t<decltype(
      std::declval<const Shape&>().collide(std::declval<const ShapeBody&>(), std::declval<const ShapeBody&>()))>;
  static constexpr bool kPatches = is_patch_geometry_v<PairGeometry>;
  // Pair forces come with moments (patches, rolling resistance): pairs once keep them too.
  static constexpr bool kMoments = has_moment_v<Law, PairGeometry>;
  using features = Features;

  Simulation(const SimulationParams<Real>& params, const PairTable<Law>& laws, const World<Real>& world,
             const ParticleState<Real>& particles, const Shape& shape = Shape{})
      : shape_(shape), params_(params), laws_(laws), r_max_(std::max(params.max_radius, max_of(particles.radius))),
        broad_(make_grid(params, r_max_), params.skin) {
    check_params(params);
    check_materials(laws, world, particles);
    reside_shape();
    check_meshes(world);
    store_.upload(particles, Integrator::keeps_previous_forces, Features::monitor, world.dynamic() || params.energy_ledger,
                  Features::thesis_power);  // checks the lengths
    if (params.periodic) store_.keep_images();
    check_finite(particles, 0);
    world_.upload(world, 0, static_cast<double>(params.dt), mesh_reach(params, r_max_));
    lists_.configure(world, params.world_lists, params.skin, static_cast<double>(params.dt), UsesSphereMeshRegions<Shape>::value);
    initial_count_ = store_.size();
    for (Index id : particles.id) next_id_ = std::max(next_id_, id + 1);
    if (params.pairs == PairEvaluation::once) broad_.keep_reverse_index();
    if (params.canonical_order) broad_.order_by_id();
    configure_contacts(world);
    first_build();
    // The forces at t = 0 for the integrator's first kick. A contact state advances by the slip
    // over a step, and no step has been taken: the history sees dt = 0 (LIGGGHTS's setup likewise
    // leaves the shear history alone), so the first step's increment is the first one.
    run_phases(Space{}, store_.size(), step_phases(Real(0)), kFirstForcePhase, kPostForcePhase, timer_);
    for_each(Space{}, store_.size(), integrate<Stage::prime>());
  }

  // Continues the run a snapshot() was taken from: same arrays, same neighbour list (rebuilt from
  // the same positions in the same order: the sort is the identity), no force evaluation and no
  // priming, so the next step is bit for bit the step the original run took.
  Simulation(const SimulationParams<Real>& params, const PairTable<Law>& laws, const World<Real>& world,
             const SimulationSnapshot<Real>& snap, const Shape& shape = Shape{})
      : shape_(shape), params_(params), laws_(laws),
        r_max_(std::max(params.max_radius, max_of(snap.store.reals.at(StoreSnapshot<Real>::kRadiusField)))),
        broad_(make_grid(params, r_max_), params.skin) {
    check_params(params);
    ParticleState<Real> materials_only;
    materials_only.material = snap.store.material;
    check_materials(laws, world, materials_only);
    reside_shape();
    check_meshes(world);
    store_.restore(snap.store);
    store_.keep_fields(Integrator::keeps_previous_forces, Features::monitor);
    if (params.periodic) store_.keep_images();
    steps_ = snap.steps;
    world_.upload(world, steps_, static_cast<double>(params.dt), mesh_reach(params, r_max_));
    lists_.configure(world, params.world_lists, params.skin, static_cast<double>(params.dt), UsesSphereMeshRegions<Shape>::value);
    if (world.dynamic() || params.energy_ledger) store_.keep_ledger(Features::thesis_power);
    initial_count_ = snap.initial_count;
    removed_count_ = snap.removed_count;
    removed_mass_ = snap.removed_mass;
    removed_energy_ = snap.removed_energy;
    inserted_count_ = snap.inserted_count;
    inserted_mass_ = snap.inserted_mass;
    inserted_energy_ = snap.inserted_energy;
    inserted_kinetic_ = snap.inserted_kinetic;
    next_id_ = snap.next_id;
    if (params.pairs == PairEvaluation::once) broad_.keep_reverse_index();
    if (params.canonical_order) broad_.order_by_id();
    configure_contacts(world);
    first_build();
    contacts_.restore(snap.contacts, store_.download_id(), broad_.neighbours());
  }

  // Rebuilds the neighbour list now (moving force and torque along), then takes the snapshot. The
  // extra rebuild is part of the run's history: a run that writes checkpoints every T differs in
  // rounding from one that writes none, and a restart from any of them matches the former exactly.
  SimulationSnapshot<Real> snapshot() {
    rebuild(true);
    SimulationSnapshot<Real> out;
    out.store = store_.snapshot();
    out.contacts = contacts_.snapshot(out.store.id, broad_.neighbours());
    out.steps = steps_;
    out.initial_count = initial_count_;
    out.removed_count = removed_count_;
    out.removed_mass = removed_mass_;
    out.removed_energy = removed_energy_;
    out.inserted_count = inserted_count_;
    out.inserted_mass = inserted_mass_;
    out.inserted_energy = inserted_energy_;
    out.inserted_kinetic = inserted_kinetic_;
    out.next_id = next_id_;
    return out;
  }

  // Rebuilds the neighbour list now (hash, sort, reorder, cells and list), as a step does when a
  // particle has moved half the skin (forces and torques move along, as between steps they are
  // still needed); benchmarks time the broad phase with it.
  void rebuild_neighbours() { rebuild(true); }

  // One step. Unless the phase timer is on (batched()), it goes through the same batch that run()
  // uses, so a trajectory is bitwise the same however its steps were grouped (on the GPU's
  // one-block path every phase runs in the one kernel; a larger system's graph and the per-phase
  // kernels that finish a step after a rebuild may round differently: the compiler contracts
  // a*b + c into FMAs per kernel).
  void step() {
    if (batched()) return run_batched(1);
    finish_step(0);
  }
  // `steps` steps; bitwise the same as calling step() that many times (with the phase timer in the
  // same state): in batches (run_batched) unless the phase timer is on.
  void run(std::uint64_t steps) {
    if (batched()) return run_batched(steps);
    for (std::uint64_t s = 0; s < steps; ++s) step();
  }
  // ---- A step in parts, for the distributed driver (pipeline/parallel/distributed_simulation.hpp,
  // issue 21), which exchanges ghost particles between the parts: begin_step() moves the world and
  // the particles (the pre-force integration; the rebuild check it carries is not acted on
  // there); needs_rebuild() is that check (0: the list holds; 1: rebuild; 2: a position is not
  // finite), which the driver answers with reload() on every rank; end_step() evaluates the
  // forces and ends the step.
  // begin_step(), end_step() with the list holding is one step() of the per-phase path.
  void begin_step() { run_phases(Space{}, store_.size(), step_phases(params_.dt), 0, kRebuildCheck + 1, timer_); }
  int needs_rebuild() {
    const int code = broad_.rebuild_check(store_);
    if (code == 0 && lists_.on()) {
      const std::uint64_t* counter = world_.step_counter();
      if (counter && read_one(counter, Space{}) > lists_.valid_until()) return 1;
    }
    return code;
  }
  void end_step() {
    run_phases(Space{}, store_.size(), step_phases(params_.dt), kFirstForcePhase, kPostForcePhase + 1, timer_);
    ++steps_;
  }
  // The particles replaced by `s` with contact states `c` (keyed by permanent ids; a particle
  // without any starts with none), sorted in and listed as a rebuild does; the counters stay.
  void reload(const StoreSnapshot<Real>& s, const ContactSnapshot<Real>& c) {
    store_.restore(s);
    store_.keep_fields(Integrator::keeps_previous_forces, Features::monitor);
    if (params_.periodic) store_.keep_images();
    if (world_.dynamic() || params_.energy_ledger) store_.keep_ledger(Features::thesis_power);
    first_build();
    contacts_.restore(c, store_.download_id(), broad_.neighbours());
  }
  // The store's arrays and the contact states as they are (no rebuild first: snapshot() does one).
  StoreSnapshot<Real> store_snapshot() const { return store_.snapshot(); }
  ContactSnapshot<Real> contact_snapshot() { return contacts_.snapshot(store_.download_id(), broad_.neighbours()); }
  std::vector<Index> ids() const { return store_.download_id(); }
  // The particles the samples and world loads count (sample(), world_loads()): a flag per
  // particle in the store's order as it is now (a rank's own particles, not its ghosts:
  // pipeline/parallel/distributed_simulation.hpp); until the store next changes order or size.
  // Empty: every particle (the default).
  void count_only(const std::vector<std::uint8_t>& flags) {
    if (!flags.empty() && flags.size() != static_cast<std::size_t>(store_.size()))
      throw std::invalid_argument("simulation: count_only needs a flag per particle (" + std::to_string(store_.size()) + "), got " +
                                  std::to_string(flags.size()));
    from_host(counted_, flags);
    counted_order_ = flags.empty() ? 0 : reorders_;
  }
  // Rows of every kept real array (ParticleStore::download_rows), indices on the host.
  void download_rows(const std::vector<Index>& which, std::vector<Real>& out) {
    from_host(rows_which_, which);
    store_.download_rows(rows_which_.data(), static_cast<Index>(which.size()), out);
  }
  void upload_rows(const std::vector<Index>& which, const std::vector<Real>& in) {
    from_host(rows_which_, which);
    store_.upload_rows(rows_which_.data(), static_cast<Index>(which.size()), in);
  }

  // Steps run in batches with one host round trip per batch (run_batched; phases.hpp: on the GPU
  // one launch per batch for small systems, one CUDA graph per batch for larger ones), unless
  // the phase timer is on (the phases are then timed one by one, with a round trip per step).
  bool batched() const { return !timer_.enabled; }

  ParticleState<Real> state() const { return state_of(store_); }
  // Periodic axes: the unwrapped positions x + image L (m) of `s`, which is state() now (grid/
  // periodic_images.hpp), continuous across the boundary; empty without periodic axes.
  std::vector<Vec3<double>> unwrapped_positions(const ParticleState<Real>& s) const {
    const std::vector<Index> image = store_.download_images();
    std::vector<Vec3<double>> out;
    if (image.empty()) return out;
    if (image.size() != 3 * s.size()) throw std::invalid_argument("simulation: unwrapped_positions() takes the state of now");
    const Vec3<double> l = vec_cast<double>(broad_.grid().length);
    out.resize(s.size());
    for (std::size_t i = 0; i < s.size(); ++i)
      out[i] = vec_cast<double>(s.position[i]) + Vec3<double>{image[3 * i] * l.x, image[3 * i + 1] * l.y, image[3 * i + 2] * l.z};
    return out;
  }

  // Contacts counted in the last force evaluation, by kind (each pair once); needs
  // Features::statistics.
  std::pair<long, long> contact_counts() {
    static_assert(Features::statistics, "contact counts need FeatureSet<..., true>");
    if (stats_vertex_face_.size() < static_cast<std::size_t>(store_.size())) return {0, 0};  // no evaluation yet
    const SampleTally t = tally(false, 0);
    return {static_cast<long>(t.vertex_face / 2), static_cast<long>(t.edge_edge / 2)};
  }
  // Elastic energy stored in the contacts at the current positions, over the same neighbour list
  // and with the same collide() calls as the force kernels, and the particle-world contact
  // count. A diagnostic for the time series: one kernel and one reduction, run only when asked
  // (never inside a step). Needs every law to have stored_energy().
  ContactEnergy contact_energy() { return stored_energy(tally(true, 0)); }
  // The force (N) and torque about the origin (N m) the particles put on each of `objects` (world
  // object indices) now, from the contacts as they stand (kernels/world_loads.hpp): a kernel and
  // a reduction per 8 objects, run only when asked (never inside a step).
  struct WorldLoad {
    Vec3<double> force, torque;
  };
  std::vector<WorldLoad> world_loads(const std::vector<int>& objects) {
    std::vector<WorldLoad> out;
    for (std::size_t first = 0; first < objects.size(); first += kLoadObjects) {
      WorldLoads<Shape, Law, Kinematics, Features> f{shape_, store_.view(), lists_.attach(world_.view()), laws_, contacts_.walls(), params_.dt, {}, 0,
                                                     counted()};
      for (int k = 0; k < kLoadObjects; ++k) f.object[k] = -1;
      for (std::size_t k = first; k < objects.size() && k < first + kLoadObjects; ++k) f.object[f.count++] = objects[k];
      const LoadTally t = reduce_in_order(Space{}, store_.size(), f, load_parts_);
      for (int k = 0; k < f.count; ++k)
        out.push_back({{t.load[k][0], t.load[k][1], t.load[k][2]}, {t.load[k][3], t.load[k][4], t.load[k][5]}});
    }
    return out;
  }
  // Deepest overlap / radius per particle since the last call, then reset (Features::monitor).
  PenetrationReport take_penetration(double threshold) {
    static_assert(Features::monitor, "penetration needs FeatureSet<..., ..., true>");
    const PenetrationReport r = penetration(tally(false, threshold));
    store_.reset_penetration();
    return r;
  }
  // One row of the time series, reduced on the particles' own memory space (kernels/
  // sample_tally.hpp): energies, mass, stored contact energy, contact counts (statistics) and the
  // penetration since the last sample (monitor; reset here). A kernel for the contacts' energy, one
  // for the reduction, and 16384 partial tallies back at most: no state download.
  struct Sample {
    Energies energies;      // J, translational, rotational, potential
    double mass = 0;        // kg, of the particles present
    ContactEnergy stored;   // J, the open contacts' elastic energy; world contacts
    long vertex_face = 0, edge_edge = 0;  // particle-particle contacts by kind, each pair once
    long vertex_face_sides = 0, edge_edge_sides = 0;  // the same from both sides (summed over ranks, then halved)
    PenetrationReport penetration;
    // The energy accounts since the last sample (blaze/particles/energy_ledger.hpp), when kept:
    bool ledger = false;
    double drive_work = 0;       // J, done by moving world objects on the particles
    double dissipated_pair = 0;  // J, taken out by particle-particle contacts
    double dissipated_walls[kContactClasses] = {};  // J, by particle-world contacts, by the object's class
    double thesis_estimate = 0;  // J, the thesis's sum |F_diss| |V| dt (Features::thesis_power; else 0)
    double dissipated() const {
      double d = dissipated_pair;
      for (double w : dissipated_walls) d += w;
      return d;
    }
  };
  Sample sample(double penetration_limit) {
    const SampleTally t = tally(true, penetration_limit);
    Sample s;
    s.energies = {t.translational, t.rotational, t.potential};
    s.mass = t.mass;
    s.stored = stored_energy(t);
    if (stats_vertex_face_.size() >= static_cast<std::size_t>(store_.size()))
      s.vertex_face = static_cast<long>(t.vertex_face / 2), s.edge_edge = static_cast<long>(t.edge_edge / 2),
      s.vertex_face_sides = static_cast<long>(t.vertex_face), s.edge_edge_sides = static_cast<long>(t.edge_edge);
    s.penetration = penetration(t);
    s.ledger = store_.keeps_ledger();
    s.drive_work = t.ledger[kLedgerDrive];
    s.dissipated_pair = t.ledger[kLedgerPair];
    for (int c = 0; c < kContactClasses; ++c) s.dissipated_walls[c] = t.ledger[kLedgerWalls + c];
    s.thesis_estimate = t.thesis_estimate;
    store_.reset_penetration();
    store_.reset_ledger();
    return s;
  }
  // The world lists (pipeline/world_candidates.hpp): on or off, builds, validity, overflow.
  const WorldCandidates<Real, Space>& world_lists() const { return lists_; }
  // The world moves or loses objects at set times (blaze/world/motion.hpp).
  bool world_moves() const { return world_.dynamic(); }
  // The particles keep energy accounts (a world that moves, or SimulationParams::energy_ledger).
  bool keeps_energy_ledger() const { return store_.keeps_ledger(); }
  // Each object's pose now (a static world: none).
  std::vector<Pose<Real>> world_poses() const { return world_.dynamic() ? world_.poses() : std::vector<Pose<Real>>{}; }
  // A copy of the state kept on the particles' memory space (keep_state()) and read back only
  // when asked (kept_state()): what `blaze run` writes as last_good.vtu when a guard stops it,
  // without a download at every sample. Costs the state's arrays once more (~16 reals and
  // 6 bytes per particle).
  void keep_state() { kept_.copy_state_from(store_); }
  ParticleState<Real> kept_state() const { return state_of(kept_); }
  const Shape& shape() const { return shape_; }
  std::vector<Vec3<Real>> forces() const { return store_.download_force(); }
  std::vector<Vec3<Real>> torques() const { return store_.download_torque(); }
  Index size() const { return store_.size(); }
  Index initial_count() const { return initial_count_; }
  Index removed_count() const { return removed_count_; }
  // Particles inserted after the start (insert()), their mass (kg) and their energy when inserted
  // (J: kinetic, translational and rotational, plus potential in the gravity of the moment).
  Index inserted_count() const { return inserted_count_; }
  double inserted_mass() const { return inserted_mass_; }
  double inserted_energy() const { return inserted_energy_; }
  double inserted_kinetic() const { return inserted_kinetic_; }  // J, their kinetic energy alone
  // The largest bounding radius the grid was made for (SimulationParams::max_radius).
  Real max_radius() const { return r_max_; }

  // Adds particles between steps (a feeder's, pipeline/feeder.hpp): they take the next permanent
  // ids, start with no contacts and no force, and the neighbour list is rebuilt at once (sorted
  // in, contact states carried over; the run's trajectory does not depend on where in memory they
  // landed). The caller placed them where they overlap nothing. Refused: a bounding radius above
  // max_radius(), a material without laws, a state that is not finite.
  // keep_ids: the particles come with their permanent ids (a run over ranks gives every rank's
  // part of a batch the ids one process would: pipeline/parallel/distributed_simulation.hpp).
  void insert(ParticleState<Real> add, bool keep_ids = false) {
    if (add.size() == 0) return;
    check_materials(laws_, World<Real>{}, add);
    check_finite(add, steps_);
    for (std::size_t k = 0; k < add.size(); ++k) {
      if (!(add.radius[k] > 0 && add.radius[k] <= r_max_))
        throw std::invalid_argument("simulation: an inserted particle's radius " + std::to_string(add.radius[k]) +
                                    " m is outside (0, max_radius = " + std::to_string(r_max_) + " m] (SimulationParams::max_radius)");
      if (keep_ids) next_id_ = std::max(next_id_, add.id[k] + 1);
      else add.id[k] = next_id_++;
      const double m = static_cast<double>(add.mass[k]);
      const Vec3<double> x = vec_cast<double>(add.position[k]), v = vec_cast<double>(add.velocity[k]);
      const Vec3<double> w = vec_cast<double>(add.angular_velocity[k]);
      const double kinetic = 0.5 * m * dot(v, v) + 0.5 * static_cast<double>(add.inertia[k].x) * dot(w, w);
      inserted_mass_ += m;
      inserted_kinetic_ += kinetic;
      inserted_energy_ += kinetic - m * dot(vec_cast<double>(params_.gravity), x);
    }
    inserted_count_ += static_cast<Index>(add.size());
    store_.append(add);
    rebuild(true);
  }
  // The particles whose centre lies in [lo, hi] (m), in memory order: x, y, z and bounding radius
  // of each in `out` (4 reals a particle, on this space), found where they live in parts
  // (kernels/region_query.hpp; a count a part comes back); returns how many. What a feeder must
  // keep clear of.
  Index spheres_in_box(const Vec3<double>& lo, const Vec3<double>& hi, Buffer<Real, Space>& out) {
    const ParticleView<Real> p = store_.view();
    if (p.n == 0) return 0;
    const Index parts = std::min(p.n, kReduceParts<Space>);
    query_count_.ensure(static_cast<std::size_t>(parts));
    InBoxParts<Real> q{p.position, p.radius, vec_cast<Real>(lo), vec_cast<Real>(hi), p.n, parts, query_count_.data(), nullptr, nullptr};
    for_each(Space{}, parts, q);
    std::vector<Index> offset = to_host(query_count_, static_cast<std::size_t>(parts));
    Index found = 0;
    for (Index& c : offset) found += std::exchange(c, found);  // exclusive: each part's first
    if (found == 0) return 0;
    copy_in(query_offset_, offset.data(), offset.size());
    out.ensure(4 * static_cast<std::size_t>(found));
    q.offset = query_offset_.data(), q.out = out.data();
    for_each(Space{}, parts, q);
    return found;
  }
  // The same on the host: centres and bounding radii (m).
  void particles_in_box(const Vec3<double>& lo, const Vec3<double>& hi, std::vector<Vec3<double>>& centre,
                        std::vector<double>& radius) {
    const std::size_t found = static_cast<std::size_t>(spheres_in_box(lo, hi, query_out_));
    const std::vector<Real> out = to_host(query_out_, 4 * found);
    centre.resize(found), radius.resize(found);
    for (std::size_t k = 0; k < found; ++k) centre[k] = {out[4 * k], out[4 * k + 1], out[4 * k + 2]}, radius[k] = out[4 * k + 3];
  }
  double removed_mass() const { return removed_mass_; }
  // Translational kinetic + potential energy the removed particles had when they were removed, J.
  double removed_energy() const { return removed_energy_; }
  std::uint64_t steps() const { return steps_; }
  double time() const { return static_cast<double>(steps_) * params_.dt; }
  // Neighbour-list builds: the host's and the in-block rebuild's.
  std::uint64_t neighbour_builds() const { return broad_.builds() + broad_.in_block_builds(); }
  Index neighbour_capacity() const { return broad_.capacity(); }
  const SimulationParams<Real>& params() const { return params_; }
  // Gravity from the next step on (a tilting plane, a turning frame; m/s^2).
  void set_gravity(const Vec3<Real>& g) { params_.gravity = g; }
  PhaseTimer<Space>& timer() { return timer_; }

  // Neighbour list on the host, indexed like state() (diagnostics and tests).
  struct HostNeighbours {
    std::vector<Index> count, index;
    Index stride, capacity;
  };
  HostNeighbours neighbour_lists() {
    const NeighbourView nl = broad_.neighbours();
    HostNeighbours h{std::vector<Index>(store_.size()), std::vector<Index>(static_cast<std::size_t>(nl.capacity) * nl.stride),
                     nl.stride, nl.capacity};
    copy_n(nl.count, h.count.size(), h.count.data(), Space{}, Host{});
    copy_n(nl.index, h.index.size(), h.index.data(), Space{}, Host{});
    return h;
  }
  // The most bytes a rebuild's spare arrays may hold, in the particle store and in the contact
  // store each (32 MiB by default; 0: one array a launch, the least memory): the reorder moves
  // as many arrays a launch as they have room for. The results are the same either way.
  void limit_spares(std::size_t bytes) {
    store_.limit_spares(bytes);
    contacts_.limit_spares(bytes);
  }
  // Mean neighbour-list length (benchmarks; reads only the counts).
  double mean_neighbours() {
    const NeighbourView nl = broad_.neighbours();
    std::vector<Index> count(store_.size());
    copy_n(nl.count, count.size(), count.data(), Space{}, Host{});
    double total = 0;
    for (Index c : count) total += c;
    return count.empty() ? 0 : total / static_cast<double>(count.size());
  }
  // Each particle's listed neighbours as permanent ids, indexed by the particle's id (tests: the
  // list a rebuild left, host or in place).
  std::vector<std::vector<Index>> neighbour_ids() {
    const NeighbourView nl = broad_.neighbours();
    const std::vector<Index> id = store_.download_id();
    std::vector<Index> count(id.size()), list(static_cast<std::size_t>(nl.capacity) * static_cast<std::size_t>(nl.stride));
    copy_n(nl.count, count.size(), count.data(), Space{}, Host{});
    copy_n(nl.index, list.size(), list.data(), Space{}, Host{});
    std::vector<std::vector<Index>> out(id.empty() ? 0 : static_cast<std::size_t>(*std::max_element(id.begin(), id.end())) + 1);
    for (std::size_t i = 0; i < id.size(); ++i)
      for (Index k = 0; k < std::min(count[i], nl.capacity); ++k)
        out[static_cast<std::size_t>(id[i])].push_back(id[static_cast<std::size_t>(list[nl.offset(k, static_cast<Index>(i))])]);
    return out;
  }
  // Neighbour lists built in place (pipeline/in_block_rebuild.hpp), of neighbour_builds().
  std::uint64_t in_block_builds() const { return broad_.in_block_builds(); }
  // Particle arrays, broad phase (not counting the sorter's scratch), pair slots and contact store, bytes.
  std::size_t memory_bytes() const {
    std::size_t slots = slot_state_.size() + slot_overlap_.size() * sizeof(Real);
    for (const auto& b : slot_reals_) slots += b.size() * sizeof(Real);
    return store_.bytes() + broad_.bytes() + slots + contacts_.bytes() + lists_.bytes();
  }

 private:
  static Real max_of(const std::vector<Real>& v) {
    Real m = 0;
    for (Real r : v) m = std::max(m, r);
    return m;
  }
  // The meshes' bins reach (mesh_wall.hpp): the largest bounding radius plus the skin, 0.1% more
  // than the world lists' own rounding allowance.
  static double mesh_reach(const SimulationParams<Real>& prm, Real r_max) {
    return (static_cast<double>(r_max) + static_cast<double>(prm.skin)) * 1.001;
  }
  static void check_params(const SimulationParams<Real>& params) {
    if (!(params.dt > 0)) throw std::invalid_argument("simulation: dt must be > 0 s");
    if (!(params.skin >= 0)) throw std::invalid_argument("simulation: skin must be >= 0 m");
    if (!(params.drag >= 0)) throw std::invalid_argument("simulation: drag must be >= 0 kg/m");
  }
  static GridSpec<Real> make_grid(const SimulationParams<Real>& prm, Real r_max) {
    if (!(r_max > 0)) throw std::invalid_argument("simulation: no particles and no max_radius (a run that starts empty sizes its grid by SimulationParams::max_radius)");
    return GridSpec<Real>::make(prm.domain_lo, prm.domain_hi, Real(2) * r_max + prm.skin, prm.periodic);
  }

  static void check_materials(const PairTable<Law>& laws, const World<Real>& world, const ParticleState<Real>& s) {
    bool used[PairTable<Law>::kMaxMaterials] = {};
    for (auto m : s.material) {
      if (m >= PairTable<Law>::kMaxMaterials) throw std::invalid_argument("particle material index too large");
      used[m] = true;
    }
    auto need = [&](int a, int b, const char* what) {
      if (!laws.has(a, b))
        throw std::invalid_argument(std::string("no contact law for material pair (") + std::to_string(a) + ", " +
                                    std::to_string(b) + ") needed by " + what);
    };
    for (int a = 0; a < PairTable<Law>::kMaxMaterials; ++a) {
      if (!used[a]) continue;
      for (int b = 0; b < PairTable<Law>::kMaxMaterials; ++b)
        if (used[b]) need(a, b, "particle-particle contacts");
      for (const auto& w : world.polygons) need(a, w.material, "a planar wall");
      for (const auto& w : world.cylinders) need(a, w.material, "a cylinder");
      for (const auto& w : world.meshes) need(a, w.material, "a mesh wall");
    }
  }
  void check_meshes(const World<Real>& world) const {
    if (world.meshes.empty()) return;
    if (static_cast<double>(world.object_count()) + static_cast<double>(world.triangle_count()) > 2147483647.0)
      throw std::invalid_argument("mesh walls: more world objects and triangles than a contact key holds (2^31)");
  }

  template <Stage S>
  Integrate<Integrator, Shape, Features, Real, S> integrate() {
    return {shape_, store_.view(), params_.dt, {params_.gravity, params_.drag}};
  }

  // The step (phases.hpp): every phase in order. A phase added here runs in every step, batched
  // or not. Builds the functors from the current views (a rebuild moves and resizes them), after
  // sizing what they write (statistics, pair slots).
  // The drift and the rebuild check are one check phase (then_check): the check reads only what
  // the drift wrote for the same particle (its position) and the world's step (move-world's).
  // Its handler rebuilds small systems in place (pipeline/in_block_rebuild.hpp); the host
  // rebuilds (on_check) what it leaves.
  static constexpr int kRebuildCheck = 1, kFirstForcePhase = 2, kPostForcePhase = 6;
  // history_dt: the step the contact states advance by (0 for the forces at t = 0).
  auto step_phases(Real history_dt) {
    prepare_statistics();
    const bool once = params_.pairs == PairEvaluation::once;
    const PairSlots<Real> slots = once ? pair_slots() : PairSlots<Real>{};
    const ParticleView<Real> p = store_.view();
    const NeighbourView nl = broad_.neighbours();
    auto phases = make_phases(
        kernel_phase("move-world", MoveWorld<Real>{world_.motion_view(), store_.size()}, world_.dynamic()),
        check_phase("integrate",
                    then_check(integrate<Stage::pre_force>(),
                               broad_.rebuild_check_functor(store_, lists_.on() ? world_.step_counter() : nullptr, lists_.valid_until_at())),
                    in_block_rebuild_phases(broad_, lists_, store_, world_.view(), world_.step_counter(), in_block_rebuild())),
        kernel_phase("contacts", contact_forces(history_dt), !once),
        kernel_phase("contacts", PairForces<Shape, Law, Kinematics, Features>{shape_, p, nl, laws_, slots, contacts_.pairs(), history_dt, broad_.images(),
                                                                             entry_threads(nl.capacity) ? store_.size() : 0}, once),
        kernel_phase("contacts", GatherPairForces<Real, Features, kMoments>{p, nl, slots, contact_stats(), broad_.images()}, once),
        kernel_phase("walls", world_forces(history_dt), !world_.empty()),
        kernel_phase("integrate", integrate<Stage::post_force>()));
    static_assert(decltype(phases)::size == kPostForcePhase + 1, "step_phases: the phase indices above are stale");
    return phases;
  }

  // Whether the rebuild check's handler may rebuild in place (the broad phase and the world
  // lists add their own conditions): not with contact history, canonical order or periodic axes.
  bool in_block_rebuild() const {
    return !Law::kHistory && !params_.canonical_order && !params_.periodic &&
           in_block_rebuild_wanted<Space>(params_.in_block_rebuild, store_.size(), one_block_particles<Shape>());
  }

  // Whether the pair phase runs a thread a list entry (PairThreads; `capacity`: the list's).
  bool entry_threads(Index capacity) const {
    if constexpr (Features::thesis_power) return false;
    const double items = static_cast<double>(store_.size()) * static_cast<double>(capacity);
    if (items > 2147483647.0) return false;  // (the items are counted in an Index)
    if (params_.pair_threads != PairThreads::automatic) return params_.pair_threads == PairThreads::entry;
    return !std::is_same_v<Space, Host> && store_.size() < kEntryThreadsBelow;
  }

  // The step's phases from `from` on; a check that stops it is acted on (on_check) and the phases
  // after it follow.
  void finish_step(int from) {
    for (;;) {
      const PhaseStop stop = run_phases(Space{}, store_.size(), step_phases(params_.dt), from, kPostForcePhase + 1, timer_);
      if (stop.index < 0) break;
      on_check(stop);
      from = stop.index + 1;
    }
    ++steps_;
  }
  // What a check phase's code asks for. The rebuild check: 1, rebuild the neighbour list (moving
  // particles in memory, dropping those that left); 2, a position is not finite.
  void on_check(const PhaseStop& stop) {
    if (stop.index != kRebuildCheck) throw std::logic_error("simulation: a check phase without a handler");
    if (stop.code == 2) throw_non_finite(steps_ + 1);
    rebuild(false);
  }
  // Hash, sort, reorder, new list (broad_phase.hpp), and the contact store carried over to it.
  // with_forces: force and torque move too (between steps).
  void rebuild(bool with_forces) {
    ++reorders_;
    apply_removal(broad_.rebuild(store_, timer_, params_.gravity, with_forces));
    build_world_lists();
    if constexpr (Law::kHistory)
      timer_.time("neighbours", [&] {
        contacts_.after_rebuild(broad_.neighbours(), broad_.previous_neighbours(), broad_.order(), store_.size(),
                                params_.pairs == PairEvaluation::once);
      });
  }
  // The store's reals per contact (all the law's state), and its wall slots (one per world object
  // up to 3 to begin with); the broad phase keeps the previous list for the carry-over.
  void configure_contacts(const World<Real>& world) {
    if constexpr (Law::kHistory) {
      int used = 0;  // the most any pair's law uses (a rolling spring only under model C)
      for (int k = 0; k < PairTable<Law>::kMaxMaterials * PairTable<Law>::kMaxMaterials; ++k)
        if (laws_.defined[k]) used = std::max(used, laws_.entries[k].state_reals());
      // A mesh may hold several contacts of one particle (a valley, a corner).
      const double walls = static_cast<double>(world.polygons.size() + world.cylinders.size()) + 3.0 * static_cast<double>(world.meshes.size());
      contacts_.configure(used, static_cast<int>(std::min(walls, 1e6)));
      broad_.keep_previous_list();
    }
  }

  // A batch of K steps with no host round trip per step (phases.hpp: one launch, or one graph; on
  // the host, the phases step after step): the batch stops at the first step whose check is set
  // (it needs a rebuild, or found a non-finite position), just after that check; the flags are
  // read once. The host acts on the check, and the next batch begins with the rest of that step
  // (on the one-block path in the same kernel as every other step, so the rounding does not
  // depend on where the batches stopped). No path runs a step past the stop, so every batch is as
  // long as it may be (kMaxBatch: the flags' room).
  static constexpr std::uint64_t kMaxBatch = 256;
  void run_batched(std::uint64_t steps) {
    flags_.ensure(kMaxBatch);
    int from = 0;  // the phase the batch's first step begins at
    while (steps > 0) {
      const std::uint64_t k = std::min(kMaxBatch, steps);
      for_each(Space{}, static_cast<Index>(k), Fill<int>{flags_.data(), 0});
      fused_steps(Space{}, store_.size(), k, step_phases(params_.dt), flags_.data(), one_block_particles<Shape>(), from);
      const std::vector<int> flags = to_host(flags_, k);  // the batch's one round trip
      const auto j = static_cast<std::uint64_t>(std::find_if(flags.begin(), flags.end(), [](int f) { return f != 0; }) - flags.begin());
      steps_ += j;
      steps -= j;
      from = 0;
      if (j == k) continue;
      const PhaseStop stop = PhaseStop::of_flag(flags[j]);  // step j, from just after its check
      on_check(stop);
      from = stop.index + 1;  // (step j is still to finish: steps >= 1)
    }
  }

  // The first neighbour list (a new run, or a restored one: the same positions in the same order
  // rebuild the same list).
  void first_build() {
    ++reorders_;
    if (broad_.rebuild_check(store_, true) == 2) throw_non_finite(steps_);
    apply_removal(broad_.rebuild(store_, timer_, params_.gravity));
    build_world_lists();
    contacts_.clear(broad_.neighbours(), store_.size());
  }
  // The world lists for the particles as the rebuild left them and the world as it stands (a
  // moving world's step read back: mid-step it is one ahead of steps_).
  void build_world_lists() {
    if (!lists_.on()) return;
    const std::uint64_t* counter = world_.step_counter();
    const std::uint64_t step = counter ? read_one(counter, Space{}) : steps_;
    timer_.time("world-lists", [&] { lists_.build(store_.view(), world_.view(), step); });
  }
  template <class Removed>
  void apply_removal(const Removed& removed) {
    removed_count_ += removed.count;
    removed_mass_ += removed.mass;
    removed_energy_ += removed.energy;
  }

  [[noreturn]] void throw_non_finite(std::uint64_t step) const {
    check_finite(store_.download(), step);
    throw NonFiniteState("non-finite state at step " + std::to_string(step), step, -1);
  }
  // Throws NonFiniteState naming the first particle with a NaN or Inf in its state.
  void check_finite(const ParticleState<Real>& s, std::uint64_t step) const {
    auto bad = [](const Vec3<Real>& v) { return !(finite_r(v.x) && finite_r(v.y) && finite_r(v.z)); };
    for (std::size_t k = 0; k < s.size(); ++k)
      if (bad(s.position[k]) || bad(s.velocity[k]) || bad(s.angular_velocity[k]) ||
          !finite_r(s.orientation[k].w + s.orientation[k].x + s.orientation[k].y + s.orientation[k].z)) {
        const auto& x = s.position[k];
        const auto& v = s.velocity[k];
        throw NonFiniteState("non-finite state at step " + std::to_string(step) + " (t = " +
                                 std::to_string(static_cast<double>(step) * params_.dt) + " s): particle id " +
                                 std::to_string(s.id[k]) + ", position (" + std::to_string(x.x) + ", " + std::to_string(x.y) +
                                 ", " + std::to_string(x.z) + ") m, velocity (" + std::to_string(v.x) + ", " +
                                 std::to_string(v.y) + ", " + std::to_string(v.z) + ") m/s",
                             step, s.id[k]);
      }
  }

  ParticleState<Real> state_of(const ParticleStore<Real, Space>& store) const {
    ParticleState<Real> s = store.download();
    const auto inv_i = store.download_inverse_inertia();
    for (std::size_t k = 0; k < s.size(); ++k) s.inertia[k] = shape_.principal_inertia(inv_i[k], s.radius[k], s.type[k]);
    return s;
  }
  // The sample's reduction; with_energy runs StoredContactEnergy's two parts first (their per-particle slots).
  // count_only's flags (null: count every particle); flags set for an order the store has left
  // are an error, never silently all.
  const std::uint8_t* counted() const {
    if (counted_order_ == 0) return nullptr;
    if (counted_order_ != reorders_) throw std::logic_error("simulation: count_only's flags are for an order the store has left");
    return counted_.data();
  }
  SampleTally tally(bool with_energy, double threshold) {
    const Index n = store_.size();
    ParticleTally<Shape, Real> f{shape_, store_.view(), params_.gravity, nullptr, nullptr, nullptr, nullptr, nullptr, threshold, counted()};
    for (int d = 0; d < 3; ++d) f.image[d] = store_.image(d);
    f.period = vec_cast<double>(broad_.grid().length);
    if (with_energy) {
      for (auto* b : {&energy_pairs_, &energy_walls_})
        b->ensure(static_cast<std::size_t>(n));
      energy_wall_contacts_.ensure(static_cast<std::size_t>(n));
      const ContactEnergySlots slots{energy_pairs_.data(), energy_walls_.data(), energy_wall_contacts_.data()};
      const auto energy = [&](auto part) {
        for_each(Space{}, n, StoredContactEnergy<Shape, Law, decltype(part)::value>{shape_, store_.view(), broad_.neighbours(),
                                                                                  lists_.attach(world_.view()), laws_, slots, contacts_.pairs(),
                                                                                  contacts_.walls(), broad_.images(), counted()});
      };
      energy(std::integral_constant<ContactEnergyPart, ContactEnergyPart::pairs>{});
      energy(std::integral_constant<ContactEnergyPart, ContactEnergyPart::walls>{});
      f.pair_energy = energy_pairs_.data(), f.wall_energy = energy_walls_.data(), f.wall_contacts = energy_wall_contacts_.data();
    }
    if constexpr (Features::statistics)
      if (stats_vertex_face_.size() >= static_cast<std::size_t>(n))
        f.vertex_face = stats_vertex_face_.data(), f.edge_edge = stats_edge_edge_.data();
    return reduce_in_order(Space{}, n, f, tally_parts_);
  }
  static ContactEnergy stored_energy(const SampleTally& t) { return {t.pair_energy, t.wall_energy, static_cast<long>(t.wall_contacts)}; }
  PenetrationReport penetration(const SampleTally& t) {
    PenetrationReport r;
    r.worst = t.worst, r.over = static_cast<long>(t.over);
    r.worst_id = t.worst_id;
    return r;
  }

  void prepare_statistics() {
    if constexpr (Features::statistics) {
      stats_vertex_face_.ensure(store_.size());
      stats_edge_edge_.ensure(store_.size());
    }
  }
  ContactStats contact_stats() {
    if constexpr (Features::statistics) return {stats_vertex_face_.data(), stats_edge_edge_.data()};
    return {nullptr, nullptr};
  }
  ContactForces<Shape, Law, Kinematics, Features> contact_forces(Real history_dt) {
    return {shape_, store_.view(), broad_.neighbours(), laws_, contact_stats(), contacts_.pairs(), history_dt, broad_.images(),
            params_.canonical_order};
  }
  WorldForces<Shape, Law, Kinematics, Features> world_forces(Real history_dt) {
    return {shape_, store_.view(), lists_.attach(world_.view()), laws_, contacts_.walls(), history_dt};
  }

  // Pairs once: the slots, one per list entry (grown with the list, never shrunk).
  PairSlots<Real> pair_slots() {
    const NeighbourView nl = broad_.neighbours();
    const std::size_t entries = static_cast<std::size_t>(nl.capacity) * static_cast<std::size_t>(nl.stride);
    // Contact points only with rotation; patch moments only with rotation and patches.
    for (int b = 0; b < (Features::rotation ? (kMoments ? 9 : 6) : 3); ++b)
      slot_reals_[b].ensure(entries);
    slot_state_.ensure(entries);
    if constexpr (Features::monitor) slot_overlap_.ensure(entries);
    PairSlots<Real> s{};
    for (int d = 0; d < 3; ++d) {
      s.force[d] = slot_reals_[d].data();
      s.point[d] = slot_reals_[3 + d].data();
      s.moment[d] = kMoments && Features::rotation ? slot_reals_[6 + d].data() : nullptr;
    }
    s.state = slot_state_.data();
    s.overlap = Features::monitor ? slot_overlap_.data() : nullptr;
    return s;
  }

  void reside_shape() {
    if constexpr (ResidentTable<Shape>::value) {
      resident_.resize(1);
      copy_n(&shape_.table, 1, resident_.data(), Host{}, Space{});
      shape_.resident = resident_.data();
    }
  }

  Shape shape_;
  Buffer<typename ResidentTable<Shape>::type, Space> resident_;  // the shape's table where its kernels read it
  SimulationParams<Real> params_;
  PairTable<Law> laws_;
  Real r_max_;  // the grid's largest bounding radius (SimulationParams::max_radius)
  Buffer<Index, Space> stats_vertex_face_, stats_edge_edge_;
  Buffer<double, Space> energy_pairs_, energy_walls_;  // contact_energy(), per particle
  Buffer<Index, Space> energy_wall_contacts_;
  Buffer<SampleTally, Space> tally_parts_;  // reduce_in_order's partial tallies
  Buffer<LoadTally, Space> load_parts_;
  ParticleStore<Real, Space> kept_;         // keep_state()
  Buffer<Real, Space> slot_reals_[9];  // pairs once: force, contact point, patch moment (x, y, z each)
  Buffer<std::uint8_t, Space> slot_state_;
  Buffer<Real, Space> slot_overlap_;
  ParticleStore<Real, Space> store_;
  ContactStore<Real, Law::State::kReals, Space> contacts_;  // laws with history (contact_store.hpp)
  WorldStore<Real, Space> world_;
  WorldCandidates<Real, Space> lists_;  // world lists (empty when off)
  BroadPhase<Real, Space> broad_;
  PhaseTimer<Space> timer_;
  Buffer<int, Space> flags_;  // rebuild check of each step of a batch (run_batched)
  Buffer<Index, Space> query_count_, query_offset_;  // particles_in_box
  Buffer<std::uint8_t, Space> counted_;      // count_only's flags, for the store's order numbered counted_order_
  std::uint64_t reorders_ = 1, counted_order_ = 0;
  Buffer<Index, Space> rows_which_;
  Buffer<Real, Space> query_out_;
  Index initial_count_ = 0;
  Index removed_count_ = 0;
  double removed_mass_ = 0, removed_energy_ = 0;
  Index inserted_count_ = 0, next_id_ = 0;
  double inserted_mass_ = 0, inserted_energy_ = 0, inserted_kinetic_ = 0;
  std::uint64_t steps_ = 0;
};

}  // namespace blaze
