// A particle's contacts with the world, object by object in index order (the world kernel and
// the stored-energy diagnostic walk them the same way):
//   f(geometry, material, w, key, group)
// for every object w that the particle may touch (WorldView::visit), unless it touches a removed
// one: a polygon or a cylinder gives the shape's collide_world() (touching or not), key w and a
// null group; a triangle
// mesh gives each of its merged contacts (blaze/world/mesh_wall.hpp, at most kMeshContacts; from
// the particle's triangle list when it has one, kernels/world_candidates.hpp),
// key mesh_key_base + the triangle that offered it, and the group of them all (for the history's
// hand-over between triangles, kernels/contact_history.hpp).
#pragma once
#include <type_traits>
#include <utility>
#include "blaze/contact/contact_patch.hpp"
#include "blaze/world/world.hpp"

namespace blaze {

// The geometry a shape's wall contacts have (ContactGeometry, or a polyhedron's patch geometry),
// and how many contacts of one particle with one mesh are kept (more: the deepest): 8 points, or
// 4 patches (each holds up to 8 points).
template <class Shape, class Body, class Real>
using WallGeometry = std::decay_t<decltype(std::declval<const Shape&>().collide_world(std::declval<const Body&>(),
                                                                                       std::declval<const PlanarPolygon<Real>&>()))>;
template <class Geometry>
constexpr int kMeshContacts = is_patch_geometry_v<Geometry> ? 4 : 8;
template <class Geometry, class Real>
using MeshGroup = MeshContacts<Real, kMeshContacts<Geometry>, Geometry>;

template <class Shape, class Body, class Real, class F>
BLAZE_HD void for_each_world_contact(const Shape& shape, const Body& body, const WorldView<Real>& world, Index i, F&& f) {
  using Group = MeshGroup<WallGeometry<Shape, Body, Real>, Real>;
  world.visit(i, [&](const auto& object, int w) {
    if constexpr (std::is_same_v<std::decay_t<decltype(object)>, MeshObject<Real>>) {
      if (!world.active(w)) return;  // a removed mesh
      Group group;
      shape.collide_mesh(body, world.surface, object, world.pose_of(w), group, world.near_triangles(i));
      for (int k = 0; k < group.count; ++k)
        f(group.contact[k], static_cast<int>(object.material), w, static_cast<WallKey>(world.mesh_key_base + group.owner[k]), &group);
    } else {
      const auto g = shape.collide_world(body, object);
      if (g.touching && !world.active(w)) return;  // a removed object (asked only of a touching one)
      f(g, static_cast<int>(object.material), w, static_cast<WallKey>(w), static_cast<const Group*>(nullptr));
    }
  });
}

// The slot a mesh contact with key `key` takes (contact_history.hpp): its own, or the slot of a
// triangle of the same mesh that shares a vertex with its triangle or lies in its plane, that no
// contact of the group holds and no contact of this step has used; or a free one.
template <class History, class Group, class Real>
BLAZE_HD int mesh_contact_slot(const History& history, Index i, WallKey key, unsigned seen, const Group& group,
                               const WorldView<Real>& world, int w) {
  const MeshObject<Real>& mesh = world.meshes[w - world.polygon_count - world.cylinder_count];
  const int t = key - world.mesh_key_base;
  return history.slot(i, key, seen, [&](WallKey old) {
    const int u = old - world.mesh_key_base;
    if (old < world.mesh_key_base || !mesh.owns(u)) return false;
    for (int k = 0; k < group.count; ++k)
      if (group.owner[k] == u) return false;
    return share_vertex(world.surface.triangle, t, u) || coplanar(world.surface, t, u);
  });
}

}  // namespace blaze
