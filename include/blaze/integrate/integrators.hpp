// Time integrators (thesis section 2.3.2). Each step runs
//   pre_force (all particles) -> broad phase -> forces -> post_force (all particles)
// with a = F/m + g. Rotation goes through the shape policy: kick_rotation adds a torque impulse
// (L += T h, w = I^-1 L with the world-frame inertia of the current orientation) and
// drift_rotation turns the orientation at constant angular momentum (spheres: the exact rotation
// of angle |w| dt; polyhedra: a midpoint rule so |L| is conserved and the energy to second order).
//
// VelocityVerlet (default; second order, one force evaluation per step, kick-drift-kick):
//   v(t+dt/2) = v(t) + a(t) dt/2;  x(t+dt) = x(t) + v(t+dt/2) dt;  forces at x(t+dt), v(t+dt/2);
//   v(t+dt) = v(t+dt/2) + a(t+dt) dt/2.   Same for w.
// The thesis avoids the classical scheme believing it needs a second force evaluation; it does
// not: a(t+dt) is the next step's force.
//
// ThesisVerlet (eqs. 2.5-2.6, kept as a named option):
//   x(t+dt) = x(t) + v(t) dt + a(t) dt^2/2;   v(t+dt) = v(t) + (a(t) + a(t-dt)) dt/2;
//   w(t+dt) = w(t) + alpha(t) dt (eq. 2.7).
// Its velocity update centres the acceleration at t - dt/2 instead of t + dt/2, so it is only
// first-order accurate (measured in the verification suite).
//
// ForwardEuler: x(t+dt) = x(t) + v(t) dt;  v(t+dt) = v(t) + a(t) dt;  w likewise.
#pragma once
#include "blaze/particles/particle_store.hpp"
#include "blaze/sim/features.hpp"

namespace blaze {

template <class Real>
BLAZE_HD inline Vec3<Real> acceleration(const ParticleView<Real>& p, Index i, const Vec3<Real>& g) {
  return p.force.get(i) * p.inv_mass[i] + g;
}

struct VelocityVerlet {
  static constexpr const char* name = "velocity-verlet";
  static constexpr bool needs_previous_acceleration = false;

  template <class Features, class Shape, class Real>
  BLAZE_HD static void prime(const Shape&, const ParticleView<Real>&, Index, const Vec3<Real>&) {}

  template <class Features, class Shape, class Real>
  BLAZE_HD static void pre_force(const Shape& shape, const ParticleView<Real>& p, Index i, Real dt, const Vec3<Real>& g) {
    const Real h = Real(0.5) * dt;
    const Vec3<Real> v = p.velocity.get(i) + acceleration(p, i, g) * h;
    p.velocity.set(i, v);
    p.position.set(i, p.position.get(i) + v * dt);
    if constexpr (Features::rotation) {
      Quat<Real> q = p.orientation.get(i);
      Vec3<Real> w = shape.kick_rotation(p, i, q, p.angular_velocity.get(i), p.torque.get(i), h);
      shape.drift_rotation(p, i, q, w, dt);
      p.angular_velocity.set(i, w);
      p.orientation.set(i, q);
    }
  }

  template <class Features, class Shape, class Real>
  BLAZE_HD static void post_force(const Shape& shape, const ParticleView<Real>& p, Index i, Real dt, const Vec3<Real>& g) {
    const Real h = Real(0.5) * dt;
    p.velocity.set(i, p.velocity.get(i) + acceleration(p, i, g) * h);
    if constexpr (Features::rotation)
      p.angular_velocity.set(
          i, shape.kick_rotation(p, i, p.orientation.get(i), p.angular_velocity.get(i), p.torque.get(i), h));
  }
};

struct ForwardEuler {
  static constexpr const char* name = "forward-euler";
  static constexpr bool needs_previous_acceleration = false;

  template <class Features, class Shape, class Real>
  BLAZE_HD static void prime(const Shape&, const ParticleView<Real>&, Index, const Vec3<Real>&) {}
  template <class Features, class Shape, class Real>
  BLAZE_HD static void pre_force(const Shape&, const ParticleView<Real>&, Index, Real, const Vec3<Real>&) {}

  template <class Features, class Shape, class Real>
  BLAZE_HD static void post_force(const Shape& shape, const ParticleView<Real>& p, Index i, Real dt, const Vec3<Real>& g) {
    const Vec3<Real> v = p.velocity.get(i);
    p.position.set(i, p.position.get(i) + v * dt);
    p.velocity.set(i, v + acceleration(p, i, g) * dt);
    if constexpr (Features::rotation) rotate_euler(shape, p, i, dt);
  }

  // w(t) turns the body, then the torque of time t changes w (eq. 2.7).
  template <class Shape, class Real>
  BLAZE_HD static void rotate_euler(const Shape& shape, const ParticleView<Real>& p, Index i, Real dt) {
    Quat<Real> q = p.orientation.get(i);
    Vec3<Real> w = p.angular_velocity.get(i);
    shape.drift_rotation(p, i, q, w, dt);
    p.orientation.set(i, q);
    p.angular_velocity.set(i, shape.kick_rotation(p, i, q, w, p.torque.get(i), dt));
  }
};

struct ThesisVerlet {
  static constexpr const char* name = "thesis-verlet";
  static constexpr bool needs_previous_acceleration = true;

  // a(t - dt) for the first step is taken as a(0).
  template <class Features, class Shape, class Real>
  BLAZE_HD static void prime(const Shape&, const ParticleView<Real>& p, Index i, const Vec3<Real>& g) {
    p.acceleration_prev.set(i, acceleration(p, i, g));
  }
  template <class Features, class Shape, class Real>
  BLAZE_HD static void pre_force(const Shape&, const ParticleView<Real>&, Index, Real, const Vec3<Real>&) {}

  template <class Features, class Shape, class Real>
  BLAZE_HD static void post_force(const Shape& shape, const ParticleView<Real>& p, Index i, Real dt, const Vec3<Real>& g) {
    const Vec3<Real> a = acceleration(p, i, g);
    const Vec3<Real> v = p.velocity.get(i);
    p.position.set(i, p.position.get(i) + v * dt + a * (Real(0.5) * dt * dt));
    p.velocity.set(i, v + (a + p.acceleration_prev.get(i)) * (Real(0.5) * dt));
    p.acceleration_prev.set(i, a);
    if constexpr (Features::rotation) ForwardEuler::rotate_euler(shape, p, i, dt);
  }
};

}  // namespace blaze
