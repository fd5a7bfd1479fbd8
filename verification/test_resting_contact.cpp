// Acceptance (issue 2, point 4): a sphere resting under gravity settles at the static overlap
//   linear: delta = m g / k          Hertz: delta = (m g / K_n)^(2/3)
// on a planar floor (face contact) and at the bottom of a drum (cylinder, concave R*).
#include <boost/test/unit_test.hpp>
#include <boost/mpl/list.hpp>
#include <cmath>
#include "verification/scenes.hpp"

using namespace blaze;
using namespace blaze::test;

namespace {

constexpr double kRadius = 5e-3, kDensity = 2500, kG = 9.81;

// Settles one sphere dropped from rest, touching, and returns its final overlap and speed.
template <class Law>
std::pair<double, double> settle(const Law& law, const World<typename Law::real_type>& world, double y0,
                                 double surface_y, double dt, double duration) {
  using Real = typename Law::real_type;
  ParticleState<Real> s;
  s.add_sphere({0, static_cast<Real>(y0), 0}, Real(kRadius), Real(kDensity), 0);
  SphereSim<Law> sim(params<Real>(dt, {0, -kG, 0}, 0.5, 0.1 * kRadius), one_law(law), world, s);
  sim.run(static_cast<std::uint64_t>(duration / dt));
  const auto st = sim.state();
  const double overlap = kRadius - (static_cast<double>(st.position[0].y) - surface_y);
  return {overlap, norm(vec_cast<double>(st.velocity[0]))};
}

}  // namespace

BOOST_AUTO_TEST_SUITE(resting_contact)

using Reals = boost::mpl::list<float, double>;

// k = 1e3 N/m gives an overlap of 0.26% of the radius, so float's rounding of y ~ r (5e-10 m) is
// 4e-5 of it.
BOOST_AUTO_TEST_CASE_TEMPLATE(linear_on_plane_static_overlap, Real, Reals) {
  const double k = 1e3, m = kDensity * 4.0 / 3.0 * kPi * std::pow(kRadius, 3);
  const auto law = LinearLaw<Real>{LinearSpringDashpot<Real>::from_restitution(k, 0.3), HistoryFreeFriction<Real>::make(0.3, 1.0)};
  World<Real> w;
  w.polygons.push_back(floor_square<Real>(0.0, 0.05));
  const double t_c = kPi / std::sqrt(k / m);
  const auto [overlap, speed] = settle(law, w, kRadius, 0.0, t_c / 50, 0.5);
  BOOST_TEST(std::fabs(overlap / (m * kG / k) - 1) <= tol::static_overlap);
  BOOST_TEST(speed < (sizeof(Real) == 8 ? tol::rest_speed_double : tol::rest_speed_float));
}

BOOST_AUTO_TEST_CASE(hertz_on_plane_static_overlap) {
  const double kn = 1e9, m = kDensity * 4.0 / 3.0 * kPi * std::pow(kRadius, 3);
  // K_D chosen for a damping ratio ~0.5 of the linearised contact (c = K_D sqrt(delta)), so it settles quickly.
  const auto law = HertzLaw<double>{Hertz<double>::from_stiffness(kn, kRadius, 1e5), HistoryFreeFriction<double>::make(0.3, 1.0)};
  World<double> w;
  w.polygons.push_back(floor_square<double>(0.0, 0.05));
  const auto [overlap, speed] = settle(law, w, kRadius, 0.0, 2e-6, 0.05);
  BOOST_TEST(std::fabs(overlap / std::pow(m * kG / kn, 2.0 / 3.0) - 1) <= tol::static_overlap);
  BOOST_TEST(speed < tol::rest_speed_double);
}

BOOST_AUTO_TEST_CASE(linear_in_drum_static_overlap) {
  const double k = 1e5, m = kDensity * 4.0 / 3.0 * kPi * std::pow(kRadius, 3), drum_r = 0.1;
  const auto law = LinearLaw<double>{LinearSpringDashpot<double>::from_restitution(k, 0.3), HistoryFreeFriction<double>::make(0.3, 1.0)};
  World<double> w;
  w.cylinders.push_back(Cylinder<double>::make({0, 0, -0.05}, {0, 0, 1}, drum_r, 0.1, 1));
  const double t_c = kPi / std::sqrt(k / m);
  const auto [overlap, speed] = settle(law, w, -drum_r + kRadius, -drum_r, t_c / 50, 0.05);
  BOOST_TEST(std::fabs(overlap / (m * kG / k) - 1) <= tol::static_overlap);
  BOOST_TEST(speed < tol::rest_speed_double);
}

BOOST_AUTO_TEST_SUITE_END()
