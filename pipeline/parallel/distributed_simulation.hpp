// One run over several ranks (issue 21): the domain decomposed into one box per rank
// (blaze/parallel/decomposition.hpp), each rank a Simulation of the particles it owns plus ghost
// copies of the other ranks' particles within the neighbour list's cutoff (2 r_max + skin) of
// its box, so every pair the list may hold has both its particles on the rank owning either.
// A step on every rank:
//   begin_step          the world and the particles move (ghosts too; their states are replaced next)
//   ghost refresh       each ghost takes its owner's arrays as they now are (every real array the
//                       store keeps; one exchange of the rows, in the order fixed at the last rebuild)
//   rebuild check       collective: when any rank's list no longer holds (a particle moved half the
//                       skin, a moving wall passed its lists' validity) every rank rebuilds:
//                       particles outside the domain are removed (counted by their owner), the
//                       decomposition is rebalanced when the imbalance passes `rebalance_above`,
//                       each particle migrates to the rank whose box holds it with its contact
//                       states, ghosts are sent anew, and each rank reloads its store (sort, list,
//                       contact states by permanent id);
//   end_step            forces (each rank evaluates every pair of its list; a ghost's own force is
//                       left unused) and the post-force integration.
// Pairs are evaluated from both sides (each particle's own copy of a pair's state): with pairs once
// a ghost's entry would hold its owned partner's state. Contact forces are summed in the order of
// the neighbours' permanent ids (SimulationParams::canonical_order), so the run is bitwise the
// same on any number of ranks, and bitwise one process's with canonical_order on. The world is
// replicated on every rank.
// Between rebuilds no particle moves in memory, so the ghosts' places stay fixed.
// Without MPI (or on one rank) it is the plain Simulation with the same step order.
// What a run's output reads (sample, world_loads, size, removed and inserted counters: RunLog,
// `blaze run`) is reduced over the ranks, each counting only its own particles (Simulation::
// count_only: a pair with a ghost counts on the rank of its lower id), in rank order, so every
// rank gets the same numbers and the guards stop every rank together. Feeders (pipeline/
// feeder.hpp) run on every rank alike: spheres_in_box gathers what is present from all ranks,
// every rank places the same batch, and insert() keeps each rank's part with the ids one process
// would give.
#pragma once
#include <algorithm>
#include <map>
#include <memory>
#include <numeric>
#include <stdexcept>
#include <string>
#include <vector>
#include <filesystem>
#include "blaze/io/checkpoint.hpp"
#include "pipeline/parallel/migration.hpp"
#include "pipeline/simulation.hpp"

namespace blaze {

template <class Sim>
class DistributedSimulation {
 public:
  using Real = typename Sim::Real;
  using space_type = typename Sim::space_type;

  // Every rank passes the whole initial state (the same on each); each keeps its box's part.
  template <class Laws, class Shape>
  DistributedSimulation(const Communicator& comm, const SimulationParams<Real>& params, const Laws& laws, const World<Real>& world,
                        const ParticleState<Real>& all, const Shape& shape, DecompositionKind kind = DecompositionKind::bisection,
                        double rebalance_above = 1.2)
      : comm_(comm), kind_(kind), rebalance_above_(rebalance_above), params_(check(params)) {
    Real r_max = params.max_radius;
    for (Real r : all.radius) r_max = std::max(r_max, r);
    for (Index id : all.id) next_id_ = std::max(next_id_, id + 1);
    reach_ = 2 * static_cast<double>(r_max) + static_cast<double>(params.skin);
    lo_ = vec_cast<double>(params.domain_lo), hi_ = vec_cast<double>(params.domain_hi);
    std::vector<Vec3<double>> x(all.size());
    for (std::size_t k = 0; k < all.size(); ++k) x[k] = vec_cast<double>(all.position[k]);
    decomposition_ = Decomposition::make(kind_, lo_, hi_, comm_.size(), params.periodic, x);
    std::size_t owned = 0;
    const std::vector<Index> local = place(x, all.id, owned);
    ParticleState<Real> mine = select_state(all, local);
    SimulationParams<Real> p = params_;
    p.max_radius = r_max, p.canonical_order = true;
    sim_ = std::make_unique<Sim>(p, laws, world, mine, shape);
    owned_ids_.assign(mine.id.begin(), mine.id.begin() + static_cast<std::ptrdiff_t>(owned));
    plan_exchange(mine.id, owned);
  }

