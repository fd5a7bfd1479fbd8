// The angle-of-repose measurement of studies/repose (include/blaze/sim/repose_angle.hpp): the
// highest sphere top per radial bin, a straight line fitted between 20% and 80% of the pile's
// radius. Each case builds a cone of known slope theta (h = H - r tan(theta)) out of spheres and
// asserts the measured angle:
//   smooth   20 000 sphere tops drawn uniformly over the cone's surface (a dense, exact surface);
//   rough    one column of beads per d x d cell, its top bead lowered by a uniform U(0, d) (a
//            surface as ragged as a poured pile's, one bead deep);
// and that an empty base or too few bins give NaN rather than a number.
#include <boost/test/unit_test.hpp>
#include <boost/test/data/test_case.hpp>
#include <cmath>
#include <random>
#include "blaze/sim/repose_angle.hpp"
#include "verification/tolerances.hpp"

using namespace blaze;
namespace bdata = boost::unit_test::data;

namespace {

constexpr double kPi = 3.14159265358979323846;
constexpr double kD = 3e-3;               // m, bead diameter
constexpr double kPileRadius = 30 * kD;   // m

struct Cloud {
  std::vector<double> x, y, z, r;
  void add(double px, double py, double pz, double radius) { x.push_back(px), y.push_back(py), z.push_back(pz), r.push_back(radius); }
};

// Sphere tops on the cone h = H - r tan(theta) over r < R_p, the base at y = base_y, axis (ax, az).
Cloud smooth_cone(double theta_deg, double base_y, double ax, double az, unsigned seed) {
  std::mt19937_64 rng(seed);
  std::uniform_real_distribution<double> u(0, 1);
  const double t = std::tan(theta_deg * kPi / 180), H = kPileRadius * t, rb = kD / 2;
  Cloud c;
  for (int i = 0; i < 20000; ++i) {
    const double r = kPileRadius * std::sqrt(u(rng)), phi = 2 * kPi * u(rng);  // uniform over the disc
    c.add(ax + r * std::cos(phi), base_y + H - r * t - rb, az + r * std::sin(phi), rb);
  }
  return c;
}

Cloud rough_cone(double theta_deg, unsigned seed) {
  std::mt19937_64 rng(seed);
  std::uniform_real_distribution<double> u(0, 1);
  const double t = std::tan(theta_deg * kPi / 180), H = kPileRadius * t, rb = kD / 2;
  Cloud c;
  for (double x = -kPileRadius; x <= kPileRadius; x += kD)
    for (double z = -kPileRadius; z <= kPileRadius; z += kD) {
      const double r = std::hypot(x, z);
      if (r >= kPileRadius) continue;
      const double top = std::max(rb, H - r * t - u(rng) * kD);
      c.add(x, top - rb, z, rb);
      c.add(x, rb, z, rb);  // the column's foot: below the surface, never the highest
    }
  return c;
}

ReposeGeometry geometry(double ax = 0, double az = 0, double base_y = 0) {
  ReposeGeometry g;
  g.axis_x = ax, g.axis_z = az, g.base_y = base_y, g.pile_radius = kPileRadius, g.bin = kD;
  return g;
}

}  // namespace

BOOST_AUTO_TEST_SUITE(repose_angle)

BOOST_DATA_TEST_CASE(smooth_cone_recovers_its_slope, bdata::make({10.0, 22.0, 30.0, 40.0}), theta) {
  // An off-centre axis and a raised base: the measurement must use both.
  const Cloud c = smooth_cone(theta, 0.05, 0.01, -0.02, 7);
  const ReposeProfile p = measure_repose(c.x, c.y, c.z, c.r, geometry(0.01, -0.02, 0.05));
  BOOST_TEST_MESSAGE("smooth cone " << theta << " deg: measured " << p.angle_deg << " deg, rms " << p.rms << " m, "
                                    << p.bins_used << " bins");
  BOOST_TEST(p.bins_used >= 15);
  BOOST_TEST(std::abs(p.angle_deg - theta) < tol::repose_synthetic_cone_deg);
  BOOST_TEST(p.rms < 0.1 * kD);
}

BOOST_DATA_TEST_CASE(rough_cone_of_beads_recovers_its_slope, bdata::make({15.0, 25.0, 35.0}), theta) {
  const Cloud c = rough_cone(theta, 11);
  const ReposeProfile p = measure_repose(c.x, c.y, c.z, c.r, geometry());
  BOOST_TEST_MESSAGE("rough cone " << theta << " deg: measured " << p.angle_deg << " deg, rms " << p.rms << " m");
  BOOST_TEST(std::abs(p.angle_deg - theta) < tol::repose_rough_cone_deg);
}

BOOST_AUTO_TEST_CASE(a_flat_layer_measures_zero) {
  Cloud c;
  for (double x = -kPileRadius; x <= kPileRadius; x += kD)
    for (double z = -kPileRadius; z <= kPileRadius; z += kD) c.add(x, kD / 2, z, kD / 2);
  const ReposeProfile p = measure_repose(c.x, c.y, c.z, c.r, geometry());
  BOOST_TEST(std::abs(p.angle_deg) < tol::repose_synthetic_cone_deg);
}

BOOST_AUTO_TEST_CASE(nothing_to_fit_gives_nan) {
  Cloud c;
  c.add(0, -0.01, 0, kD / 2);  // below the base: ignored
  BOOST_TEST(std::isnan(measure_repose(c.x, c.y, c.z, c.r, geometry()).angle_deg));
  ReposeGeometry no_bin = geometry();
  no_bin.bin = 0;
  BOOST_TEST(std::isnan(measure_repose(c.x, c.y, c.z, c.r, no_bin).angle_deg));
}

BOOST_AUTO_TEST_SUITE_END()
