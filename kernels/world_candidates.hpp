// World lists (issue 19): per particle, the world objects it may touch before the next rebuild,
// so the world kernel tests those instead of every object (a mill's 99 shell, end-plate and
// lifter faces: the thesis's 2D mill; 64 lifter rows of a SAG mill).
// Built at each neighbour-list rebuild from the bounding sphere (x_i, r_i) and the objects as
// placed then: object w is listed when some point of it lies within r_i + skin of x_i
// (within_reach, planar_polygon.hpp and cylinder.hpp; 1e-4 more for rounding; a mesh when its
// bins, built with that reach or more, list triangles in x_i's cell). The list stays valid while no particle
// has moved more than skin / 2 (the rebuild check) and no point of a moving object has moved
// more than skin / 2: together less than the skin, so a body inside its bounding sphere that
// touches w later was within reach of it at the build. The rebuild check (broad_phase_kernels.hpp)
// also trips when the world's step passes the last step the objects' peak speeds allow
// (pipeline/world_candidates.hpp). Objects are listed in index order, so the world kernel sums
// its contacts in the same order as a full pass: the forces are bitwise those of the full pass.
// A particle with more than kWorldCandidates objects in reach is marked and tests every object.
#pragma once
#include <cstdint>
#include "blaze/exec/launch.hpp"
#include "blaze/world/world.hpp"

namespace blaze {

template <class Real>
struct BuildWorldCandidates {
  Vec3Field<Real> position;
  const Real* radius;
  WorldView<Real> world;
  Real margin;  // m, the skin
  std::uint16_t* object;
  std::uint8_t* count;
  Index stride;

  BLAZE_HD void operator()(Index i) const {
    const Vec3<Real> x = position.get(i);
    // 1e-4 more for rounding: the list must hold every contact the world kernel finds, which it
    // computes in the same precision from differently formed terms.
    const Real reach = (radius[i] + margin) * Real(1.0001);
    int c = 0;
    const auto take = [&](bool near, int w) {
      if (!near || c > kWorldCandidates) return;
      if (c < kWorldCandidates) object[static_cast<std::size_t>(c) * stride + i] = static_cast<std::uint16_t>(w);
      ++c;
    };
    int w = 0;
    for (int k = 0; k < world.polygon_count; ++k, ++w)
      if (!world.pose || world.pose[w].active) take(within_reach(x, reach, world.polygons[k]), w);
    for (int k = 0; k < world.cylinder_count; ++k, ++w)
      if (!world.pose || world.pose[w].active) take(within_reach(x, reach, world.cylinders[k]), w);
    for (int k = 0; k < world.mesh_count; ++k, ++w)  // its bins' reach covers reach (mesh_wall.hpp)
      if (!world.pose || world.pose[w].active) take(mesh_near(x, world.meshes[k], world.pose_of(w)), w);
    count[i] = c > kWorldCandidates ? kWorldCandidatesOverflow : static_cast<std::uint8_t>(c);
  }
};

}  // namespace blaze
