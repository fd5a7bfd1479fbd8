// The move-world phase (issue 19): the first phase of a step in a world with moving or removable
// objects. Object o (polygons, cylinders, meshes) advances its step count and takes its pose at
// t = step dt (blaze/world/motion.hpp): a polygon's or cylinder's current geometry is the
// reference geometry placed by that pose (a mesh keeps its reference vertices: the world kernel
// takes the particle into its frame), its pose (velocity field, active flag) is what the world
// kernel reads. The phase
// runs over the particles [0, n) like every phase; thread i moves objects i, i + n, ... so any
// number of objects is moved by any number of particles (n >= 1; with no particle left the world
// stands still, and nothing touches it).
#pragma once
#include "blaze/exec/launch.hpp"
#include "blaze/world/world.hpp"

namespace blaze {

template <class Real>
struct MoveWorld {
  WorldMotionView<Real> w;
  Index n;  // the particles the phase runs over

  BLAZE_HD void operator()(Index i) const {
    const int objects = w.polygon_count + w.cylinder_count + w.mesh_count;
    for (long o = i; o < objects; o += n) {
      const std::uint64_t s = w.step[o] + 1;
      const Motion m = w.motion[o];
      // The reference geometry is read first (its load overlaps the pose's arithmetic), and the
      // pose is formed once, before the object's kind branches: a warp whose threads hold both
      // polygons and cylinders took the branches in turn, forming the pose (double-precision
      // sine and cosine: most of this phase's chain) twice.
      const bool polygon = o < w.polygon_count, cylinder = !polygon && o < w.polygon_count + w.cylinder_count;
      PlanarPolygon<Real> polygon_ref;
      Cylinder<Real> cylinder_ref;
      if (polygon) polygon_ref = w.polygon_ref[o];
      else if (cylinder) cylinder_ref = w.cylinder_ref[o - w.polygon_count];
      const Pose<Real> p = pose_at<Real>(m, static_cast<double>(s) * w.dt);
      if (polygon) w.polygons[o] = moved(polygon_ref, p);
      else if (cylinder) w.cylinders[o - w.polygon_count] = moved(cylinder_ref, p);
      w.step[o] = s;
      w.pose[o] = p;
    }
  }
};

}  // namespace blaze
