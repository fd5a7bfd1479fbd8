// Energy balance of the time series (issue 17, item 8): energy in = energy out + stored,
//   E(0) = E_kin(t) + E_pot(t) + E_elastic(t) + dissipated(t) + E_removed(t),
// E_elastic the energy held in the open contacts (Simulation::contact_energy(): 1/2 K_n delta^2
// per linear contact, (2/5) K_n delta^(5/2) per Hertzian one, particle-particle and -wall), as
// RunLog writes it to timeseries.csv (elastic_J, total_J, dissipated_J).
// - The stored energy is the integral of the elastic force (both laws; the no-tension clamp
//   leaves it unchanged), and the kernel's sum (each pair once, walls and cylinders) equals a
//   brute-force host sum over all pairs and walls.
// - Elastic box (e = 1, mu = 0, six walls, gravity on and off, linear and Hertz, double), swept
//   over dt, stiffness and particle count: |dissipated_J| / scale stays within velocity
//   Verlet's wobble tol::energy_balance_wobble x (omega dt)^2 (tolerances.hpp derives it), and
//   without elastic_J the same rows breach that bound (so the test can fail).
// - Damped packing (e < 1, friction): dissipated_J never falls between rows by more than the
//   wobble; each row balances exactly as defined (columns add up).
// - A column of N spheres at rest on a floor (linear law): the contact k-th from the bottom
//   carries (N - k) m g, so E_elastic = sum_{j=1..N} (j m g)^2 / (2 K_n), the heights follow
//   from the overlaps, and dissipated_J = E(0) - E_pot - E_elastic (all in closed form).
// - contacts_wall counts particle-world contacts: 9 spheres resting on a floor give 9.
// - `blaze run` writes elastic_J and contacts_wall, and its rows balance.
#include <boost/test/data/test_case.hpp>
#include <boost/test/unit_test.hpp>
#include <cctype>
#include <cmath>
#include <filesystem>
#include <random>
#include <string>
#include "pipeline/run_log.hpp"
#include "verification/cases/single_body.hpp"
#include "verification/report.hpp"
#include "verification/run_program.hpp"
#include "verification/scenes.hpp"

using namespace blaze;
using namespace blaze::test;
namespace fs = std::filesystem;

