// Energy conservation (thesis section 2.3.2, Fig 2.8): "a system of particles falling under
// gravity for 1 second onto a planar surface". Elastic, frictionless spheres in an open box, so
// the total energy
//   E = sum 1/2 m v.v + 1/2 w.I w + m g y           (J; y above the floor, gravity -g y)
//     + sum over contacts 1/2 K_n delta^2            (linear spring, thesis eq. 2.2)
//       or (2/5) K_n delta^(5/2), K_n = k_hat sqrt(R*) (Hertz, eq. 3.6: the integral of K_n delta^(3/2))
// is a constant of the motion. The stored contact energy is computed on the host from the state,
// independently of the kernels: sphere-sphere overlaps r_i + r_j - |x_i - x_j| and sphere-wall
// overlaps r - (distance of the centre from the wall's plane).
// Error: max over the run of |E(t) - E(0)| / E(0), sampled every max(dt, 1e-4 s).
//
// Scene (defaults): 48 spheres of radius 5 cm and density 2500 kg/m^3 (m = 1.31 kg) on a
// 4 x 4 x 3 lattice of pitch 3 r, the lowest layer 0.1 m above the floor of a 0.6 m square box
// (four side walls), random velocities (+-0.2 m/s per component, seeded): they fall, hit the
// floor at up to 2.8 m/s, and bounce off the floor, the walls and each other for 1 s.
// Stiffness: a sphere-wall contact lasts t_c = 5 ms (linear law: t_c = pi sqrt(m / K_n) at any
// speed; Hertz: at 2 m/s, t_c = 2.9432 delta_max / v), so the thesis's dt = 1e-4 s resolves a
// wall contact in 50 steps and a sphere-sphere one (m_eff = m/2) in 35-45; the deepest overlaps
// are then up to 13% of the radius (max_overlap). Velocity Verlet's energy error scales with
// (dt / t_c)^2: the ratio is what matters, not the size of the spheres.
// Which law: Hertz by default. The linear spring's force has a kink at first touch (dF/d(delta)
// jumps from 0 to K_n), and the trapezoidal velocity update of the step that contains the touch
// (or the separation) errs by K_n v s (dt - s) / (2 m), s the part of the step after it: O(dt^2),
// but with a coefficient that jumps with where the crossing falls in the step. Each contact so
// leaves an energy error of erratic size and sign (one bounce: residual / dt^2 scatters over
// +-5e4 for dt from 1e-4 to 6e-6 s, no trend), which adds up over the run like a random walk. The
// Hertz force is smooth to first order at touch (dF/d(delta) = 1.5 K_n delta^(1/2) -> 0): the
// energy returns to its shadow value after each contact and the error is a bounded O(dt^2)
// oscillation (one bounce: max error / dt^2 within +-15% over the same range).
//
// falling_particles<Real, Integrator, NormalLaw>(dt, scene) returns the error, its history and
// the wall time of the stepping (fenced; host snapshots excluded): the verification test and the
// work-precision study use it.
#pragma once
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <random>
#include <stdexcept>
#include <vector>
#include "verification/cases/timed_run.hpp"
#include "verification/scenes.hpp"

namespace blaze::test::cases {

struct FallingParticles {
  int nx = 4, ny = 3, nz = 4;        // lattice sites (x, y layers, z)
  double radius = 0.05;              // m
  double density = 2500;             // kg/m^3
  double pitch_in_radii = 3;         // lattice spacing / r
  double lowest_gap = 0.1;           // m, floor to the lowest spheres' bottoms
  double speed = 0.2;                // m/s, each initial velocity component uniform in +-speed
  unsigned seed = 1;
  double g = 9.81;                   // m/s^2
  double wall_contact_time = 5e-3;   // s, linear law: t_c = pi sqrt(m / K_n) against a wall
  double duration = 1.0;             // s (the thesis's 1 s)
  double sample_interval = 1e-4;     // s; at least one step

