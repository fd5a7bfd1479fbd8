// World objects (thesis section 3.2.1): everything that is not a particle. One host description,
// one device store, one view; kernels loop over each object kind with that kind's collide().
// New kinds (triangle meshes) add an array here and a collide() overload.
// Objects may move (motion.hpp): each keeps its reference geometry, and a phase of the step
// (kernels/move_world.hpp) places the current geometry and records the pose; the world kernel
// reads the pose for the wall's velocity at a contact and skips objects that were removed.
#pragma once
#include <cmath>
#include <cstdint>
#include <stdexcept>
#include <string>
#include <vector>
#include "blaze/exec/buffer.hpp"
#include "blaze/particles/energy_ledger.hpp"
#include "blaze/world/cylinder.hpp"
#include "blaze/world/motion.hpp"
#include "blaze/world/planar_polygon.hpp"

namespace blaze {

template <class Real>
struct World {
  std::vector<PlanarPolygon<Real>> polygons;
  std::vector<Cylinder<Real>> cylinders;
  // Per object (polygons first, then cylinders: the world's object index); empty: all static.
  std::vector<Motion> motions;
  // Per object, the contact class its dissipation is booked under (energy_ledger.hpp); empty:
  // all plain walls.
  std::vector<ContactClass> classes;
  bool empty() const { return polygons.empty() && cylinders.empty(); }
  int object_count() const { return static_cast<int>(polygons.size() + cylinders.size()); }
  // Any object moves or is removed at some time.
  bool dynamic() const {
    for (const auto& m : motions)
      if (!m.is_static()) return true;
    return false;
  }
  void set_motion(int object, const Motion& m) {
    if (object < 0 || object >= object_count()) throw std::out_of_range("world: no object " + std::to_string(object));
    motions.resize(static_cast<std::size_t>(object_count()));
    motions[static_cast<std::size_t>(object)] = m;
  }
  void set_class(int object, ContactClass c) {
    if (object < 0 || object >= object_count()) throw std::out_of_range("world: no object " + std::to_string(object));
    classes.resize(static_cast<std::size_t>(object_count()), ContactClass::wall);
    classes[static_cast<std::size_t>(object)] = c;
  }
  ContactClass contact_class(int object) const {
    return static_cast<std::size_t>(object) < classes.size() ? classes[static_cast<std::size_t>(object)] : ContactClass::wall;
  }
  Motion motion(int object) const {
    return static_cast<std::size_t>(object) < motions.size() ? motions[static_cast<std::size_t>(object)] : Motion{};
  }
  // A bound on how fast the object's surface moves (m/s): the peak speed of its points
  // (motion.hpp), over a polygon's vertices (the farthest from any axis, as it is convex) or, for
  // a cylinder, its centre's distance from the axis plus its half-diagonal; 0 for a cylinder
  // turning about its own axis (its surface stays where it is).
  double surface_speed(int object) const {
    const Motion m = motion(object);
    if (!m.moves()) return 0;
    const auto np = static_cast<int>(polygons.size());
    if (object < np) {
      const PlanarPolygon<Real>& g = polygons[static_cast<std::size_t>(object)];
      std::vector<Vec3<double>> v;
      for (int k = 0; k < g.vertex_count; ++k) v.push_back(vec_cast<double>(g.vertex[k]));
      return peak_speed(m, v);
    }
    const Cylinder<Real>& c = cylinders[static_cast<std::size_t>(object - np)];
    const Vec3<double> a = vec_cast<double>(c.axis), o = vec_cast<double>(c.origin);
    const double r = static_cast<double>(c.radius), l = static_cast<double>(c.length);
    if (m.kind == MotionKind::rotation) {
      const Vec3<double> off = m.point - o;
      const double tilt = norm(cross(m.axis, a)), miss = norm(off - a * dot(off, a));
      if (tilt <= 1e-12 && miss <= 1e-12 * r) return 0;
    }
    const Vec3<double> centre = o + a * (0.5 * l);
    const double half_diagonal = std::sqrt(r * r + 0.25 * l * l);
    if (m.kind != MotionKind::rotation) return peak_speed(m, {centre});
    return peak_speed(m, {centre}) + std::fabs(m.omega) * half_diagonal;
  }
};

// The reference geometry placed by a pose.
template <class Real>
BLAZE_HD PlanarPolygon<Real> moved(const PlanarPolygon<Real>& ref, const Pose<Real>& p) {
  PlanarPolygon<Real> w = ref;
  for (int k = 0; k < ref.vertex_count; ++k) w.vertex[k] = p.place(ref.vertex[k]);
  w.normal = p.turn(ref.normal);
  w.centroid = p.place(ref.centroid);
  return w;
}
template <class Real>
BLAZE_HD Cylinder<Real> moved(const Cylinder<Real>& ref, const Pose<Real>& p) {
  Cylinder<Real> c = ref;
  c.origin = p.place(ref.origin);
  c.axis = p.turn(ref.axis);
  return c;
}

// The world as the poses place it (output): each object moved, removed ones left out, no motions.
template <class Real>
World<Real> placed(const World<Real>& ref, const std::vector<Pose<Real>>& poses) {
  if (poses.empty()) return ref;
  World<Real> w;
  std::size_t k = 0;
  for (const auto& p : ref.polygons) {
    if (poses[k].active) w.polygons.push_back(moved(p, poses[k]));
    ++k;
  }
  for (const auto& c : ref.cylinders) {
    if (poses[k].active) w.cylinders.push_back(moved(c, poses[k]));
    ++k;
  }
  return w;
}

// World lists (kernels/world_candidates.hpp): at most this many objects per particle; a particle
// that reaches more is marked with the overflow count and tests every object.
constexpr int kWorldCandidates = 8;
constexpr std::uint8_t kWorldCandidatesOverflow = 255;

template <class Real>
struct WorldView {
  const PlanarPolygon<Real>* polygons;
  int polygon_count;
  const Cylinder<Real>* cylinders;
  int cylinder_count;
  const Pose<Real>* pose;  // per object; null: a static world (every object still, none removed)
  const ContactClass* object_class;  // per object; null: all plain walls (energy_ledger.hpp)
  // Per particle i, its world list: objects candidate[k * stride + i], k < candidate_count[i]
  // (kWorldCandidatesOverflow: every object); null: every object for every particle.
  const std::uint16_t* candidate = nullptr;
  const std::uint8_t* candidate_count = nullptr;
  Index candidate_stride = 0;