  // The run continued from a checkpoint that any number of ranks wrote (write_checkpoint(): the
  // parts `path`.part<k>of<n>): every rank reads every part and keeps its box's particles, with
  // their contact states, and ghosts; the next step is bitwise the step the writers would have
  // taken (canonical order), on any number of ranks.
  template <class Laws, class Shape>
  DistributedSimulation(const Communicator& comm, const SimulationParams<Real>& params, const Laws& laws, const World<Real>& world,
                        const std::string& path, const Shape& shape, DecompositionKind kind = DecompositionKind::bisection,
                        double rebalance_above = 1.2)
      : comm_(comm), kind_(kind), rebalance_above_(rebalance_above), params_(check(params)) {
    const std::vector<std::string> files = checkpoint_files(path);
    ParticleRecords<Real> all;
    SimulationSnapshot<Real> counters;
    for (std::size_t k = 0; k < files.size(); ++k) {
      const Checkpoint<Real> c = read_checkpoint<Real>(files[k]);
      if (k == 0) counters = c.snapshot, text_ = c.text, feeders_ = c.feeders;
      else if (c.snapshot.steps != counters.steps)
        throw CheckpointError(files[k] + ": written at step " + std::to_string(c.snapshot.steps) + ", part 0 at step " +
                              std::to_string(counters.steps));
      else
        counters.removed_count += c.snapshot.removed_count, counters.removed_mass += c.snapshot.removed_mass,
            counters.removed_energy += c.snapshot.removed_energy, counters.inserted_count += c.snapshot.inserted_count,
            counters.inserted_mass += c.snapshot.inserted_mass, counters.inserted_energy += c.snapshot.inserted_energy,
            counters.inserted_kinetic += c.snapshot.inserted_kinetic;
      next_id_ = std::max(next_id_, c.snapshot.next_id);
      append_records(all, ParticleRecords<Real>{c.snapshot.store, c.snapshot.contacts});
    }
    Real r_max = params.max_radius;
    for (Real r : all.store.reals.at(StoreSnapshot<Real>::kRadiusField)) r_max = std::max(r_max, r);
    reach_ = 2 * static_cast<double>(r_max) + static_cast<double>(params.skin);
    lo_ = vec_cast<double>(params.domain_lo), hi_ = vec_cast<double>(params.domain_hi);
    std::vector<Vec3<double>> x(all.size());
    for (std::size_t k = 0; k < all.size(); ++k) x[k] = record_position(all.store, k);
    decomposition_ = Decomposition::make(kind_, lo_, hi_, comm_.size(), params.periodic, x);
    std::size_t owned = 0;
    const std::vector<Index> local = place(x, all.store.id, owned);
    const std::vector<Index> owned_part(local.begin(), local.begin() + static_cast<std::ptrdiff_t>(owned));
    ParticleRecords<Real> mine = select_records(all.store, all.contacts, owned_part);
    append_records(mine, select_records(all.store, all.contacts, std::vector<Index>(local.begin() + static_cast<std::ptrdiff_t>(owned), local.end()), false));
    SimulationSnapshot<Real> snap = counters;
    snap.store = mine.store, snap.contacts = mine.contacts;
    if (comm_.rank() == 0)
      removed_ += counters.removed_count, removed_mass_ += counters.removed_mass, removed_energy_ += counters.removed_energy,
          inserted_count_ += counters.inserted_count, inserted_mass_ += counters.inserted_mass,
          inserted_energy_ += counters.inserted_energy, inserted_kinetic_ += counters.inserted_kinetic;
    SimulationParams<Real> p = params_;
    p.max_radius = r_max, p.canonical_order = true;
    sim_ = std::make_unique<Sim>(p, laws, world, snap, shape);
    owned_ids_.assign(mine.store.id.begin(), mine.store.id.begin() + static_cast<std::ptrdiff_t>(owned));
    plan_exchange(mine.store.id, owned);
  }

