// Initial particle-world overlaps, checked at placement as particle-particle overlaps are
// (scene_build.hpp): a particle that starts inside a wall, across a wall's plane, outside a drum,
// or under a wall whose normal faces away from it is refused, naming the placement and the
// object. Without the check such scenes ended in the energy guard, which blamed the time step.
//
// Geometry, in double, with the walls' own definitions (planar_polygon.hpp, cylinder.hpp):
//   polygon, centre x, radius r:  d = (x - c) . n; with the foot point x - d n inside the polygon
//     the particle overlaps when d < r (polyhedra: a vertex with (v - c) . n < 0), and lies across
//     the wall when its centre is behind it (d <= 0) by less than its size; with the foot outside,
//     an active rim edge closer than r overlaps (spheres);
//   cylinder: with s = (x - a) . u in [0, L] and rho = |(x - a) - s u|, the particle overlaps when
//     rho + r > R (polyhedra: a vertex beyond R), and is outside the drum when rho > R;
//   a wall faces away when particles lie behind it within its outline, none in front, and gravity
//     draws them towards its back (g . n > 0): they would fall into the side it does not act on;
//     a wall or mesh faces away from a feed that throws its particles when every ray along the
//     feed's velocity that meets it first meets its back.
// Touching is allowed: an overlap up to `slack` (1e-9 of the largest size) is not one.
#pragma once
#include <cmath>
#include <string>
#include <vector>
#include "blaze/core/counter_random.hpp"
#include "blaze/scene/scene.hpp"
#include "blaze/scene/world_block.hpp"
#include "blaze/world/cylinder.hpp"
#include "blaze/world/mesh_bins.hpp"
#include "blaze/world/planar_polygon.hpp"

namespace blaze {

class WorldOverlapCheck {
  // The [mill]'s generated objects are named "mill <part>" (scene_toml.cpp): messages name the [mill].
  static bool is_mill(const std::string& name) { return name.rfind("mill ", 0) == 0; }
  std::string mill_name(const std::string& name) const {
    return "the [mill]'s " + name.substr(5) + " (" + s_.place("mill.diameter") + " = " + Scene::shortest(s_.mill.diameter) + " m)";
  }

 public:
  WorldOverlapCheck(const Scene& s, double slack) : s_(s), slack_(slack) {
    // The objects' names for messages, formed once (a check runs per particle and object).
    for (std::size_t k = 0; k < s.walls.size(); ++k) {
      polygons_.push_back(PlanarPolygon<double>::make(s.walls[k].vertices, 0, s.walls[k].rim_edges));
      mill_part_.push_back(is_mill(s.walls[k].name));
      polygon_names_.push_back(is_mill(s.walls[k].name)
                                   ? mill_name(s.walls[k].name)
                                   : "[[wall]] #" + std::to_string(k + 1) + " (" + s.place("wall[" + std::to_string(k) + "].vertices") + ")");
    }
    for (std::size_t k = 0; k < s.cylinders.size(); ++k) {
      const CylinderSpec& c = s.cylinders[k];
      cylinders_.push_back(Cylinder<double>::make(c.origin, c.axis, c.radius, c.length, 0));
      cylinder_names_.push_back(is_mill(c.name) ? mill_name(c.name)
                                                : "[[cylinder]] #" + std::to_string(k + 1) + " (" +
                                                      s.place("cylinder[" + std::to_string(k) + "].radius") + " = " +
                                                      Scene::shortest(c.radius) + " m)");
    }
    front_.assign(polygons_.size(), 0);
    behind_.assign(polygons_.size(), 0);
    aim_.assign(polygons_.size(), Aim{});
    double largest = 0;
    for (const auto& t : s.types) largest = std::fmax(largest, t.is_sphere() ? t.radius : t.bounding_radius);
    for (std::size_t k = 0; k < s.meshes.size(); ++k) {
      const TriangleMesh& m = s.meshes[k].mesh;
      mesh_bins_.push_back(bin_mesh(m, largest, std::fmax(largest, 1e-6 * std::fmax(m.extent(), 1e-300))));
      mesh_corners_.emplace_back();
      for (std::size_t t = 0; t < m.size(); ++t)
        for (int a = 0; a < 3; ++a) mesh_corners_.back().push_back(m.corner(t, a));
      mesh_names_.push_back("[[mesh]] #" + std::to_string(k + 1) + " '" + s.meshes[k].name + "' (" + s.place("mesh[" + std::to_string(k) + "].file") + ")");
    }
    mesh_facing_.assign(s.meshes.size(), MeshFacing{});
    // (the views point into the vectors above: moving the check keeps them, copying would not)
    for (std::size_t k = 0; k < mesh_bins_.size(); ++k) {
      const MeshBinsHost& b = mesh_bins_[k];
      mesh_views_.push_back({bins_view<double>(b, b.start.data(), b.entry.data()), mesh_corners_[k].data()});
    }
  }
  WorldOverlapCheck(const WorldOverlapCheck&) = delete;
  WorldOverlapCheck& operator=(const WorldOverlapCheck&) = delete;
  WorldOverlapCheck(WorldOverlapCheck&&) = default;

