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
// Placement: random sequential addition. The next particle's size is drawn once (SizeDistribution)
// and kept until it is placed, so a crowded region does not bias the delivered sizes towards the
// small ones. A centre is drawn in the region (InsertionRegion::draw) and accepted when the
// particle's bounding sphere overlaps no particle present (the simulation's particles near the
// region: Simulation::particles_in_box) or placed before it, no world object (WorldOverlapCheck,
// as fills are: the world at its initial pose), and lies inside the domain; after kTries rejected
// centres the region counts as full until the next insertion.
//
// State (save()/restore(), in the checkpoint): the random engine, the delivered count and mass,
// the drawn size waiting to be placed, the shortfall counters and the delivered sizes (for the
// Kolmogorov-Smirnov distance, SizeDistribution::ks_distance).
#pragma once
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <random>
#include <sstream>
#include <string>
#include <vector>
#include "blaze/scene/scene.hpp"
#include "blaze/scene/scene_build.hpp"
#include "blaze/scene/world_overlap.hpp"

namespace blaze {

// The particles a feeder must keep clear of, in a flat grid over the box it places in (cells of
// the largest diameter, each a linked list through `next_`): an overlap test reads the 27 cells
// around a centre, an addition is O(1), and nothing is allocated per particle beyond its entry
// (an unordered_map of cells cost ~1 us per placement, 10% of a 1e6-particle feed's run).
class PlacementGrid {
 public:
  PlacementGrid(const Vec3<double>& lo, const Vec3<double>& hi, double cell) : lo_(lo) {
    const Vec3<double> span = hi - lo;
    // at most 2^24 cells: a huge region takes coarser cells (still correct, a little slower)
    for (cell_ = cell;; cell_ *= 1.5) {
      n_[0] = 1 + static_cast<long>(span.x / cell_), n_[1] = 1 + static_cast<long>(span.y / cell_), n_[2] = 1 + static_cast<long>(span.z / cell_);
      if (static_cast<double>(n_[0]) * static_cast<double>(n_[1]) * static_cast<double>(n_[2]) <= 16777216.0) break;
    }
    head_.assign(static_cast<std::size_t>(n_[0] * n_[1] * n_[2]), -1);
  }
  // Does a sphere (x, r) overlap one added (by more than 0)? Centres outside the box clamp to
  // its border cells: the box holds every centre added, so none is missed.
  bool overlapping(const Vec3<double>& x, double r) const {
    long c[3];
    cell_of(x, c);
    for (long i = std::max(0L, c[0] - 1); i <= std::min(n_[0] - 1, c[0] + 1); ++i)
      for (long j = std::max(0L, c[1] - 1); j <= std::min(n_[1] - 1, c[1] + 1); ++j)
        for (long k = std::max(0L, c[2] - 1); k <= std::min(n_[2] - 1, c[2] + 1); ++k)
          for (long e = head_[static_cast<std::size_t>((i * n_[1] + j) * n_[2] + k)]; e >= 0; e = next_[static_cast<std::size_t>(e)]) {
            const double reach = r + radius_[static_cast<std::size_t>(e)];
            if (norm2(x - centre_[static_cast<std::size_t>(e)]) < reach * reach) return true;
          }
    return false;
  }
  void add(const Vec3<double>& x, double r) {
    long c[3];
    cell_of(x, c);
    long& h = head_[static_cast<std::size_t>((c[0] * n_[1] + c[1]) * n_[2] + c[2])];
    next_.push_back(h);
    h = static_cast<long>(centre_.size());
    centre_.push_back(x), radius_.push_back(r);
  }

 private:
  void cell_of(const Vec3<double>& x, long* c) const {
    const double v[3] = {x.x - lo_.x, x.y - lo_.y, x.z - lo_.z};
    for (int d = 0; d < 3; ++d) c[d] = std::clamp(static_cast<long>(std::floor(v[d] / cell_)), 0L, n_[d] - 1);
  }
  Vec3<double> lo_;
  double cell_;
  long n_[3];
  std::vector<long> head_, next_;
  std::vector<Vec3<double>> centre_;
  std::vector<double> radius_;
};

template <class Real>
class Feeder {
 public:
  static constexpr int kTries = 200;  // centres drawn per particle before the region counts as full

