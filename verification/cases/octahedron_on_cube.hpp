// Head-on elastic collision of the thesis's section 3.3.1.1 (Table 3.1, Figs 3.9-3.11): an
// octahedron moving at speed v along -y strikes, vertex first, the centre of the upper face of a
// free cube at rest (single_body.hpp: bounding radii 0.25 cm, K_n = 1e9 N/m^(3/2), no gravity, no
// friction). The vertex meets the face on the line of centres, so the contact is a 1-D Hertz
// contact (overlap = the vertex's depth below the face, normal along y, no torque):
//   delta_max = (5 m_eff v^2 / (4 K_n))^(2/5),  t_c = (4/5) B(2/5, 1/2) delta_max / v = 2.9432 delta_max / v,
//   m_eff = m_o m_c / (m_o + m_c)
// and afterwards, as for any elastic 1-D collision (momentum and energy),
//   v_o' = -(m_o - m_c)/(m_o + m_c) v,   v_c' = -2 m_o/(m_o + m_c) v   (y components, m/s),
// so the separation speed equals the approach speed v.
// K_n is exact for this contact: Hertz::from_stiffness(K_n, r_ref) with r_ref = the effective
// radius polyhedron_shape.hpp gives a polyhedron pair, R_o R_c / (R_o + R_c) = 1.25 mm.
// Precision and integrator are template parameters (the work-precision study times this runner);
// with `record` every step's penetration, force and velocities are kept (one host copy per step).
#pragma once
#include <chrono>
#include <cmath>
#include <vector>
#include "blaze/laws/contact_law.hpp"
#include "blaze/laws/hertz.hpp"
#include "blaze/laws/history_free_friction.hpp"
#include "pipeline/simulation.hpp"
#include "verification/cases/single_body.hpp"

namespace blaze::test::cases {

struct HeadOnSample {
  double t;         // s
  double delta;     // m, from the positions: (R_o + h_c) - (y_o - y_c)
  double force;     // N, normal force on the cube (along -y), from the simulation's force array
  double v_octa;    // m/s, y velocities
  double v_cube;
};

struct OctahedronOnCubeResult {
  double speed, dt;                        // m/s, s
  double m_octa, m_cube, m_eff, k_n;       // kg, N/m^(3/2)
  double delta_max_exact, contact_time_exact;
  double v_octa_exact, v_cube_exact;       // final y velocities, m/s
  double v_octa, v_cube;                   // measured final y velocities, m/s
  double rebound_ratio;                    // (v_octa - v_cube) / v: separation over approach speed
  double max_spin;                         // rad/s, largest |w| of either body at the end
  bool separated;                          // the bodies no longer overlap at the end
  long steps;
  double wall_s;                           // stepping wall time, s
  std::vector<HeadOnSample> samples;       // only with record
};

struct OctahedronOnCubeScene {
  ConvexShape octa = thesis_octahedron(), cube = thesis_cube();
  double density = kThesisDensity, k_n = kThesisKn;
  double m_octa() const { return density * octa.volume; }
  double m_cube() const { return density * cube.volume; }
  double m_eff() const { return m_octa() * m_cube() / (m_octa() + m_cube()); }
  double r_eff() const { return octa.bounding_radius * cube.bounding_radius / (octa.bounding_radius + cube.bounding_radius); }
  double delta_max(double v) const { return std::pow(5 * m_eff() * v * v / (4 * k_n), 0.4); }
  double contact_time(double v) const { return 2.9432 * delta_max(v) / v; }
};

template <class Real, class Integrator>
OctahedronOnCubeResult octahedron_on_cube(const OctahedronOnCubeScene& sc, double v, double dt, bool record) {
  using Law = ContactLaw<Real, Hertz, NoFriction>;
  using Shape = PolyhedronShape<Real>;
  Shape shape;
  const int t_octa = shape.table.add(sc.octa, sc.density), t_cube = shape.table.add(sc.cube, sc.density);
  const double r_o = sc.octa.vertices[0].norm(), h_c = cube_half_edge(sc.cube);
  const double gap = 0.05 * sc.delta_max(v);  // vertex above the face at the start
  const Eigen::Vector3d up(0, 1, 0), side(1, 0, 0);
  ParticleState<Real> s;
  add_polyhedron(s, shape.table, t_octa, Vec3<Real>{0, static_cast<Real>(h_c + r_o + gap), 0},
                 octahedron_pointing<Real>(sc.octa, -up, side), 0, Vec3<Real>{0, static_cast<Real>(-v), 0});
  add_polyhedron(s, shape.table, t_cube, Vec3<Real>{0, 0, 0}, cube_facing<Real>(sc.cube, up, side), 0);
  PairTable<Law> laws;
  laws.set(0, 0, Law{Hertz<Real>::from_stiffness(sc.k_n, sc.r_eff(), 0), {}});
  const Real box = static_cast<Real>(10 * kThesisBoundingRadius);
  const SimulationParams<Real> prm{static_cast<Real>(dt), {0, 0, 0}, {-box, -box, -box}, {box, box, box},
                                   static_cast<Real>(0.2 * kThesisBoundingRadius)};
  Simulation<DefaultSpace, Shape, Law, Integrator> sim(prm, laws, World<Real>{}, s, shape);

  OctahedronOnCubeResult r{};
  r.speed = v, r.dt = dt, r.m_octa = sc.m_octa(), r.m_cube = sc.m_cube(), r.m_eff = sc.m_eff(), r.k_n = sc.k_n;
  r.delta_max_exact = sc.delta_max(v), r.contact_time_exact = sc.contact_time(v);
  r.v_octa_exact = -(r.m_octa - r.m_cube) / (r.m_octa + r.m_cube) * v;
  r.v_cube_exact = -2 * r.m_octa / (r.m_octa + r.m_cube) * v;
  // Approach, contact, and a quarter contact time to spare.
  r.steps = static_cast<long>(std::ceil((gap / v + 1.25 * r.contact_time_exact) / dt));
  const auto octa_first = [](const ParticleState<Real>& st) { return st.id[0] == 0 ? 0 : 1; };
  const auto delta_of = [&](const ParticleState<Real>& st, int io) {
    return (h_c + r_o) - (static_cast<double>(st.position[io].y) - static_cast<double>(st.position[1 - io].y));
  };
  const auto t0 = std::chrono::steady_clock::now();
  if (record) {
    for (long k = 0; k < r.steps; ++k) {
      sim.step();
      const auto st = sim.state();
      const int io = octa_first(st);
      r.samples.push_back({sim.time(), delta_of(st, io), -static_cast<double>(sim.forces()[1 - io].y),
                           static_cast<double>(st.velocity[io].y), static_cast<double>(st.velocity[1 - io].y)});
    }
  } else {
    sim.run(static_cast<std::uint64_t>(r.steps));
  }
  const auto st = sim.state();  // also waits for the device
  r.wall_s = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  const int io = octa_first(st);
  r.v_octa = static_cast<double>(st.velocity[io].y);
  r.v_cube = static_cast<double>(st.velocity[1 - io].y);
  r.rebound_ratio = (r.v_octa - r.v_cube) / v;
  r.max_spin = std::max(norm(vec_cast<double>(st.angular_velocity[0])), norm(vec_cast<double>(st.angular_velocity[1])));
  r.separated = delta_of(st, io) < 0;
  return r;
}

}  // namespace blaze::test::cases
