// Force hysteresis of the Hertz contact with delta^(1/2) damping (thesis section 3.3.1.2, eq. 3.7,
// Figs 3.12-3.13):
//   F_N = K_n delta^(3/2) + K_D delta^(1/2) v_n     (N; v_n approach speed, m/s; delta overlap, m)
// The thesis's scene: an octahedron of bounding radius 2.5 mm falling vertex-first onto a surface
// (here a planar wall, y = 0; density 2500 kg/m^3, no gravity: it arrives at exactly V),
// K_n = 1e9 N/m^1.5 (Hertz::from_stiffness with r_ref = the contact's r_eff, the bounding radius,
// so K_n is exact), K_D = 5e4 kg s^-1 m^-1/2 (the thesis writes kg/s; with the delta^(1/2) factor
// the unit is kg s^-1 m^-1/2), V = 2 m/s, no friction.
// Energy balance (the check): the walls do no work and the spring is conservative, so the kinetic
// energy lost over the whole contact equals the work of the damping part of the force,
//   KE_in - KE_out = integral (F_N(delta, v_n) - K_n delta^(3/2)) v_n dt,
// integrated here from the states after each step (trapezoids; on the first and last interval the
// power grows like sqrt(t - t_touch), integrated as such). The difference is the integrator's own
// energy error.
// In SI units these parameters are heavily overdamped: with L = (m V^2 / K_n)^(2/5), the
// dimensionless damping K_D L^(3/2) / (m V) is ~12, the body stops within ~0.25 L and creeps back
// out (restitution ~2e-5, or ~0.02 with the clamp). A lighter K_D = 5e2 (dimensionless 0.12) gives
// the bouncing contact and elliptical loop the thesis's figure shows; both are checked.
// Near separation the damping outlasts the spring (delta^(1/2) vs delta^(3/2)) and the total force
// turns attractive (thesis Fig 3.12); the row reports min F / max F. Hertz::without_tension clamps
// F_N >= 0: then the applied force is never attractive, and the energy balance still holds (the
// dissipative part is then max(F_el + F_d, 0) - F_el).
#include <boost/test/unit_test.hpp>
#include <algorithm>
#include <cmath>
#include <string>
#include <vector>
#include "blaze/shapes/polyhedron_shape.hpp"
#include "blaze/shapes/shape_io.hpp"
#include "verification/report.hpp"
#include "verification/scenes.hpp"

using namespace blaze;
using namespace blaze::test;

