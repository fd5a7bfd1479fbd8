// A tumbling mill as world objects (issue 19; thesis chapter 4): a drum shell (internal cylinder),
// two end plates and rows of lifters, all turning with the drum. A lifter row is a prismatic bar
// along the drum's axis whose cross-section is a trapezoid standing on the shell: base width w
// (where it meets the shell), height h (radially inwards), its two faces leaning by the face angle
// alpha from the radial direction (alpha = 0: a rectangular bar; the top is w - 2 h tan(alpha)
// wide). The bar is built from planar polygons: its top and its two faces; its ends lie on the end
// plates and its base on the shell, so neither is needed. Each convex edge of the bar (top-face
// edges) is contactable from the top face only, so a ball on an edge feels it once, and edges
// meeting the shell or the end plates are not contactable (they are corners of the container).
// The thesis's mills (section 4.2.1: eight 4 cm square lifters; 4.3: 64 high-low rows) are rows
// of this kind: a high-low pattern is two lifter sets with different heights and offsets.
//
// Frame: the drum's axis a (unit) through `centre` (m, the middle of the drum); angles phi (deg)
// of the rows are measured about a from a reference direction e1 perpendicular to a (the world's
// y axis projected, or x when a is along y: phi = 0 points "down" for a horizontal drum with y up
// only if e1 = -y, so e1 is -y projected: phi = 0 is the bottom of the drum).
#pragma once
#include <cmath>
#include <stdexcept>
#include <string>
#include <vector>
#include "blaze/particles/energy_ledger.hpp"
#include "blaze/world/motion.hpp"
#include "blaze/world/planar_polygon.hpp"

