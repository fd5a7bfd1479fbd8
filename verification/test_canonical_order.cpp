// Canonical order (issue 21; SimulationParams::canonical_order, kernels/broad_phase_kernels.hpp
// SortNeighboursById, kernels/contact_forces.hpp by_id): each particle's contact forces summed in
// its neighbours' permanent-id order and each pair formed from its lower id, so a run does not
// depend on where its particles lie in memory, the property that makes a run over several ranks
// bitwise one process's (verification/mpi/test_distributed.cpp).
// - The same spheres (Hertz-Mindlin) and cubes (linear spring), given in two orders (as loaded
//   and shuffled), settling in a box for 600 steps: bitwise the same by id with canonical order;
//   without it the orders part (the sums round differently), which shows the test can fail.
#include <boost/test/unit_test.hpp>
#include <algorithm>
#include <map>
#include <random>
#include <sstream>
#include "blaze/shapes/polyhedron_shape.hpp"
#include "blaze/shapes/shape_io.hpp"
#include "verification/report.hpp"
#include "verification/scenes.hpp"
#include "verification/tolerances.hpp"

using namespace blaze;
using namespace blaze::test;

namespace {

const char* const kCase = "Canonical order (issue 21)";

template <class Real>
ParticleState<Real> shuffled(const ParticleState<Real>& s, unsigned seed) {
  std::vector<std::size_t> order(s.size());
  for (std::size_t k = 0; k < order.size(); ++k) order[k] = k;
  std::shuffle(order.begin(), order.end(), std::mt19937_64(seed));
  ParticleState<Real> out;
  for (std::size_t k : order) {
    out.position.push_back(s.position[k]), out.velocity.push_back(s.velocity[k]), out.angular_velocity.push_back(s.angular_velocity[k]);
    out.orientation.push_back(s.orientation[k]), out.radius.push_back(s.radius[k]), out.mass.push_back(s.mass[k]);
    out.inertia.push_back(s.inertia[k]), out.material.push_back(s.material[k]), out.type.push_back(s.type[k]), out.id.push_back(s.id[k]);
  }
  return out;
}

// Largest |x_a - x_b| over ids (m), the two states in any order.
template <class Real>
double parting(const ParticleState<Real>& a, const ParticleState<Real>& b) {
  std::map<Index, Vec3<Real>> at;
  for (std::size_t k = 0; k < b.size(); ++k) at[b.id[k]] = b.position[k];
  double worst = a.size() == b.size() ? 0 : 1;
  for (std::size_t k = 0; k < a.size(); ++k) worst = std::fmax(worst, static_cast<double>(norm(a.position[k] - at.at(a.id[k]))));
  return worst;
}

World<double> cup(double half) {
  World<double> w;
  w.polygons.push_back(floor_square<double>(0, half));
  w.polygons.push_back(PlanarPolygon<double>::make({{-half, 0, -half}, {-half, 0.2, -half}, {-half, 0.2, half}, {-half, 0, half}}, 1));
  w.polygons.push_back(PlanarPolygon<double>::make({{half, 0, -half}, {half, 0, half}, {half, 0.2, half}, {half, 0.2, -half}}, 1));
  return w;
}

}  // namespace

BOOST_AUTO_TEST_SUITE(canonical_order)