namespace {

const char* const kCase = "Energy balance (issue 17)";
using Csv = std::map<std::string, std::vector<double>>;

template <class Law>
using LoggedSim = Simulation<DefaultSpace, SphereShape, Law, VelocityVerlet, ContactPointVelocity, MonitoredFeatures>;

// The six walls of the cube [-a, a]^3, normals inwards (a polygon acts on the side its normal
// points to, vertices counter-clockwise seen from there: t1 x t2 = n).
template <class Real>
World<Real> closed_box(double a, std::uint8_t material = 1) {
  using V = Vec3<double>;
  World<Real> w;
  const V axes[3] = {{1, 0, 0}, {0, 1, 0}, {0, 0, 1}};
  for (int d = 0; d < 3; ++d)
    for (double sign : {1.0, -1.0}) {
      const V n = axes[d] * sign, t1 = axes[(d + 1) % 3], t2 = cross(n, t1), c = n * (-a);
      w.polygons.push_back(PlanarPolygon<Real>::make(
          {c + (t1 + t2) * (-a), c + (t1 - t2) * a, c + (t1 + t2) * a, c + (t2 - t1) * a}, material));
    }
  return w;
}

// A run through RunLog (the time series `blaze run` writes), one row every `every` steps.
struct LoggedRun {
  Csv csv;
  double worst_penetration = 0;  // overlap / radius, over every step
  double scale = 0;              // J, RunLog's energy scale: E_kin(0) + E_elastic(0) + sum m g h
};

template <class Law>
LoggedRun logged_run(LoggedSim<Law>& sim, const Vec3<double>& g, double height, long steps, long every, const std::string& name) {
  std::string file = "blaze_energy_balance_" + name + ".csv";
  for (char& ch : file)
    if (!std::isalnum(static_cast<unsigned char>(ch)) && ch != '.') ch = '_';
  const std::string path = (fs::temp_directory_path() / file).string();
  LoggedRun out;
  {
    RunLog<double> log(path, 1.0, 1.0, g, height);
    for (long k = 0; k <= steps; k += every) {
      log.sample(sim);
      if (k < steps) sim.run(static_cast<std::uint64_t>(std::min(every, steps - k)));
    }
    out.worst_penetration = log.worst_penetration();
  }
  out.csv = read_csv(path);
  fs::remove(path);
  const auto& c = out.csv;
  double mass = 0;
  for (double m : sim.state().mass) mass += m;
  out.scale = c.at("kinetic_translational_J")[0] + c.at("kinetic_rotational_J")[0] + c.at("elastic_J")[0] + mass * norm(g) * height;
  return out;
}

// Largest |column| / scale over the rows, and the same of dissipated_J + elastic_J - elastic_J(0):
// what dissipated_J was before the stored energy was counted.
double max_share(const std::vector<double>& col, double scale) {
  double m = 0;
  for (double x : col) m = std::fmax(m, std::fabs(x) / scale);
  return m;
}
double max_share_without_elastic(const Csv& c, double scale) {
  double m = 0;
  const auto &d = c.at("dissipated_J"), &el = c.at("elastic_J");
  for (std::size_t k = 0; k < d.size(); ++k) m = std::fmax(m, std::fabs(d[k] + el[k] - el[0]) / scale);
  return m;
}
// Largest |E(0) - (columns of row k summed)| / scale: the balance as defined, to the CSV's 10 digits.
double balance_residual(const Csv& c, double scale) {
  double m = 0;
  const double e0 = c.at("total_J")[0];
  for (std::size_t k = 0; k < c.at("t_s").size(); ++k) {
    const double parts = c.at("kinetic_translational_J")[k] + c.at("kinetic_rotational_J")[k] + c.at("potential_J")[k] +
                         c.at("elastic_J")[k];
    m = std::fmax(m, std::fabs(parts - c.at("total_J")[k]) / scale);
    m = std::fmax(m, std::fabs(e0 - c.at("total_J")[k] - c.at("dissipated_J")[k]) / scale);
  }
  return m;
}

// ---- the elastic box --------------------------------------------------------------------------

struct BoxCase {
  std::string name;
  bool hertz;
  bool gravity;
  int n;                // spheres per side of the starting lattice (n^3 spheres)
  double contact_time;  // s, a sphere-wall contact at 1 m/s (linear: at any speed)
  double steps_per_contact;
};

constexpr double kRadius = 0.01, kDensity = 2500, kG = 9.81;
double sphere_mass() { return kDensity * 4.0 / 3.0 * kPi * kRadius * kRadius * kRadius; }

std::ostream& operator<<(std::ostream& o, const BoxCase& c) { return o << c.name; }

struct BoxOutcome {
  double with = 0, without = 0, limit = 0, omega_dt = 0, balance = 0;
  long removed = 0;
};

template <template <class> class NormalLaw>
NormalLaw<double> box_law(const BoxCase& c) {
  const double m = sphere_mass();
  if constexpr (std::is_same_v<NormalLaw<double>, Hertz<double>>) {
    const double v = 1.0, delta_max = c.contact_time * v / 2.9432;  // t_c = 2.9432 delta_max / v (hertz.hpp)
    return Hertz<double>::from_stiffness(5 * m * v * v / (4 * std::pow(delta_max, 2.5)), kRadius, 0.0);
  } else {
    return LinearSpringDashpot<double>::from_restitution(m * kPi * kPi / (c.contact_time * c.contact_time), 1.0);
  }
}

// The fastest contact frequency of the run (rad/s): the pair contact (m_eff = m/2, R* = r/2) at
// the deepest overlap seen; for the linear law sqrt(2 K_n / m) at any overlap.
template <class NormalLaw>
double fastest_omega(const NormalLaw& law, double deepest) {
  const double m = sphere_mass();
  return std::fmax(std::sqrt(law.stiffness(deepest, kRadius / 2) / (m / 2)), std::sqrt(law.stiffness(deepest, kRadius) / m));
}

template <template <class> class NormalLaw>
BoxOutcome elastic_box(const BoxCase& c) {
  using Law = ContactLaw<double, NormalLaw, NoFriction>;
  const NormalLaw<double> law = box_law<NormalLaw>(c);
  const double pitch = 3 * kRadius, a = 0.5 * c.n * pitch, dt = c.contact_time / c.steps_per_contact;
  std::mt19937_64 rng(7 + c.n);
  std::uniform_real_distribution<double> u(-1, 1);
  ParticleState<double> s;
  for (int i = 0; i < c.n; ++i)
    for (int j = 0; j < c.n; ++j)
      for (int k = 0; k < c.n; ++k)
        s.add_sphere({-a + (i + 0.5) * pitch, -a + (j + 0.5) * pitch, -a + (k + 0.5) * pitch}, kRadius, kDensity, 0,
                     {0.7 * u(rng), 0.7 * u(rng), 0.7 * u(rng)});
  const Vec3<double> g{0, c.gravity ? -kG : 0, 0};
  LoggedSim<Law> sim(params<double>(dt, g, a + 5 * kRadius, 0.1 * kRadius), one_law(Law{law, {}}), closed_box<double>(a), s);
  // 0.25 s: each sphere meets walls and others many times; a row every 4 steps (>= 6 per contact)
  const long steps = std::lround(0.25 / dt);
  const LoggedRun r = logged_run(sim, g, 2 * a, steps, 4, c.name);
  BoxOutcome o;
  o.omega_dt = fastest_omega(law, r.worst_penetration * kRadius) * dt;
  o.limit = tol::energy_balance_wobble * o.omega_dt * o.omega_dt;
  o.with = max_share(r.csv.at("dissipated_J"), r.scale);
  o.without = max_share_without_elastic(r.csv, r.scale);
  o.balance = balance_residual(r.csv, r.scale);
  o.removed = static_cast<long>(sim.removed_count());
  return o;
}

const BoxCase kBoxes[] = {
    {"linear, gravity, 27 spheres, t_c = 2 ms, t_c/50", false, true, 3, 2e-3, 50},
    {"linear, gravity, 27 spheres, t_c = 2 ms, t_c/100", false, true, 3, 2e-3, 100},
    {"linear, gravity, 27 spheres, t_c = 1 ms, t_c/50", false, true, 3, 1e-3, 50},
    {"linear, gravity, 8 spheres, t_c = 2 ms, t_c/50", false, true, 2, 2e-3, 50},
    {"linear, no gravity, 27 spheres, t_c = 2 ms, t_c/50", false, false, 3, 2e-3, 50},
    {"linear, no gravity, 64 spheres, t_c = 2 ms, t_c/25", false, false, 4, 2e-3, 25},
    {"Hertz, gravity, 27 spheres, t_c = 2 ms, t_c/50", true, true, 3, 2e-3, 50},
    {"Hertz, gravity, 27 spheres, t_c = 2 ms, t_c/100", true, true, 3, 2e-3, 100},
    {"Hertz, gravity, 27 spheres, t_c = 1 ms, t_c/50", true, true, 3, 1e-3, 50},
    {"Hertz, gravity, 8 spheres, t_c = 2 ms, t_c/50", true, true, 2, 2e-3, 50},
    {"Hertz, no gravity, 27 spheres, t_c = 2 ms, t_c/50", true, false, 3, 2e-3, 50},
    {"Hertz, no gravity, 64 spheres, t_c = 2 ms, t_c/25", true, false, 4, 2e-3, 25},
};

// ---- the resting column ---------------------------------------------------------------------

struct Column {
  int n = 5;
  double kn = 1e4;      // N/m, sphere-sphere and sphere-floor
  double e = 0.3;       // restitution
  double mu = 0.5;      // friction (on, though nothing slides)
  double kt = 1.0;      // kg/s
  double dt = 1e-5;     // s: omega dt = sqrt(k / m) dt = 0.0098
  double duration = 1;  // s: the slowest mode decays as exp(-t / 0.036 s) (header), 28 decay times
};

}  // namespace

