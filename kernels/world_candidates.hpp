// World lists (issue 19): per particle, the world objects it may touch before the next rebuild,
// so the world kernel tests those instead of every object (a mill's 99 shell, end-plate and
// lifter faces: the thesis's 2D mill; 64 lifter rows of a SAG mill).
// Built at each neighbour-list rebuild from the bounding sphere (x_i, r_i) and the objects as
// placed then: object w is listed when some point of it lies within r_i + m of x_i
// (within_reach, planar_polygon.hpp and cylinder.hpp; 1e-4 more for rounding; a mesh when its
// bins, built with that reach or more, list triangles in x_i's cell). The list stays valid while no particle
// has moved more than skin / 2 (the rebuild check) and no point of a moving object has moved
// more than skin / 2: m is the skin when objects move, skin / 2 in a still world, so a body
// inside its bounding sphere that touches w later was within reach of it at the build. The rebuild check (broad_phase_kernels.hpp)
// also trips when the world's step passes the last step the objects' peak speeds allow
// (pipeline/world_candidates.hpp). Objects are listed in index order, so the world kernel sums
// its contacts in the same order as a full pass: the forces are bitwise those of the full pass.
// A particle with more than kWorldCandidates objects in reach is marked and tests every object.
// Triangle lists (issue 20): with `triangle` given, the same build lists the mesh triangles within
// the same reach of x_i (triangle_near: its nearest point, in the mesh's frame as placed then;
// in ascending index, as its bins' cell lists them), and a mesh is listed only when some of its
// triangles are. The mesh contact then tests those few instead of its cell's (at 1e5 triangles
// ~40 for a ball near the dense bed's wall): a triangle it can touch before the next rebuild
// lies within r_i + m now, by the argument above, and one farther than the particle's
// bounding radius offers no contact (mesh_wall.hpp, polyhedron_shape.hpp), so the contacts are
// bitwise those of the cell's triangles. For spheres the triangles of a flat patch other than the
// one a sphere lies well over leave the list (drop_flat_neighbours, mesh_wall.hpp: they cannot
// offer it a contact before the next rebuild; not while objects rotate, pipeline/world_candidates.hpp). The count is kept even past the room (up to 65535), so
// the pipeline grows the room to fit; a particle past it tests its cell.
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
  // m: how far a particle may move relative to an object before the next rebuild (skin / 2 in a
  // still world, the skin when objects move: pipeline/world_candidates.hpp)
  Real margin;
  std::uint16_t* object;
  std::uint8_t* count;
  Index stride;
  int* triangle = nullptr;  // triangle lists (null: none)
  std::uint16_t* triangle_count = nullptr;
  int triangle_capacity = 0;
  bool drop_flat = false;  // spheres: a flat patch's far triangles leave the list (drop_flat_neighbours)

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
    int tc = 0;
    for (int k = 0; k < world.mesh_count; ++k, ++w) {
      if (world.pose && !world.pose[w].active) continue;
      if (!triangle) {  // its bins' reach covers reach (mesh_wall.hpp)
        take(mesh_near(x, world.meshes[k], world.pose_of(w)), w);
        continue;
      }
      const Pose<Real>* pose = world.pose_of(w);
      const Vec3<Real> xr = pose ? pose->to_reference(x) : x;
      int found = 0;
      const int first = tc;
      for_each_near_triangle(world.meshes[k], xr, TriangleList{}, [&](int t) {
        if (!triangle_near(world.surface, t, xr, reach)) return;
        if (tc < triangle_capacity) triangle[static_cast<std::size_t>(tc) * stride + i] = t;
        if (tc < 65535) ++tc;
        ++found;
      });
      if (drop_flat && found > 1 && tc <= triangle_capacity) {  // all of them stored
        found = drop_flat_neighbours(world.surface, xr, radius[i], margin, triangle + static_cast<std::size_t>(first) * stride + i,
                                     static_cast<std::size_t>(stride), found);
        tc = first + found;
      }
      take(found > 0, w);
    }
    if (triangle) triangle_count[i] = static_cast<std::uint16_t>(tc);
    count[i] = c > kWorldCandidates ? kWorldCandidatesOverflow : static_cast<std::uint8_t>(c);
  }
};

// The in-block rebuild's last phase (pipeline/in_block_rebuild.hpp): the world lists built again
// for the particles as they are and the world as it stands (world step *world_step; null in a
// still world), valid for valid_steps more; particle 0 counts the build (with the neighbour
// list's, built before it).
template <class Real>
struct WorldListsInPlace {
  BuildWorldCandidates<Real> build;
  bool lists;  // world lists kept (without triangle lists: the host builds those)
  const std::uint64_t* world_step;
  std::uint64_t valid_steps;
  std::uint64_t* valid_until;     // the rebuild check's (pipeline/world_candidates.hpp)
  std::uint64_t* list_builds;     // world lists built in place
  std::uint64_t* neighbour_builds;  // neighbour lists built in place
  BLAZE_HD void operator()(Index i) const {
    if (lists) build(i);
    if (i != 0) return;
    ++*neighbour_builds;
    if (!lists) return;
    ++*list_builds;
    if (!world_step) return;  // a still world: the lists hold until particles move
    const std::uint64_t s = *world_step;
    *valid_until = s > ~std::uint64_t{0} - valid_steps ? ~std::uint64_t{0} : s + valid_steps;
  }
};

}  // namespace blaze
