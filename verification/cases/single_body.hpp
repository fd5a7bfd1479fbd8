// The thesis's section 3.3 scene (Fig 3.8b): a cube and a regular octahedron, both of bounding
// radius 0.25 cm, with the Hertzian normal law of eq. 3.6, F_n = K_n delta^(3/2), K_n = 1e9.
// The thesis writes K_n in "N.cm^-1"; the exponent 3/2 makes it N/m^(3/2), and it is used as such
// here. The thesis gives no density; 2500 kg/m^3 (glass) is assumed:
//   cube:       edge a = 2 R / sqrt(3) = 2.887 mm, m = rho a^3          = 6.01e-5 kg
//   octahedron: edge a = sqrt(2) R     = 3.536 mm, m = rho sqrt(2)/3 a^3 = 5.21e-5 kg
// Helpers to place them: shapes scaled from data/shapes/ and orientations that put a cube face or
// an octahedron vertex on a world axis (the body frame is the principal frame, which for these
// isotropic solids is any frame the eigen-solver returns, so directions are taken from the body
// frame's own vertices and normals).
#pragma once
#include <Eigen/Geometry>
#include <cmath>
#include <stdexcept>
#include <string>
#include "blaze/shapes/polyhedron_shape.hpp"
#include "blaze/shapes/shape_io.hpp"
#include "pipeline/simulation.hpp"

namespace blaze::test::cases {

constexpr double kThesisBoundingRadius = 2.5e-3;  // m (thesis section 3.3.1.1: 0.25 cm)
constexpr double kThesisDensity = 2500;           // kg/m^3 (assumed: the thesis gives none)
constexpr double kThesisKn = 1e9;                 // N/m^(3/2) (thesis: "N.cm^-1")

inline ConvexShape thesis_cube() { return load_scaled_shape("data/shapes/cube.shape", kThesisBoundingRadius); }
inline ConvexShape thesis_octahedron() { return load_scaled_shape("data/shapes/octahedron.shape", kThesisBoundingRadius); }

// The rotation taking the body-frame directions a1, a2 (orthogonal) to the world directions b1, b2.
template <class Real>
Quat<Real> orientation_mapping(Eigen::Vector3d a1, Eigen::Vector3d a2, Eigen::Vector3d b1, Eigen::Vector3d b2) {
  a1.normalize(), a2.normalize(), b1.normalize(), b2.normalize();
  if (std::fabs(a1.dot(a2)) > 1e-9 || std::fabs(b1.dot(b2)) > 1e-9)
    throw std::invalid_argument("orientation_mapping: direction pairs must be orthogonal");
  Eigen::Matrix3d a, b;
  a << a1, a2, a1.cross(a2);
  b << b1, b2, b1.cross(b2);
  const Eigen::Quaterniond q(Eigen::Matrix3d(b * a.transpose()));
  return normalized(Quat<Real>{static_cast<Real>(q.w()), static_cast<Real>(q.x()), static_cast<Real>(q.y()),
                               static_cast<Real>(q.z())});
}

// A face normal n0 of a cube and a second face normal perpendicular to it (body frame).
inline std::pair<Eigen::Vector3d, Eigen::Vector3d> cube_face_pair(const ConvexShape& cube) {
  for (std::size_t f = 1; f < cube.normals.size(); ++f)
    if (std::fabs(cube.normals[0].dot(cube.normals[f])) < 1e-9) return {cube.normals[0], cube.normals[f]};
  throw std::invalid_argument("cube_face_pair: no perpendicular faces");
}
// Cube with a face normal along world `face_dir` and another along world `side_dir` (orthogonal).
template <class Real>
Quat<Real> cube_facing(const ConvexShape& cube, const Eigen::Vector3d& face_dir, const Eigen::Vector3d& side_dir) {
  const auto [n0, n1] = cube_face_pair(cube);
  return orientation_mapping<Real>(n0, n1, face_dir, side_dir);
}
// Distance from the centre of mass to the face planes of a cube (all equal), m.
inline double cube_half_edge(const ConvexShape& cube) { return cube.normals[0].dot(cube.centroids[0]); }

// Octahedron with vertex 0 along world `vertex_dir` and a vertex perpendicular to it along `side_dir`.
template <class Real>
Quat<Real> octahedron_pointing(const ConvexShape& octa, const Eigen::Vector3d& vertex_dir, const Eigen::Vector3d& side_dir) {
  const Eigen::Vector3d v0 = octa.vertices[0];
  for (const auto& v : octa.vertices)
    if (std::fabs(v0.dot(v)) < 1e-9 * v0.squaredNorm()) return orientation_mapping<Real>(v0, v, vertex_dir, side_dir);
  throw std::invalid_argument("octahedron_pointing: no vertex perpendicular to vertex 0");
}

// One polyhedron of shape `body` (density in kg/m^3, table type 0, material 0) over the square
// floor `floor` (material 1), in the box [lo, hi] (m), under gravity g (m/s^2). The state form
// resumes a body from an earlier simulation's state() (e.g. with another time step).
template <class Law, class Integrator = VelocityVerlet>
using PolyhedronSim = Simulation<DefaultSpace, PolyhedronShape<typename Law::real_type>, Law, Integrator>;

template <class Law, class Integrator = VelocityVerlet>
PolyhedronSim<Law, Integrator> body_over_floor(const ConvexShape& body, double density, const Law& law,
                                               const PlanarPolygon<typename Law::real_type>& floor,
                                               const ParticleState<typename Law::real_type>& state,
                                               const Vec3<double>& g, double dt, const Vec3<double>& lo,
                                               const Vec3<double>& hi) {
  using Real = typename Law::real_type;
  PolyhedronShape<Real> shape;
  shape.table.add(body, density);
  PairTable<Law> laws;
  laws.set(0, 0, law);
  laws.set(0, 1, law);
  World<Real> world;
  world.polygons.push_back(floor);
  const SimulationParams<Real> prm{static_cast<Real>(dt), vec_cast<Real>(g), vec_cast<Real>(lo), vec_cast<Real>(hi),
                                   static_cast<Real>(0.2 * body.bounding_radius)};
  return PolyhedronSim<Law, Integrator>(prm, laws, world, state, shape);
}

template <class Law, class Integrator = VelocityVerlet>
PolyhedronSim<Law, Integrator> body_over_floor(const ConvexShape& body, double density, const Law& law,
                                               const PlanarPolygon<typename Law::real_type>& floor,
                                               const Quat<typename Law::real_type>& q, const Vec3<double>& x0,
                                               const Vec3<double>& v0, const Vec3<double>& g, double dt,
                                               const Vec3<double>& lo, const Vec3<double>& hi) {
  using Real = typename Law::real_type;
  PolyhedronTable<Real> table;
  table.add(body, density);
  ParticleState<Real> s;
  add_polyhedron(s, table, 0, vec_cast<Real>(x0), q, 0, vec_cast<Real>(v0));
  return body_over_floor<Law, Integrator>(body, density, law, floor, s, g, dt, lo, hi);
}

}  // namespace blaze::test::cases
