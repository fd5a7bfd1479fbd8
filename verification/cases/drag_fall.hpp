// Drag fall (thesis section 2.5.1, Fig 2.11): one sphere falls from rest under gravity and
// quadratic air drag, F = m g - alpha v^2 (alpha in kg/m), measured downwards. Closed forms:
//   v(t) = V tanh(t / tau),   x(t) = (m / alpha) ln cosh(t / tau),
//   V = sqrt(m g / alpha) (terminal speed, m/s),   tau = sqrt(m / (g alpha)) (time constant, s).
// The same ODE (x' = v, v' = g - (alpha/m)|v| v) is also solved with GSL odeiv2 (rk8pd, adaptive,
// abs/rel 1e-12), an independent reference that proves the closed forms as coded.
//
// The thesis gives alpha = 0.5 kg/m but no mass. We take m = 1 kg (a sphere of radius 5 cm): exact
// in float as well as double, and it puts V = 4.43 m/s and tau = 0.452 s at order one, so
// dt = 1e-3 s is tau/450. The run lasts 3 s = 6.6 tau (v within 4e-6 of V), long enough for the
// transient and the approach to terminal velocity both to count.
//
// Error metric (state it with every number): samples at t_k = k n dt, n = floor(0.01 s / dt) (>= 1);
// for x and for v separately
//   max_k |y_k - y_ref(t_k)| / max_k |y_ref(t_k)|,
// the largest error over the run relative to the largest value of the signal (x(3 s) = 11.9 m,
// V). A pointwise relative error is 0/0 at t = 0 and, for Euler, 100% at the first step (x lags
// one step), so it cannot measure convergence.
//
// drag_fall<Real, Integrator>(dt, problem) runs the case through the Simulation API on
// DefaultSpace and returns the samples, the errors against the closed forms and the wall time of
// the stepping (fenced; host snapshots excluded), for the verification test and for the
// work-precision study. Any dt up to the duration works; it need not divide the sample interval.
#pragma once
#include <gsl/gsl_errno.h>
#include <gsl/gsl_odeiv2.h>
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <stdexcept>
#include <vector>
#include "verification/cases/timed_run.hpp"
#include "verification/scenes.hpp"

namespace blaze::test::cases {

struct DragFall {
  double mass = 1.0;              // kg
  double alpha = 0.5;             // kg/m (thesis Fig 2.11)
  double g = 9.81;                // m/s^2
  double radius = 0.05;           // m; irrelevant to the motion (drag is given as alpha)
  double duration = 3.0;          // s
  double sample_interval = 0.01;  // s