BOOST_AUTO_TEST_SUITE(energy_balance)

// U(delta) = int_0^delta F_elastic: Simpson's rule over [0, delta] (exact to ~1e-10 for these
// smooth integrands at 2000 intervals: Hertz's delta^(3/2) has a bounded fourth derivative away
// from 0, and the error there is O(h^(5/2)) of a vanishing force). The clamp changes nothing.
BOOST_AUTO_TEST_CASE(stored_energy_is_the_integral_of_the_elastic_force) {
  const auto linear = LinearSpringDashpot<double>::from_restitution(3e4, 0.4);
  const auto hertz = Hertz<double>::from_restitution(1e8, 0.4);
  const double r_eff = 4e-3;
  for (double delta : {1e-6, 1e-5, 2e-4}) {
    auto integral = [&](const auto& law) {
      const int n = 2000;
      const double h = delta / n;
      double sum = law.elastic_force(0.0, r_eff) + law.elastic_force(delta, r_eff);
      for (int k = 1; k < n; ++k) sum += (k % 2 ? 4 : 2) * law.elastic_force(k * h, r_eff);
      return sum * h / 3;
    };
    check_relative({kCase, "linear stored energy vs int F_el, delta = " + std::to_string(delta) + " m", "-", "U = 1/2 K_n delta^2"},
                   linear.stored_energy(delta, r_eff), integral(linear), tol::stored_energy_integral);
    check_relative({kCase, "Hertz stored energy vs int F_el, delta = " + std::to_string(delta) + " m", "-",
                    "U = 2/5 K_n delta^(5/2) (Johnson 1985, 4.2)"},
                   hertz.stored_energy(delta, r_eff), integral(hertz), tol::stored_energy_integral);
    BOOST_TEST(linear.without_tension().stored_energy(delta, r_eff) == linear.stored_energy(delta, r_eff));
    BOOST_TEST(hertz.without_tension().stored_energy(delta, r_eff) == hertz.stored_energy(delta, r_eff));
  }
  BOOST_TEST(linear.stored_energy(-1e-6, r_eff) == 0.0);
  BOOST_TEST(hertz.stored_energy(-1e-6, r_eff) == 0.0);
}

