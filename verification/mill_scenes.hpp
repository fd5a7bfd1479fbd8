// A small mill shared by the cases of moving worlds (test_world_lists.cpp, test_in_block_rebuild.cpp,
// test_triangle_lists.cpp's balls):
// the 0.3 m drum with four 2 cm lifters of test_energy_ledger.cpp, and a bed of its balls.
#pragma once
#include <cmath>
#include "blaze/scene/mill_geometry.hpp"
#include "verification/scenes.hpp"

namespace blaze::test {

// The drum (0.3 m x 0.06 m, axis z) with four 2 cm lifters, turning at `rpm` after a ramp (s).
template <class Real>
World<Real> small_mill(double rpm, double ramp) {
  MillSpec mill;
  mill.axis = {0, 0, 1}, mill.diameter = 0.3, mill.length = 0.06, mill.omega = rpm * 2 * kPi / 60, mill.ramp = ramp;
  mill.lifters.push_back({4, 0.02, 0.02, 0, 0});
  World<Real> w;
  for (const MillWall& mw : mill_walls(mill)) w.polygons.push_back(PlanarPolygon<Real>::make(mw.vertices, 1, mw.rim_edges));
  w.cylinders.push_back(Cylinder<Real>::make({0, 0, -0.03}, {0, 0, 1}, 0.15, 0.06, 1));
  w.motions.assign(static_cast<std::size_t>(w.object_count()), mill_motion(mill));
  return w;
}
// Balls of radius r (7800 kg/m^3) on a 22 mm lattice in a drum's lower half (axis z, 6 cm
// long): two layers from y = bottom up, within `reach` (m) of the axis.
template <class Real>
ParticleState<Real> mill_balls(double r, double bottom = -0.115, double reach = 0.105) {
  ParticleState<Real> s;
  for (double x = -0.11; x < 0.111; x += 0.022)
    for (double y = bottom; y < -0.005; y += 0.022)
      for (double z : {-0.0125, 0.0125})
        if (std::hypot(x, y) < reach) s.add_sphere(vec_cast<Real>(Vec3<double>{x, y, z}), Real(r), Real(7800), 0);
  return s;
}

}  // namespace blaze::test
