// Time integrators (thesis section 2.3.2). Each step runs
//   pre_force (all particles) -> broad phase -> forces -> post_force (all particles)
// with a = F/m + g and alpha = I^-1 T (shape policy). Orientation always advances by the exact
// rotation of angle |w| dt (quat.hpp).
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

  template <class Shape, class Features, class Real>
  BLAZE_HD static void prime(const ParticleView<Real>&, Index, const Vec3<Real>&) {}

  template <class Shape, class Features, class Real>
  BLAZE_HD static void pre_force(const ParticleView<Real>& p, Index i, Real dt, const Vec3<Real>& g) {
    const Real h = Real(0.5) * dt;
    const Vec3<Real> v = p.velocity.get(i) + acceleration(p, i, g) * h;
    p.velocity.set(i, v);
    p.position.set(i, p.position.get(i) + v * dt);
    if constexpr (Features::rotation) {
      const Vec3<Real> w = p.angular_velocity.get(i) + Shape::angular_acceleration(p, i, p.torque.get(i)) * h;
      p.angular_velocity.set(i, w);
      p.orientation.set(i, integrate_orientation(p.orientation.get(i), w, dt));
    }
  }

  template <class Shape, class Features, class Real>
  BLAZE_HD static void post_force(const ParticleView<Real>& p, Index i, Real dt, const Vec3<Real>& g) {
    const Real h = Real(0.5) * dt;
    p.velocity.set(i, p.velocity.get(i) + acceleration(p, i, g) * h);
    if constexpr (Features::rotation)
      p.angular_velocity.set(i, p.angular_velocity.get(i) + Shape::angular_acceleration(p, i, p.torque.get(i)) * h);
  }
};

struct ForwardEuler {
  static constexpr const char* name = "forward-euler";
  static constexpr bool needs_previous_acceleration = false;

  template <class Shape, class Features, class Real>
  BLAZE_HD static void prime(const ParticleView<Real>&, Index, const Vec3<Real>&) {}
  template <class Shape, class Features, class Real>
  BLAZE_HD static void pre_force(const ParticleView<Real>&, Index, Real, const Vec3<Real>&) {}

  template <class Shape, class Features, class Real>
  BLAZE_HD static void post_force(const ParticleView<Real>& p, Index i, Real dt, const Vec3<Real>& g) {
    const Vec3<Real> v = p.velocity.get(i);
    p.position.set(i, p.position.get(i) + v * dt);
    p.velocity.set(i, v + acceleration(p, i, g) * dt);
    if constexpr (Features::rotation) rotate_euler<Shape>(p, i, dt);
  }

  template <class Shape, class Real>
  BLAZE_HD static void rotate_euler(const ParticleView<Real>& p, Index i, Real dt) {
    const Vec3<Real> w = p.angular_velocity.get(i);
    p.orientation.set(i, integrate_orientation(p.orientation.get(i), w, dt));
    p.angular_velocity.set(i, w + Shape::angular_acceleration(p, i, p.torque.get(i)) * dt);
  }
};

struct ThesisVerlet {
  static constexpr const char* name = "thesis-verlet";
  static constexpr bool needs_previous_acceleration = true;

  // a(t - dt) for the first step is taken as a(0).
  template <class Shape, class Features, class Real>
  BLAZE_HD static void prime(const ParticleView<Real>& p, Index i, const Vec3<Real>& g) {
    p.acceleration_prev.set(i, acceleration(p, i, g));
  }
  template <class Shape, class Features, class Real>
  BLAZE_HD static void pre_force(const ParticleView<Real>&, Index, Real, const Vec3<Real>&) {}

  template <class Shape, class Features, class Real>
  BLAZE_HD static void post_force(const ParticleView<Real>& p, Index i, Real dt, const Vec3<Real>& g) {
    const Vec3<Real> a = acceleration(p, i, g);
    const Vec3<Real> v = p.velocity.get(i);
    p.position.set(i, p.position.get(i) + v * dt + a * (Real(0.5) * dt * dt));
    p.velocity.set(i, v + (a + p.acceleration_prev.get(i)) * (Real(0.5) * dt));
    p.acceleration_prev.set(i, a);
    if constexpr (Features::rotation) ForwardEuler::rotate_euler<Shape>(p, i, dt);
  }
};

}  // namespace blaze
