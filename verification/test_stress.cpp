// Stress tests sized for CI (issue 5); `make stress` (BLAZE_STRESS=full) runs the big versions.
// - Impacts up to 50 m/s on a planar wall and between two spheres, with the softest stiffness and
//   the largest dt the scene validation accepts: neither tunnels; a slightly softer contact is
//   refused by the validation.
// - A dt sweep on a dense packing, run by the blaze program as a user would (force_dt past the
//   validation): every run either ends clean or is stopped by a guard (energy created, NaN)
//   before a bad row is written; the accepted fraction of the critical step is stable.
// - A packing of 4096 (full: 101 614) spheres for 5000 (full: 10^5) steps at the largest accepted
//   dt: no NaN, nothing escapes, the energy never rises above its initial value.
#include <boost/test/unit_test.hpp>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <string>
#include "blaze/shapes/sphere_shape.hpp"
#include "blaze/scene/scene_build.hpp"
#include "blaze/scene/scene_file.hpp"
#include "pipeline/simulation.hpp"
#include "verification/report.hpp"
#include "verification/run_program.hpp"
#include "verification/stress_size.hpp"
#include "verification/tolerances.hpp"

using namespace blaze;
using blaze::test::full_size;
namespace fs = std::filesystem;

namespace {

constexpr double kPi = 3.14159265358979323846;
constexpr double kRadius = 5e-3, kDensity = 2500;

// One bead 0.2 mm above a floor falling at v (gravity off), and, off its path, two beads meeting
// head-on at a closing speed of v; one material for beads and floor.
std::string impact_scene(const char* law, double v, const std::string& pair_keys) {
  char buf[4096];
  std::snprintf(buf, sizeof buf, R"([simulation]
law = "%s"
dt = 1e-9
end_time = 1e-3
gravity = [0, 0, 0]
domain_lo = [-0.1, -0.1, -0.1]
domain_hi = [0.1, 0.3, 0.1]
max_impact_speed = %.17g
[[material]]
name = "glass"
density = %g
%s
[[pair]]
materials = ["glass", "glass"]
restitution = 1
%s
[[particle_type]]
name = "bead"
material = "glass"
radius = %g
[[particles]]
type = "bead"
positions = [[0, 0.0052, 0], [-0.03, 0.05, 0.05], [0.03, 0.05, 0.05]]
velocities = [[0, -%.17g, 0], [%.17g, 0, 0], [-%.17g, 0, 0]]
[[wall]]
material = "glass"
vertices = [[-0.05, 0, -0.05], [-0.05, 0, 0.05], [0.05, 0, 0.05], [0.05, 0, -0.05]]
)",
                law, v, kDensity,
                std::string(law) == "hertz" ? "youngs_modulus = 1e9\npoisson_ratio = 0.3" : "", pair_keys.c_str(), kRadius, v,
                v / 2, v / 2);
  return buf;
}

template <class Law>
void no_tunnelling(const Scene& s, double v, const char* label) {
  const auto particles = build_particles<double>(s, nullptr);
  const SimulationParams<double> prm{s.dt, s.gravity, s.domain_lo, s.domain_hi, 0.2 * kRadius, 0};
  Simulation<DefaultSpace, SphereShape, Law, VelocityVerlet, ContactPointVelocity, MonitoredFeatures> sim(
      prm, build_laws<Law>(s), build_world<double>(s), particles, {});
  // Long enough for every impact to end (the pair closes 50 mm at v; contacts last a few
  // dt_critical), short enough that nothing leaves the domain.
  const double t_end = 0.06 / v + 10 * s.dt_critical;
  sim.run(static_cast<std::uint64_t>(t_end / s.dt) + 1);
  const auto st = sim.state();
  const PenetrationReport pen = sim.take_penetration(1);
  BOOST_TEST_CONTEXT(label << ", v = " << v << " m/s, dt = " << s.dt << " s, predicted overlap " << s.impact_overlap) {
    BOOST_TEST(sim.removed_count() == 0);
    for (std::size_t k = 0; k < st.size(); ++k) {
      if (st.id[k] == 0) {  // bounced off the floor, on its side
        BOOST_TEST(st.position[k].y > kRadius);
        BOOST_TEST(st.velocity[k].y > 0.9 * v);
      }
      if (st.id[k] == 1) BOOST_TEST(st.velocity[k].x < 0);  // the pair rebounded, not passed
      if (st.id[k] == 2) BOOST_TEST(st.velocity[k].x > 0);
    }
    BOOST_TEST(pen.worst < kMaxImpactOverlap * (1 + tol::impact_overlap_margin));
  }
}