  // Collective: each rank writes its particles (owned, with their contact states) and counters to
  // `path`.part<rank>of<ranks> (io/checkpoint.hpp: atomically, checksummed); returns when all have,
  // or throws on every rank when any could not (naming the first rank's error).
  void write_checkpoint(const std::string& path, const std::string& text = "", const std::string& feeders = "") {
    // at a rebuild, as one process's checkpoint (Simulation::snapshot): periodic particles wrapped
    // at the same step, so a one-rank run of the plain Simulation stays bitwise this one
    rebuild();
    const StoreSnapshot<Real> store = sim_->store_snapshot();
    const ContactSnapshot<Real> contacts = sim_->contact_snapshot();
    const ParticleRecords<Real> r = select_records(store, contacts, rows_of(store.id, owned_ids_));
    SimulationSnapshot<Real> s;
    s.store = r.store, s.contacts = r.contacts, s.steps = steps(), s.removed_count = removed_;
    s.removed_mass = removed_mass_, s.removed_energy = removed_energy_, s.next_id = next_id_;
    s.inserted_count = inserted_count_, s.inserted_mass = inserted_mass_, s.inserted_energy = inserted_energy_,
    s.inserted_kinetic = inserted_kinetic_;
    s.initial_count = static_cast<Index>(r.size());
    std::string error;
    try {
      blaze::write_checkpoint(part_path(path, comm_.rank(), comm_.size()), s, text, feeders);
    } catch (const std::exception& e) {
      error = e.what();
    }
    for (const std::string& e : comm_.all_gather_bytes(error))
      if (!e.empty()) throw CheckpointError("distributed checkpoint: " + e);
  }
  static std::string part_path(const std::string& path, int rank, int ranks) {
    return path + ".part" + std::to_string(rank) + "of" + std::to_string(ranks);
  }
  // How many parts the checkpoint at `path` has (its files `path`.part0of<n>).
  static int checkpoint_parts(const std::string& path) {
    const std::filesystem::path p(path);
    const std::filesystem::path dir = p.has_parent_path() ? p.parent_path() : std::filesystem::path(".");
    const std::string stem = p.filename().string() + ".part0of";
    int parts = 0;
    std::error_code ec;
    for (const auto& e : std::filesystem::directory_iterator(dir, ec)) {
      const std::string name = e.path().filename().string();
      if (name.rfind(stem, 0) == 0 && name.size() > stem.size() && name.find_first_not_of("0123456789", stem.size()) == std::string::npos) {
        if (parts) throw CheckpointError(path + ": parts of more than one checkpoint (" + stem + std::to_string(parts) + " and " + name + ")");
        parts = std::stoi(name.substr(stem.size()));
      }
    }
    if (parts < 1) throw CheckpointError(path + ": no checkpoint parts (" + stem + "<n>) in " + dir.string());
    return parts;
  }
  // The files of the checkpoint at `path`: its parts, or the one file a single process wrote there
  // (a run of the build without MPI continues on any number of ranks).
  static std::vector<std::string> checkpoint_files(const std::string& path) {
    std::error_code ec;
    if (std::filesystem::is_regular_file(path, ec)) return {path};
    const int parts = checkpoint_parts(path);
    std::vector<std::string> out;
    for (int k = 0; k < parts; ++k) out.push_back(part_path(path, k, parts));
    return out;
  }

  Sim& local() { return *sim_; }
  const Decomposition& decomposition() const { return decomposition_; }
  const Communicator& communicator() const { return comm_; }
  std::uint64_t steps() const { return sim_->steps(); }
  // Particles this rank owns, and over all ranks.
  Index owned() const { return static_cast<Index>(owned_ids_.size()); }
  long total() const { return comm_.sum(static_cast<long>(owned_ids_.size())); }
  Index removed_count() const { return static_cast<Index>(comm_.sum(static_cast<long>(removed_))); }
  std::uint64_t rebuilds() const { return rebuilds_; }
  std::uint64_t rebalances() const { return rebalances_; }
  // A restarted run's text and feeders' state, as part 0 holds them (empty for a new run).
  const std::string& restart_text() const { return text_; }
  const std::string& restart_feeders() const { return feeders_; }