namespace {

using Law = ContactLaw<double, Hertz, NoFriction>;
using Shape = PolyhedronShape<double>;
using Sim = Simulation<DefaultSpace, Shape, Law, VelocityVerlet>;

constexpr double kBoundingRadius = 2.5e-3, kDensity = 2500, kKn = 1e9;  // m, kg/m^3, N/m^1.5
constexpr double kThesisKd = 5e4, kLightKd = 5e2;                        // kg s^-1 m^-1/2

// data/shapes/octahedron.shape scaled to the thesis's bounding radius.
ConvexShape thesis_octahedron() {
  const ConvexShape unit = load_shape("data/shapes/octahedron.shape");
  std::vector<Eigen::Vector3d> v;
  for (const auto& p : unit.vertices) v.push_back(p * (kBoundingRadius / unit.bounding_radius));
  return make_convex_shape("octahedron-2.5mm", v, unit.faces, "octahedron.shape scaled to bound_R 2.5 mm");
}

// Unit quaternion turning unit vector a onto unit vector b (not antiparallel).
Quat<double> turning(const Vec3<double>& a, const Vec3<double>& b) {
  const Vec3<double> c = cross(a, b);
  return normalized(Quat<double>{1 + dot(a, b), c.x, c.y, c.z});
}

struct Impact {
  double ke_in = 0, ke_out = 0, dissipated = 0;  // J
  double f_min = HUGE_VAL, f_max = -HUGE_VAL;    // applied normal force on the body, N (+ = repulsive)
  double duration = 0, max_overlap = 0, max_spin = 0;
  struct Sample {
    double t, delta, v_n, f, f_el;
  };
  std::vector<Sample> samples;
};

double kinetic(const ParticleState<double>& s) {
  const Vec3<double> w = s.angular_velocity[0], i = s.inertia[0];
  return 0.5 * s.mass[0] * norm2(s.velocity[0]) + 0.5 * (i.x * w.x * w.x + i.y * w.y * w.y + i.z * w.z * w.z);
}

// One vertex-first impact at speed v with damping kd; dt = t_c / steps of the elastic contact.
Impact drop(double v, double kd, bool clamp) {
  Shape shape;
  shape.table.add(thesis_octahedron(), kDensity);
  const PolyhedronData<double>& d = shape.table.type[0];
  const double m = d.mass;
  const double delta_elastic = std::pow(5 * m * v * v / (4 * kKn), 0.4), t_c = 2.9432 * delta_elastic / v;
  const double dt = t_c / tol::hysteresis_steps_per_contact;
  // The vertex farthest from the centre points straight down.
  int low = 0;
  for (int k = 1; k < d.vertex_count; ++k)
    if (norm2(d.vertex[k]) > norm2(d.vertex[low])) low = k;
  const Quat<double> q = turning(d.vertex[low] * (1 / norm(d.vertex[low])), {0, -1, 0});
  ParticleState<double> s;
  add_polyhedron(s, shape.table, 0, Vec3<double>{0, kBoundingRadius + 10 * v * dt, 0}, q, 0, {0, -v, 0});
  World<double> world;
  world.polygons.push_back(floor_square<double>(0, 4 * kBoundingRadius, 1));
  Hertz<double> hertz = Hertz<double>::from_stiffness(kKn, kBoundingRadius, kd);
  if (clamp) hertz = hertz.without_tension();
  const Law law{hertz, {}};
  Sim sim(params<double>(dt, {0, 0, 0}, 8 * kBoundingRadius, 0.2 * kBoundingRadius), one_law(law), world, s, shape);

  // Overlap from the state: depth of the lowest vertex below the plane.
  const auto overlap = [&](const ParticleState<double>& st) {
    double lowest = HUGE_VAL;
    for (int k = 0; k < d.vertex_count; ++k) lowest = std::min(lowest, st.position[0].y + rotate(st.orientation[0], d.vertex[k]).y);
    return -lowest;
  };
  // Power of the dissipative part of the law at a state (W, >= 0 when it removes energy).
  const auto damping_power = [&](double delta, double v_n) {
    if (delta <= 0) return 0.0;
    return (law.normal.normal_force(delta, v_n, m, kBoundingRadius) - law.normal.elastic_force(delta, kBoundingRadius)) * v_n;
  };
  Impact out;
  out.ke_in = kinetic(s);
  double t_prev = 0, delta_prev = overlap(s), p_prev = 0, t_touch = -1;
  for (long k = 0; k < tol::hysteresis_max_steps; ++k) {
    sim.step();
    const auto st = sim.state();
    const double t = sim.time(), delta = overlap(st), v_n = -st.velocity[0].y;
    const double p = damping_power(delta, v_n);
    out.max_spin = std::max(out.max_spin, norm(st.angular_velocity[0]));
    if (t_touch < 0 && delta > 0) {
      t_touch = t_prev + (t - t_prev) * delta_prev / (delta_prev - delta);  // delta_prev <= 0
      out.dissipated += 2.0 / 3.0 * p * (t - t_touch);  // p ~ sqrt(t - t_touch) from the touch
    } else if (t_touch >= 0 && delta > 0) {
      out.dissipated += 0.5 * (p_prev + p) * (t - t_prev);
    }
    if (t_touch >= 0 && delta > 0) {
      const double f = sim.forces()[0].y;
      out.f_min = std::min(out.f_min, f);
      out.f_max = std::max(out.f_max, f);
      out.max_overlap = std::max(out.max_overlap, delta);
      out.samples.push_back({t - t_touch, delta, v_n, f, law.normal.elastic_force(delta, kBoundingRadius)});
    }
    if (t_touch >= 0 && delta <= 0) {
      const double t_sep = t_prev + (t - t_prev) * delta_prev / (delta_prev - delta);
      out.dissipated += 2.0 / 3.0 * p_prev * (t_sep - t_prev);  // p ~ sqrt(t_sep - t) to the end
      out.duration = t_sep - t_touch;
      out.ke_out = kinetic(st);
      return out;
    }
    t_prev = t;
    delta_prev = delta;
    p_prev = p;
  }
  BOOST_FAIL("octahedron did not separate within " << tol::hysteresis_max_steps << " steps");
  return out;
}

std::string kd_text(double kd) { return kd == kThesisKd ? "K_D = 5e4 (thesis)" : "K_D = 5e2"; }

}  // namespace

BOOST_AUTO_TEST_SUITE(force_hysteresis)

