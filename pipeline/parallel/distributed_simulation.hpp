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

  // Every rank passes the whole initial state (the same on each); each keeps its box's part.
  template <class Laws, class Shape>
  DistributedSimulation(const Communicator& comm, const SimulationParams<Real>& params, const Laws& laws, const World<Real>& world,
                        const ParticleState<Real>& all, const Shape& shape, DecompositionKind kind = DecompositionKind::bisection,
                        double rebalance_above = 1.2)
      : comm_(comm), kind_(kind), rebalance_above_(rebalance_above), params_(check(params)) {
    Real r_max = params.max_radius;
    for (Real r : all.radius) r_max = std::max(r_max, r);
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
    const int parts = checkpoint_parts(path);
    ParticleRecords<Real> all;
    SimulationSnapshot<Real> counters;
    for (int k = 0; k < parts; ++k) {
      const Checkpoint<Real> c = read_checkpoint<Real>(part_path(path, k, parts));
      if (k == 0) counters = c.snapshot;
      else if (c.snapshot.steps != counters.steps)
        throw CheckpointError(part_path(path, k, parts) + ": written at step " + std::to_string(c.snapshot.steps) + ", part 0 at step " +
                              std::to_string(counters.steps));
      else counters.removed_count += c.snapshot.removed_count;
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
    if (comm_.rank() == 0) removed_ += counters.removed_count;
    SimulationParams<Real> p = params_;
    p.max_radius = r_max, p.canonical_order = true;
    sim_ = std::make_unique<Sim>(p, laws, world, snap, shape);
    owned_ids_.assign(mine.store.id.begin(), mine.store.id.begin() + static_cast<std::ptrdiff_t>(owned));
    plan_exchange(mine.store.id, owned);
  }

  // Collective: each rank writes its particles (owned, with their contact states) and counters to
  // `path`.part<rank>of<ranks> (io/checkpoint.hpp: atomically, checksummed); returns when all have,
  // or throws on every rank when any could not (naming the first rank's error).
  void write_checkpoint(const std::string& path, const std::string& text = "") {
    const StoreSnapshot<Real> store = sim_->store_snapshot();
    const ContactSnapshot<Real> contacts = sim_->contact_snapshot();
    std::vector<Index> mine;
    for (std::size_t k = 0; k < store.id.size(); ++k)
      if (std::binary_search(owned_ids_.begin(), owned_ids_.end(), store.id[k])) mine.push_back(static_cast<Index>(k));
    const ParticleRecords<Real> r = select_records(store, contacts, mine);
    SimulationSnapshot<Real> s;
    s.store = r.store, s.contacts = r.contacts, s.steps = steps(), s.removed_count = removed_;
    s.initial_count = static_cast<Index>(r.size());
    std::string error;
    try {
      blaze::write_checkpoint(part_path(path, comm_.rank(), comm_.size()), s, text);
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

  void step() {
    sim_->begin_step();
    refresh_ghosts();
    const long code = comm_.max(static_cast<long>(sim_->needs_rebuild()));
    if (code == 2) throw std::runtime_error("distributed run: a position is not finite at step " + std::to_string(steps() + 1));
    if (code == 1) rebuild();
    sim_->end_step();
  }
  void run(std::uint64_t steps) {
    for (std::uint64_t s = 0; s < steps; ++s) step();
  }

  // The particles this rank owns, in permanent-id order.
  ParticleState<Real> owned_state() const {
    const ParticleState<Real> s = sim_->state();
    std::vector<Index> which;
    for (std::size_t k = 0; k < s.size(); ++k)
      if (std::binary_search(owned_ids_.begin(), owned_ids_.end(), s.id[k])) which.push_back(static_cast<Index>(k));
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
      else ++removed_;
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
  std::vector<std::vector<Index>> send_, recv_;       // per rank: store indices
  Index removed_ = 0;
  std::uint64_t rebuilds_ = 0, rebalances_ = 0;
};

}  // namespace blaze