// A touching simple-cubic block of n^3 beads (r = 1 mm, spacing `spacing` radii, jittered by
// `jitter` of the gap) in a snug box of five walls, under gravity, linear law in float.
std::string packing_scene(long n, double spacing, double jitter) {
  const double r = 1e-3, a = spacing * r, half = 0.5 * n * a + 0.1 * r, top = n * a + 2 * r;
  char buf[4096];
  std::snprintf(buf, sizeof buf, R"([simulation]
law = "linear"
precision = "float"
dt = 1e-6
end_time = 1e-3
domain_lo = [%.9g, -0.002, %.9g]
domain_hi = [%.9g, %.9g, %.9g]
[output]
csv_interval = 0
[[material]]
name = "glass"
density = 2500
[[pair]]
materials = ["glass", "glass"]
stiffness = 1e4
restitution = 0.5
friction = 0.5
[[particle_type]]
name = "bead"
material = "glass"
radius = %.9g
[[lattice]]
type = "bead"
origin = [%.9g, %.9g, %.9g]
count = [%ld, %ld, %ld]
spacing = %.9g
jitter = %g
[[wall]]
material = "glass"
vertices = [[%.9g, 0, %.9g], [%.9g, 0, %.9g], [%.9g, 0, %.9g], [%.9g, 0, %.9g]]
rim = false
[[wall]]
material = "glass"
vertices = [[%.9g, 0, %.9g], [%.9g, %.9g, %.9g], [%.9g, %.9g, %.9g], [%.9g, 0, %.9g]]
rim = false
[[wall]]
material = "glass"
vertices = [[%.9g, 0, %.9g], [%.9g, %.9g, %.9g], [%.9g, %.9g, %.9g], [%.9g, 0, %.9g]]
rim = false
[[wall]]
material = "glass"
vertices = [[%.9g, 0, %.9g], [%.9g, %.9g, %.9g], [%.9g, %.9g, %.9g], [%.9g, 0, %.9g]]
rim = false
[[wall]]
material = "glass"
vertices = [[%.9g, 0, %.9g], [%.9g, %.9g, %.9g], [%.9g, %.9g, %.9g], [%.9g, 0, %.9g]]
rim = false
)",
                -half - 3 * r, -half - 3 * r, half + 3 * r, top + 3 * r, half + 3 * r, r, -half + 0.1 * r + 0.5 * a, 0.5 * a,
                -half + 0.1 * r + 0.5 * a, n, n, n, a, jitter,
                // floor (+y), then x = -half, x = +half, z = -half, z = +half (normals inward)
                -half, half, half, half, half, -half, -half, -half,  //
                -half, -half, -half, top, -half, -half, top, half, -half, half,  //
                half, half, half, top, half, half, top, -half, half, -half,  //
                half, -half, half, top, -half, -half, top, -half, -half, -half,  //
                -half, half, -half, top, half, half, top, half, half, half);
  return buf;
}

// Runs `scene` (written to a file) with `sets` through the blaze program.
blaze::test::ProgramResult run_scene_file(const std::string& scene, const fs::path& dir, const std::string& sets) {
  fs::remove_all(dir);
  fs::create_directories(dir);
  std::ofstream(dir / "scene.toml") << scene;
  return blaze::test::run_blaze("run " + (dir / "scene.toml").string() + " --quiet --set output.directory=" +
                                (dir / "out").string() + " " + sets);
}

double max_energy_gain(const std::map<std::string, std::vector<double>>& csv) {
  double g = -1e300;
  for (double d : csv.at("dissipated_J")) g = std::max(g, -d);  // dissipated = E(0) - E(t) - E_removed
  return g;
}
bool all_finite(const std::map<std::string, std::vector<double>>& csv) {
  for (const auto& [name, col] : csv)
    for (double v : col)
      if (!std::isfinite(v)) return false;
  return true;
}

}  // namespace