// Random overlapping spheres of two materials in a box with a drum: contact_energy() (each pair
// once, over the neighbour list) against the host sum over every pair and every wall.
BOOST_AUTO_TEST_CASE(contact_energy_matches_a_brute_force_sum) {
  using Law = ContactLaw<double, Hertz, NoFriction>;
  PairTable<Law> laws;
  const Law soft{Hertz<double>::from_modulus(2e7, 0), {}}, hard{Hertz<double>::from_modulus(9e7, 0), {}};
  laws.set(0, 0, soft), laws.set(0, 1, hard), laws.set(1, 1, hard), laws.set(0, 2, hard), laws.set(1, 2, soft);
  auto s = random_spheres<double>(400, 1e-3, 3e-3, 0.036, 11);
  for (std::size_t k = 0; k < s.size(); ++k) s.material[k] = static_cast<std::uint8_t>(k % 2);
  World<double> w = closed_box<double>(0.02, 2);
  w.cylinders.push_back(Cylinder<double>::make({0, 0, -0.02}, {0, 0, 1}, 0.019, 0.04, 2));
  SphereSim<Law> sim(params<double>(1e-7, {0, 0, 0}, 0.03, 1e-3), laws, w, s);
  const ContactEnergy e = sim.contact_energy();
  const ParticleState<double> st = sim.state();
  double pairs = 0, walls = 0;
  long touching = 0, pair_contacts = 0;
  const SphereShape shape;
  for (std::size_t i = 0; i < st.size(); ++i) {
    const SphereShape::Body<double> bi{st.position[i], st.radius[i], static_cast<Index>(i)};
    for (std::size_t j = i + 1; j < st.size(); ++j) {
      const auto g = shape.collide(bi, SphereShape::Body<double>{st.position[j], st.radius[j], static_cast<Index>(j)});
      if (g.touching) pairs += laws(st.material[i], st.material[j]).normal.stored_energy(g.overlap, g.r_eff), ++pair_contacts;
    }
    for (const auto& p : w.polygons)
      if (const auto g = shape.collide_world(bi, p); g.touching) walls += laws(st.material[i], 2).stored_energy(g), ++touching;
    for (const auto& c : w.cylinders)
      if (const auto g = shape.collide_world(bi, c); g.touching) walls += laws(st.material[i], 2).stored_energy(g), ++touching;
  }
  BOOST_TEST_MESSAGE("brute force: " << pair_contacts << " pair contacts " << pairs << " J, " << touching << " wall contacts "
                                     << walls << " J; kernel " << e.pairs << " J, " << e.walls << " J");
  BOOST_TEST_REQUIRE(pair_contacts > 100);
  BOOST_TEST_REQUIRE(touching > 20);
  check_relative({kCase, "contact_energy() pairs vs all-pairs host sum, 400 spheres", "-", "each pair once"}, e.pairs, pairs,
                 tol::stored_energy_sum);
  check_relative({kCase, "contact_energy() walls vs host sum over walls and drum", "-", "every wall contact"}, e.walls, walls,
                 tol::stored_energy_sum);
  BOOST_TEST(e.wall_contacts == touching);
}

