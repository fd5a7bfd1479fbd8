// A feeder: the particles of one [[feed]] (scene.hpp's FeedSpec) inserted into a running
// Simulation (Simulation::insert) at every insertion interval from start to end.
//
// Due: by the insertion at time t the feed owes what its rate delivers up to the next one,
//   N(t) = rate (min(t + interval, end) - start)   (particles; capped by count), or
//   M(t) = mass_rate (min(t + interval, end) - start)   (kg: particles are added while the
//          delivered mass plus half the next particle's stays within M),
// so what could not be placed at one insertion stays due at the next (LIGGGHTS's insert/rate
// drops it instead) and the delivered rate converges to the requested one. What is still due
// after an insertion is its shortfall: counted, and reported by the run (never dropped silently).
//
// Placement: random sequential addition, in parallel rounds. The due particles' sizes are drawn
// in order (SizeDistribution) and each keeps its size until it is placed, so a crowded region does
// not bias the delivered sizes towards the small ones. In a round every particle not yet placed
// draws centres in the region (InsertionRegion::draw; from its own counter-based stream,
// core/counter_random.hpp, so any number of threads gives the same result), up to kDrawsPerRound
// until one is clear of what is there: of the particles present (the simulation's particles near
// the region: Simulation::spheres_in_box) and placed in earlier rounds, of the world
// (WorldOverlapCheck's test, as fills are, with moving objects where they are now) and inside the
// domain.
// That centre is kept when it also overlaps no candidate of the same round before it that passed
// those tests. The rounds run where the particles live (kernels/placement.hpp: on the GPU for a
// GPU run, on all host threads otherwise); after kTries rounds the particles still open stay due
// (the region counts as full until the next insertion). At the low fractions a feed region should
// have, a round places nearly all.
// (Stop 32's one-at-a-time placement took 120% of the steps' time for 1e6 beads on the H200, the
// host's parallel rounds 6-9%.)
//
// State (save()/restore(), in the checkpoint): the size engine, the placement stream's counter,
// the delivered count and mass, the drawn sizes waiting to be placed, the shortfall counters and
// the delivered sizes (for the Kolmogorov-Smirnov distance, SizeDistribution::ks_distance).
#pragma once
#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <random>
#include <sstream>
#include <string>
#include <vector>
#include <limits>
#include <optional>
#include <type_traits>
#include "blaze/core/counter_random.hpp"
#include "blaze/scene/scene.hpp"
#include "blaze/scene/scene_build.hpp"
#include "blaze/exec/buffer.hpp"
#include "blaze/exec/primitives.hpp"
#include "blaze/scene/world_overlap.hpp"
#include "kernels/placement.hpp"
#include "pipeline/world_block_arrays.hpp"

namespace blaze {

template <class Real, class Space = DefaultSpace>
class Feeder {
 public:
  static constexpr int kTries = 50;  // rounds (of kDrawsPerRound centres) before the region counts as full
  // Centres a particle draws in a round until one is clear of what is there (the round's own
  // candidates are checked after). One draw a round took 26 rounds an insertion for the 1e6-bead
  // slab (bench/scenes/feed_box_1m.toml), 8 take 5.
  static constexpr int kDrawsPerRound = 8;
  // Particles a batch needs to be made on all threads (fewer: waking the team costs more).
  static constexpr long kParallelRound = 256;

  // `shapes`: the scene's polyhedron table (null for spheres).
  Feeder(const Scene& s, std::size_t index, const PolyhedronTable<Real>* shapes)
      : s_(s), spec_(s.feeds.at(index)), shapes_(shapes), rng_(spec_.seed), world_(s, 1e-9 * largest_type(s)) {
    every_ = std::max<std::uint64_t>(1, static_cast<std::uint64_t>(std::ceil(spec_.interval / s.dt - 1e-9)));
    first_ = static_cast<std::uint64_t>(std::ceil(spec_.start / s.dt - 1e-9));
    pending_.assign(1, spec_.size.draw(rng_));
  }

  const FeedSpec& spec() const { return spec_; }
  // Batches of more particles than this are made on all threads (tests set 0: every batch is).
  void parallel_from(long candidates) { parallel_round_ = candidates; }
  // Steps between insertions, and whether step k is an insertion.
  std::uint64_t every() const { return every_; }
  bool inserts_at(std::uint64_t k) const {
    return k >= first_ && (k - first_) % every_ == 0 && before_end(k) && !finished();
  }
  // The next insertion at or after step k (~0: none).
  std::uint64_t next_insertion(std::uint64_t k) const {
    if (finished()) return ~std::uint64_t{0};
    const std::uint64_t n = k <= first_ ? first_ : first_ + (k - first_ + every_ - 1) / every_ * every_;
    return before_end(n) ? n : ~std::uint64_t{0};
  }