BOOST_AUTO_TEST_CASE(damping_work_equals_kinetic_energy_loss) {
  const double v = 2.0;
  FigureData fig("fig-3.12", "delta_um F_N_N F_elastic_N F_diss_N  (octahedron vertex-first, V = 2 m/s, K_n = 1e9 N/m^1.5)");
  const std::string case_name = "Force hysteresis, delta^1/2 damping (3.3.1.2, Fig 3.12)";
  const std::string src = "energy balance: KE loss = work of the damping force";
  for (double kd : {kThesisKd, kLightKd}) {
    for (bool clamp : {false, true}) {
      const Impact r = drop(v, kd, clamp);
      const std::string setting = kd_text(kd) + (clamp ? ", no-tension clamp" : ", free contact") + ", V = 2 m/s, dt = t_c/" +
                                  std::to_string(static_cast<int>(tol::hysteresis_steps_per_contact));
      const double loss = r.ke_in - r.ke_out;
      BOOST_TEST_MESSAGE(setting << ": KE in " << r.ke_in << " J, out " << r.ke_out << " J (e = " << std::sqrt(r.ke_out / r.ke_in)
                                 << "), damping work " << r.dissipated << " J, contact " << r.duration << " s, delta_max "
                                 << r.max_overlap << " m, F min/max " << r.f_min << " / " << r.f_max << " N, max |w| " << r.max_spin);
      check_relative({case_name, "damping work vs KE loss, " + setting, "qualitative loop", src}, r.dissipated, loss,
                     tol::hysteresis_energy_balance);
      if (clamp) {
        check_at_least({case_name, "min F_N / max F_N (>= 0: never attractive), " + setting, "-", "Hertz::without_tension"},
                       r.f_min / r.f_max, 0.0);
      } else {
        // Reported: the free contact pulls near separation (thesis Fig 3.12 shows it); asserted
        // only that it does, since the dashpot must outlast the spring as delta -> 0.
        check_at_most({case_name, "min F_N / max F_N (< 0: attractive near separation), " + setting, "negative (Fig 3.12)",
                       "delta^1/2 damping outlasts delta^3/2 spring"},
                      r.f_min / r.f_max, 0.0);
      }
      fig.block(setting);
      for (const auto& smp : r.samples) fig.row(smp.delta * 1e6, smp.f, smp.f_el, smp.f - smp.f_el);
    }
  }
}

// Speed dependence (Fig 3.13 and the thesis's reading of it: dissipation grows with impact speed).
// Scaled by L = (m V^2 / K_n)^(2/5) and L / V, the equation of motion keeps one parameter,
// K_D L^(3/2) / (m V), proportional to K_D V^(1/5): the restitution is a function of K_D V^(1/5)
// alone and the contact time is (L / V) times a function of it. So an impact at V / 32 with 2 K_D
// must give the same e and last exactly 32^(1/5) = 2 times as long; and at fixed K_D,
// e falls as V rises. Figure data (|F_el| - |F_diss| through the contact for five speeds, both
// K_D) only when BLAZE_FIGURE_DIR is set.
BOOST_AUTO_TEST_CASE(restitution_depends_on_kd_times_speed_to_one_fifth) {
  const std::string case_name = "Force hysteresis, speed dependence (3.3.1.2, Fig 3.13)";
  FigureData fig("fig-3.13", "t_us v_n_m_per_s F_el_N F_diss_N F_el_minus_F_diss_N  (octahedron vertex-first, K_n = 1e9 N/m^1.5)");
  const double speeds[] = {0.25, 0.5, 1.0, 2.0, 4.0};
  for (double kd : {kLightKd, kThesisKd}) {
    if (kd == kThesisKd && !fig.enabled()) break;  // the overdamped runs are for the figure only
    int falling = 0;
    double e_prev = 2;
    for (double v : speeds) {
      const Impact r = drop(v, kd, false);
      const double e = std::sqrt(r.ke_out / r.ke_in);
      BOOST_TEST_MESSAGE(kd_text(kd) << ", V = " << v << " m/s: e = " << e << ", contact " << r.duration << " s");
      falling += e < e_prev;
      e_prev = e;
      fig.block(kd_text(kd) + ", V = " + std::to_string(v).substr(0, 4) + " m/s");
      for (const auto& smp : r.samples)
        fig.row(smp.t * 1e6, smp.v_n, smp.f_el, smp.f - smp.f_el, std::fabs(smp.f_el) - std::fabs(smp.f - smp.f_el));
    }
    if (kd == kLightKd)
      check_at_least({case_name, "successive speeds 0.25..4 m/s with lower e (of 5), K_D = 5e2, free contact",
                      "dissipation grows with speed", "e = f(K_D V^(1/5))"},
                     falling, 5);
  }
  const Impact fast = drop(4.0, kLightKd, false), slow = drop(4.0 / 32, 2 * kLightKd, false);
  const double e_fast = std::sqrt(fast.ke_out / fast.ke_in), e_slow = std::sqrt(slow.ke_out / slow.ke_in);
  BOOST_TEST_MESSAGE("similarity: e(4 m/s, 5e2) = " << e_fast << ", e(0.125 m/s, 1e3) = " << e_slow << ", durations " << fast.duration
                                                    << ", " << slow.duration);
  check_at_most({case_name, "|e(V, K_D) - e(V/32, 2 K_D)|, V = 4 m/s, K_D = 5e2, free contact", "-",
                 "similarity: e depends on K_D V^(1/5)"},
                std::fabs(e_fast - e_slow), tol::hysteresis_similarity);
  check_relative({case_name, "contact time t(V/32, 2 K_D) / t(V, K_D) vs 32^(1/5) = 2", "-", "similarity: t_c ~ L / V ~ V^(-1/5)"},
                 slow.duration / fast.duration, 2.0, tol::hysteresis_similarity);
}

BOOST_AUTO_TEST_SUITE_END()