  double mass() const { return density * 4.0 / 3.0 * kPi * radius * radius * radius; }
  double stiffness() const { return mass() * kPi * kPi / (wall_contact_time * wall_contact_time); }  // N/m
  double half_width() const { return 0.5 * nx * pitch_in_radii * radius; }                              // m
  int count() const { return nx * ny * nz; }
};

// Stored elastic energy of one contact (J), for overlap delta (m) and effective radius r_eff (m).
inline double stored_energy(const LinearSpringDashpot<double>& law, double delta, double) {
  return 0.5 * law.kn * delta * delta;
}
inline double stored_energy(const Hertz<double>& law, double delta, double r_eff) {
  return 0.4 * law.k_hat * std::sqrt(r_eff) * delta * delta * std::sqrt(delta);
}

// The elastic normal law of the scene, in double (the energy bookkeeping uses double).
template <template <class> class NormalLaw>
NormalLaw<double> falling_particles_law(const FallingParticles& p);
template <>
inline LinearSpringDashpot<double> falling_particles_law<LinearSpringDashpot>(const FallingParticles& p) {
  return LinearSpringDashpot<double>::from_restitution(p.stiffness(), 1.0);
}
// Hertz: k_hat chosen so that a sphere hitting a wall at 2 m/s has the linear law's contact time.
template <>
inline Hertz<double> falling_particles_law<Hertz>(const FallingParticles& p) {
  const double v = 2.0, m = p.mass();
  // t_c = 2.9432 delta_max / v, delta_max = (5 m v^2 / (4 K_n))^(2/5)  =>  K_n from t_c
  const double delta_max = p.wall_contact_time * v / 2.9432;
  const double kn = 5 * m * v * v / (4 * std::pow(delta_max, 2.5));
  return Hertz<double>::from_stiffness(kn, p.radius, 0.0);
}

template <class Real>
World<Real> falling_particles_box(const FallingParticles& p) {
  using V = Vec3<double>;
  const double a = p.half_width(), h = 4 * a;  // walls far above any bounce (elastic: E is bounded)
  World<Real> w;
  w.polygons = {PlanarPolygon<Real>::make({V{-a, 0, a}, {a, 0, a}, {a, 0, -a}, {-a, 0, -a}}, 1),
                PlanarPolygon<Real>::make({V{-a, 0, -a}, {-a, h, -a}, {-a, h, a}, {-a, 0, a}}, 1),
                PlanarPolygon<Real>::make({V{a, 0, a}, {a, h, a}, {a, h, -a}, {a, 0, -a}}, 1),
                PlanarPolygon<Real>::make({V{a, 0, -a}, {a, h, -a}, {-a, h, -a}, {-a, 0, -a}}, 1),
                PlanarPolygon<Real>::make({V{-a, 0, a}, {-a, h, a}, {a, h, a}, {a, 0, a}}, 1)};
  return w;
}

template <class Real>
ParticleState<Real> falling_particles_state(const FallingParticles& p) {
  std::mt19937_64 rng(p.seed);
  std::uniform_real_distribution<double> u(-1, 1);
  const double pitch = p.pitch_in_radii * p.radius, a = p.half_width();
  ParticleState<Real> s;
  for (int iy = 0; iy < p.ny; ++iy)
    for (int iz = 0; iz < p.nz; ++iz)
      for (int ix = 0; ix < p.nx; ++ix) {
        const Vec3<double> x{-a + (ix + 0.5) * pitch, p.lowest_gap + p.radius + iy * pitch, -a + (iz + 0.5) * pitch};
        const Vec3<double> v{p.speed * u(rng), p.speed * u(rng), p.speed * u(rng)};
        s.add_sphere(vec_cast<Real>(x), static_cast<Real>(p.radius), static_cast<Real>(p.density), 0, vec_cast<Real>(v));
      }
  return s;
}

struct EnergyParts {
  double kinetic = 0, potential = 0, elastic = 0, max_overlap = 0;  // J, J, J, m
  double total() const { return kinetic + potential + elastic; }
};

// Energies of a host snapshot in the box (floor y = 0, side walls x, z = +-a).
template <class Real, class NormalLaw>
EnergyParts falling_particles_energy(const ParticleState<Real>& s, const NormalLaw& law, const FallingParticles& p) {
  EnergyParts e;
  const Energies body = energies(s, Vec3<Real>{0, static_cast<Real>(-p.g), 0});
  e.kinetic = body.kinetic();
  e.potential = body.potential;
  const double a = p.half_width();
  std::vector<Vec3<double>> x(s.size());
  for (std::size_t i = 0; i < s.size(); ++i) x[i] = vec_cast<double>(s.position[i]);
  auto add = [&](double delta, double r_eff) {
    if (!(delta > 0)) return;
    e.elastic += stored_energy(law, delta, r_eff);
    e.max_overlap = std::fmax(e.max_overlap, delta);
  };
  for (std::size_t i = 0; i < s.size(); ++i) {
    const double r = s.radius[i];
    for (double d : {x[i].y, a - x[i].x, a + x[i].x, a - x[i].z, a + x[i].z}) add(r - d, r);
    for (std::size_t j = i + 1; j < s.size(); ++j) {
      const double rj = s.radius[j];
      add(r + rj - norm(x[j] - x[i]), r * rj / (r + rj));
    }
  }
  return e;
}

struct FallingParticlesResult {
  double error = 0;                // max |E - E0| / E0 over the run
  double error_first_quarter = 0;  // the same over [0, T/4] and over [3T/4, T]
  double error_last_quarter = 0;
  double max_overlap = 0;          // m, deepest contact seen at a sample
  double wall_s = 0;               // stepping only, fenced
  std::uint64_t steps = 0;
  long removed = 0;                // particles that left the domain (must be 0)
  std::vector<double> t, relative_error;  // (E - E0) / E0 at the samples
};

template <class Real, class Integrator, template <class> class NormalLaw = Hertz>
FallingParticlesResult falling_particles(double dt, const FallingParticles& p = {}) {
  if (!(dt > 0) || dt > p.duration) throw std::invalid_argument("falling particles: need 0 < dt <= duration");
  using Law = ContactLaw<Real, NormalLaw, NoFriction>;
  const NormalLaw<double> law = falling_particles_law<NormalLaw>(p);
  NormalLaw<Real> law_r{};
  if constexpr (std::is_same_v<NormalLaw<double>, Hertz<double>>)
    law_r = Hertz<Real>{static_cast<Real>(law.k_hat), Real(0)};
  else
    law_r = NormalLaw<Real>::from_restitution(law.kn, 1.0);
  PairTable<Law> laws;
  laws.set(0, 0, Law{law_r, {}});
  laws.set(0, 1, Law{law_r, {}});
  const ParticleState<Real> s0 = falling_particles_state<Real>(p);
  const double a = p.half_width(), r = p.radius;
  SimulationParams<Real> prm{static_cast<Real>(dt), Vec3<Real>{0, static_cast<Real>(-p.g), 0},
                             vec_cast<Real>(Vec3<double>{-a - 4 * r, -4 * r, -a - 4 * r}),
                             vec_cast<Real>(Vec3<double>{a + 4 * r, 4 * a + 4 * r, a + 4 * r}), static_cast<Real>(0.2 * r)};
  Simulation<DefaultSpace, SphereShape, Law, Integrator> sim(prm, laws, falling_particles_box<Real>(p), s0);
  const long steps = std::lround(p.duration / dt);
  const long per_sample = std::max(1L, static_cast<long>(std::floor(p.sample_interval / dt + 1e-9)));
  FallingParticlesResult out;
  const double e0 = falling_particles_energy(s0, law, p).total();
  auto sample = [&] {
    const EnergyParts e = falling_particles_energy(sim.state(), law, p);
    const double t = static_cast<double>(sim.steps()) * dt, rel = (e.total() - e0) / e0;
    out.t.push_back(t);
    out.relative_error.push_back(rel);
    out.max_overlap = std::fmax(out.max_overlap, e.max_overlap);
    out.error = std::fmax(out.error, std::fabs(rel));
    if (t <= 0.25 * p.duration) out.error_first_quarter = std::fmax(out.error_first_quarter, std::fabs(rel));
    if (t >= 0.75 * p.duration) out.error_last_quarter = std::fmax(out.error_last_quarter, std::fabs(rel));
  };
  out.wall_s = run_sampled(sim, steps, per_sample, sample);
  out.steps = sim.steps();
  out.removed = static_cast<long>(sim.removed_count());
  return out;
}

}  // namespace blaze::test::cases
