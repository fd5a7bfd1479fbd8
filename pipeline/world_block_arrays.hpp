// The arrays a WorldBlockView reads (blaze/scene/world_block.hpp: the world's test of a sphere,
// at its initial pose or, after at_time(), at its pose then), copied from a WorldOverlapCheck to
// a memory space: a feeder's rounds test their draws where the particles live
// (pipeline/feeder.hpp, kernels/placement.hpp). Move-only; the view points into its buffers.
#pragma once
#include <cstddef>
#include <vector>
#include "blaze/exec/buffer.hpp"
#include "blaze/scene/world_block.hpp"
#include "blaze/scene/world_overlap.hpp"

namespace blaze {

template <class Space>
class WorldBlockArrays {
 public:
  explicit WorldBlockArrays(const WorldOverlapCheck& check) {
    copy_in(cylinders_, check.cylinders());
    copy_in(polygons_, check.polygons());
    copy_in(mill_parts_, check.mill_parts());
    const std::size_t meshes = check.mesh_bins().size();
    starts_.resize(meshes), entries_.resize(meshes), corners_.resize(meshes);
    std::vector<MeshBlockView> views(meshes);
    for (std::size_t k = 0; k < meshes; ++k) {
      const MeshBinsHost& b = check.mesh_bins()[k];
      copy_in(starts_[k], b.start);
      copy_in(entries_[k], b.entry);
      copy_in(corners_[k], check.mesh_corners()[k]);
      views[k] = {bins_view<double>(b, starts_[k].data(), entries_[k].data()), corners_[k].data()};
    }
    copy_in(meshes_, views);
    view_.cylinder = cylinders_.data(), view_.cylinders = static_cast<int>(check.cylinders().size());
    view_.polygon = polygons_.data(), view_.mill_part = mill_parts_.data(), view_.polygons = static_cast<int>(check.polygons().size());
    view_.mesh = meshes_.data(), view_.meshes = static_cast<int>(meshes);
    view_.slack = check.slack();
  }
  const WorldBlockView& view() const { return view_; }

  // The world as it stands at time t (s) of a scene whose objects move or are removed (the view's
  // poses; a still world keeps none: its reference geometry is where it is).
  void at_time(const Scene& s, double t) {
    std::vector<const Motion*> motions;
    for (const auto& w : s.walls) motions.push_back(&w.motion);
    for (const auto& c : s.cylinders) motions.push_back(&c.motion);
    for (const auto& m : s.meshes) motions.push_back(&m.motion);
    bool still = true;
    for (const Motion* m : motions) still = still && m->is_static();
    if (still) return;
    std::vector<Pose<double>> poses;
    for (const Motion* m : motions) poses.push_back(pose_at<double>(*m, t));
    copy_in(poses_, poses);
    view_.pose = poses_.data();
  }

 private:
  Buffer<Cylinder<double>, Space> cylinders_;
  Buffer<PlanarPolygon<double>, Space> polygons_;
  Buffer<std::uint8_t, Space> mill_parts_;
  std::vector<Buffer<int, Space>> starts_, entries_;
  std::vector<Buffer<Vec3<double>, Space>> corners_;
  Buffer<MeshBlockView, Space> meshes_;
  Buffer<Pose<double>, Space> poses_;
  WorldBlockView view_;
};

}  // namespace blaze