namespace blaze {

struct LifterRowSpec {
  int count = 0;             // rows, evenly spaced
  double height = 0;         // m, radially inwards from the shell
  double width = 0;          // m, at the shell
  double face_angle = 0;     // deg, each face's lean from the radial direction (0: rectangular)
  double offset = 0;         // deg, the first row's angle phi
};

struct MillSpec {
  bool present = false;
  int material = 0;
  Vec3<double> centre{0, 0, 0};  // m, middle of the drum
  Vec3<double> axis{0, 0, 1};    // unit
  double diameter = 0;           // m, inside the shell
  double length = 0;             // m, between the end plates
  // false: no end plates, for a slice of a long mill with the domain periodic along the axis
  bool end_plates = true;
  double omega = 0;              // rad/s, about axis (right-hand rule)
  double ramp = 0;               // s
  double start = 0;              // s
  std::vector<LifterRowSpec> lifters;
};

// One generated wall: its polygon's vertices (outward normal by the right-hand rule), rim mask and
// a name saying what it is ("shell", "end plate", "lifter").
struct MillWall {
  std::vector<Vec3<double>> vertices;
  std::uint32_t rim_edges;
  std::string name;
  ContactClass contact_class;  // its dissipation's account (energy_ledger.hpp)
};

namespace mill_detail {

// The face through `v` with the normal facing `outward`, its edges from `a` to `b` (pairs of
// vertex indices in `v`'s order, either direction) contactable, the others not.
inline MillWall face(std::vector<Vec3<double>> v, const Vec3<double>& outward, const std::vector<std::pair<int, int>>& active,
                     const std::string& name) {
  const int n = static_cast<int>(v.size());
  std::vector<int> order(n);
  for (int k = 0; k < n; ++k) order[k] = k;
  const Vec3<double> normal = cross(v[1] - v[0], v[2] - v[1]);
  if (dot(normal, outward) < 0)
    for (int k = 0; k < n; ++k) order[k] = n - 1 - k;
  MillWall w{{}, 0u, name, name == "lifter" ? ContactClass::lifter : name == "end plate" ? ContactClass::end_plate : ContactClass::wall};
  for (int k = 0; k < n; ++k) w.vertices.push_back(v[order[k]]);
  for (int k = 0; k < n; ++k) {
    const int a = order[k], b = order[(k + 1) % n];
    for (const auto& [p, q] : active)
      if ((a == p && b == q) || (a == q && b == p)) w.rim_edges |= 1u << k;
  }
  return w;
}

}  // namespace mill_detail

// The reference direction phi = 0 (unit, perpendicular to the axis) and the third axis e2 = a x e1.
inline void mill_frame(const Vec3<double>& a, Vec3<double>& e1, Vec3<double>& e2) {
  Vec3<double> down{0, -1, 0};
  if (std::fabs(dot(down, a)) > 0.99) down = {1, 0, 0};
  e1 = down - a * dot(down, a);
  e1 = e1 * (1 / norm(e1));
  e2 = cross(a, e1);
}

// The mill's planar walls (end plates unless m.end_plates is false, then every lifter's top and
// faces); the shell is the
// cylinder of mill_shell(). Throws std::invalid_argument naming what does not fit.
inline std::vector<MillWall> mill_walls(const MillSpec& m) {
  using V = Vec3<double>;
  const double r = 0.5 * m.diameter, half = 0.5 * m.length;
  const V a = m.axis * (1 / norm(m.axis));
  V e1, e2;
  mill_frame(a, e1, e2);
  std::vector<MillWall> out;
  // End plates: squares circumscribing the shell, normals into the drum; their edges lie outside
  // the shell, where no particle comes (not contactable).
  for (double side : {-1.0, 1.0}) {
    if (!m.end_plates) break;
    const V c = m.centre + a * (side * half);
    const double s = 1.05 * r;
    std::vector<V> v = {c + e1 * s + e2 * s, c - e1 * s + e2 * s, c - e1 * s - e2 * s, c + e1 * s - e2 * s};
    out.push_back(mill_detail::face(v, a * -side, {}, "end plate"));
  }
  for (std::size_t set = 0; set < m.lifters.size(); ++set) {
    const LifterRowSpec& l = m.lifters[set];
    const double lean = l.face_angle * 3.14159265358979323846 / 180;
    const double top = l.width - 2 * l.height * std::tan(lean);
    if (!(l.height > 0 && l.height < r)) throw std::invalid_argument("lifter height must lie in (0, the drum's radius)");
    if (!(l.width > 0 && l.width < r)) throw std::invalid_argument("lifter width must lie in (0, the drum's radius)");
    if (!(std::fabs(l.face_angle) < 60)) throw std::invalid_argument("lifter face_angle must lie in (-60, 60) deg");
    if (!(top > 1e-6 * l.width)) throw std::invalid_argument("lifter faces meet below the top: height tan(face_angle) must stay below width / 2");
    for (int k = 0; k < l.count; ++k) {
      const double phi = (l.offset + 360.0 * k / l.count) * 3.14159265358979323846 / 180;
      const V radial = e1 * std::cos(phi) + e2 * std::sin(phi);  // from the axis out to the shell
      const V across = cross(a, radial);                         // tangential, the bar's width
      // base corners on the shell (on the circle), top corners h further in
      const double base_depth = std::sqrt(r * r - 0.25 * l.width * l.width);
      const V b0 = m.centre + radial * base_depth - across * (0.5 * l.width), b1 = m.centre + radial * base_depth + across * (0.5 * l.width);
      const V t0 = m.centre + radial * (base_depth - l.height) - across * (0.5 * top);
      const V t1 = m.centre + radial * (base_depth - l.height) + across * (0.5 * top);
      const V lo = a * -half, hi = a * half;
      // top: t0, t1 along both ends; its long edges (t0-t0', t1-t1') are the bar's convex edges
      out.push_back(mill_detail::face({t0 + lo, t1 + lo, t1 + hi, t0 + hi}, radial * -1.0, {{1, 2}, {3, 0}}, "lifter"));
      // faces: from the base corner to the top corner, no contactable edge
      const V n0 = cross(a, t0 - b0), n1 = cross(t1 - b1, a);
      out.push_back(mill_detail::face({b0 + lo, t0 + lo, t0 + hi, b0 + hi}, dot(n0, across) < 0 ? n0 : n0 * -1.0, {}, "lifter"));
      out.push_back(mill_detail::face({b1 + lo, t1 + lo, t1 + hi, b1 + hi}, dot(n1, across) > 0 ? n1 : n1 * -1.0, {}, "lifter"));
    }
  }
  return out;
}

// The rotation all of the mill's objects share.
inline Motion mill_motion(const MillSpec& m) {
  Motion mo;
  mo.kind = MotionKind::rotation;
  mo.axis = m.axis * (1 / norm(m.axis));
  mo.point = m.centre;
  mo.omega = m.omega;
  mo.ramp = m.ramp;
  mo.start = m.start;
  return mo;
}

}  // namespace blaze