  BLAZE_HD ContactClass class_of(int w) const { return object_class ? object_class[w] : ContactClass::wall; }
  BLAZE_HD bool active(int w) const { return !pose || pose[w].active; }
  // f(object, w) for each object present (not removed) that particle i may touch: its world list,
  // or every object; in object index order (polygons first, then cylinders) either way.
  template <class F>
  BLAZE_HD void visit(Index i, F&& f) const {
    if (candidate) {
      const int c = candidate_count[i];
      if (c != kWorldCandidatesOverflow) {
        for (int k = 0; k < c; ++k) {
          const int w = candidate[static_cast<std::size_t>(k) * candidate_stride + i];
          if (!active(w)) continue;
          if (w < polygon_count) f(polygons[w], w);
          else f(cylinders[w - polygon_count], w);
        }
        return;
      }
    }
    int w = 0;
    for (int k = 0; k < polygon_count; ++k, ++w)
      if (active(w)) f(polygons[k], w);
    for (int k = 0; k < cylinder_count; ++k, ++w)
      if (active(w)) f(cylinders[k], w);
  }
};

// What the move-world phase reads and writes (kernels/move_world.hpp).
template <class Real>
struct WorldMotionView {
  const PlanarPolygon<Real>* polygon_ref;
  PlanarPolygon<Real>* polygons;
  int polygon_count;
  const Cylinder<Real>* cylinder_ref;
  Cylinder<Real>* cylinders;
  int cylinder_count;
  const Motion* motion;
  Pose<Real>* pose;
  std::uint64_t* step;  // per object: the step its pose is for (t = step dt)
  double dt;            // s
};

template <class Real, class Space>
class WorldStore {
 public:
  // The world as it stands after `step` steps of dt (a restored run continues where it was).
  void upload(const World<Real>& w, std::uint64_t step, double dt) {
    if (!w.motions.empty() && w.motions.size() != static_cast<std::size_t>(w.object_count()))
      throw std::invalid_argument("world: motions must be given for every object or none");
    dynamic_ = w.dynamic();
    dt_ = dt;
    if (!w.classes.empty() && w.classes.size() != static_cast<std::size_t>(w.object_count()))
      throw std::invalid_argument("world: contact classes must be given for every object or none");
    from_host(classes_, w.classes);
    if (!dynamic_) {
      from_host(polygons_, w.polygons);
      from_host(cylinders_, w.cylinders);
      return;
    }
    const int n = w.object_count();
    std::vector<Pose<Real>> poses(static_cast<std::size_t>(n));
    std::vector<PlanarPolygon<Real>> polygons(w.polygons);
    std::vector<Cylinder<Real>> cylinders(w.cylinders);
    const double t = static_cast<double>(step) * dt;
    for (int k = 0; k < n; ++k) poses[static_cast<std::size_t>(k)] = pose_at<Real>(w.motions[static_cast<std::size_t>(k)], t);
    for (std::size_t k = 0; k < polygons.size(); ++k) polygons[k] = moved(w.polygons[k], poses[k]);
    for (std::size_t k = 0; k < cylinders.size(); ++k) cylinders[k] = moved(w.cylinders[k], poses[w.polygons.size() + k]);
    from_host(polygon_ref_, w.polygons);
    from_host(cylinder_ref_, w.cylinders);
    from_host(polygons_, polygons);
    from_host(cylinders_, cylinders);
    from_host(motions_, w.motions);
    from_host(poses_, poses);
    from_host(steps_, std::vector<std::uint64_t>(static_cast<std::size_t>(n), step));
  }
  WorldView<Real> view() const {
    return {polygons_.data(), static_cast<int>(polygons_.size()), cylinders_.data(), static_cast<int>(cylinders_.size()),
            dynamic_ ? poses_.data() : nullptr, classes_.size() ? classes_.data() : nullptr};
  }
  WorldMotionView<Real> motion_view() {
    return {polygon_ref_.data(), polygons_.data(), static_cast<int>(polygons_.size()), cylinder_ref_.data(), cylinders_.data(),
            static_cast<int>(cylinders_.size()), motions_.data(), poses_.data(), steps_.data(), dt_};
  }
  bool empty() const { return polygons_.size() == 0 && cylinders_.size() == 0; }
  // Some object moves or is removed at a time: the step places the world first (move-world).
  bool dynamic() const { return dynamic_; }
  // The step each object's pose is for (t = step dt; all objects advance together); null in a
  // static world. The rebuild check reads it (world lists, pipeline/world_candidates.hpp).
  const std::uint64_t* step_counter() const { return dynamic_ ? steps_.data() : nullptr; }
  // Poses as they stand (tests, output).
  std::vector<Pose<Real>> poses() const { return to_host(poses_, poses_.size()); }

 private:
  Buffer<PlanarPolygon<Real>, Space> polygons_, polygon_ref_;
  Buffer<Cylinder<Real>, Space> cylinders_, cylinder_ref_;
  Buffer<Motion, Space> motions_;
  Buffer<Pose<Real>, Space> poses_;
  Buffer<std::uint64_t, Space> steps_;
  Buffer<ContactClass, Space> classes_;
  bool dynamic_ = false;
  double dt_ = 0;
};

}  // namespace blaze