BOOST_AUTO_TEST_SUITE(stress)

// dt from 0.1 to 2 critical steps on a touching simple-cubic packing. Every run must end clean
// (exit 0, every row finite, the energy never above its initial value by the guard's limit) or
// be stopped by a guard (exit 3) with every row written before finite and within the limit; the
// largest dt must trip a guard, the accepted fraction (kSafeStepFraction) must run clean. The
// smallest fraction that trips is the packing's stability limit: in a simple-cubic lattice the
// fastest mode of a chain is 2 sqrt(k/m), so without damping the limit is 1/sqrt(2) = 0.71 of the
// pair estimate 2/sqrt(2k/m); the collective modes of denser packings push it lower still, which
// is why the accepted fraction is 0.2 (critical_step.hpp).
BOOST_AUTO_TEST_CASE(dt_sweep_on_a_dense_packing) {
  const long n = full_size() ? 20 : 10;
  const std::string scene = packing_scene(n, 2.0, 0);
  const Scene s = parse_scene(scene, "packing.toml", {"force_dt=true"});
  const std::vector<double> fractions = full_size() ? std::vector<double>{0.1, 0.2, 0.3, 0.4, 0.5, 0.55, 0.6, 0.65, 0.7, 0.75, 0.8, 0.9, 1.0, 1.5, 2.0}
                                                    : std::vector<double>{0.1, 0.2, 0.4, 0.6, 0.7, 0.8, 1.0, 2.0};
  const long steps = full_size() ? 20000 : 3000;
  // The guard's energy scale (run_log.hpp): the bed starts at rest, so sum m |g| h.
  const double mass = 2500 * 4.0 / 3.0 * kPi * 1e-9;
  const double scale = static_cast<double>(n * n * n) * mass * 9.81 * (s.domain_hi.y - s.domain_lo.y);
  double first_trip = 0;
  for (double f : fractions) {
    const double dt = f * s.dt_critical;
    char sets[256];
    std::snprintf(sets, sizeof sets, "--set force_dt=true --set dt=%.17g --set end_time=%.17g --set output.csv_interval=%.17g",
                  dt, steps * dt, 10 * dt);
    const fs::path dir = fs::temp_directory_path() / "blaze_dt_sweep";
    const auto r = run_scene_file(scene, dir, sets);
    const auto csv = blaze::test::read_csv(dir / "out" / "timeseries.csv");
    BOOST_TEST_CONTEXT("dt = " << f << " dt_critical: " << r.output) {
      BOOST_TEST((r.status == 0 || r.status == 3));
      BOOST_TEST_REQUIRE(csv.count("dissipated_J") == 1u);
      BOOST_TEST(all_finite(csv));
      BOOST_TEST(max_energy_gain(csv) <= s.output.energy_gain_limit * scale);
      if (f <= kSafeStepFraction) BOOST_TEST(r.status == 0);
      if (r.status == 3) {
        BOOST_TEST((r.output.find("energy rose") != std::string::npos || r.output.find("non-finite") != std::string::npos));
        if (first_trip == 0) first_trip = f;
        // last_good.vtu holds the last sample that passed the guards, so the whole bed is in it
        std::ifstream vtu(dir / "out" / "last_good.vtu");
        const std::string text((std::istreambuf_iterator<char>(vtu)), std::istreambuf_iterator<char>());
        BOOST_TEST(text.find("NumberOfPoints=\"" + std::to_string(n * n * n) + "\"") != std::string::npos);
      }
      BOOST_TEST_MESSAGE("dt sweep: " << f << " x dt_critical: exit " << r.status << ", " << csv.at("t_s").size()
                                      << " rows, largest energy gain " << max_energy_gain(csv) << " J");
    }
    fs::remove_all(dir);
  }
  const blaze::test::Row row{"Stress: dt sweep, touching cubic packing", "smallest dt / dt_critical stopped by a guard",
                             "-", "chain mode: 1/sqrt(2) undamped"};
  blaze::test::check_at_least(row, first_trip, 2 * kSafeStepFraction);
  BOOST_TEST(first_trip <= 1.0, "the largest dt must trip a guard");
  BOOST_TEST(first_trip > 0);
}