  // `shapes`: the scene's polyhedron table (null for spheres).
  Feeder(const Scene& s, std::size_t index, const PolyhedronTable<Real>* shapes)
      : s_(s), spec_(s.feeds.at(index)), shapes_(shapes), rng_(spec_.seed), world_(s, 1e-9 * largest_type(s)) {
    every_ = std::max<std::uint64_t>(1, static_cast<std::uint64_t>(std::ceil(spec_.interval / s.dt - 1e-9)));
    first_ = static_cast<std::uint64_t>(std::ceil(spec_.start / s.dt - 1e-9));
    next_radius_ = spec_.size.draw(rng_);
  }

  const FeedSpec& spec() const { return spec_; }
  // Steps between insertions, and whether step k is an insertion.
  std::uint64_t every() const { return every_; }
  bool inserts_at(std::uint64_t k) const {
    return k >= first_ && (k - first_) % every_ == 0 && static_cast<double>(k) * s_.dt < spec_.end && !finished();
  }
  // The next insertion at or after step k (~0: none).
  std::uint64_t next_insertion(std::uint64_t k) const {
    if (finished()) return ~std::uint64_t{0};
    const std::uint64_t n = k <= first_ ? first_ : first_ + (k - first_ + every_ - 1) / every_ * every_;
    return static_cast<double>(n) * s_.dt < spec_.end ? n : ~std::uint64_t{0};
  }

  // The insertion at the simulation's current step: places what is due, inserts it.
  template <class Sim>
  void feed(Sim& sim) {
    const double t = sim.time();
    const double span = std::min(t + static_cast<double>(every_) * s_.dt, spec_.end) - spec_.start;
    const double due_mass = spec_.mass_rate * span;
    long due = spec_.rate > 0 ? static_cast<long>(std::floor(spec_.rate * span + 1e-9)) : -1;
    if (spec_.count > 0 && due >= 0) due = std::min(due, spec_.count);
    Vec3<double> lo, hi;
    spec_.region.bounds(lo, hi);
    const double reach = 2 * static_cast<double>(sim.max_radius());
    std::vector<Vec3<double>> centre;
    std::vector<double> radius;
    const Vec3<double> margin{reach, reach, reach};
    sim.particles_in_box(lo - margin, hi + margin, centre, radius);
    PlacementGrid occupied(lo - margin, hi + margin, reach);
    for (std::size_t k = 0; k < centre.size(); ++k) occupied.add(centre[k], radius[k]);
    ParticleState<Real> batch;
    std::uniform_real_distribution<double> u(-1, 1);
    const std::vector<Vec3<double>> no_vertices;
    for (;;) {
      if (spec_.count > 0 && inserted_ >= spec_.count) break;
      if (due >= 0 ? inserted_ >= due : mass_ + 0.5 * mass_of(next_radius_) > due_mass) break;
      const double r = next_radius_;
      bool placed = false;
      Vec3<double> x;
      for (int tries = 0; tries < kTries && !placed; ++tries) {
        x = spec_.region.draw(rng_, r);
        placed = inside_domain(x, r) && !occupied.overlapping(x, r) && !world_.blocked(x, r, no_vertices);
      }
      if (!placed) break;  // the region is full: the rest stays due
      occupied.add(x, r);
      const Vec3<double> v = spec_.velocity + Vec3<double>{u(rng_), u(rng_), u(rng_)} * spec_.spread;
      add(batch, x, r, v);
      delivered_.push_back(r);
      ++inserted_;
      mass_ += mass_of(r);
      next_radius_ = spec_.size.draw(rng_);
    }
    // what is still due: a shortfall (the run reports it)
    const double left = due >= 0 ? static_cast<double>(due - inserted_) : (due_mass - mass_) / mass_of(next_radius_);
    shortfall_now_ = left >= 1 ? static_cast<long>(left) : 0;
    if (shortfall_now_ > 0) ++short_insertions_;
    sim.insert(batch);
  }

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
    const double mean = inserted_ > 0 ? mass_ / static_cast<double>(inserted_) : mass_of(next_radius_);
    return missing > 0.5 * mean ? static_cast<long>(std::lround(missing / mean)) : 0;
  }
  bool finished() const { return spec_.count > 0 && inserted_ >= spec_.count; }
  // The delivered sizes' Kolmogorov-Smirnov distance from the requested distribution.
  double ks_distance() const { return spec_.size.ks_distance(delivered_); }
  const std::vector<double>& delivered() const { return delivered_; }

