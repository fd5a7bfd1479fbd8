// Head-on collision of two equal spheres with a damped Hertzian contact of prescribed restitution
// (Hertz::from_restitution: delta^(1/4) damping, e independent of speed), used by the
// work-precision study. Reference: the separation speed is e times the approach speed exactly
// (hertz_restitution.hpp; verified against GSL in the suite), so the error is |e_out / e - 1|.
// Spheres of radius 5 mm, glass-like E* = 3.5e10 Pa, rho = 2500 kg/m^3, closing at 1 m/s.
// The damping force eta sqrt(m K) delta^(1/4) v has an unbounded derivative at first touch and at
// separation, so the error converges irregularly (about order 5/4, with a scatter set by where
// first touch falls between two steps): ~1e-3 at t_c/100, ~2e-4 at t_c/400 (measured).
#pragma once
#include <chrono>
#include <cmath>
#include "blaze/shapes/sphere_shape.hpp"
#include "blaze/laws/contact_law.hpp"
#include "blaze/laws/hertz.hpp"
#include "blaze/laws/history_free_friction.hpp"
#include "pipeline/simulation.hpp"

namespace blaze::test::cases {

struct HeadOnResult {
  double error;   // |e_out / e - 1|
  double wall_s;  // wall time of the stepping, s
  long steps;
};

struct HeadOnSetup {
  double radius = 5e-3, density = 2500, e_star = 3.5e10, restitution = 0.5, speed = 1.0;
  // Hertz contact time of the elastic impact, s: 2.9432 delta_max / v.
  double contact_time() const {
    const double pi = 3.14159265358979323846;
    const double m_eff = 0.5 * density * 4.0 / 3.0 * pi * radius * radius * radius;
    const double k_n = 4.0 / 3.0 * e_star * std::sqrt(0.5 * radius);
    return 2.9432 * std::pow(5 * m_eff * speed * speed / (4 * k_n), 0.4) / speed;
  }
};

template <class Real, class Integrator>
HeadOnResult head_on_restitution(const HeadOnSetup& s, double dt) {
  using Law = ContactLaw<Real, Hertz, NoFriction>;
  PairTable<Law> laws;
  laws.set(0, 0, Law{Hertz<Real>::from_restitution(s.e_star, s.restitution), {}});
  ParticleState<Real> p;
  const double gap = 0.01 * s.radius;
  p.add_sphere({static_cast<Real>(-(s.radius + gap)), 0, 0}, static_cast<Real>(s.radius), static_cast<Real>(s.density), 0,
               {static_cast<Real>(0.5 * s.speed), 0, 0});
  p.add_sphere({static_cast<Real>(s.radius + gap), 0, 0}, static_cast<Real>(s.radius), static_cast<Real>(s.density), 0,
               {static_cast<Real>(-0.5 * s.speed), 0, 0});
  const Real box = static_cast<Real>(10 * s.radius);
  SimulationParams<Real> prm{static_cast<Real>(dt), {0, 0, 0}, {-box, -box, -box}, {box, box, box}, static_cast<Real>(0.5 * s.radius)};
  Simulation<DefaultSpace, SphereShape, Law, Integrator, ContactPointVelocity, TranslationOnly> sim(prm, laws, World<Real>{}, p);
  // Run until well after separation: approach of the gap + contact + margin.
  const long steps = static_cast<long>(std::ceil((2 * gap / s.speed + 2 * s.contact_time()) / dt));
  const auto t0 = std::chrono::steady_clock::now();
  sim.run(static_cast<std::uint64_t>(steps));
  const auto st = sim.state();  // also waits for the device
  const double wall = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  const double separation = std::fabs(static_cast<double>(st.velocity[0].x) - static_cast<double>(st.velocity[1].x));
  return {std::fabs(separation / (s.restitution * s.speed) - 1), wall, steps};
}

}  // namespace blaze::test::cases
