// World objects (thesis section 3.2.1): everything that is not a particle. One host description,
// one device store, one view; kernels loop over each object kind with that kind's collide().
// New kinds (triangle meshes, moving walls) add an array here and a collide() overload.
#pragma once
#include <vector>
#include "blaze/exec/buffer.hpp"
#include "blaze/world/cylinder.hpp"
#include "blaze/world/planar_polygon.hpp"

namespace blaze {

template <class Real>
struct World {
  std::vector<PlanarPolygon<Real>> polygons;
  std::vector<Cylinder<Real>> cylinders;
  bool empty() const { return polygons.empty() && cylinders.empty(); }
};

template <class Real>
struct WorldView {
  const PlanarPolygon<Real>* polygons;
  int polygon_count;
  const Cylinder<Real>* cylinders;
  int cylinder_count;
};

template <class Real, class Space>
class WorldStore {
 public:
  void upload(const World<Real>& w) {
    from_host(polygons_, w.polygons);
    from_host(cylinders_, w.cylinders);
  }
  WorldView<Real> view() const {
    return {polygons_.data(), static_cast<int>(polygons_.size()), cylinders_.data(),
            static_cast<int>(cylinders_.size())};
  }
  bool empty() const { return polygons_.size() == 0 && cylinders_.size() == 0; }

 private:
  Buffer<PlanarPolygon<Real>, Space> polygons_;
  Buffer<Cylinder<Real>, Space> cylinders_;
};

}  // namespace blaze
