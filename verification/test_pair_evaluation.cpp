// Each pair once (PairEvaluation::once, kernels/pair_forces.hpp) gives bitwise the trajectory of
// each pair from both sides (kernels/contact_forces.hpp): the second side's force is the exact
// negation of the first's, its torque the same expression, and both add in list order. Checked
// on a falling sphere bed (friction, rotation, walls, rebuilds and re-sorting) and a falling bed
// of cubes, with the contact counts by kind and the penetration monitor that `blaze run` keeps.
#include <boost/test/unit_test.hpp>
#include <cstring>
#include "verification/scenes.hpp"
#include "blaze/scenes/polyhedron_packing.hpp"
#include "blaze/shapes/shape_io.hpp"

using namespace blaze;
using namespace blaze::test;

namespace {

struct Outcome {
  ParticleState<double> state;
  std::pair<long, long> contacts{0, 0};  // summed over the steps: vertex-face, edge-edge
  double worst_penetration = 0;
  std::uint64_t builds = 0;
};

template <class Sim, class Scene, class Laws, class Shape>
Outcome run(const Scene& scene, const Laws& laws, const Shape& shape, PairEvaluation pairs, int steps) {
  auto params = scene.params;
  params.pairs = pairs;
  Sim sim(params, laws, scene.world, scene.particles, shape);
  Outcome out;
  for (int s = 0; s < steps; ++s) {
    sim.step();
    const auto c = sim.contact_counts();
    out.contacts.first += c.first, out.contacts.second += c.second;
  }
  out.worst_penetration = sim.take_penetration(1.0).worst;
  out.builds = sim.neighbour_builds();
  const auto s = sim.state();
  for (std::size_t i = 0; i < s.size(); ++i) {
    out.state.position.push_back(vec_cast<double>(s.position[i]));
    out.state.velocity.push_back(vec_cast<double>(s.velocity[i]));
    out.state.angular_velocity.push_back(vec_cast<double>(s.angular_velocity[i]));
    const auto& q = s.orientation[i];
    out.state.orientation.push_back({double(q.w), double(q.x), double(q.y), double(q.z)});
  }
  return out;
}

// Every component of every particle, compared as bits (so -0 and 0 differ, NaN equals NaN).
long differing_particles(const ParticleState<double>& a, const ParticleState<double>& b) {
  auto same = [](const auto& x, const auto& y) { return std::memcmp(&x, &y, sizeof x) == 0; };
  long n = 0;
  for (std::size_t i = 0; i < a.size(); ++i)
    n += !(same(a.position[i], b.position[i]) && same(a.velocity[i], b.velocity[i]) &&
           same(a.angular_velocity[i], b.angular_velocity[i]) && same(a.orientation[i], b.orientation[i]));
  return n;
}

template <class Sim, class Scene, class Laws, class Shape>
void check_once_equals_both_sides(const std::string& name, const Scene& scene, const Laws& laws, const Shape& shape, int steps) {
  const Outcome both = run<Sim>(scene, laws, shape, PairEvaluation::both_sides, steps);
  const Outcome once = run<Sim>(scene, laws, shape, PairEvaluation::once, steps);
  BOOST_TEST_MESSAGE(name << ": " << both.state.size() << " bodies, " << steps << " steps, " << both.builds
                          << " neighbour builds, contacts summed over the steps " << both.contacts.first << " vertex-face + "
                          << both.contacts.second << " edge-edge; particles that differ: "
                          << differing_particles(both.state, once.state));
  BOOST_TEST_REQUIRE(both.state.size() == once.state.size());
  BOOST_TEST(both.builds > 2u);                                  // the list was rebuilt and re-sorted
  BOOST_TEST(both.contacts.first + both.contacts.second > 1000);  // the beds collided
  BOOST_TEST(differing_particles(both.state, once.state) == 0);
  BOOST_TEST(both.contacts.first == once.contacts.first);
  BOOST_TEST(both.contacts.second == once.contacts.second);
  BOOST_TEST(both.worst_penetration == once.worst_penetration);
  BOOST_TEST(both.builds == once.builds);
}

}  // namespace

BOOST_AUTO_TEST_SUITE(pair_evaluation)

BOOST_AUTO_TEST_CASE(spheres_once_equal_both_sides) {
  using Law = LinearLaw<double>;
  const double r = 2e-3, m = 2500 * 4.0 / 3.0 * kPi * r * r * r, k = 1e5;
  const auto scene = gravity_packing<double>(1000, r, 2024, kPi * std::sqrt(0.5 * m / k) / 25);
  const Law law{LinearSpringDashpot<double>::from_restitution(k, 0.5), HistoryFreeFriction<double>::make(0.4, 0.05)};
  using Sim = Simulation<DefaultSpace, SphereShape, Law, VelocityVerlet, ContactPointVelocity, MonitoredFeatures>;
  check_once_equals_both_sides<Sim>("spheres, double", scene, one_law(law), SphereShape{}, 3000);
}

BOOST_AUTO_TEST_CASE(cubes_once_equal_both_sides) {
  using Law = LinearLaw<float>;
  PolyhedronShape<float> shape;
  shape.table.add(load_shape("data/shapes/cube.shape"), 2500);
  const double k = 1e5, dt = kPi * std::sqrt(0.5 * shape.table.type[0].mass / k) / 25;
  const auto scene = polyhedron_packing(shape.table, 0, 64, 5, dt);
  const Law law{LinearSpringDashpot<float>::from_restitution(k, 0.5), HistoryFreeFriction<float>::make(0.4, 0.05)};
  using Sim = Simulation<DefaultSpace, PolyhedronShape<float>, Law, VelocityVerlet, ContactPointVelocity, MonitoredFeatures>;
  check_once_equals_both_sides<Sim>("cubes, float", scene, one_law(law), shape, 3000);
}

BOOST_AUTO_TEST_SUITE_END()
