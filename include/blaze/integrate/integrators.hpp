// Time integrators (thesis section 2.3.2). Each step runs
//   pre_force (all particles) -> broad phase -> forces -> post_force (all particles)
// with a = F/m + g - (alpha/m)|v| v (BodyForces: gravity and an optional quadratic drag,
// thesis section 2.5.1). Rotation goes through the shape policy: kick_rotation adds a torque
// impulse (L += T h, w = I^-1 L with the world-frame inertia of the current orientation; linear in
// T) and drift_rotation turns the orientation at constant angular momentum (spheres: the exact
// rotation of angle |w| dt; polyhedra: a midpoint rule so |L| is conserved and the energy to
// second order).
//
// VelocityVerlet (default; second order also for velocity-dependent forces, one force
// evaluation per step, kick-drift-kick):
//   v(t+dt/2) = v(t) + a(t) dt/2;   x(t+dt) = x(t) + v(t+dt/2) dt;
//   forces at x(t+dt) and the predicted v*(t+dt) = v(t+dt/2) + a(t) dt/2   (error O(dt^2));
//   v(t+dt) = v(t+dt/2) + a(t+dt) dt/2 = v* + (a(t+dt) - a(t)) dt/2.        Same for w with T.
// Dashpots, friction and drag depend on velocity. Evaluating them at the half-step velocity
// v(t+dt/2), as HalfStepVerlet (and LIGGGHTS) does, lags them by dt/2: a first-order error that
// shows as 0.1% in the drag fall at dt = 1e-3 s (the thesis's number) and ~0.5% in the
// restitution of a strongly damped contact at t_c/400. The prediction removes it for the price
// of a(t) and T(t) kept per particle (24 bytes in float).
// The thesis avoids the classical scheme believing it needs a second force evaluation; it does
// not: a(t+dt) is the next step's force.
//
// HalfStepVerlet: the same kick-drift-kick with forces at v(t+dt/2); exact for position-only
// forces (springs, gravity), first order for velocity-dependent ones; keeps no per-particle extra.
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

// Forces that act on every particle besides contacts: uniform gravity g (m/s^2) and quadratic air
// drag F = -alpha |v| v (alpha in kg/m; 0 = none; thesis section 2.5.1, F = mg - alpha v^2).
template <class Real>
struct BodyForces {
  Vec3<Real> gravity;
  Real drag;

  // a = F_contact/m + g - (alpha/m)|v| v, for the velocity v the forces were evaluated at.
  BLAZE_HD Vec3<Real> acceleration(const ParticleView<Real>& p, Index i, const Vec3<Real>& v) const {
    Vec3<Real> a = p.force.get(i) * p.inv_mass[i] + gravity;
    if (drag != Real(0)) a -= v * (drag * norm(v) * p.inv_mass[i]);
    return a;
  }
};

struct VelocityVerlet {
  static constexpr const char* name = "velocity-verlet";
  static constexpr bool keeps_previous_forces = true;

  template <class Features, class Shape, class Real>
  BLAZE_HD static void prime(const Shape&, const ParticleView<Real>& p, Index i, const BodyForces<Real>& body) {
    p.acceleration_prev.set(i, body.acceleration(p, i, p.velocity.get(i)));
    if constexpr (Features::rotation) p.torque_prev.set(i, p.torque.get(i));
  }

  template <class Features, class Shape, class Real>
  BLAZE_HD static void pre_force(const Shape& shape, const ParticleView<Real>& p, Index i, Real dt, const BodyForces<Real>&) {
    const Real h = Real(0.5) * dt;
    const Vec3<Real> a = p.acceleration_prev.get(i);
    const Vec3<Real> v_half = p.velocity.get(i) + a * h;
    p.position.set(i, p.position.get(i) + v_half * dt);
    p.velocity.set(i, v_half + a * h);
    if constexpr (Features::rotation) {
      const Vec3<Real> t = p.torque_prev.get(i);
      Quat<Real> q = p.orientation.get(i);
      Vec3<Real> w = shape.kick_rotation(p, i, q, p.angular_velocity.get(i), t, h);
      shape.drift_rotation(p, i, q, w, dt);
      p.angular_velocity.set(i, shape.kick_rotation(p, i, q, w, t, h));
      p.orientation.set(i, q);
    }
  }

