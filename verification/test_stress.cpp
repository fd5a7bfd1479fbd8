// Stress tests sized for CI (issue 5): impacts up to 50 m/s on a planar wall and between two
// spheres, with the softest stiffness and the largest dt the scene validation accepts, neither
// tunnel; a slightly softer contact is refused by the validation.
#include <boost/test/unit_test.hpp>
#include <cmath>
#include <cstdio>
#include "blaze/contact/sphere.hpp"
#include "blaze/scene/scene_build.hpp"
#include "blaze/scene/scene_file.hpp"
#include "blaze/sim/simulation.hpp"
#include "verification/tolerances.hpp"

using namespace blaze;

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

}  // namespace

BOOST_AUTO_TEST_SUITE(stress)

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