  // The insertion at the simulation's current step: places what is due, inserts it.
  template <class Sim>
  void feed(Sim& sim) {
    static_assert(std::is_same_v<typename Sim::space_type, Space>, "a feeder places where its simulation's particles live");
    const auto started = std::chrono::steady_clock::now();
    // up to the next insertion, or to the end when there is none (in whole steps, as inserts_at
    // counts: the last insertion owes all that is due by the end)
    const std::uint64_t next = sim.steps() + every_;
    const double span = (before_end(next) ? static_cast<double>(next) * s_.dt : spec_.end) - spec_.start;
    const std::size_t want = due_now(span);
    Vec3<double> lo, hi;
    spec_.region.bounds(lo, hi);
    const double r_max = static_cast<double>(sim.max_radius()), reach = 2 * r_max;
    const Vec3<double> margin{reach, reach, reach};
    // The particles present (found where they live, and left there), binned in cells one largest
    // diameter wide from the region's box less a diameter: the occupied cells.
    Rounds& d = rounds_scratch_;
    const int present = static_cast<int>(sim.spheres_in_box(lo - margin, hi + margin, d.found));
    const std::size_t capacity = static_cast<std::size_t>(present) + want;
    if (capacity > static_cast<std::size_t>(0x7fffffff)) throw std::length_error("feeder: more than 2^31 particles in and near the region");
    SphereCellsView occupied = lay_cells(d.head, d.next, d.sphere, capacity, lo - margin, reach, r_max);
    for_each(Space{}, present, PutFound<Real>{occupied, d.found.data(), 0});
    if (!d.world) d.world.emplace(world_);
    d.world->at_time(s_, static_cast<double>(sim.steps()) * s_.dt);  // (a moving world: where it is now)
    copy_in(d.radius, pending_.data(), want);
    const int due = static_cast<int>(want);
    d.placed.ensure(want), d.centre.ensure(3 * want), d.ok.ensure(want);
    for_each(Space{}, due, Fill<std::uint8_t>{d.placed.data(), 0});
    const auto found_at = std::chrono::steady_clock::now();
    // Rounds of parallel random sequential addition (kernels/placement.hpp): every particle still
    // open draws centres (its own counter-based stream: the same on any number of threads), kept
    // when it is clear of the particles present and placed, of the world and of the domain's
    // faces, and of every candidate of the round before it (so candidates need not be tested one
    // by one). The open ones draw again, up to kTries rounds; then the region counts as full until
    // the next insertion. The rounds run where the particles live; a round reads back one number
    // (is any particle left?), the placed centres come back at the end.
    bool open = due > 0;
    for (int round = 0; round < kTries && open; ++round) {
      ++rounds_;
      for_each(Space{}, due, DrawCandidates{occupied, d.world->view(), spec_.region, s_.domain_lo, s_.domain_hi, spec_.seed, draws_,
                                            kDrawsPerRound, d.radius.data(), d.placed.data(), d.centre.data(), d.ok.data()});
      draws_ += static_cast<std::uint64_t>(due);
      const SphereCellsView fresh = lay_cells(d.fresh_head, d.fresh_next, d.fresh_sphere, want, lo - margin, reach, r_max);
      for_each(Space{}, due, PutCandidates{fresh, d.radius.data(), d.centre.data(), d.ok.data()});
      for_each(Space{}, due, TestAgainstEarlier{fresh, d.radius.data(), d.centre.data(), d.ok.data()});
      for_each(Space{}, due, KeepCandidates{occupied, d.radius.data(), d.centre.data(), d.ok.data(), present, d.placed.data()});
      open = reduce_max(Space{}, due, StillOpen{d.placed.data()}, 0) > 0;
    }
    const std::vector<std::uint8_t> placed = to_host(d.placed, want);
    const std::vector<double> centre = to_host(d.centre, 3 * want);
    std::vector<Vec3<double>>& at = scratch_.at;
    at.resize(want);
    for (std::size_t k = 0; k < want; ++k) at[k] = {centre[3 * k], centre[3 * k + 1], centre[3 * k + 2]};
    // the placed, in the order drawn; the rest stay pending, in order, for the next insertion
    std::vector<std::size_t>& chosen = scratch_.chosen;
    std::vector<double>& left = scratch_.left;
    chosen.clear(), left.clear();
    for (std::size_t k = 0; k < pending_.size(); ++k) {
      if (k >= want || !placed[k]) {
        left.push_back(pending_[k]);
        continue;
      }
      chosen.push_back(k);
      delivered_.push_back(pending_[k]);
      mass_ += mass_of(pending_[k]);
    }
    ParticleState<Real> batch;
    make_batch(batch, chosen, at);
    inserted_ += static_cast<long>(chosen.size());
    pending_.swap(left);
    if (pending_.empty()) pending_.push_back(spec_.size.draw(rng_));
    // what is still due: a shortfall (the run reports it)
    const double left_due = spec_.rate > 0 ? static_cast<double>(due_count(span) - inserted_)
                                           : (spec_.mass_rate * span - mass_) / mass_of(pending_.front());
    shortfall_now_ = left_due >= 1 ? static_cast<long>(left_due) : 0;
    if (shortfall_now_ > 0) ++short_insertions_;
    const auto placed_at = std::chrono::steady_clock::now();
    sim.insert(batch);
    place_seconds_ += std::chrono::duration<double>(placed_at - started).count();
    find_seconds_ += std::chrono::duration<double>(found_at - started).count();
    ++insertions_;
    insert_seconds_ += std::chrono::duration<double>(std::chrono::steady_clock::now() - placed_at).count();
  }
  // Wall time so far (s) in finding the particles present and placing (the host's part), and in
  // Simulation::insert (appending to the store and re-sorting).
  double place_seconds() const { return place_seconds_; }
  // Of place_seconds: finding the particles present (read from the store) and binning them.
  double find_seconds() const { return find_seconds_; }
  // Insertions so far in this process, and the placement rounds they took.
  long insertions() const { return insertions_; }
  long rounds() const { return rounds_; }
  double insert_seconds() const { return insert_seconds_; }