  double terminal_speed() const { return std::sqrt(mass * g / alpha); }
  double time_constant() const { return std::sqrt(mass / (g * alpha)); }
  double v_exact(double t) const { return terminal_speed() * std::tanh(t / time_constant()); }
  // ln cosh(u) = u - ln 2 + log1p(exp(-2u)): no overflow, no cancellation at large u.
  double x_exact(double t) const {
    const double u = t / time_constant();
    return mass / alpha * (u - std::log(2.0) + std::log1p(std::exp(-2 * u)));
  }
};

// Fall distance and downward speed at the sample times.
struct Trajectory {
  std::vector<double> t, x, v;
};

struct TrajectoryError {
  double x = 0, v = 0;  // max |y - y_ref| / max |y_ref| (see the header)
  double worst() const { return std::fmax(x, v); }
};

inline TrajectoryError max_relative_error(const Trajectory& a, const Trajectory& ref) {
  if (a.t.size() != ref.t.size()) throw std::invalid_argument("drag fall: trajectories sampled differently");
  double dx = 0, dv = 0, sx = 0, sv = 0;
  for (std::size_t k = 0; k < a.t.size(); ++k) {
    dx = std::fmax(dx, std::fabs(a.x[k] - ref.x[k]));
    dv = std::fmax(dv, std::fabs(a.v[k] - ref.v[k]));
    sx = std::fmax(sx, std::fabs(ref.x[k]));
    sv = std::fmax(sv, std::fabs(ref.v[k]));
  }
  return {dx / sx, dv / sv};
}

inline Trajectory drag_fall_exact(const DragFall& p, const std::vector<double>& times) {
  Trajectory r;
  r.t = times;
  for (double t : r.t) {
    r.x.push_back(p.x_exact(t));
    r.v.push_back(p.v_exact(t));
  }
  return r;
}

// The same ODE by GSL's embedded Runge-Kutta-Prince-Dormand (8, 9), step size adapted to keep the
// local error below abs + rel |y|.
inline Trajectory drag_fall_gsl(const DragFall& p, const std::vector<double>& times, double tolerance = 1e-12) {
  auto rhs = [](double, const double y[], double dydt[], void* params) -> int {
    const DragFall& q = *static_cast<const DragFall*>(params);
    dydt[0] = y[1];
    dydt[1] = q.g - q.alpha / q.mass * std::fabs(y[1]) * y[1];
    return GSL_SUCCESS;
  };
  gsl_odeiv2_system sys{+rhs, nullptr, 2, const_cast<DragFall*>(&p)};
  gsl_odeiv2_driver* d = gsl_odeiv2_driver_alloc_y_new(&sys, gsl_odeiv2_step_rk8pd, 1e-6, tolerance, tolerance);
  Trajectory r;
  r.t = times;
  double t = 0, y[2] = {0, 0};
  for (double ti : r.t) {
    if (ti > t && gsl_odeiv2_driver_apply(d, &t, ti, y) != GSL_SUCCESS) {
      gsl_odeiv2_driver_free(d);
      throw std::runtime_error("drag fall: GSL odeiv2 failed");
    }
    r.x.push_back(y[0]);
    r.v.push_back(y[1]);
  }
  gsl_odeiv2_driver_free(d);
  return r;
}

struct DragFallResult {
  double dt = 0;              // s
  std::uint64_t steps = 0;
  Trajectory samples;         // at t = k dt for every k-th step, k = floor(sample_interval / dt) (>= 1)
  TrajectoryError errors;     // x and v against the closed forms
  double error = 0;           // the larger of the two
  double wall_s = 0;          // wall time of the stepping, fenced; host snapshots excluded
};

// Falls along -y from the origin (x = -y) for round(duration / dt) steps, on DefaultSpace.
template <class Real, class Integrator>
DragFallResult drag_fall(double dt, const DragFall& p = {}) {
  if (!(dt > 0) || dt > p.duration) throw std::invalid_argument("drag fall: need 0 < dt <= duration");
  const long steps = std::lround(p.duration / dt);
  const long per_sample = std::max(1L, static_cast<long>(std::floor(p.sample_interval / dt + 1e-9)));
  using Law = ContactLaw<Real, LinearSpringDashpot, NoFriction>;  // no contacts: any law will do
  ParticleState<Real> s;
  s.add_sphere({0, 0, 0}, static_cast<Real>(p.radius), Real(1000), 0);
  s.mass[0] = static_cast<Real>(p.mass);
  const Real inertia = static_cast<Real>(0.4 * p.mass * p.radius * p.radius);
  s.inertia[0] = {inertia, inertia, inertia};
  // A tall thin domain; the skin of 1 m keeps neighbour rebuilds rare.
  const double depth = 1.5 * p.x_exact(steps * dt) + 1;
  SimulationParams<Real> prm{static_cast<Real>(dt),
                             {0, static_cast<Real>(-p.g), 0},
                             vec_cast<Real>(Vec3<double>{-0.5, -depth, -0.5}),
                             vec_cast<Real>(Vec3<double>{0.5, 1.0, 0.5}),
                             Real(1),
                             static_cast<Real>(p.alpha)};
  PairTable<Law> laws;
  laws.set(0, 0, Law{LinearSpringDashpot<Real>::from_restitution(1e3, 1), {}});
  Simulation<DefaultSpace, SphereShape, Law, Integrator, ContactPointVelocity, TranslationOnly> sim(prm, laws, World<Real>{}, s);
  DragFallResult out;
  out.dt = dt;
  auto sample = [&] {
    const auto st = sim.state();
    out.samples.t.push_back(static_cast<double>(sim.steps()) * dt);
    out.samples.x.push_back(-static_cast<double>(st.position[0].y));
    out.samples.v.push_back(-static_cast<double>(st.velocity[0].y));
  };
  out.wall_s = run_sampled(sim, steps, per_sample, sample);
  out.steps = sim.steps();
  out.errors = max_relative_error(out.samples, drag_fall_exact(p, out.samples.t));
  out.error = out.errors.worst();
  return out;
}

}  // namespace blaze::test::cases