// A time-series sample is reduced where the particles live (Simulation::sample(), a kernel and
// reduce_in_order): its energies and mass against the host's sums over a downloaded state
// (energies(), blaze/sim/energy.hpp), for moving, spinning, overlapping spheres in float and double
// and for a spinning cube (moments from the polyhedron table on the device); the kept state
// (keep_state(), what a guard writes as last_good.vtu) is the state at the keep, bit for bit.
template <class Real>
void check_sample_against_host(unsigned seed) {
  using Law = ContactLaw<Real, Hertz, NoFriction>;
  auto s = random_spheres<Real>(3000, 1e-3, 3e-3, 0.05, seed);
  std::mt19937_64 rng(seed);
  std::normal_distribution<double> n01(0, 1);
  for (std::size_t k = 0; k < s.size(); ++k) {
    s.velocity[k] = vec_cast<Real>(Vec3<double>{n01(rng), n01(rng), n01(rng)} * 0.1);
    s.angular_velocity[k] = vec_cast<Real>(Vec3<double>{n01(rng), n01(rng), n01(rng)} * 30.0);
  }
  const Vec3<double> g{0.3, -9.81, 0.1};
  LoggedSim<Law> sim(params<Real>(1e-7, g, 0.07, 1e-3), one_law(Law{Hertz<Real>::from_modulus(5e7, 0), {}}, 2),
                     closed_box<Real>(0.03), s);
  sim.run(20);
  const ParticleState<Real> st = sim.state();
  const Energies host = energies(st, vec_cast<Real>(g));
  double mass = 0;
  for (Real m : st.mass) mass += static_cast<double>(m);
  sim.keep_state();
  const auto smp = sim.sample(0.01);
  const char* precision = sizeof(Real) == 4 ? "float" : "double";
  const std::string what = std::string(" (sample() vs host sum, 3000 spheres, ") + precision + ")";
  check_relative({kCase, "translational energy" + what, "-", "same terms, another order"}, smp.energies.translational,
                 host.translational, tol::stored_energy_sum);
  check_relative({kCase, "rotational energy" + what, "-", "same terms, another order"}, smp.energies.rotational,
                 host.rotational, tol::stored_energy_sum);
  check_relative({kCase, "potential energy" + what, "-", "same terms, another order"}, smp.energies.potential,
                 host.potential, tol::stored_energy_sum);
  check_relative({kCase, "mass" + what, "-", "same terms, another order"}, smp.mass, mass, tol::stored_energy_sum);
  BOOST_TEST(smp.stored.pairs > 0);  // the random fill overlaps
  BOOST_TEST(smp.vertex_face > 0);
  BOOST_TEST(smp.penetration.worst > 0);
  BOOST_TEST(smp.penetration.worst_id >= 0);
  sim.run(30);
  const ParticleState<Real> kept = sim.kept_state(), now = sim.state();
  BOOST_TEST_REQUIRE(kept.size() == st.size());
  bool same = true, moved = false;
  for (std::size_t k = 0; k < st.size(); ++k) {
    same = same && kept.position[k].x == st.position[k].x && kept.position[k].y == st.position[k].y &&
           kept.velocity[k].z == st.velocity[k].z && kept.angular_velocity[k].x == st.angular_velocity[k].x &&
           kept.id[k] == st.id[k] && kept.mass[k] == st.mass[k] && kept.inertia[k].x == st.inertia[k].x;
    moved = moved || now.position[k].x != st.position[k].x;
  }
  BOOST_TEST(same, "kept_state() is the state at keep_state()");
  BOOST_TEST(moved, "the run went on after the keep");
}

BOOST_AUTO_TEST_CASE(a_sample_reduced_in_place_matches_the_host_sums) {
  for (unsigned seed : {3u, 4u}) {
    check_sample_against_host<double>(seed);
    check_sample_against_host<float>(seed);
  }
  // a spinning, moving cube: its moments come from the shape table in the kernel
  using Law = ContactLaw<double, Hertz, NoFriction>;
  const ConvexShape cube = cases::thesis_cube();
  auto sim = cases::body_over_floor<Law>(cube, 2500, Law{Hertz<double>::from_modulus(5e7, 0), {}}, floor_square<double>(0, 0.05),
                                         normalized(Quat<double>{0.9, 0.3, 0.2, 0.1}), {0, 0.01, 0}, {0.2, -0.1, 0.3}, {0, -9.81, 0}, 1e-6,
                                         {-0.1, -0.1, -0.1}, {0.1, 0.1, 0.1});
  ParticleState<double> st = sim.state();
  st.angular_velocity[0] = {40, -25, 10};
  auto spun = cases::body_over_floor<Law>(cube, 2500, Law{Hertz<double>::from_modulus(5e7, 0), {}}, floor_square<double>(0, 0.05),
                                          st, {0, -9.81, 0}, 1e-6, {-0.1, -0.1, -0.1}, {0.1, 0.1, 0.1});
  const Energies host = energies(spun.state(), Vec3<double>{0, -9.81, 0});
  const auto smp = spun.sample(0.01);
  BOOST_TEST(smp.stored.walls == 0.0);  // above the floor
  BOOST_TEST_REQUIRE(host.rotational > 0);
  check_relative({kCase, "cube: rotational energy, sample() vs host sum", "-", "one body, the same formula"},
                 smp.energies.rotational, host.rotational, tol::stored_energy_sum);
  check_relative({kCase, "cube: translational energy, sample() vs host sum", "-", "one body, the same formula"},
                 smp.energies.translational, host.translational, tol::stored_energy_sum);
}