  // ---- what a run's output reads: collective, the same numbers on every rank ----
  double time() const { return sim_->time(); }
  Index size() const { return static_cast<Index>(total()); }
  Real max_radius() const { return sim_->max_radius(); }
  double removed_mass() const { return sum_in_rank_order({removed_mass_})[0]; }
  double removed_energy() const { return sum_in_rank_order({removed_energy_})[0]; }
  Index inserted_count() const { return static_cast<Index>(comm_.sum(static_cast<long>(inserted_count_))); }
  double inserted_mass() const { return sum_in_rank_order({inserted_mass_})[0]; }
  double inserted_energy() const { return sum_in_rank_order({inserted_energy_})[0]; }
  double inserted_kinetic() const { return sum_in_rank_order({inserted_kinetic_})[0]; }
  bool keeps_energy_ledger() const { return sim_->keeps_energy_ledger(); }
  using Sample = typename Sim::Sample;
  using WorldLoad = typename Sim::WorldLoad;
  // Simulation::sample over all ranks: sums, and the deepest penetration (the lowest id on a tie).
  Sample sample(double penetration_limit) {
    Sample s = sim_->sample(penetration_limit);
    std::vector<double> v = {s.energies.translational, s.energies.rotational, s.energies.potential, s.mass, s.stored.pairs,
                             s.stored.walls, static_cast<double>(s.stored.wall_contacts), static_cast<double>(s.vertex_face_sides),
                             static_cast<double>(s.edge_edge_sides), static_cast<double>(s.penetration.over), s.drive_work,
                             s.dissipated_pair, s.thesis_estimate};
    for (double d : s.dissipated_walls) v.push_back(d);
    v = sum_in_rank_order(v);
    s.energies = {v[0], v[1], v[2]};
    s.mass = v[3];
    s.stored = {v[4], v[5], std::lround(v[6])};
    s.vertex_face_sides = std::lround(v[7]), s.edge_edge_sides = std::lround(v[8]);
    s.vertex_face = s.vertex_face_sides / 2, s.edge_edge = s.edge_edge_sides / 2;
    s.penetration.over = std::lround(v[9]);
    s.drive_work = v[10], s.dissipated_pair = v[11], s.thesis_estimate = v[12];
    for (int c = 0; c < kContactClasses; ++c) s.dissipated_walls[c] = v[13 + static_cast<std::size_t>(c)];
    const std::vector<std::pair<double, long>> worst = comm_.all_gather(std::pair<double, long>{s.penetration.worst, static_cast<long>(s.penetration.worst_id)});
    for (const auto& [d, id] : worst)
      if (d > s.penetration.worst || (d == s.penetration.worst && id >= 0 && (s.penetration.worst_id < 0 || id < s.penetration.worst_id)))
        s.penetration.worst = d, s.penetration.worst_id = static_cast<Index>(id);
    return s;
  }
  // Simulation::world_loads over all ranks.
  std::vector<WorldLoad> world_loads(const std::vector<int>& objects) {
    const std::vector<WorldLoad> mine = sim_->world_loads(objects);
    std::vector<double> v;
    for (const auto& l : mine) v.insert(v.end(), {l.force.x, l.force.y, l.force.z, l.torque.x, l.torque.y, l.torque.z});
    v = sum_in_rank_order(v);
    std::vector<WorldLoad> out(mine.size());
    for (std::size_t k = 0; k < out.size(); ++k)
      out[k] = {{v[6 * k], v[6 * k + 1], v[6 * k + 2]}, {v[6 * k + 3], v[6 * k + 4], v[6 * k + 5]}};
    return out;
  }