BOOST_AUTO_TEST_CASE(a_run_does_not_depend_on_the_particles_order_in_memory) {
  const double r = 0.004, half = 0.04;
  ParticleState<double> balls;
  std::mt19937_64 rng(5);
  std::uniform_real_distribution<double> u(-1, 1);
  for (int k = 0; k < 8; ++k)
    for (int j = 0; j < 8; ++j)
      for (int i = 0; i < 8; ++i) {
        balls.add_sphere({-3.5 * 2 * r + i * 2 * r, 0.005 + j * 1.99 * r, -3.5 * 2 * r + k * 2 * r + 0.01 * r * u(rng)}, r * (1 + 0.01 * u(rng)), 2500, 0);
        balls.velocity.back() = {0.05 * u(rng), 0.05 * u(rng), 0.05 * u(rng)};
      }
  using Hm = HertzMindlinLaw<double>;
  const Hm hm{Hertz<double>::from_restitution(5e7, 0.5), TangentialSpring<double>::mindlin(0.4, 5e7 / 1.5 / 2.5, 0.5)};
  double sphere_parting[2] = {0, 0};
  for (int canonical = 0; canonical < 2; ++canonical) {
    auto prm = params<double>(2e-5, {0, -9.81, 0}, 0.1, 0.2 * r);
    prm.canonical_order = canonical == 1;
    SphereSim<Hm> a(prm, one_law(hm), cup(half), balls), b(prm, one_law(hm), cup(half), shuffled(balls, 9));
    a.run(600), b.run(600);
    sphere_parting[canonical] = parting(a.state(), b.state()) / r;
  }

  std::istringstream text("vertices 8\n0 0 0\n0.006 0 0\n0.006 0.006 0\n0 0.006 0\n0 0 0.006\n0.006 0 0.006\n0.006 0.006 0.006\n"
                          "0 0.006 0.006\nfaces 6\n4 0 3 2 1\n4 4 5 6 7\n4 0 1 5 4\n4 1 2 6 5\n4 2 3 7 6\n4 3 0 4 7\n");
  PolyhedronShape<double> shape;
  shape.table.add(parse_blaze_shape(text, "cube-6mm"), 2500);
  ParticleState<double> cubes;
  for (int k = 0; k < 6; ++k)
    for (int j = 0; j < 6; ++j)
      for (int i = 0; i < 6; ++i) {
        const double a = 3 * u(rng);
        add_polyhedron(cubes, shape.table, 0, Vec3<double>{-0.025 + i * 0.0095, 0.01 + j * 0.0095, -0.025 + k * 0.0095},
                       Quat<double>{std::cos(a / 2), 0.6 * std::sin(a / 2), 0, 0.8 * std::sin(a / 2)}, 0,
                       Vec3<double>{0.1 * u(rng), 0.1 * u(rng), 0.1 * u(rng)});
      }
  using Law = LinearSpringLaw<double>;
  const auto normal = LinearSpringDashpot<double>::from_restitution(2e4, 0.5);
  const Law law{normal, TangentialSpring<double>::linear(0.5, 2.0 / 7.0 * 2e4, normal.beta)};
  using CubeSim = Simulation<DefaultSpace, PolyhedronShape<double>, Law, VelocityVerlet>;
  const double rc = shape.table.type[0].bounding_radius;
  double cube_parting[2] = {0, 0};
  for (int canonical = 0; canonical < 2; ++canonical) {
    auto prm = params<double>(2e-5, {0, -9.81, 0}, 0.1, 0.2 * rc);
    prm.canonical_order = canonical == 1;
    CubeSim a(prm, one_law(law), cup(half), cubes, shape), b(prm, one_law(law), cup(half), shuffled(cubes, 9), shape);
    a.run(600), b.run(600);
    cube_parting[canonical] = parting(a.state(), b.state()) / rc;
  }
  BOOST_TEST_MESSAGE("canonical order: spheres in two memory orders part by " << sphere_parting[0] << " r without it, "
                                                                            << sphere_parting[1] << " with it; cubes " << cube_parting[0]
                                                                            << ", " << cube_parting[1]);
  check_at_most({kCase, "max |x_a - x_b| / r of 512 spheres given in two orders, 600 steps (Hertz-Mindlin)", "-",
                 "sums in permanent-id order: bitwise"},
                sphere_parting[1], 0);
  check_at_most({kCase, "max |x_a - x_b| / r of 216 cubes given in two orders, 600 steps (linear spring)", "-",
                 "sums in permanent-id order, pairs from the lower id: bitwise"},
                cube_parting[1], 0);
  BOOST_TEST(sphere_parting[0] + cube_parting[0] > 0);  // without it the orders do part: the test can fail
}

BOOST_AUTO_TEST_SUITE_END()
