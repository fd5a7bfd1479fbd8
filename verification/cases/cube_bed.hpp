// A small bed of cubes falling in a box, the polyhedron scene several checks share (restart,
// pair evaluation): 64 cubes of data/shapes/cube.shape (2500 kg/m^3) from polyhedron_packing
// (random orientations on a loose lattice, seed 5), float, linear spring-dashpot k = 1e5 N/m with
// e = 0.5, history-free friction mu = 0.4, K_T = 0.05 kg/s, dt = t_c / 25 (m* = m / 2).
#pragma once
#include <cmath>
#include "blaze/shapes/polyhedron_shape.hpp"
#include "blaze/laws/standard_laws.hpp"
#include "pipeline/polyhedron_packing.hpp"
#include "blaze/shapes/shape_io.hpp"

namespace blaze::test::cases {

struct CubeBed {
  PolyhedronShape<float> shape;
  double dt = 0;  // s
  Packing<float> scene;
  LinearLaw<float> law;
};

inline CubeBed cube_bed() {
  CubeBed b;
  b.shape.table.add(load_shape("data/shapes/cube.shape"), 2500);
  const double k = 1e5, pi = 3.14159265358979323846;
  b.dt = pi * std::sqrt(0.5 * b.shape.table.type[0].mass / k) / 25;
  b.scene = polyhedron_packing(b.shape.table, 0, 64, 5, b.dt);
  b.law = {LinearSpringDashpot<float>::from_restitution(k, 0.5), HistoryFreeFriction<float>::make(0.4, 0.05)};
  return b;
}

}  // namespace blaze::test::cases