  // ---- feeders (pipeline/feeder.hpp), run alike on every rank ----
  // The centres and bounding radii in [lo, hi] on every rank (owned and ghosts: a particle may come
  // twice, which changes no overlap test), gathered in rank order: the same on every rank.
  void particles_in_box(const Vec3<double>& lo, const Vec3<double>& hi, std::vector<Vec3<double>>& centre, std::vector<double>& radius) {
    std::vector<Vec3<double>> c;
    std::vector<double> r;
    sim_->particles_in_box(lo, hi, c, r);
    std::string mine;
    put_array(mine, c);
    put_array(mine, r);
    centre.clear(), radius.clear();
    const std::vector<std::string> all = comm_.all_gather_bytes(mine);
    for (std::size_t k = 0; k < all.size(); ++k) {
      ByteReader<CommunicatorError> in(all[k], "particles in the box from rank " + std::to_string(k) + ": ");
      const std::vector<Vec3<double>> ck = in.template array<Vec3<double>>();
      const std::vector<double> rk = in.template array<double>();
      centre.insert(centre.end(), ck.begin(), ck.end()), radius.insert(radius.end(), rk.begin(), rk.end());
    }
  }
  // The same as x, y, z, r in `out` (4 reals a particle, on the particles' space); returns how many.
  Index spheres_in_box(const Vec3<double>& lo, const Vec3<double>& hi, Buffer<Real, space_type>& out) {
    std::vector<Vec3<double>> c;
    std::vector<double> r;
    particles_in_box(lo, hi, c, r);
    std::vector<Real> v(4 * c.size());
    for (std::size_t k = 0; k < c.size(); ++k)
      v[4 * k] = static_cast<Real>(c[k].x), v[4 * k + 1] = static_cast<Real>(c[k].y), v[4 * k + 2] = static_cast<Real>(c[k].z),
               v[4 * k + 3] = static_cast<Real>(r[k]);
    copy_in(out, v);
    return static_cast<Index>(c.size());
  }
  // A batch every rank holds alike: ids as one process gives them (in batch order from the next
  // id), each rank inserts the particles its box holds, then a collective rebuild sends ghosts.
  void insert(ParticleState<Real> add) {
    ParticleState<Real> mine;
    std::vector<Index> which;
    for (std::size_t k = 0; k < add.size(); ++k) {
      add.id[k] = next_id_++;
      if (decomposition_.owner(vec_cast<double>(add.position[k])) == comm_.rank()) which.push_back(static_cast<Index>(k));
    }
    mine = select_state(add, which);
    const double before_mass = sim_->inserted_mass(), before_energy = sim_->inserted_energy(), before_kinetic = sim_->inserted_kinetic();
    if (!mine.id.empty()) sim_->insert(mine, true);
    inserted_count_ += static_cast<Index>(mine.size());
    inserted_mass_ += sim_->inserted_mass() - before_mass;
    inserted_energy_ += sim_->inserted_energy() - before_energy;
    inserted_kinetic_ += sim_->inserted_kinetic() - before_kinetic;
    owned_ids_.insert(owned_ids_.end(), mine.id.begin(), mine.id.end());
    std::sort(owned_ids_.begin(), owned_ids_.end());
    rebuild();
  }

  // ---- what `blaze run`'s loop reads besides (apps/blaze/run_scene.hpp) ----
  std::uint64_t neighbour_builds() const { return rebuilds_ + 1; }  // the first build, then each collective rebuild
  auto& timer() { return sim_->timer(); }
  bool world_moves() const { return sim_->world_moves(); }
  auto world_poses() const { return sim_->world_poses(); }
  // The rank's own particles (its piece of a frame), in the store's order, and with periodic axes
  // their unwrapped positions.
  ParticleState<Real> piece(std::vector<Vec3<double>>& unwrapped) const {
    const ParticleState<Real> s = sim_->state();
    const std::vector<Vec3<double>> u = sim_->unwrapped_positions(s);
    const std::vector<Index> which = rows_of(s.id, owned_ids_);
    unwrapped.clear();
    if (!u.empty())
      for (Index k : which) unwrapped.push_back(u[static_cast<std::size_t>(k)]);
    return select_state(s, which);
  }
  // The last good state kept at a sample (Simulation::keep_state, each rank its own particles as
  // they were then) and, when a guard stops the run, all of it on rank 0 (collective).
  void keep_state() {
    sim_->keep_state();
    kept_ids_ = owned_ids_;
  }
  ParticleState<Real> kept_state() const {
    const ParticleState<Real> s = sim_->kept_state();
    return gather(select_state(s, rows_of(s.id, kept_ids_)), 0);
  }

  // Every rank's particles (owned) in permanent-id order on rank 0 (`root`), none on the others:
  // frames and the last good state written by one rank.
  ParticleState<Real> gathered_state(int root = 0) const { return gather(owned_state(), root); }

