// Sphere shape policy: a body is its centre and radius; contact is exact (thesis section 2.2.4:
// spheres need no narrow phase beyond the centre distance).
//
//   delta = r_i + r_j - |x_j - x_i|,  n = (x_j - x_i) / |x_j - x_i|,
//   contact point = x_i + n (r_i - delta/2)   (middle of the overlap),  R* = r_i r_j / (r_i + r_j)
// Rotation: isotropic inertia I = (2/5) m r^2, so L = I w in any frame.
#pragma once
#include "blaze/contact/contact_geometry.hpp"
#include "blaze/particles/particle_store.hpp"
#include "blaze/world/world.hpp"

namespace blaze {

struct SphereShape {
  static constexpr const char* name = "sphere";
  // The contact kernel reads a partner's velocity, spin, mass and material with its position
  // (kernels/contact_forces.hpp, BLAZE_PAIR_EARLY_SIDE): a sphere's collision is cheap, so the
  // loads it would otherwise wait for dominate.
  static constexpr bool kEarlySide = true;
  // Its mesh contacts are mesh_surface.hpp's regions (a triangle list may drop a flat patch's
  // triangles the sphere cannot reach: pipeline/world_candidates.hpp).
  static constexpr bool kSphereMeshRegions = true;

  template <class Real>
  struct Body {
    Vec3<Real> x;
    Real r;
    Index index;
  };

  template <class Real>
  BLAZE_HD Body<Real> body(const ParticleView<Real>& p, Index i) const {
    return {p.position.get(i), p.radius[i], i};
  }

  template <class Real>
  BLAZE_HD ContactGeometry<Real> collide(const Body<Real>& a, const Body<Real>& b) const {
    const Vec3<Real> d = b.x - a.x;
    const Real reach = a.r + b.r;
    const Real d2 = norm2(d);
    if (!(d2 < reach * reach)) return ContactGeometry<Real>::none();
    const Real dist = sqrt_r(d2);
    // Coincident centres: any axis will do, as long as the two bodies get opposite ones.
    const Vec3<Real> n = dist > Real(0) ? d * (Real(1) / dist)
                                        : Vec3<Real>{0, 0, a.index < b.index ? Real(1) : Real(-1)};
    const Real delta = reach - dist;
    return {true, n, delta, a.x + n * (a.r - Real(0.5) * delta), a.r * b.r / reach};
  }

  // Contact with a world object (planar polygon, cylinder, ...): its collide_sphere() overload.
  template <class Real, class Object>
  BLAZE_HD ContactGeometry<Real> collide_world(const Body<Real>& a, const Object& w) const {
    return collide_sphere(a.x, a.r, w);
  }
  // Contacts with a triangle mesh (blaze/world/mesh_wall.hpp), merged per surface point; the
  // triangles of `near` (the particle's triangle list) or of its bins' cell.
  template <class Real, int K>
  BLAZE_HD void collide_mesh(const Body<Real>& a, const MeshSurfaceView<Real>& s, const MeshObject<Real>& m, const Pose<Real>* pose,
                             MeshContacts<Real, K>& out, const TriangleList& near = {}) const {
    collide_sphere_mesh(a.x, a.r, s, m, pose, out, near);
  }

  // Rotation steps the integrators call. kick: w += I^-1 T h. drift: turn q by w dt (w is constant
  // for an isotropic body).
  template <class Real>
  BLAZE_HD Vec3<Real> kick_rotation(const ParticleView<Real>& p, Index i, const Quat<Real>&, const Vec3<Real>& w,
                                    const Vec3<Real>& torque, Real h) const {
    return w + torque * (p.inv_inertia[i] * h);
  }
  template <class Real>
  BLAZE_HD void drift_rotation(const ParticleView<Real>&, Index, Quat<Real>& q, Vec3<Real>& w, Real dt) const {
    q = integrate_orientation(q, w, dt);
  }
  // Principal moments (host snapshots, the time series' energies).
  template <class Real>
  BLAZE_HD Vec3<Real> principal_inertia(Real inv_inertia, Real, std::uint8_t) const {
    const Real i = Real(1) / inv_inertia;
    return {i, i, i};
  }
};

}  // namespace blaze