  long inserted() const { return inserted_; }
  double inserted_mass() const { return mass_; }
  // Particles still due after the last insertion (0: it placed all), and insertions that fell short.
  long shortfall() const { return shortfall_now_; }
  long short_insertions() const { return short_insertions_; }
  // What the feed owed by its end and did not place (particles; by mass: the missing mass over the
  // mean delivered particle's). Meaningful once the feed has ended.
  long undelivered() const {
    if (spec_.rate > 0) {
      long due = static_cast<long>(std::floor(spec_.rate * (spec_.end - spec_.start) + 1e-9));
      if (spec_.count > 0) due = std::min(due, spec_.count);
      return std::max(0L, due - inserted_);
    }
    if (spec_.count > 0 && inserted_ >= spec_.count) return 0;
    const double missing = spec_.mass_rate * (spec_.end - spec_.start) - mass_;
    const double mean = inserted_ > 0 ? mass_ / static_cast<double>(inserted_) : mass_of(pending_.front());
    return missing > 0.5 * mean ? static_cast<long>(std::lround(missing / mean)) : 0;
  }
  bool finished() const { return spec_.count > 0 && inserted_ >= spec_.count; }
  // The delivered sizes' Kolmogorov-Smirnov distance from the requested distribution.
  double ks_distance() const { return spec_.size.ks_distance(delivered_); }
  const std::vector<double>& delivered() const { return delivered_; }