  // The sphere test over this check's arrays (world_block.hpp), on the host.
  WorldBlockView view() const {
    WorldBlockView v;
    v.cylinder = cylinders_.data(), v.cylinders = static_cast<int>(cylinders_.size());
    v.polygon = polygons_.data(), v.mill_part = mill_part_.data(), v.polygons = static_cast<int>(polygons_.size());
    v.mesh = mesh_views_.data(), v.meshes = static_cast<int>(mesh_views_.size());
    v.slack = slack_;
    return v;
  }
  // The arrays view() reads, for a copy where the particles live (kernels/placement.hpp).
  const std::vector<Cylinder<double>>& cylinders() const { return cylinders_; }
  const std::vector<PlanarPolygon<double>>& polygons() const { return polygons_; }
  const std::vector<std::uint8_t>& mill_parts() const { return mill_part_; }
  const std::vector<MeshBinsHost>& mesh_bins() const { return mesh_bins_; }
  const std::vector<std::vector<Vec3<double>>>& mesh_corners() const { return mesh_corners_; }
  double slack() const { return slack_; }

  // A particle of centre x and size r (bounding radius), with its vertices in the world frame
  // (empty for a sphere); `who` names it for the message. Throws SceneError on an overlap.
  void check(const Vec3<double>& x, double r, const std::vector<Vec3<double>>& vertices, const std::string& who) {
    for (std::size_t k = 0; k < polygons_.size(); ++k) check_polygon(k, x, r, vertices, who);
    for (std::size_t k = 0; k < cylinders_.size(); ++k) check_cylinder(k, x, r, vertices, who);
    for (std::size_t k = 0; k < mesh_bins_.size(); ++k) {
      look_down(k, x);
      const WorldBlockView::MeshTouch t = view().mesh_touch(static_cast<int>(k), x, r);
      if (t.triangle < 0) continue;
      const std::string at = " at its triangle " + std::to_string(s_.meshes[k].mesh.file_index[static_cast<std::size_t>(t.triangle)]) + " (in the file)";
      if (t.across) fail(who, x, mesh_names_[k] + at, "lies across, with its centre behind the face (the side its normal points away from),");
      fail(who, x, mesh_names_[k] + at, "overlaps by " + Scene::shortest(r - t.distance) + " m");
    }
  }

