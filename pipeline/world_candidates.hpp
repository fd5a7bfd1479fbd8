// World lists on one memory space (kernels/world_candidates.hpp): whether a run keeps them, their
// buffers, the build at each neighbour-list rebuild and the last step a build stays valid for
// while objects move. A list holds while every point of every moving object has moved at most
// skin / 2 since its build: at most floor(skin / (2 v dt)) steps for the fastest surface speed v
// (World::surface_speed: a drum turning about its own axis does not count; its lifters do). With
// skin 0 every step rebuilds once anything moves, as the neighbour list does.
// With meshes the same build keeps each particle's triangle list (kernels/world_candidates.hpp),
// in room for `triangle_capacity` triangles a particle: when a particle reaches more, the room
// grows (to 1.25x the most, up to kTriangleCandidatesLargest) and the build runs again, as the
// neighbour list grows; never during the steps between rebuilds.
#pragma once
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <stdexcept>
#include <string>
#include <type_traits>
#include <vector>
#include "blaze/exec/primitives.hpp"
#include "blaze/particles/particle_store.hpp"
#include "blaze/world/world.hpp"
#include "kernels/broad_phase_kernels.hpp"  // ValueOf
#include "kernels/world_candidates.hpp"

namespace blaze {

// automatic: lists from kWorldListsMinObjects objects on (below it a full pass is as cheap), and
// with any mesh (a particle far from it then skips even its bins' lookup, a random read);
// on / off: always / never (tests compare the two).
enum class WorldLists { automatic, on, off };
constexpr int kWorldListsMinObjects = 8;

// Does a shape's mesh contact follow mesh_surface.hpp's regions for spheres (Shape::kSphereMeshRegions)?
// Then its triangle lists drop a flat patch's far triangles (drop_flat_neighbours).
template <class Shape, class = void>
struct UsesSphereMeshRegions : std::false_type {};
template <class Shape>
struct UsesSphereMeshRegions<Shape, std::void_t<decltype(Shape::kSphereMeshRegions)>> : std::bool_constant<Shape::kSphereMeshRegions> {};

template <class Real, class Space>
class WorldCandidates {
 public:
  static constexpr std::uint64_t kForever = ~std::uint64_t{0};

  // sphere_bodies: the particles are spheres (their lists drop a flat patch's far triangles).
  void configure(const World<Real>& world, WorldLists mode, Real skin, double dt, bool sphere_bodies = false) {
    const int objects = world.object_count();
    if (mode == WorldLists::on && objects > 65535)
      throw std::invalid_argument("world lists: at most 65535 world objects, got " + std::to_string(objects));
    on_ = objects > 0 && objects <= 65535 &&
          (mode == WorldLists::on || (mode == WorldLists::automatic && (objects >= kWorldListsMinObjects || !world.meshes.empty())));
    triangles_ = on_ && !world.meshes.empty();
    double v = 0;
    bool turns = false;
    for (int k = 0; k < objects; ++k)
      v = std::fmax(v, world.surface_speed(k)), turns = turns || (world.motion(k).moves() && world.motion(k).kind == MotionKind::rotation);
    // A flat patch's far triangles leave a sphere's list when its place in the mesh's frame moves
    // no more than the margin before the next build: true in a still world and under translation
    // and vibration (the frame moves as fast as its surface), not under rotation (a sphere farther
    // from the axis than the mesh's vertices moves in the frame faster than they do).
    drop_flat_ = sphere_bodies && !turns;
    // A particle moves at most skin / 2 before the rebuild check trips; a moving object's points
    // at most skin / 2 more before valid_until.
    margin_ = v > 0 ? skin : Real(0.5) * skin;
    from_host(device_state_, std::vector<std::uint64_t>{kForever, 0});
    const double steps = v > 0 ? std::floor(0.5 * static_cast<double>(skin) / (v * dt)) : HUGE_VAL;
    valid_steps_ = steps < 1e18 ? static_cast<std::uint64_t>(steps) : kForever;
  }
  bool on() const { return on_; }
  // Do the spheres' triangle lists drop a flat patch's far triangles (configure)?
  bool drops_flat_patches() const { return triangles_ && drop_flat_; }