  // The feeder's state as bytes (the checkpoint's), and back.
  std::string save() const {
    std::ostringstream engine;
    engine << rng_;
    std::string out = engine.str();
    out += '\n';
    auto put = [&](const auto& v) { out.append(reinterpret_cast<const char*>(&v), sizeof v); };
    put(static_cast<std::int64_t>(inserted_));
    put(mass_);
    put(next_radius_);
    put(static_cast<std::int64_t>(shortfall_now_));
    put(static_cast<std::int64_t>(short_insertions_));
    put(static_cast<std::uint64_t>(delivered_.size()));
    out.append(reinterpret_cast<const char*>(delivered_.data()), delivered_.size() * sizeof(double));
    return out;
  }
  void restore(const std::string& bytes) {
    const auto line = bytes.find('\n');
    if (line == std::string::npos) throw std::runtime_error("checkpoint: a feeder's state is corrupt");
    std::istringstream engine(bytes.substr(0, line));
    engine >> rng_;
    if (!engine) throw std::runtime_error("checkpoint: a feeder's random engine is corrupt");
    std::size_t at = line + 1;
    auto get = [&](auto& v) {
      if (bytes.size() - at < sizeof v) throw std::runtime_error("checkpoint: a feeder's state is truncated");
      std::memcpy(&v, bytes.data() + at, sizeof v);
      at += sizeof v;
    };
    std::int64_t inserted = 0, shortfall = 0, shorts = 0;
    std::uint64_t n = 0;
    get(inserted), get(mass_), get(next_radius_), get(shortfall), get(shorts), get(n);
    if ((bytes.size() - at) != n * sizeof(double)) throw std::runtime_error("checkpoint: a feeder's delivered sizes are truncated");
    delivered_.resize(n);
    if (n) std::memcpy(delivered_.data(), bytes.data() + at, n * sizeof(double));
    inserted_ = static_cast<long>(inserted), shortfall_now_ = static_cast<long>(shortfall), short_insertions_ = static_cast<long>(shorts);
  }

 private:
  static double largest_type(const Scene& s) {
    double r = 0;
    for (const auto& t : s.types) r = std::max(r, t.size());
    return r;
  }
  const ParticleTypeSpec& type() const { return s_.types[static_cast<std::size_t>(spec_.type)]; }
  double density() const { return s_.materials[static_cast<std::size_t>(type().material)].density; }
  // kg: a sphere of radius r, or the polyhedral type's mass
  double mass_of(double r) const {
    return type().is_sphere() ? density() * 4.0 / 3.0 * M_PI * r * r * r : density() * type().volume;
  }
  bool inside_domain(const Vec3<double>& x, double r) const {
    return x.x - r >= s_.domain_lo.x && x.x + r <= s_.domain_hi.x && x.y - r >= s_.domain_lo.y && x.y + r <= s_.domain_hi.y &&
           x.z - r >= s_.domain_lo.z && x.z + r <= s_.domain_hi.z;
  }
  void add(ParticleState<Real>& batch, const Vec3<double>& x, double r, const Vec3<double>& v) {
    const auto mat = static_cast<std::uint8_t>(type().material);
    if (shapes_ == nullptr) {  // a sphere scene (type 0, as build_particles gives)
      batch.add_sphere(vec_cast<Real>(x), static_cast<Real>(r), static_cast<Real>(density()), mat, vec_cast<Real>(v));
      return;
    }
    const Quat<double> q = spec_.random_orientation ? scene_detail::random_orientation(rng_) : Quat<double>::identity();
    add_polyhedron(batch, *shapes_, spec_.type, vec_cast<Real>(x), Quat<Real>{Real(q.w), Real(q.x), Real(q.y), Real(q.z)}, mat,
                   vec_cast<Real>(v));
  }

  const Scene& s_;
  FeedSpec spec_;
  const PolyhedronTable<Real>* shapes_;
  std::mt19937_64 rng_;
  WorldOverlapCheck world_;
  std::uint64_t every_ = 1, first_ = 0;
  long inserted_ = 0;
  double mass_ = 0;  // kg delivered
  double next_radius_ = 0;  // m, drawn and waiting to be placed
  long shortfall_now_ = 0, short_insertions_ = 0;
  std::vector<double> delivered_;  // m, every delivered radius (polyhedra: the bounding radius)
};

}  // namespace blaze
