// World objects (thesis section 3.2.1): everything that is not a particle. One host description,
// one device store, one view; kernels loop over each object kind with that kind's collide().
// Object index: polygons first, then cylinders, then triangle meshes (mesh_wall.hpp).
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
#include "blaze/world/mesh_wall.hpp"
#include "blaze/world/motion.hpp"
#include "blaze/world/planar_polygon.hpp"

namespace blaze {

template <class Real>
struct World {
  std::vector<PlanarPolygon<Real>> polygons;
  std::vector<Cylinder<Real>> cylinders;
  std::vector<MeshWall> meshes;
  // Per object (polygons, cylinders, meshes: the world's object index); empty: all static.
  std::vector<Motion> motions;
  // Per object, the contact class its dissipation is booked under (energy_ledger.hpp); empty:
  // all plain walls.
  std::vector<ContactClass> classes;
  bool empty() const { return polygons.empty() && cylinders.empty() && meshes.empty(); }
  int object_count() const { return static_cast<int>(polygons.size() + cylinders.size() + meshes.size()); }
  // The object index of mesh k.
  int mesh_object(std::size_t k) const { return static_cast<int>(polygons.size() + cylinders.size() + k); }
  // Triangles over all meshes.
  long triangle_count() const {
    long t = 0;
    for (const auto& m : meshes) t += static_cast<long>(m.mesh.size());
    return t;
  }
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
  // turning about its own axis (its surface stays where it is); over a mesh's vertices.
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
    const auto nc = static_cast<int>(cylinders.size());
    if (object >= np + nc) return peak_speed(m, meshes[static_cast<std::size_t>(object - np - nc)].mesh.vertices);
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
  for (const auto& m : ref.meshes) {
    if (poses[k].active) {
      MeshWall placed_mesh = m;
      for (auto& v : placed_mesh.mesh.vertices) v = vec_cast<double>(poses[k].place(vec_cast<Real>(v)));
      w.meshes.push_back(std::move(placed_mesh));
    }
    ++k;
  }
  return w;
}

// World lists (kernels/world_candidates.hpp): at most this many objects per particle; a particle
// that reaches more is marked with the overflow count and tests every object.
constexpr int kWorldCandidates = 8;
constexpr std::uint8_t kWorldCandidatesOverflow = 255;
// Triangle lists (the same kernel): room for this many mesh triangles per particle at first; the
// room grows to the most a particle reaches, up to the largest; a particle beyond it tests its
// bins' cell.
constexpr int kTriangleCandidatesFirst = 8;
constexpr int kTriangleCandidatesLargest = 256;

template <class Real>
struct WorldView {
  const PlanarPolygon<Real>* polygons;
  int polygon_count;
  const Cylinder<Real>* cylinders;
  int cylinder_count;
  const MeshObject<Real>* meshes;
  int mesh_count;
  MeshSurfaceView<Real> surface;  // every mesh's vertices, triangles, neighbours (mesh_wall.hpp)
  int mesh_key_base;              // a mesh contact's history key: mesh_key_base + its triangle
  const Pose<Real>* pose;  // per object (a still world's: identities); null only without objects
  const ContactClass* object_class;  // per object; null: all plain walls (energy_ledger.hpp)
  // Per particle i, its world list: objects candidate[k * stride + i], k < candidate_count[i]
  // (kWorldCandidatesOverflow: every object); null: every object for every particle.
  const std::uint16_t* candidate = nullptr;
  const std::uint8_t* candidate_count = nullptr;
  Index candidate_stride = 0;
  // Per particle i, its triangle list: triangles triangle_candidate[k * candidate_stride + i],
  // k < triangle_candidate_count[i] (more than triangle_capacity: its cells'); null: cells for all.
  const int* triangle_candidate = nullptr;
  const std::uint16_t* triangle_candidate_count = nullptr;
  int triangle_capacity = 0;