  // For random fills (scene_build.hpp): would check() refuse a particle here, does it lie behind
  // a [mill]'s end plate or lifter face it is over (at any depth: inside a lifter bar, beyond the
  // mill's ends), or outside a drum along its length? Counts nothing, throws nothing. (Behind a
  // user's wall deeper than its size a particle is let through, as check() does: finish() then
  // tells the user which wall faces away.)
  bool blocked(const Vec3<double>& x, double r, const std::vector<Vec3<double>>& vertices) const {
    const WorldBlockView world = view();
    if (vertices.empty()) return world.blocked(x, r);
    // A polyhedron: its centre as a sphere's for the drums' shells and the walls' backs, its
    // vertices for the overlaps. The drums first: one test each.
    for (const Cylinder<double>& c : cylinders_) {
      const double s = dot(x - c.origin, c.axis);
      if (!(s >= 0 && s <= c.length)) continue;
      if (norm(x - c.origin - s * c.axis) > c.radius) return true;
      for (const auto& v : vertices) {
        const double sv = dot(v - c.origin, c.axis);
        if (sv >= 0 && sv <= c.length && norm(v - c.origin - sv * c.axis) > c.radius + slack_) return true;
      }
    }
    for (std::size_t k = 0; k < polygons_.size(); ++k) {
      const PlanarPolygon<double>& w = polygons_[k];
      const double d = dot(x - w.centroid, w.normal);
      // as WorldBlockView::blocked (a polyhedron's vertex lies within r of x)
      if (d > 0 && norm2(x - w.centroid) > (w.bound + 2 * r) * (w.bound + 2 * r)) continue;
      const bool over = w.contains(x - d * w.normal);
      if (over && d <= 0 && (d > -r || mill_part_[k])) return true;
      if (!(d > 0 && d < r)) continue;
      for (const auto& v : vertices) {
        const double dv = dot(v - w.centroid, w.normal);
        if (dv < -slack_ && w.contains(v - dv * w.normal)) return true;
      }
    }
    for (int k = 0; k < world.meshes; ++k)
      if (world.mesh_touch(k, x, r).triangle >= 0) return true;
    return false;
  }

  // A feed's region as the particles it will place (stop 50: a scene of feeds alone was never
  // looked at): kRegionLooks centres drawn in it, counted over the walls and meshes as placed
  // particles are, so that finish() refuses a wall or mesh facing away from what falls onto it.
  // A feed that throws its particles (velocity not zero) is also looked at along its aim (stop 52:
  // a feed aimed sideways at the back of a wall was let through): from the same centres, the first
  // wall or mesh triangle a ray along the velocity meets, met from the front or the back.
  void look_from_region(const InsertionRegion& region, double r, const Vec3<double>& velocity = {0, 0, 0},
                        const std::string& feed = "") {
    CounterEngine rng(0x5eed, 0);
    const double speed = norm(velocity);
    for (int i = 0; i < kRegionLooks; ++i) {
      const Vec3<double> x = region.draw(rng, r);
      for (std::size_t k = 0; k < polygons_.size(); ++k) {
        const PlanarPolygon<double>& w = polygons_[k];
        const double d = dot(x - w.centroid, w.normal);
        if (w.contains(x - d * w.normal)) (d > 0 ? front_[k] : behind_[k]) += 1;
      }
      for (std::size_t k = 0; k < mesh_facing_.size(); ++k) look_down(k, x);
      if (speed > 0) look_along(x, velocity * (1 / speed), feed);
    }
  }

