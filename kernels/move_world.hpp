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
      const std::uint64_t s = ++w.step[o];
      const Pose<Real> p = pose_at<Real>(w.motion[o], static_cast<double>(s) * w.dt);
      w.pose[o] = p;
      if (o < w.polygon_count) w.polygons[o] = moved(w.polygon_ref[o], p);
      else if (o < w.polygon_count + w.cylinder_count) w.cylinders[o - w.polygon_count] = moved(w.cylinder_ref[o - w.polygon_count], p);
    }
  }
};

}  // namespace blaze