  // The lists for the particles as they are and the world as it stands at world step `step`.
  void build(const ParticleView<Real>& p, const WorldView<Real>& world, std::uint64_t step) {
    if (!on_) return;
    stride_ = p.n;
    object_.ensure(static_cast<std::size_t>(kWorldCandidates) * p.n);
    count_.ensure(p.n);
    for (;;) {
      if (triangles_) {
        triangle_.ensure(static_cast<std::size_t>(triangle_capacity_) * p.n);
        triangle_count_.ensure(p.n);
      }
      for_each(Space{}, p.n,
               BuildWorldCandidates<Real>{p.position, p.radius, world, margin_, object_.data(), count_.data(), stride_,
                                          triangles_ ? triangle_.data() : nullptr, triangles_ ? triangle_count_.data() : nullptr,
                                          triangle_capacity_, drop_flat_});
      if (!triangles_ || triangle_capacity_ >= kTriangleCandidatesLargest) break;
      const int most = reduce_max(Space{}, p.n, ValueOf<std::uint16_t>{triangle_count_.data()}, 0);
      if (most <= triangle_capacity_) break;
      triangle_capacity_ = std::min(kTriangleCandidatesLargest, most + most / 4);
      const std::size_t need = static_cast<std::size_t>(triangle_capacity_) * p.n;  // exact: no headroom on a capacity step
      if (triangle_.size() < need) triangle_.resize(need);
    }
    valid_until_ = valid_steps_ == kForever || step > kForever - valid_steps_ ? kForever : step + valid_steps_;
    copy_n(&valid_until_, 1, device_state_.data(), Host{}, Space{});
    ++builds_;
  }
  // The in-block rebuild's world-list phase (kernels/world_candidates.hpp), counting
  // `neighbour_builds` too; the lists only when kept without triangle lists (in_place()).
  WorldListsInPlace<Real> in_place(const ParticleView<Real>& p, const WorldView<Real>& world, const std::uint64_t* world_step,
                                   std::uint64_t* neighbour_builds) {
    const bool lists = on_ && !triangles_ && stride_ == p.n;
    return {BuildWorldCandidates<Real>{p.position, p.radius, world, margin_, object_.data(), count_.data(), stride_},
            lists, world_step, valid_steps_, device_state_.data(), device_state_.data() + 1, neighbour_builds};
  }
  // Can the in-block rebuild keep these lists (triangle lists: only the host)?
  bool in_place() const { return !triangles_; }
  // The world view with the lists attached (unchanged when off).
  WorldView<Real> attach(WorldView<Real> w) const {
    if (!on_) return w;
    w.candidate = object_.data(), w.candidate_count = count_.data(), w.candidate_stride = stride_;
    if (triangles_)
      w.triangle_candidate = triangle_.data(), w.triangle_candidate_count = triangle_count_.data(), w.triangle_capacity = triangle_capacity_;
    return w;
  }
  // The last world step the lists hold for (kForever: a static world, or lists off), as the
  // last build left it (an in-block build's too); the rebuild check reads it where it is.
  std::uint64_t valid_until() const { return on_ && builds_ ? read_one(device_state_.data(), Space{}) : kForever; }
  const std::uint64_t* valid_until_at() const { return on_ ? device_state_.data() : nullptr; }
  std::uint64_t valid_steps() const { return valid_steps_; }
  // Particles whose list overflowed at the last build (they test every object).
  Index overflowed() const {
    const std::vector<std::uint8_t> c = counts();
    return static_cast<Index>(std::count(c.begin(), c.end(), kWorldCandidatesOverflow));
  }
  // Objects listed at the last build, over all particles (an overflowed particle counts all).
  double mean_listed(int objects) const {
    const std::vector<std::uint8_t> c = counts();
    if (c.empty()) return objects;
    double total = 0;
    for (auto k : c) total += k == kWorldCandidatesOverflow ? objects : k;
    return total / static_cast<double>(c.size());
  }
  // Builds so far, the host's and the in-block rebuild's.
  std::uint64_t builds() const { return builds_ + (builds_ ? read_one(device_state_.data() + 1, Space{}) : 0); }
  // Triangle lists: kept (a world with meshes and lists on); the room per particle; at the last
  // build, the particles past it (they test their bins' cells) and the mean triangles in reach.
  bool triangle_lists_on() const { return triangles_; }
  int triangle_capacity() const { return triangle_capacity_; }
  Index triangle_overflowed() const {
    const std::vector<std::uint16_t> c = triangle_counts();
    return static_cast<Index>(std::count_if(c.begin(), c.end(), [&](int k) { return k > triangle_capacity_; }));
  }
  double mean_triangles_listed() const {
    const std::vector<std::uint16_t> c = triangle_counts();
    double total = 0;
    for (auto k : c) total += k;
    return c.empty() ? 0 : total / static_cast<double>(c.size());
  }
  // Particle i's list as the last build left it (tests); empty when off, every object on overflow.
  std::vector<std::vector<int>> lists(int objects) const {
    const std::vector<std::uint8_t> c = counts();
    std::vector<std::uint16_t> o(c.empty() ? 0 : static_cast<std::size_t>(kWorldCandidates) * stride_);
    copy_n(object_.data(), o.size(), o.data(), Space{}, Host{});
    std::vector<std::vector<int>> out(c.size());
    for (std::size_t i = 0; i < c.size(); ++i) {
      if (c[i] == kWorldCandidatesOverflow)
        for (int w = 0; w < objects; ++w) out[i].push_back(w);
      else
        for (int k = 0; k < c[i]; ++k) out[i].push_back(o[static_cast<std::size_t>(k) * stride_ + i]);
    }
    return out;
  }
  // Particle i's triangle list as the last build left it (tests): global triangle indices, or
  // {-1} when it overflowed; empty without triangle lists.
  std::vector<std::vector<int>> triangle_lists() const {
    const std::vector<std::uint16_t> c = triangle_counts();
    std::vector<int> t(c.empty() ? 0 : static_cast<std::size_t>(triangle_capacity_) * stride_);
    copy_n(triangle_.data(), t.size(), t.data(), Space{}, Host{});
    std::vector<std::vector<int>> out(c.size());
    for (std::size_t i = 0; i < c.size(); ++i) {
      if (c[i] > triangle_capacity_) out[i] = {-1};
      else
        for (int k = 0; k < c[i]; ++k) out[i].push_back(t[static_cast<std::size_t>(k) * stride_ + i]);
    }
    return out;
  }
  std::size_t bytes() const {
    return object_.size() * sizeof(std::uint16_t) + count_.size() + triangle_.size() * sizeof(int) +
           triangle_count_.size() * sizeof(std::uint16_t);
  }

 private:
  std::vector<std::uint8_t> counts() const {
    std::vector<std::uint8_t> c(on_ ? static_cast<std::size_t>(stride_) : 0);
    copy_n(count_.data(), c.size(), c.data(), Space{}, Host{});
    return c;
  }
  std::vector<std::uint16_t> triangle_counts() const {
    std::vector<std::uint16_t> c(triangles_ && builds_ ? static_cast<std::size_t>(stride_) : 0);
    copy_n(triangle_count_.data(), c.size(), c.data(), Space{}, Host{});
    return c;
  }
  bool on_ = false, triangles_ = false, drop_flat_ = false;
  int triangle_capacity_ = kTriangleCandidatesFirst;
  Real margin_ = 0;  // m: how far a particle may move relative to any object between builds
  std::uint64_t valid_steps_ = kForever, valid_until_ = kForever, builds_ = 0;
  Index stride_ = 0;
  Buffer<std::uint16_t, Space> object_;
  Buffer<std::uint8_t, Space> count_;
  Buffer<int, Space> triangle_;
  Buffer<std::uint16_t, Space> triangle_count_;
  Buffer<std::uint64_t, Space> device_state_;  // [0]: valid_until, [1]: lists built in place
};

}  // namespace blaze