  // After every particle: walls that face away from all the particles over them. Not the [mill]'s
  // own faces, oriented by construction: an undercut lifter's face (face_angle < 0) looks down at
  // the shell, with the charge behind its plane and none over its front.
  void finish() const {
    for (std::size_t k = 0; k < polygons_.size(); ++k) {
      if (mill_part_[k]) continue;
      const Vec3<double> n = polygons_[k].normal;
      if (behind_[k] > 0 && front_[k] == 0 && dot(s_.gravity, n) > 0)
        throw SceneError(s_.place("wall[" + std::to_string(k) + "].vertices") + ": the wall faces away from the " +
                         std::to_string(behind_[k]) + " particles over it (normal " + vec_text(n) +
                         " by the right-hand rule of its vertex order, gravity draws them to its back, the side it does "
                         "not act on); list its vertices in the opposite order");
    }
    for (std::size_t k = 0; k < polygons_.size(); ++k)
      if (!mill_part_[k] && aim_[k].behind > 0 && aim_[k].front == 0)
        throw SceneError(s_.place("wall[" + std::to_string(k) + "].vertices") + ": the wall faces away from " + aim_[k].feed +
                         ", which throws its particles at its back (of " + std::to_string(kRegionLooks) + " rays along its velocity, " +
                         std::to_string(aim_[k].behind) + " meet this wall first, from behind; normal " + vec_text(polygons_[k].normal) +
                         " by the right-hand rule of its vertex order): list its vertices in the opposite order");
    for (std::size_t k = 0; k < mesh_facing_.size(); ++k) {
      const MeshFacing& f = mesh_facing_[k];
      if (f.aim.behind > 0 && f.aim.front == 0) {
        const TriangleMesh& m = s_.meshes[k].mesh;
        throw SceneError(s_.place("mesh[" + std::to_string(k) + "].file") + ": the mesh '" + s_.meshes[k].name + "' faces away from " +
                         f.aim.feed + ", which throws its particles at its back (of " + std::to_string(kRegionLooks) +
                         " rays along its velocity, " + std::to_string(f.aim.behind) + " meet this mesh first, from behind; triangle " +
                         std::to_string(m.file_index[static_cast<std::size_t>(f.aim.example)]) + " in the file, normal " +
                         vec_text(f.aim.normal) + " by the right-hand rule of its vertex order): set flip = " +
                         (s_.meshes[k].flip ? "false" : "true") + " or reverse the file's vertex order");
      }
    }
    for (std::size_t k = 0; k < mesh_facing_.size(); ++k) {
      const MeshFacing& f = mesh_facing_[k];
      if (f.behind > 0 && f.front == 0) {
        const TriangleMesh& m = s_.meshes[k].mesh;
        throw SceneError(s_.place("mesh[" + std::to_string(k) + "].file") + ": the mesh '" + s_.meshes[k].name + "' faces away from the particles over it: of " +
                         std::to_string(f.looked) + " looked at, the " + std::to_string(f.behind) +
                         " that gravity draws onto it meet its back first (the side it does not act on; triangle " +
                         std::to_string(m.file_index[static_cast<std::size_t>(f.example)]) + " in the file, normal " +
                         vec_text(f.normal) + " by the right-hand rule of its vertex order; a file's stored normals are ignored): "
                         "set flip = " + (s_.meshes[k].flip ? "false" : "true") + " or reverse the file's vertex order");
      }
    }
  }

 private:
  static std::string vec_text(const Vec3<double>& v) {
    return "(" + Scene::shortest(v.x) + ", " + Scene::shortest(v.y) + ", " + Scene::shortest(v.z) + ")";
  }
  [[noreturn]] void fail(const std::string& who, const Vec3<double>& x, const std::string& object, const std::string& what) const {
    throw SceneError(s_.path + ": " + who + " at " + vec_text(x) + " m " + what + " " + object +
                     " at the start; move the placement or the object");
  }

