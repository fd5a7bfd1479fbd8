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
//     draws them towards its back (g . n > 0): they would fall into the side it does not act on.
// Touching is allowed: an overlap up to `slack` (1e-9 of the largest size) is not one.
#pragma once
#include <cmath>
#include <string>
#include <vector>
#include "blaze/scene/scene.hpp"
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
    double largest = 0;
    for (const auto& t : s.types) largest = std::fmax(largest, t.is_sphere() ? t.radius : t.bounding_radius);
    for (std::size_t k = 0; k < s.meshes.size(); ++k) {
      const TriangleMesh& m = s.meshes[k].mesh;
      mesh_bins_.push_back(bin_mesh(m, largest, std::fmax(largest, 1e-6 * std::fmax(m.extent(), 1e-300))));
      mesh_names_.push_back("[[mesh]] #" + std::to_string(k + 1) + " '" + s.meshes[k].name + "' (" + s.place("mesh[" + std::to_string(k) + "].file") + ")");
    }
  }

  // A particle of centre x and size r (bounding radius), with its vertices in the world frame
  // (empty for a sphere); `who` names it for the message. Throws SceneError on an overlap.
  void check(const Vec3<double>& x, double r, const std::vector<Vec3<double>>& vertices, const std::string& who) {
    for (std::size_t k = 0; k < polygons_.size(); ++k) check_polygon(k, x, r, vertices, who);
    for (std::size_t k = 0; k < cylinders_.size(); ++k) check_cylinder(k, x, r, vertices, who);
    for (std::size_t k = 0; k < mesh_bins_.size(); ++k) {
      const MeshTouch t = mesh_touch(k, x, r);
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
    // The drums first: one test each, and they refuse every draw outside the shell.
    for (const Cylinder<double>& c : cylinders_) {
      const double s = dot(x - c.origin, c.axis);
      if (!(s >= 0 && s <= c.length)) continue;
      const double rho = norm(x - c.origin - s * c.axis);
      if (vertices.empty()) {
        if (rho + r > c.radius + slack_) return true;
        continue;
      }
      if (rho > c.radius) return true;
      for (const auto& v : vertices) {
        const double sv = dot(v - c.origin, c.axis);
        if (sv >= 0 && sv <= c.length && norm(v - c.origin - sv * c.axis) > c.radius + slack_) return true;
      }
    }
    for (std::size_t k = 0; k < polygons_.size(); ++k) {
      const PlanarPolygon<double>& w = polygons_[k];
      const double d = dot(x - w.centroid, w.normal);
      // In front and beyond bound + 2 r of the centroid: no point of the polygon is within r of x
      // or of its projection, so nothing below can refuse it (a polyhedron's vertex lies within
      // r of x; skipping the point-in-polygon tests matters for a mill's hundreds of faces).
      if (d > 0 && norm2(x - w.centroid) > (w.bound + 2 * r) * (w.bound + 2 * r)) continue;
      const bool over = w.contains(x - d * w.normal);
      if (over && d <= 0 && (d > -r || mill_part_[k])) return true;
      if (over && d <= 0) continue;  // behind a user's wall, deeper than the particle's size
      if (vertices.empty()) {
        if (over && d < r - slack_) return true;
        if (!over && std::fabs(d) < r && rim_distance(w, x) < r - slack_) return true;
        continue;
      }
      if (!(d > 0 && d < r)) continue;
      for (const auto& v : vertices) {
        const double dv = dot(v - w.centroid, w.normal);
        if (dv < -slack_ && w.contains(v - dv * w.normal)) return true;
      }
    }
    for (std::size_t k = 0; k < mesh_bins_.size(); ++k)
      if (mesh_touch(k, x, r).triangle >= 0) return true;
    return false;
  }

  // After every particle: walls that face away from all the particles over them.
  void finish() const {
    for (std::size_t k = 0; k < polygons_.size(); ++k) {
      const Vec3<double> n = polygons_[k].normal;
      if (behind_[k] > 0 && front_[k] == 0 && dot(s_.gravity, n) > 0)
        throw SceneError(s_.place("wall[" + std::to_string(k) + "].vertices") + ": the wall faces away from the " +
                         std::to_string(behind_[k]) + " particles over it (normal " + vec_text(n) +
                         " by the right-hand rule of its vertex order, gravity draws them to its back, the side it does "
                         "not act on); list its vertices in the opposite order");
    }
  }

 private:
  // The triangle of mesh k nearest x within r - slack (or across it within r), or none.
  struct MeshTouch {
    int triangle = -1;
    double distance = 0;
    bool across = false;
  };
  MeshTouch mesh_touch(std::size_t k, const Vec3<double>& x, double r) const {
    const MeshBinsHost& b = mesh_bins_[k];
    const TriangleMesh& m = s_.meshes[k].mesh;
    const Vec3<double> g = (x - b.origin) * (1 / b.cell);
    MeshTouch best;
    if (!(g.x >= 0 && g.y >= 0 && g.z >= 0)) return best;
    const long i = static_cast<long>(g.x), j = static_cast<long>(g.y), l = static_cast<long>(g.z);
    if (i >= b.nx || j >= b.ny || l >= b.nz) return best;
    const std::size_t c = static_cast<std::size_t>((l * b.ny + j) * b.nx + i);
    double nearest = r - slack_;
    for (int e = b.start[c]; e < b.start[c + 1]; ++e) {
      const auto t = static_cast<std::size_t>(b.entry[static_cast<std::size_t>(e)]);
      const Vec3<double> p0 = m.corner(t, 0), p1 = m.corner(t, 1), p2 = m.corner(t, 2);
      const Vec3<double> n = cross(p1 - p0, p2 - p0) * (1 / norm(cross(p1 - p0, p2 - p0)));
      const double d = dot(x - p0, n);
      const Vec3<double> q = x - d * n;
      const bool over = dot(cross(p1 - p0, q - p0), n) >= 0 && dot(cross(p2 - p1, q - p1), n) >= 0 && dot(cross(p0 - p2, q - p2), n) >= 0;
      if (over && d <= 0 && d > -r) return {static_cast<int>(t), -d, true};
      double dist = over ? std::fabs(d) : INFINITY;
      if (!over)
        for (int a = 0; a < 3; ++a) {
          const Vec3<double> u = m.corner(t, a), v = m.corner(t, (a + 1) % 3), uv = v - u;
          const double s = std::fmin(1.0, std::fmax(0.0, dot(x - u, uv) / norm2(uv)));
          dist = std::fmin(dist, norm(x - (u + s * uv)));
        }
      if (dist < nearest) nearest = dist, best = {static_cast<int>(t), dist, false};
    }
    return best;
  }
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
        const double gap = rim_distance(w, x);
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

  // Distance from x to the nearest active rim edge of w (infinite when none is active).
  static double rim_distance(const PlanarPolygon<double>& w, const Vec3<double>& x) {
    double best = INFINITY;
    for (int e = 0; e < w.vertex_count; ++e) {
      if (!((w.active_edges >> e) & 1u)) continue;
      const Vec3<double> a = w.vertex[e], b = w.vertex[e + 1 < w.vertex_count ? e + 1 : 0], ab = b - a;
      const double t = std::fmin(1.0, std::fmax(0.0, dot(x - a, ab) / norm2(ab)));
      best = std::fmin(best, norm(x - (a + t * ab)));
    }
    return best;
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
  std::vector<char> mill_part_;  // per polygon: generated by the [mill] (its back is the mill's outside)
  std::vector<Cylinder<double>> cylinders_;
  std::vector<std::string> polygon_names_, cylinder_names_, mesh_names_;
  std::vector<MeshBinsHost> mesh_bins_;
  std::vector<long> front_, behind_;
};

}  // namespace blaze
