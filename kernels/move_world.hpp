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
      // Everything the object needs is read before anything is written (the reads overlap: this
      // phase is one thread's chain of latencies per object).
      const std::uint64_t s = w.step[o] + 1;
      const Motion m = w.motion[o];
      if (o < w.polygon_count) {
        const PlanarPolygon<Real> ref = w.polygon_ref[o];
        const Pose<Real> p = place(o, s, m);
        w.polygons[o] = moved(ref, p);
      } else if (o < w.polygon_count + w.cylinder_count) {
        const Cylinder<Real> ref = w.cylinder_ref[o - w.polygon_count];
        const Pose<Real> p = place(o, s, m);
        w.cylinders[o - w.polygon_count] = moved(ref, p);
      } else {
        place(o, s, m);
      }
    }
  }

 private:
  // Object o's pose at step s, written with the step.
  BLAZE_HD Pose<Real> place(long o, std::uint64_t s, const Motion& m) const {
    const Pose<Real> p = pose_at<Real>(m, static_cast<double>(s) * w.dt);
    w.step[o] = s;
    w.pose[o] = p;
    return p;
  }
};

}  // namespace blaze