  void check_polygon(std::size_t k, const Vec3<double>& x, double r, const std::vector<Vec3<double>>& vertices,
                     const std::string& who) {
    const PlanarPolygon<double>& w = polygons_[k];
    const std::string& object = polygon_names_[k];
    const double d = dot(x - w.centroid, w.normal);
    // In front, out of reach (as blocked()), and a particle over the front already counted: only
    // the count's zero-ness is read (finish()), so nothing below would change.
    if (d > 0 && front_[k] > 0 && norm2(x - w.centroid) > (w.bound + 2 * r) * (w.bound + 2 * r)) return;
    const bool over = w.contains(x - d * w.normal);
    if (over) (d > 0 ? front_[k] : behind_[k]) += 1;
    if (over && d <= 0 && d > -r)
      fail(who, x, object, "lies across the plane of, with its centre " + Scene::shortest(-d) +
                               " m behind (the side the normal by the right-hand rule of the vertex order points away from),");
    if (vertices.empty()) {
      if (over && d > 0 && d < r - slack_) fail(who, x, object, "overlaps by " + Scene::shortest(r - d) + " m");
      if (!over && std::fabs(d) < r) {
        const double gap = WorldBlockView::rim_distance(w, x);
        if (gap < r - slack_) fail(who, x, object, "overlaps the rim by " + Scene::shortest(r - gap) + " m");
      }
      return;
    }
    if (!(d > 0 && d < r)) return;
    for (const auto& v : vertices) {
      const double dv = dot(v - w.centroid, w.normal);
      if (dv < -slack_ && w.contains(v - dv * w.normal))
        fail(who, x, object, "has a vertex " + Scene::shortest(-dv) + " m deep in");
    }
  }

  // A mesh faces away when the particles that gravity draws onto it meet its back: from centre x,
  // along g, the first triangle the ray crosses (Moller-Trumbore, every triangle: the first
  // kFacingLooks particles only), front (its normal against g) or back. Kept per mesh for finish().
  static constexpr long kFacingLooks = 256;
  static constexpr int kRegionLooks = 64;  // centres drawn in a feed's region (look_from_region)
  // A feed's aim met an object (look_along): rays that met it first from the front, from behind,
  // and the first feed that did so from behind (for the message).
  struct Aim {
    long front = 0, behind = 0;
    std::string feed;
    long example = -1;  // meshes: a triangle met from behind
    Vec3<double> normal{0, 0, 0};
  };
  struct MeshFacing {
    long looked = 0, front = 0, behind = 0;
    long example = -1;  // a triangle met from behind
    Vec3<double> normal{0, 0, 0};
    Aim aim;
  };
  // The first triangle of mesh k that the ray x + t d (t > 0, d a unit vector) crosses, or -1;
  // `along`: its t. Moller-Trumbore over every triangle.
  long first_triangle(std::size_t k, const Vec3<double>& x, const Vec3<double>& d, double& along) const {
    const TriangleMesh& m = s_.meshes[k].mesh;
    along = INFINITY;
    long hit = -1;
    for (std::size_t t = 0; t < m.size(); ++t) {
      const Vec3<double> a = m.corner(t, 0), e1 = m.corner(t, 1) - a, e2 = m.corner(t, 2) - a;
      const Vec3<double> p = cross(d, e2);
      const double det = dot(e1, p);
      if (std::fabs(det) < 1e-300) continue;  // the ray runs in its plane
      const Vec3<double> q = x - a;
      const double u = dot(q, p) / det;
      if (u < 0 || u > 1) continue;
      const Vec3<double> qe = cross(q, e1);
      const double v = dot(d, qe) / det;
      if (v < 0 || u + v > 1) continue;
      const double at = dot(e2, qe) / det;
      if (at > 0 && at < along) along = at, hit = static_cast<long>(t);
    }
    return hit;
  }
  Vec3<double> triangle_normal(std::size_t k, long hit) const {
    const TriangleMesh& m = s_.meshes[k].mesh;
    const std::size_t t = static_cast<std::size_t>(hit);
    return cross(m.corner(t, 1) - m.corner(t, 0), m.corner(t, 2) - m.corner(t, 0));
  }
  void look_down(std::size_t k, const Vec3<double>& x) {
    MeshFacing& f = mesh_facing_[k];
    const double g = norm(s_.gravity);
    if (!(g > 0) || f.looked >= kFacingLooks) return;
    ++f.looked;
    const Vec3<double> d = s_.gravity * (1 / g);
    double along = 0;
    const long hit = first_triangle(k, x, d, along);
    if (hit < 0) return;
    const Vec3<double> n = triangle_normal(k, hit);
    if (dot(n, d) < 0) {
      ++f.front;
    } else {
      ++f.behind;
      if (f.example < 0) f.example = hit, f.normal = n * (1 / norm(n));
    }
  }
  // From x along the unit vector d (a feed's aim): the first wall (the ray through its outline)
  // or mesh triangle, counted as met from the front (d against its normal) or from behind.
  void look_along(const Vec3<double>& x, const Vec3<double>& d, const std::string& feed) {
    double nearest = INFINITY;
    long wall = -1, mesh = -1, triangle = -1;
    for (std::size_t k = 0; k < polygons_.size(); ++k) {
      const PlanarPolygon<double>& w = polygons_[k];
      const double towards = dot(d, w.normal);
      if (std::fabs(towards) < 1e-12) continue;  // the ray runs along its plane
      const double t = dot(w.centroid - x, w.normal) / towards;
      if (t > 0 && t < nearest && w.contains(x + t * d)) nearest = t, wall = static_cast<long>(k);
    }
    for (std::size_t k = 0; k < mesh_facing_.size(); ++k) {
      double along = 0;
      const long hit = first_triangle(k, x, d, along);
      if (hit >= 0 && along < nearest) nearest = along, wall = -1, mesh = static_cast<long>(k), triangle = hit;
    }
    const auto count = [&](Aim& a, const Vec3<double>& n, long example) {
      if (dot(n, d) < 0) return void(++a.front);
      if (a.behind++ == 0) a.feed = feed, a.example = example, a.normal = n * (1 / norm(n));
    };
    if (wall >= 0) count(aim_[static_cast<std::size_t>(wall)], polygons_[static_cast<std::size_t>(wall)].normal, -1);
    if (mesh >= 0) count(mesh_facing_[static_cast<std::size_t>(mesh)].aim, triangle_normal(static_cast<std::size_t>(mesh), triangle), triangle);
  }