#if BLAZE_DEVICE_CODE
// The same overlapping packing on both backends: the stored energies agree to the ulps in which
// the GPU's fused multiply-adds differ, the wall contacts exactly.
BOOST_AUTO_TEST_CASE(contact_energy_cpu_and_gpu_agree) {
  using Law = ContactLaw<double, Hertz, NoFriction>;
  const auto laws = one_law(Law{Hertz<double>::from_modulus(5e7, 0), {}}, 3);
  const auto s = random_spheres<double>(2000, 1e-3, 3e-3, 0.038, 12);
  World<double> w = closed_box<double>(0.02, 2);
  w.cylinders.push_back(Cylinder<double>::make({0, 0, -0.02}, {0, 0, 1}, 0.019, 0.04, 2));
  Simulation<Host, SphereShape, Law, VelocityVerlet> cpu(params<double>(1e-7, {0, 0, 0}, 0.03, 1e-3), laws, w, s);
  Simulation<Cuda, SphereShape, Law, VelocityVerlet> gpu(params<double>(1e-7, {0, 0, 0}, 0.03, 1e-3), laws, w, s);
  const ContactEnergy a = cpu.contact_energy(), b = gpu.contact_energy();
  check_relative({kCase, "contact_energy() pairs, GPU vs CPU, 2000 spheres", "-", "same double arithmetic"}, b.pairs, a.pairs,
                 tol::cpu_gpu_contact_energy);
  check_relative({kCase, "contact_energy() walls, GPU vs CPU", "-", "same double arithmetic"}, b.walls, a.walls,
                 tol::cpu_gpu_contact_energy);
  BOOST_TEST(a.wall_contacts == b.wall_contacts);
}
#endif

BOOST_DATA_TEST_CASE(elastic_box_balances, boost::unit_test::data::make(kBoxes), c) {
  const BoxOutcome o = c.hertz ? elastic_box<Hertz>(c) : elastic_box<LinearSpringDashpot>(c);
  BOOST_TEST_MESSAGE("elastic box, " << c.name << ": omega dt " << o.omega_dt << ", max |dissipated| / scale " << o.with
                                     << " (" << o.with / (o.omega_dt * o.omega_dt) << " (omega dt)^2), without elastic_J "
                                     << o.without << ", limit " << o.limit << ", balance residual " << o.balance);
  BOOST_TEST(o.removed == 0);
  check_at_most({kCase, "elastic box, " + c.name + ": max |dissipated_J| / scale", "-", "velocity Verlet wobble, (omega dt)^2"},
                o.with, o.limit);
  check_at_least({kCase, "elastic box, " + c.name + ": the same without elastic_J", "-", "must breach the wobble bound"},
                 o.without, o.limit);
  check_at_most({kCase, "elastic box, " + c.name + ": |E(0) - parts - dissipated_J| / scale", "-", "columns add up"},
                o.balance, tol::csv_balance);
}

// Spheres poured into the closed box with dashpots and friction (linear and Hertz): dissipation
// only ever takes energy out, so dissipated_J never falls between rows by more than the wobble,
// and every row balances as defined.
template <class Law>
void damped_packing(const Law& law, const std::string& name, double contact_time) {
  const int n = 3;
  const double pitch = 3 * kRadius, a = 0.5 * n * pitch, dt = contact_time / 50;
  std::mt19937_64 rng(3);
  std::uniform_real_distribution<double> u(-1, 1);
  ParticleState<double> s;
  for (int i = 0; i < n; ++i)
    for (int j = 0; j < n; ++j)
      for (int k = 0; k < n; ++k)
        s.add_sphere({-a + (i + 0.5) * pitch, -a + (j + 0.5) * pitch, -a + (k + 0.5) * pitch}, kRadius, kDensity, 0,
                     {0.5 * u(rng), 0.5 * u(rng), 0.5 * u(rng)});
  const Vec3<double> g{0, -kG, 0};
  LoggedSim<Law> sim(params<double>(dt, g, a + 5 * kRadius, 0.1 * kRadius), one_law(law), closed_box<double>(a), s);
  const LoggedRun r = logged_run(sim, g, 2 * a, std::lround(0.4 / dt), 5, "damped_" + name);
  const auto& d = r.csv.at("dissipated_J");
  double worst_fall = 0;  // largest decrease of dissipated_J between rows, J
  for (std::size_t k = 1; k < d.size(); ++k) worst_fall = std::fmax(worst_fall, d[k - 1] - d[k]);
  const double omega_dt = fastest_omega(law.normal, r.worst_penetration * kRadius) * dt;
  const double limit = tol::energy_balance_wobble * omega_dt * omega_dt;
  BOOST_TEST_MESSAGE("damped packing, " << name << ": dissipated " << d.back() << " J of scale " << r.scale
                                        << " J; largest fall between rows " << worst_fall / r.scale << " of the scale ("
                                        << worst_fall / r.scale / (omega_dt * omega_dt) << " (omega dt)^2)");
  BOOST_TEST(sim.removed_count() == 0);
  BOOST_TEST(d.back() > 0.5 * r.csv.at("kinetic_translational_J").front());  // it did dissipate
  check_at_most({kCase, "damped packing, 27 spheres, " + name + ": largest fall of dissipated_J between rows / scale", "-",
                 "dissipation >= 0, up to the Verlet wobble"},
                worst_fall / r.scale, limit);
  check_at_most({kCase, "damped packing, 27 spheres, " + name + ": |E(0) - parts - dissipated_J| / scale", "-", "columns add up"},
                balance_residual(r.csv, r.scale), tol::csv_balance);
}