// A jittered packing at the largest accepted dt: runs clean, nothing escapes, no NaN, and the
// energy (kinetic + gravitational, + what left) never exceeds its initial value.
BOOST_AUTO_TEST_CASE(large_packing_stays_finite_and_loses_energy) {
  const long n = full_size() ? 47 : 16;  // 47^3 = 103 823 >= 10^5
  const long steps = full_size() ? 100000 : 5000;
  const std::string scene = packing_scene(n, 2.1, 0.5);
  const Scene s = parse_scene(scene, "packing.toml");
  const double dt = kSafeStepFraction * s.dt_critical;
  char sets[256];
  std::snprintf(sets, sizeof sets, "--set dt=%.17g --set end_time=%.17g --set output.csv_interval=%.17g", dt, steps * dt,
                steps / 100 * dt);
  const fs::path dir = fs::temp_directory_path() / "blaze_packing";
  const auto r = run_scene_file(scene, dir, sets);
  const auto csv = blaze::test::read_csv(dir / "out" / "timeseries.csv");
  BOOST_TEST_REQUIRE(r.status == 0, r.output);
  BOOST_TEST_REQUIRE(csv.count("total_J") == 1u);
  BOOST_TEST(all_finite(csv));
  BOOST_TEST(csv.at("removed").back() == 0);
  BOOST_TEST(csv.at("particles").back() == static_cast<double>(n * n * n));
  BOOST_TEST(csv.at("t_s").size() >= 100u);
  // Gain relative to the bed's potential energy above the floor (the energy it can exchange).
  double potential = csv.at("potential_J").front();
  const blaze::test::Row row{"Stress: " + std::to_string(n * n * n) + " spheres, " + std::to_string(steps) + " steps",
                             "max (E(t) - E(0)) / E_potential(0)", "-", "no energy source"};
  blaze::test::check_at_most(row, max_energy_gain(csv) / potential, tol::packing_energy_gain);
  fs::remove_all(dir);
}



// Linear spring: overlap v sqrt(m*/k) = r/2 at k = 4 m v^2 / r^2 (wall, m* = m); 5% stiffer is
// accepted, 10% softer refused.
BOOST_AUTO_TEST_CASE(fast_impacts_do_not_tunnel_linear) {
  const double m = kDensity * 4.0 / 3.0 * kPi * std::pow(kRadius, 3);
  for (double v : {5.0, 20.0, 50.0}) {
    const double k_min = 4 * m * v * v / (kRadius * kRadius);
    char keys[64];
    std::snprintf(keys, sizeof keys, "stiffness = %.17g", 0.9 * k_min);
    const std::string soft = impact_scene("linear", v, keys);
    BOOST_CHECK_THROW(parse_scene(soft, "soft.toml"), SceneError);
    std::snprintf(keys, sizeof keys, "stiffness = %.17g", 1.05 * k_min);
    const std::string text = impact_scene("linear", v, keys);
    const double dt_max = kSafeStepFraction * parse_scene(text, "impact.toml").dt_critical;
    char dt[48];
    std::snprintf(dt, sizeof dt, "dt=%.17g", dt_max);
    no_tunnelling<LinearLaw<double>>(parse_scene(text, "impact.toml", {dt}), v, "linear");
  }
}

// Hertz: the scene's elastic modulus is fixed, so the validation limits the speed; at the fastest
// accepted speed and dt the beads still bounce.
BOOST_AUTO_TEST_CASE(fast_impacts_do_not_tunnel_hertz) {
  for (double v : {5.0, 20.0, 50.0}) {
    const std::string text = impact_scene("hertz", v, "");
    Scene probe = parse_scene(text, "impact.toml", {"force_dt=true"});
    if (probe.impact_overlap > kMaxImpactOverlap) {
      BOOST_CHECK_THROW(parse_scene(text, "impact.toml"), SceneError);
      continue;
    }
    char dt[48];
    std::snprintf(dt, sizeof dt, "dt=%.17g", kSafeStepFraction * probe.dt_critical);
    no_tunnelling<HertzLaw<double>>(parse_scene(text, "impact.toml", {dt}), v, "hertz");
  }
}

BOOST_AUTO_TEST_SUITE_END()