  // The feeder's state as bytes (the checkpoint's), and back. Layout 2 (this one): "feeder2\n",
  // the size engine's text and '\n', then inserted, mass, shortfall, short insertions, placement
  // draws, and the pending and delivered radii (count, then doubles). Layout 1 (stop 32's, one
  // drawn radius where the pending list is now) is still read; its feed then continues with the
  // placement of this version.
  std::string save() const {
    std::ostringstream engine;
    engine << rng_;
    std::string out = kLayout2 + engine.str() + '\n';
    auto put = [&](const auto& v) { out.append(reinterpret_cast<const char*>(&v), sizeof v); };
    auto put_all = [&](const std::vector<double>& v) {
      put(static_cast<std::uint64_t>(v.size()));
      out.append(reinterpret_cast<const char*>(v.data()), v.size() * sizeof(double));
    };
    put(static_cast<std::int64_t>(inserted_));
    put(mass_);
    put(static_cast<std::int64_t>(shortfall_now_));
    put(static_cast<std::int64_t>(short_insertions_));
    put(draws_);
    put_all(pending_);
    put_all(delivered_);
    return out;
  }
  void restore(const std::string& bytes) {
    const bool layout2 = bytes.compare(0, kLayout2.size(), kLayout2) == 0;
    const std::size_t from = layout2 ? kLayout2.size() : 0;
    const auto line = bytes.find('\n', from);
    if (line == std::string::npos) throw std::runtime_error("checkpoint: a feeder's state is corrupt");
    std::istringstream engine(bytes.substr(from, line - from));
    engine >> rng_;
    if (!engine) throw std::runtime_error("checkpoint: a feeder's random engine is corrupt");
    std::size_t at = line + 1;
    auto get = [&](auto& v) {
      if (bytes.size() - at < sizeof v) throw std::runtime_error("checkpoint: a feeder's state is truncated");
      std::memcpy(&v, bytes.data() + at, sizeof v);
      at += sizeof v;
    };
    auto get_all = [&](std::vector<double>& v) {
      std::uint64_t n = 0;
      get(n);
      if ((bytes.size() - at) / sizeof(double) < n) throw std::runtime_error("checkpoint: a feeder's radii are truncated");
      v.resize(n);
      if (n) std::memcpy(v.data(), bytes.data() + at, n * sizeof(double));
      at += n * sizeof(double);
    };
    std::int64_t inserted = 0, shortfall = 0, shorts = 0;
    if (layout2) {
      get(inserted), get(mass_), get(shortfall), get(shorts), get(draws_);
      get_all(pending_);
    } else {
      double next = 0;
      get(inserted), get(mass_), get(next), get(shortfall), get(shorts);
      pending_.assign(1, next), draws_ = 0;
    }
    get_all(delivered_);
    if (at != bytes.size() || pending_.empty()) throw std::runtime_error("checkpoint: a feeder's state is corrupt");
    inserted_ = static_cast<long>(inserted), shortfall_now_ = static_cast<long>(shortfall), short_insertions_ = static_cast<long>(shorts);
  }

 private:
  static double largest_type(const Scene& s) {
    double r = 0;
    for (const auto& t : s.types) r = std::max(r, t.size());
    return r;
  }
  // Is step k before the feed's end? The end is rounded to the nearest step, as the run's is: a
  // feed that ends with the run makes its last insertion an interval before, not at the last step.
  bool before_end(std::uint64_t k) const { return static_cast<double>(k) * s_.dt < spec_.end - 0.5 * s_.dt; }
  // Particles due by the end of `span` (s from the start) for a feed by number, capped by count.
  long due_count(double span) const {
    long due = static_cast<long>(std::floor(spec_.rate * span + 1e-9));
    return spec_.count > 0 ? std::min(due, spec_.count) : due;
  }
  // How many of the pending particles (drawing more as needed) this insertion owes: by number,
  // what the count due lacks; by mass, those whose mass, added in order with half the next one's,
  // stays within the mass due (capped by count).
  std::size_t due_now(double span) {
    const long cap = spec_.count > 0 ? spec_.count - inserted_ : std::numeric_limits<long>::max();
    if (spec_.rate > 0) {
      const long n = std::min(cap, std::max(0L, due_count(span) - inserted_));
      while (static_cast<long>(pending_.size()) < n) pending_.push_back(spec_.size.draw(rng_));
      return static_cast<std::size_t>(n);
    }
    const double due_mass = spec_.mass_rate * span;
    double mass = mass_;
    for (std::size_t k = 0;; ++k) {
      if (static_cast<long>(k) >= cap) return k;
      if (k == pending_.size()) pending_.push_back(spec_.size.draw(rng_));
      if (mass + 0.5 * mass_of(pending_[k]) > due_mass) return k;
      mass += mass_of(pending_[k]);
    }
  }
  const ParticleTypeSpec& type() const { return s_.types[static_cast<std::size_t>(spec_.type)]; }
  double density() const { return s_.materials[static_cast<std::size_t>(type().material)].density; }
  // kg: a sphere of radius r, or the polyhedral type's shape scaled to bounding radius r
  double mass_of(double r) const {
    if (type().is_sphere()) return density() * 4.0 / 3.0 * M_PI * r * r * r;
    const double k = r / type().bounding_radius;
    return density() * type().volume * k * k * k;
  }
  // The batch of the placed particles chosen[i] (centres at[chosen[i]], radii pending_[chosen[i]]),
  // the i-th of them the feed's (inserted_ + i)-th: its velocity's jitter from that counter.
  void make_batch(ParticleState<Real>& batch, const std::vector<std::size_t>& chosen, const std::vector<Vec3<double>>& at) const {
    const long n = static_cast<long>(chosen.size());
    const auto mat = static_cast<std::uint8_t>(type().material);
    if (shapes_ == nullptr) {  // a sphere scene (type 0, as build_particles gives): filled on all threads
      batch.resize(static_cast<std::size_t>(n));
#pragma omp parallel for schedule(static) if (n > parallel_round_)
      for (long i = 0; i < n; ++i) {
        const std::size_t k = chosen[static_cast<std::size_t>(i)];
        batch.set_sphere(static_cast<std::size_t>(i), vec_cast<Real>(at[k]), static_cast<Real>(pending_[k]), static_cast<Real>(density()), mat,
                         vec_cast<Real>(velocity_of(inserted_ + i)));
      }
      return;
    }
    batch.reserve(static_cast<std::size_t>(n));
    for (long i = 0; i < n; ++i) {
      CounterEngine e = velocity_stream(inserted_ + i);
      const Vec3<double> v = jittered(e);
      const Quat<double> q = spec_.random_orientation ? scene_detail::random_orientation(e) : Quat<double>::identity();
      const std::size_t k = chosen[static_cast<std::size_t>(i)];
      add_polyhedron(batch, *shapes_, spec_.type, vec_cast<Real>(at[k]), Quat<Real>{Real(q.w), Real(q.x), Real(q.y), Real(q.z)}, mat,
                     vec_cast<Real>(v), Vec3<Real>{0, 0, 0}, spec_.size.kind == SizeKind::constant ? Real(0) : static_cast<Real>(pending_[k]));
    }
  }
  // The (n)-th delivered particle's stream: its velocity's jitter, then (polyhedra) its orientation.
  CounterEngine velocity_stream(long n) const { return CounterEngine(spec_.seed ^ kVelocityStream, static_cast<std::uint64_t>(n)); }
  Vec3<double> jittered(CounterEngine& e) const {
    std::uniform_real_distribution<double> u(-1, 1);
    const double ux = u(e), uy = u(e), uz = u(e);
    return spec_.velocity + Vec3<double>{ux, uy, uz} * spec_.spread;
  }
  Vec3<double> velocity_of(long n) const {
    CounterEngine e = velocity_stream(n);
    return jittered(e);
  }