  template <class Features, class Shape, class Real>
  BLAZE_HD static void post_force(const Shape& shape, const ParticleView<Real>& p, Index i, Real dt, const BodyForces<Real>& body) {
    const Real h = Real(0.5) * dt;
    const Vec3<Real> v_predicted = p.velocity.get(i);
    const Vec3<Real> a = body.acceleration(p, i, v_predicted);
    p.velocity.set(i, v_predicted + (a - p.acceleration_prev.get(i)) * h);
    p.acceleration_prev.set(i, a);
    if constexpr (Features::rotation) {
      const Vec3<Real> t = p.torque.get(i);
      p.angular_velocity.set(
          i, shape.kick_rotation(p, i, p.orientation.get(i), p.angular_velocity.get(i), t - p.torque_prev.get(i), h));
      p.torque_prev.set(i, t);
    }
  }
};

struct HalfStepVerlet {
  static constexpr const char* name = "half-step-verlet";
  static constexpr bool keeps_previous_forces = false;

  template <class Features, class Shape, class Real>
  BLAZE_HD static void prime(const Shape&, const ParticleView<Real>&, Index, const BodyForces<Real>&) {}

  template <class Features, class Shape, class Real>
  BLAZE_HD static void pre_force(const Shape& shape, const ParticleView<Real>& p, Index i, Real dt, const BodyForces<Real>& body) {
    const Real h = Real(0.5) * dt;
    const Vec3<Real> v = p.velocity.get(i) + body.acceleration(p, i, p.velocity.get(i)) * h;
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
  BLAZE_HD static void post_force(const Shape& shape, const ParticleView<Real>& p, Index i, Real dt, const BodyForces<Real>& body) {
    const Real h = Real(0.5) * dt;
    const Vec3<Real> v = p.velocity.get(i);
    p.velocity.set(i, v + body.acceleration(p, i, v) * h);
    if constexpr (Features::rotation)
      p.angular_velocity.set(
          i, shape.kick_rotation(p, i, p.orientation.get(i), p.angular_velocity.get(i), p.torque.get(i), h));
  }
};

struct ForwardEuler {
  static constexpr const char* name = "forward-euler";
  static constexpr bool keeps_previous_forces = false;

  template <class Features, class Shape, class Real>
  BLAZE_HD static void prime(const Shape&, const ParticleView<Real>&, Index, const BodyForces<Real>&) {}
  template <class Features, class Shape, class Real>
  BLAZE_HD static void pre_force(const Shape&, const ParticleView<Real>&, Index, Real, const BodyForces<Real>&) {}

  template <class Features, class Shape, class Real>
  BLAZE_HD static void post_force(const Shape& shape, const ParticleView<Real>& p, Index i, Real dt, const BodyForces<Real>& body) {
    const Vec3<Real> v = p.velocity.get(i);
    p.position.set(i, p.position.get(i) + v * dt);
    p.velocity.set(i, v + body.acceleration(p, i, v) * dt);
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
  static constexpr bool keeps_previous_forces = true;

  // a(t - dt) for the first step is taken as a(0).
  template <class Features, class Shape, class Real>
  BLAZE_HD static void prime(const Shape&, const ParticleView<Real>& p, Index i, const BodyForces<Real>& body) {
    p.acceleration_prev.set(i, body.acceleration(p, i, p.velocity.get(i)));
  }
  template <class Features, class Shape, class Real>
  BLAZE_HD static void pre_force(const Shape&, const ParticleView<Real>&, Index, Real, const BodyForces<Real>&) {}

  template <class Features, class Shape, class Real>
  BLAZE_HD static void post_force(const Shape& shape, const ParticleView<Real>& p, Index i, Real dt, const BodyForces<Real>& body) {
    const Vec3<Real> v = p.velocity.get(i);
    const Vec3<Real> a = body.acceleration(p, i, v);
    p.position.set(i, p.position.get(i) + v * dt + a * (Real(0.5) * dt * dt));
    p.velocity.set(i, v + (a + p.acceleration_prev.get(i)) * (Real(0.5) * dt));
    p.acceleration_prev.set(i, a);
    if constexpr (Features::rotation) ForwardEuler::rotate_euler(shape, p, i, dt);
  }
};

}  // namespace blaze