  BLAZE_HD TriangleList near_triangles(Index i) const {
    if (!triangle_candidate) return {};
    const int c = triangle_candidate_count[i];
    if (c > triangle_capacity) return {};
    return {triangle_candidate + i, candidate_stride, c};
  }
  BLAZE_HD ContactClass class_of(int w) const { return object_class ? object_class[w] : ContactClass::wall; }
  BLAZE_HD bool active(int w) const { return pose[w].active; }
  BLAZE_HD const Pose<Real>* pose_of(int w) const { return pose + w; }
  // f(object, w) for each object that particle i may touch, present or removed (f asks active(w)
  // where it matters: after a polygon's or cylinder's own test, which a removed object's flag
  // would otherwise hold up by a memory latency): its world list, or every object; in object
  // index order (polygons, cylinders, meshes) either way.
  template <class F>
  BLAZE_HD void visit(Index i, F&& f) const {
    if (candidate) {
      const int c = candidate_count[i];
      if (c != kWorldCandidatesOverflow) {
        for (int k = 0; k < c; ++k) {
          const int w = candidate[static_cast<std::size_t>(k) * candidate_stride + i];
          if (w < polygon_count) f(polygons[w], w);
          else if (w < polygon_count + cylinder_count) f(cylinders[w - polygon_count], w);
          else f(meshes[w - polygon_count - cylinder_count], w);
        }
        return;
      }
    }
    int w = 0;
    for (int k = 0; k < polygon_count; ++k, ++w) f(polygons[k], w);
    for (int k = 0; k < cylinder_count; ++k, ++w) f(cylinders[k], w);
    for (int k = 0; k < mesh_count; ++k, ++w) f(meshes[k], w);
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
  int mesh_count;  // meshes keep their vertices: only their poses move
  const Motion* motion;
  Pose<Real>* pose;
  std::uint64_t* step;  // per object: the step its pose is for (t = step dt)
  double dt;            // s
};

template <class Real, class Space>
class WorldStore {
 public:
  // The world as it stands after `step` steps of dt (a restored run continues where it was).
  // mesh_reach (m): the bins' reach (mesh_wall.hpp: the largest bounding radius plus the skin).
  void upload(const World<Real>& w, std::uint64_t step, double dt, double mesh_reach) {
    if (!w.motions.empty() && w.motions.size() != static_cast<std::size_t>(w.object_count()))
      throw std::invalid_argument("world: motions must be given for every object or none");
    dynamic_ = w.dynamic();
    dt_ = dt;
    if (!w.classes.empty() && w.classes.size() != static_cast<std::size_t>(w.object_count()))
      throw std::invalid_argument("world: contact classes must be given for every object or none");
    from_host(classes_, w.classes);
    upload_meshes(w, mesh_reach);
    if (!dynamic_) {
      from_host(polygons_, w.polygons);
      from_host(cylinders_, w.cylinders);
      // A still world has poses too, each the identity (x = x_ref, v = 0, exactly): the kernels
      // never meet a null pose. With null poses guarded by `pose ? ... : ...`, nvcc 13 (sm_90) hoisted
      // the load of pose->omega above the guard in the fused kernel of the 242-ball mill
      // (cuda-gdb: LD [null + 0x30]), an illegal address depending on the build.
      from_host(poses_, std::vector<Pose<Real>>(static_cast<std::size_t>(w.object_count()), pose_at<Real>(Motion{}, 0.0)));
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
    const int np = static_cast<int>(polygons_.size()), nc = static_cast<int>(cylinders_.size()), nm = static_cast<int>(meshes_.size());
    return {polygons_.data(),
            np,
            cylinders_.data(),
            nc,
            meshes_.data(),
            nm,
            {mesh_vertex_.data(), mesh_triangle_.data(), mesh_neighbour_.data(), mesh_adjacency_start_.data(), mesh_adjacency_.data(),
             mesh_normal_.data(), mesh_corner_.data(), mesh_patch_.data()},
            np + nc + nm,
            poses_.data(),
            classes_.size() ? classes_.data() : nullptr};
  }
  WorldMotionView<Real> motion_view() {
    return {polygon_ref_.data(), polygons_.data(), static_cast<int>(polygons_.size()), cylinder_ref_.data(), cylinders_.data(),
            static_cast<int>(cylinders_.size()), static_cast<int>(meshes_.size()), motions_.data(), poses_.data(), steps_.data(), dt_};
  }
  bool empty() const { return polygons_.size() == 0 && cylinders_.size() == 0 && meshes_.size() == 0; }
  // Per mesh: the most triangles one of its bins' cells lists (0 without meshes).
  const std::vector<long>& mesh_longest_cell() const { return longest_cell_; }
  // Some object moves or is removed at a time: the step places the world first (move-world).
  bool dynamic() const { return dynamic_; }
  // The step each object's pose is for (t = step dt; all objects advance together); null in a
  // static world. The rebuild check reads it (world lists, pipeline/world_candidates.hpp).
  const std::uint64_t* step_counter() const { return dynamic_ ? steps_.data() : nullptr; }
  // Poses as they stand (tests, output).
  std::vector<Pose<Real>> poses() const { return to_host(poses_, poses_.size()); }

 private:
  void upload_meshes(const World<Real>& w, double reach) {
    MeshArrays<Real> a;
    if (!w.meshes.empty()) a = mesh_arrays<Real>(w.meshes, reach);
    from_host(mesh_vertex_, a.vertex);
    from_host(mesh_normal_, a.normal);
    from_host(mesh_corner_, a.corner);
    from_host(mesh_triangle_, a.triangle);
    from_host(mesh_neighbour_, a.neighbour);
    from_host(mesh_adjacency_start_, a.adjacency_start);
    from_host(mesh_adjacency_, a.adjacency);
    from_host(mesh_patch_, a.patch);
    from_host(mesh_bin_start_, a.bin_start);
    from_host(mesh_bin_entry_, a.bin_entry);
    for (std::size_t k = 0; k < a.objects.size(); ++k) {
      a.objects[k].bins.start = mesh_bin_start_.data() + a.bin_start_offset[k];
      a.objects[k].bins.entry = mesh_bin_entry_.data() + a.bin_entry_offset[k];
    }
    from_host(meshes_, a.objects);
    longest_cell_ = a.longest_cell;
  }
  Buffer<PlanarPolygon<Real>, Space> polygons_, polygon_ref_;
  Buffer<Cylinder<Real>, Space> cylinders_, cylinder_ref_;
  Buffer<Motion, Space> motions_;
  Buffer<Pose<Real>, Space> poses_;
  Buffer<std::uint64_t, Space> steps_;
  Buffer<ContactClass, Space> classes_;
  Buffer<MeshObject<Real>, Space> meshes_;
  Buffer<Vec3<Real>, Space> mesh_vertex_, mesh_normal_, mesh_corner_;
  Buffer<int, Space> mesh_triangle_, mesh_neighbour_, mesh_adjacency_start_, mesh_adjacency_, mesh_bin_start_, mesh_bin_entry_,
      mesh_patch_;
  std::vector<long> longest_cell_;
  bool dynamic_ = false;
  double dt_ = 0;
};

}  // namespace blaze
