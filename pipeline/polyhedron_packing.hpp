// Polyhedron beds on the sphere packing's lattice and walls (gravity_packing.hpp), one table type
// at each site, its bounding sphere where the sphere was.
//   polyhedron_packing: random orientations on a loose lattice: a bed falling under gravity.
//   packed_polyhedra (issue 6's "packed and in contact" benchmark state): a simple cubic lattice
//   at `pitch_ratio` times the shape's extent along the axes (both sides), inside six walls at
//   half a pitch from the outer sites. Sites alternate (checkerboard) between the table's own
//   orientation and that turned 90 degrees about x, and every body is then turned by a random
//   angle of up to `tilt` radians about a random axis. With pitch_ratio < 1 each body presses on
//   its six axial neighbours and the walls. The checkerboard matters for shapes whose extremes
//   along the axes are edges (the dodecahedron): parallel ridges pressed together slide off each
//   other and the bed lost its contacts within a few hundred steps; turned, the ridges cross (a
//   point contact, as crossed cylinders). For a cube it changes nothing. The dodecahedron bed
//   still relaxes: turning a body lowers its extent along the axes (to second order), so after
//   ~150 steps (at dt = t_c/25) the compression has gone into rotation and most contacts open;
//   cubes, face to face, keep theirs. Benchmarks measure within the first 100 steps. A lattice,
//   not a random packing: each cube also touches its 12 diagonal neighbours edge to edge (about
//   10 contacts per cube); a dodecahedron has 6 (a random packing of either has about 6 to 8).
#pragma once
#include <algorithm>
#include <cmath>
#include "blaze/shapes/polyhedron_shape.hpp"
#include "pipeline/gravity_packing.hpp"

namespace blaze {

// The sphere packing with a body of table type `type` at each site, oriented by orientation(k, rng)
// (body to world).
template <class Real, class Orientation>
Packing<Real> place_polyhedra(const PolyhedronTable<Real>& table, int type, int n, unsigned seed, double dt,
                              const PackingOptions& o, Orientation&& orientation) {
  PackingOptions spheres = o;
  spheres.radius_spread = 0;
  Packing<Real> p = gravity_packing<Real>(n, table.type[type].bounding_radius, seed, dt, spheres);
  std::mt19937_64 rng(seed + 1);
  ParticleState<Real> poly;
  poly.reserve(p.particles.size());
  for (std::size_t i = 0; i < p.particles.size(); ++i) {
    const Quat<double> q = orientation(static_cast<int>(i), rng);
    add_polyhedron(poly, table, type, p.particles.position[i], Quat<Real>{Real(q.w), Real(q.x), Real(q.y), Real(q.z)},
                   p.particles.material[i], p.particles.velocity[i]);
  }
  p.particles = std::move(poly);
  return p;
}

template <class Real>
Packing<Real> polyhedron_packing(const PolyhedronTable<Real>& table, int type, int n, unsigned seed, double dt,
                                 const PackingOptions& o = {}) {
  return place_polyhedra(table, type, n, seed, dt, o, [](int, std::mt19937_64& rng) {
    std::normal_distribution<double> g;
    const double w = g(rng), x = g(rng), y = g(rng), z = g(rng);  // in this order: the scenes stay as they were
    return normalized(Quat<double>{w, x, y, z});                   // uniform on SO(3)
  });
}

// The orientation that shows a shape as its file drew it: the table holds it in its principal
// frame (ConvexShape::axes_in_input), whose axes are arbitrary for isotropic shapes.
inline Quat<double> drawn_orientation(const ConvexShape& s) {
  const Eigen::Quaterniond q(s.axes_in_input);
  return {q.w(), q.x(), q.y(), q.z()};
}

// base: the orientation of the even sites, usually drawn_orientation(shape).
template <class Real>
Packing<Real> packed_polyhedra(const PolyhedronTable<Real>& table, int type, int n, unsigned seed, double dt,
                               const Quat<double>& base, double pitch_ratio = 0.99, double tilt = 0.01) {
  const PolyhedronData<Real>& d = table.type[type];
  const Mat3<double> rb = Mat3<double>::rotation(base);
  double extent = 0;  // largest |coordinate| of a vertex at the base orientation: the half-width along the axes
  for (int k = 0; k < d.vertex_count; ++k) {
    const Vec3<double> v = rb * vec_cast<double>(d.vertex[k]);
    extent = std::max({extent, std::abs(v.x), std::abs(v.y), std::abs(v.z)});
  }
  PackingOptions o;
  o.lattice = Lattice::cubic;
  o.pitch_in_radii = 2 * extent * pitch_ratio / d.bounding_radius;
  o.speed = 0.01;
  o.lid = true;
  const int side = lattice_side(n);
  const double r = std::sqrt(0.5);
  const Quat<double> quarter_turn{r, r, 0, 0};  // 90 degrees about x
  return place_polyhedra(table, type, n, seed, dt, o, [&](int k, std::mt19937_64& rng) {
    std::normal_distribution<double> g;
    std::uniform_real_distribution<double> u(0, 1);
    Vec3<double> axis{g(rng), g(rng), g(rng)};
    axis *= 1 / norm(axis);
    const double half_angle = 0.5 * tilt * u(rng);  // a turn of up to `tilt` about a random axis
    const double s = std::sin(half_angle);
    const Quat<double> turn{std::cos(half_angle), s * axis.x, s * axis.y, s * axis.z};
    const auto [ix, iy, iz] = lattice_cell(k, side);
    return (ix + iy + iz) % 2 == 1 ? turn * quarter_turn * base : turn * base;
  });
}

}  // namespace blaze