BOOST_AUTO_TEST_CASE(damped_packing_dissipates_monotonically) {
  const double m = sphere_mass(), t_c = 2e-3, kn = m * kPi * kPi / (t_c * t_c);
  damped_packing(LinearLaw<double>{LinearSpringDashpot<double>::from_restitution(kn, 0.5), HistoryFreeFriction<double>::make(0.5, 1.0)},
                 "linear, e = 0.5, mu = 0.5", t_c);
  const BoxCase hertz_case{"", true, true, 3, t_c, 50};
  Hertz<double> h = box_law<Hertz>(hertz_case);
  h.eta = static_cast<double>(hertz_damping_for_restitution(0.5, false));
  damped_packing(HertzLaw<double>{h, HistoryFreeFriction<double>::make(0.5, 1.0)}, "Hertz, e = 0.5, mu = 0.5", t_c);
}

// N spheres stacked on a floor, released touching (no overlap, no stored energy), settle with
// dashpots and friction. At rest the contact k-th from the bottom (k = 0: the floor) carries
// (N - k) m g, so its overlap is (N - k) m g / K_n and
//   E_elastic = sum_{j=1..N} (j m g)^2 / (2 K_n),
//   y_1 = r - N m g / K_n,  y_{k+1} = y_k + 2 r - (N - k) m g / K_n,
//   dissipated = E(0) - E_pot(rest) - E_elastic(rest)
// (the static spring keeps half the potential energy the compression released, the dashpots took
// the other half). contacts_wall = 1, contacts_vertex_face = N - 1.
BOOST_AUTO_TEST_CASE(resting_column_stores_the_closed_form_energy) {
  const Column c;
  const double m = sphere_mass(), w = m * kG, r = kRadius;
  ParticleState<double> s;
  for (int j = 0; j < c.n; ++j) s.add_sphere({0, r + 2 * r * j, 0}, r, kDensity, 0);
  World<double> world;
  world.polygons.push_back(floor_square<double>(0, 0.05));
  using Law = LinearLaw<double>;
  const Law law{LinearSpringDashpot<double>::from_restitution(c.kn, c.e), HistoryFreeFriction<double>::make(c.mu, c.kt)};
  const Vec3<double> g{0, -kG, 0};
  LoggedSim<Law> sim(params<double>(c.dt, g, 0.2, 0.1 * r), one_law(law), world, s);
  const LoggedRun run = logged_run(sim, g, 0.4, std::lround(c.duration / c.dt), 100, "column");
  const auto& csv = run.csv;
  double elastic = 0, potential = 0, y = r - c.n * w / c.kn, worst_y = 0;
  std::vector<double> expected_y;
  for (int k = 0; k < c.n; ++k) {
    elastic += std::pow((k + 1) * w, 2) / (2 * c.kn);
    if (k > 0) y += 2 * r - (c.n - k) * w / c.kn;
    expected_y.push_back(y);
    potential += w * y;
  }
  const ParticleState<double> st = sim.state();
  for (std::size_t k = 0; k < st.size(); ++k)  // the column keeps its order: sort by height
    for (std::size_t j = 0; j < st.size(); ++j)
      if (st.id[j] == static_cast<Index>(k)) worst_y = std::fmax(worst_y, std::fabs(st.position[j].y - expected_y[k]));
  double e0 = 0;  // E(0) from the initial state (the CSV's 10 digits of it would be 5e-7 of the answer)
  for (std::size_t k = 0; k < s.size(); ++k) e0 += s.mass[k] * kG * s.position[k].y;
  const double d = csv.at("dissipated_J").back();
  const auto& dis = csv.at("dissipated_J");
  double worst_fall = 0;
  for (std::size_t k = 1; k < dis.size(); ++k) worst_fall = std::fmax(worst_fall, dis[k - 1] - dis[k]);
  const double omega_dt = std::sqrt(2 * c.kn / m) * c.dt;
  BOOST_TEST_MESSAGE("column of " << c.n << ": elastic " << csv.at("elastic_J").back() << " J (closed form " << elastic
                                  << "), dissipated " << d << " J (closed form " << e0 - potential - elastic << "), kinetic "
                                  << csv.at("kinetic_translational_J").back() << " J, worst height error " << worst_y
                                  << " m, largest fall of dissipated " << worst_fall << " J");
  BOOST_TEST(csv.at("elastic_J").front() < 1e-12 * elastic);  // touching: overlaps of rounding only
  check_relative({kCase, "resting column of 5 spheres, linear: elastic_J vs sum (j m g)^2 / (2 K_n)", "-", "static equilibrium"},
                 csv.at("elastic_J").back(), elastic, tol::resting_column);
  check_relative({kCase, "resting column of 5 spheres, linear: dissipated_J vs E(0) - E_pot - E_elastic (closed form)", "-",
                  "energy balance at rest"},
                 d, e0 - potential - elastic, tol::resting_column);
  check_at_most({kCase, "resting column of 5 spheres: max |y - y_rest| / (N m g / K_n)", "-", "static overlaps"},
                worst_y / (c.n * w / c.kn), tol::resting_column);
  check_at_most({kCase, "resting column of 5 spheres: largest fall of dissipated_J between rows / E_elastic(rest)", "-",
                 "dissipation >= 0, up to the Verlet wobble"},
                worst_fall / elastic, tol::energy_balance_wobble * omega_dt * omega_dt);
  BOOST_TEST(csv.at("contacts_wall").back() == 1.0);
  BOOST_TEST(csv.at("contacts_vertex_face").back() == static_cast<double>(c.n - 1));
  check_at_most({kCase, "resting column: |E(0) - parts - dissipated_J| / scale", "-", "columns add up"},
                balance_residual(csv, run.scale), tol::csv_balance);
}