  void step() {
    sim_->begin_step();
    refresh_ghosts();
    const long code = comm_.max(static_cast<long>(sim_->needs_rebuild()));
    if (code == 2)  // on every rank: the guard's report and the last good state are collective
      throw NonFiniteState("a position is not finite at step " + std::to_string(steps() + 1) + " (a run over ranks: the particle's rank "
                           "found it)", steps() + 1, -1);
    if (code == 1) rebuild();
    sim_->end_step();
  }
  void run(std::uint64_t steps) {
    for (std::uint64_t s = 0; s < steps; ++s) step();
  }

  // The particles this rank owns, in permanent-id order.
  ParticleState<Real> owned_state() const {
    const ParticleState<Real> s = sim_->state();
    std::vector<Index> which = rows_of(s.id, owned_ids_);
    std::sort(which.begin(), which.end(), [&](Index a, Index b) { return s.id[static_cast<std::size_t>(a)] < s.id[static_cast<std::size_t>(b)]; });
    return select_state(s, which);
  }

 private:
  static const SimulationParams<Real>& check(const SimulationParams<Real>& p) {
    if (p.pairs != PairEvaluation::both_sides)
      throw std::invalid_argument("distributed run: pairs must be evaluated from both sides (SimulationParams::pairs = both_sides)");
    return p;
  }
  // x lies in the domain along every axis that is not periodic (a periodic one wraps).
  bool inside_domain(const Vec3<double>& x) const {
    const double xa[3] = {x.x, x.y, x.z}, la[3] = {lo_.x, lo_.y, lo_.z}, ha[3] = {hi_.x, hi_.y, hi_.z};
    for (int a = 0; a < 3; ++a)
      if (!((params_.periodic >> a) & 1u) && !(xa[a] >= la[a] && xa[a] < ha[a])) return false;
    return true;
  }
  // The rows whose permanent id is in `sorted` (a rank's own particles among its store's).
  static std::vector<Index> rows_of(const std::vector<Index>& id, const std::vector<Index>& sorted) {
    std::vector<Index> rows;
    for (std::size_t k = 0; k < id.size(); ++k)
      if (std::binary_search(sorted.begin(), sorted.end(), id[k])) rows.push_back(static_cast<Index>(k));
    return rows;
  }
  ParticleState<Real> gather(const ParticleState<Real>& part, int root) const {
    std::string mine;
    pack_state(mine, part);
    const std::vector<std::string> all = comm_.gather_bytes(mine, root);
    ParticleState<Real> out;
    if (comm_.rank() != root) return out;
    for (std::size_t k = 0; k < all.size(); ++k) {
      ByteReader<CommunicatorError> in(all[k], "state from rank " + std::to_string(k) + ": ");
      unpack_state(in, out);
    }
    std::vector<Index> order(out.size());
    std::iota(order.begin(), order.end(), Index{0});
    std::sort(order.begin(), order.end(), [&](Index a, Index b) { return out.id[static_cast<std::size_t>(a)] < out.id[static_cast<std::size_t>(b)]; });
    return select_state(out, order);
  }