  void check_cylinder(std::size_t k, const Vec3<double>& x, double r, const std::vector<Vec3<double>>& vertices,
                      const std::string& who) const {
    const Cylinder<double>& c = cylinders_[k];
    const std::string& object = cylinder_names_[k];
    const auto radial = [&](const Vec3<double>& p, double& s) {
      s = dot(p - c.origin, c.axis);
      return norm(p - c.origin - s * c.axis);
    };
    double s = 0;
    const double rho = radial(x, s);
    if (!(s >= 0 && s <= c.length)) return;
    if (r >= c.radius) fail(who, x, object, "is wider (size " + Scene::shortest(r) + " m) than");
    if (rho > c.radius) fail(who, x, object, "is outside (" + Scene::shortest(rho) + " m from the axis; particles live inside)");
    if (vertices.empty()) {
      if (rho + r > c.radius + slack_) fail(who, x, object, "overlaps by " + Scene::shortest(rho + r - c.radius) + " m");
      return;
    }
    for (const auto& v : vertices) {
      double sv = 0;
      const double rv = radial(v, sv);
      if (sv >= 0 && sv <= c.length && rv > c.radius + slack_)
        fail(who, x, object, "has a vertex " + Scene::shortest(rv - c.radius) + " m deep in");
    }
  }

  const Scene& s_;
  double slack_;
  std::vector<PlanarPolygon<double>> polygons_;
  std::vector<std::uint8_t> mill_part_;  // per polygon: generated by the [mill] (its back is the mill's outside)
  std::vector<Cylinder<double>> cylinders_;
  std::vector<std::string> polygon_names_, cylinder_names_, mesh_names_;
  std::vector<MeshBinsHost> mesh_bins_;
  std::vector<std::vector<Vec3<double>>> mesh_corners_;  // per mesh: 3 a triangle
  std::vector<MeshBlockView> mesh_views_;
  std::vector<long> front_, behind_;
  std::vector<Aim> aim_;  // per polygon: the feeds' aims (look_along)
  std::vector<MeshFacing> mesh_facing_;
};

}  // namespace blaze