// 9 spheres resting apart on a floor (placed at their static overlap m g / K_n): contacts_wall is
// 9 in every row, no particle-particle contact, and the stored energy 9 (m g)^2 / (2 K_n).
BOOST_AUTO_TEST_CASE(wall_contacts_are_counted) {
  const double m = sphere_mass(), k = 1e4, w = m * kG, r = kRadius;
  ParticleState<double> s;
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) s.add_sphere({3 * r * (i - 1), r - w / k, 3 * r * (j - 1)}, r, kDensity, 0);
  World<double> world;
  world.polygons.push_back(floor_square<double>(0, 0.05));
  using Law = LinearLaw<double>;
  const Law law{LinearSpringDashpot<double>::from_restitution(k, 0.3), HistoryFreeFriction<double>::make(0.5, 1.0)};
  const Vec3<double> g{0, -kG, 0};
  LoggedSim<Law> sim(params<double>(1e-5, g, 0.2, 0.1 * r), one_law(law), world, s);
  const LoggedRun run = logged_run(sim, g, 0.4, 2000, 200, "wall_count");
  for (double c : run.csv.at("contacts_wall")) BOOST_TEST(c == 9.0);
  for (double c : run.csv.at("contacts_vertex_face")) BOOST_TEST(c == 0.0);
  check_relative({kCase, "9 spheres resting on a floor: elastic_J vs 9 (m g)^2 / (2 K_n)", "-", "static overlap"},
                 run.csv.at("elastic_J").back(), 9 * w * w / (2 * k), tol::resting_column);
  check_at_least({kCase, "9 spheres resting on a floor: contacts_wall", "-", "one floor contact each"},
                 run.csv.at("contacts_wall").back(), 9);
}

// `blaze run` on the shipped scene (626 beads poured into a box, 0.1 s): the time series has
// elastic_J and contacts_wall, the beads reach the floor, and every row balances.
BOOST_AUTO_TEST_CASE(blaze_run_writes_a_balanced_time_series) {
  const fs::path dir = fs::temp_directory_path() / "blaze_energy_balance_run";
  fs::remove_all(dir);
  const ProgramResult r = run_blaze("run data/scenes/box_fill.toml --quiet --set end_time=0.1 --set output.csv_interval=0.002 "
                                    "--set output.vtu_interval=0 --set output.directory=" + dir.string());
  BOOST_TEST_REQUIRE(r.status == 0, r.output);
  const Csv csv = read_csv(dir / "timeseries.csv");
  for (const char* column : {"elastic_J", "contacts_wall", "total_J", "dissipated_J"}) BOOST_TEST_REQUIRE(csv.count(column) == 1u, column);
  BOOST_TEST_REQUIRE(csv.at("removed").back() == 0.0);
  BOOST_TEST(csv.at("contacts_wall").back() > 0.0);
  BOOST_TEST(csv.at("elastic_J").back() > 0.0);
  const double scale = csv.at("total_J").front();  // the bed starts above the floor: E(0) > 0
  check_at_most({kCase, "blaze run box_fill.toml, 0.1 s: |E(0) - parts - dissipated_J| / E(0)", "-", "columns add up"},
                balance_residual(csv, scale), tol::csv_balance);
  fs::remove_all(dir);
}

BOOST_AUTO_TEST_SUITE_END()