  // v summed over the ranks in rank order (the same on every rank).
  std::vector<double> sum_in_rank_order(const std::vector<double>& v) const {
    std::string mine;
    put_array(mine, v);
    std::vector<double> out(v.size(), 0.0);
    const std::vector<std::string> all = comm_.all_gather_bytes(mine);
    for (std::size_t k = 0; k < all.size(); ++k) {
      ByteReader<CommunicatorError> in(all[k], "sums from rank " + std::to_string(k) + ": ");
      const std::vector<double> vk = in.template array<double>();
      if (vk.size() != out.size()) throw CommunicatorError("sums: rank " + std::to_string(k) + " sent " + std::to_string(vk.size()) + " values, not " + std::to_string(out.size()));
      for (std::size_t j = 0; j < out.size(); ++j) out[j] += vk[j];
    }
    return out;
  }
  // A particle leaving the domain at a rebuild, counted by its owner with its mass and its
  // translational kinetic plus potential energy (as Simulation counts its removals).
  void count_removed(const StoreSnapshot<Real>& store, std::size_t k) {
    ++removed_;
    const double m = 1.0 / static_cast<double>(store.reals.at(StoreSnapshot<Real>::kInverseMassField)[k]);
    Vec3<double> v;
    v.x = static_cast<double>(store.reals.at(StoreSnapshot<Real>::kVelocityField)[k]);
    v.y = static_cast<double>(store.reals.at(StoreSnapshot<Real>::kVelocityField + 1)[k]);
    v.z = static_cast<double>(store.reals.at(StoreSnapshot<Real>::kVelocityField + 2)[k]);
    removed_mass_ += m;
    removed_energy_ += 0.5 * m * dot(v, v) - m * dot(vec_cast<double>(params_.gravity), record_position(store, k));
  }
  static void pack_state(std::string& out, const ParticleState<Real>& s) {
    put_array(out, s.position), put_array(out, s.velocity), put_array(out, s.angular_velocity), put_array(out, s.orientation);
    put_array(out, s.radius), put_array(out, s.mass), put_array(out, s.inertia), put_array(out, s.material), put_array(out, s.type);
    put_array(out, s.id);
  }
  static void unpack_state(ByteReader<CommunicatorError>& in, ParticleState<Real>& s) {
    const auto add = [&](auto& field) {
      using T = typename std::decay_t<decltype(field)>::value_type;
      const std::vector<T> v = in.template array<T>();
      field.insert(field.end(), v.begin(), v.end());
    };
    add(s.position), add(s.velocity), add(s.angular_velocity), add(s.orientation), add(s.radius), add(s.mass), add(s.inertia);
    add(s.material), add(s.type), add(s.id);
  }
  static ParticleState<Real> select_state(const ParticleState<Real>& s, const std::vector<Index>& which) {
    ParticleState<Real> out;
    for (Index k : which) {
      const auto u = static_cast<std::size_t>(k);
      out.position.push_back(s.position[u]), out.velocity.push_back(s.velocity[u]), out.angular_velocity.push_back(s.angular_velocity[u]);
      out.orientation.push_back(s.orientation[u]), out.radius.push_back(s.radius[u]), out.mass.push_back(s.mass[u]);
      out.inertia.push_back(s.inertia[u]), out.material.push_back(s.material[u]), out.type.push_back(s.type[u]), out.id.push_back(s.id[u]);
    }
    return out;
  }

  // This rank's particles among all (positions x, ids): those its box holds in id order (`owned`
  // of them), then the ghosts, in (owner rank, id) order: the order each owner sends them in. A
  // particle outside the domain is removed here (counted once, on rank 0), as a one-process run's
  // first rebuild does.
  std::vector<Index> place(const std::vector<Vec3<double>>& x, const std::vector<Index>& id, std::size_t& owned) {
    std::vector<Index> order(x.size());
    std::iota(order.begin(), order.end(), Index{0});
    std::sort(order.begin(), order.end(), [&](Index a, Index b) { return id[static_cast<std::size_t>(a)] < id[static_cast<std::size_t>(b)]; });
    Index outside = 0;
    order.erase(std::remove_if(order.begin(), order.end(),
                               [&](Index k) { return !inside_domain(x[static_cast<std::size_t>(k)]) && (++outside, true); }),
                order.end());
    if (comm_.rank() == 0) removed_ += outside;
    std::vector<Index> local;
    for (Index k : order)
      if (decomposition_.owner(x[static_cast<std::size_t>(k)]) == comm_.rank()) local.push_back(k);
    owned = local.size();
    for (int r = 0; r < comm_.size(); ++r)
      for (Index k : order)
        if (r != comm_.rank() && decomposition_.owner(x[static_cast<std::size_t>(k)]) == r &&
            Decomposition::distance2(x[static_cast<std::size_t>(k)], decomposition_.box(comm_.rank())) <= reach_ * reach_)
          local.push_back(k);
    return local;
  }