  const Scene& s_;
  FeedSpec spec_;
  const PolyhedronTable<Real>* shapes_;
  std::mt19937_64 rng_;
  WorldOverlapCheck world_;
  std::uint64_t every_ = 1, first_ = 0;
  long inserted_ = 0;
  double mass_ = 0;  // kg delivered
  std::vector<double> pending_;  // m, radii drawn and waiting to be placed, in order (never empty)
  std::uint64_t draws_ = 0;  // placement centres drawn so far (their counter-based stream's position)
  static inline const std::string kLayout2 = "feeder2\n";
  static constexpr std::uint64_t kVelocityStream = 0x5be1d0c7a3e8f2b1ull;  // its key, with the feed's seed
  long shortfall_now_ = 0, short_insertions_ = 0;
  double place_seconds_ = 0, insert_seconds_ = 0, find_seconds_ = 0;  // not state: timing of this process
  long insertions_ = 0, rounds_ = 0;
  long parallel_round_ = kParallelRound;
  std::vector<double> delivered_;  // m, every delivered radius (polyhedra: the bounding radius)
  struct Scratch {  // not state: placement's host buffers, kept between insertions
    std::vector<Vec3<double>> at;
    std::vector<double> left;
    std::vector<std::size_t> chosen;
  } scratch_;
  // Not state: the rounds' arrays where the particles live (kernels/placement.hpp), kept between
  // insertions.
  struct Rounds {
    Buffer<Real, Space> found;  // the particles present: x, y, z, r
    Buffer<int, Space> head, next, fresh_head, fresh_next;
    Buffer<double, Space> sphere, fresh_sphere, radius, centre;
    Buffer<std::uint8_t, Space> ok, placed;
    std::optional<WorldBlockArrays<Space>> world;  // uploaded at the first insertion
  } rounds_scratch_;

  // Cells for up to `capacity` spheres of radius <= r_max, `cell` wide from lo, emptied.
  static SphereCellsView lay_cells(Buffer<int, Space>& head, Buffer<int, Space>& next, Buffer<double, Space>& sphere, std::size_t capacity,
                                   const Vec3<double>& lo, double cell, double r_max) {
    std::size_t heads = 1024;  // a power of two, at least twice the spheres: chains of ~1 sphere a cell
    while (heads < 2 * capacity) heads *= 2;
    head.ensure(heads), next.ensure(std::max<std::size_t>(capacity, 1)), sphere.ensure(4 * std::max<std::size_t>(capacity, 1));
    for_each(Space{}, static_cast<Index>(heads), Fill<int>{head.data(), -1});
    return {lo, 1 / cell, r_max, static_cast<std::uint32_t>(heads - 1), head.data(), next.data(), sphere.data()};
  }
};

}  // namespace blaze