  // The exchange's plan from the local store's ids (owned first, `owned` of them, then ghosts in
  // (owner rank, id) order): each rank sends its owned particles near another rank's box in id
  // order, and its ghosts from rank r are those in the same order.
  void plan_exchange(const std::vector<Index>& ids_in_order, std::size_t owned) {
    const std::vector<Index> now = sim_->ids();  // the store's order after its sort
    std::vector<std::uint8_t> counted(now.size());
    for (std::size_t k = 0; k < now.size(); ++k) counted[k] = std::binary_search(owned_ids_.begin(), owned_ids_.end(), now[k]) ? 1 : 0;
    sim_->count_only(counted);
    std::map<Index, Index> at;
    for (std::size_t k = 0; k < now.size(); ++k) at[now[k]] = static_cast<Index>(k);
    send_.assign(static_cast<std::size_t>(comm_.size()), {});
    recv_.assign(static_cast<std::size_t>(comm_.size()), {});
    const ParticleState<Real> s = sim_->state();
    std::map<Index, Vec3<double>> x;
    for (std::size_t k = 0; k < s.size(); ++k) x[s.id[k]] = vec_cast<double>(s.position[k]);
    for (std::size_t k = 0; k < owned; ++k)
      decomposition_.near(x.at(ids_in_order[k]), reach_, comm_.rank(), [&](int r) { send_[static_cast<std::size_t>(r)].push_back(at.at(ids_in_order[k])); });
    for (std::size_t k = owned; k < ids_in_order.size(); ++k)
      recv_[static_cast<std::size_t>(decomposition_.owner(x.at(ids_in_order[k])))].push_back(at.at(ids_in_order[k]));
  }

  void refresh_ghosts() {
    if (comm_.size() == 1) return;
    std::vector<std::string> out(static_cast<std::size_t>(comm_.size()));
    std::vector<Real> rows;
    for (int r = 0; r < comm_.size(); ++r) {
      if (send_[static_cast<std::size_t>(r)].empty()) continue;
      sim_->download_rows(send_[static_cast<std::size_t>(r)], rows);
      put_array(out[static_cast<std::size_t>(r)], rows);
    }
    const std::vector<std::string> in = comm_.exchange(out);
    for (int r = 0; r < comm_.size(); ++r) {
      const std::vector<Index>& to = recv_[static_cast<std::size_t>(r)];
      if (to.empty()) continue;
      ByteReader<CommunicatorError> bytes(in[static_cast<std::size_t>(r)], "ghost rows from rank " + std::to_string(r) + ": ");
      sim_->upload_rows(to, bytes.array<Real>());
    }
  }

  void rebuild() {
    ++rebuilds_;
    const StoreSnapshot<Real> store = sim_->store_snapshot();
    const ContactSnapshot<Real> contacts = sim_->contact_snapshot();
    std::vector<Index> keep;
    for (std::size_t k = 0; k < store.id.size(); ++k) {
      if (!std::binary_search(owned_ids_.begin(), owned_ids_.end(), store.id[k])) continue;
      if (inside_domain(record_position(store, k))) keep.push_back(static_cast<Index>(k));
      else count_removed(store, k);
    }
    const ParticleRecords<Real> owned = select_records(store, contacts, keep);
    const std::vector<long> counts = comm_.all_gather(static_cast<long>(owned.size()));
    if (comm_.size() > 1 && Decomposition::imbalance(counts) > rebalance_above_) {
      std::vector<Vec3<double>> x(owned.size());
      for (std::size_t k = 0; k < owned.size(); ++k) x[k] = record_position(owned.store, k);
      decomposition_ = balanced_decomposition(comm_, kind_, lo_, hi_, params_.periodic, x);
      ++rebalances_;
    }
    ParticleRecords<Real> mine = migrate(comm_, decomposition_, owned);
    const std::size_t n_owned = mine.size();
    const ParticleRecords<Real> halo = ghosts(comm_, decomposition_, mine, reach_);
    owned_ids_ = mine.store.id;
    append_records(mine, halo);
    sim_->reload(mine.store, mine.contacts);
    plan_exchange(mine.store.id, n_owned);
  }

  const Communicator& comm_;
  DecompositionKind kind_;
  double rebalance_above_;
  SimulationParams<Real> params_;
  double reach_ = 0;
  Vec3<double> lo_, hi_;
  Decomposition decomposition_;
  std::unique_ptr<Sim> sim_;
  std::vector<Index> owned_ids_;                      // sorted
  std::vector<Index> kept_ids_;                       // owned_ids_ at the last keep_state()
  std::vector<std::vector<Index>> send_, recv_;       // per rank: store indices
  Index removed_ = 0, next_id_ = 0, inserted_count_ = 0;
  double removed_mass_ = 0, removed_energy_ = 0, inserted_mass_ = 0, inserted_energy_ = 0, inserted_kinetic_ = 0;
  std::string text_, feeders_;  // a restart's (part 0)
  std::uint64_t rebuilds_ = 0, rebalances_ = 0;
};

}  // namespace blaze
