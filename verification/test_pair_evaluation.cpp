// Each pair once (PairEvaluation::once, kernels/pair_forces.hpp) against each pair from both sides
// (kernels/contact_forces.hpp), on a falling sphere bed (friction, rotation, walls, rebuilds and
// re-sorting) and a falling bed of cubes, with the contact counts by kind and the penetration
// monitor that `blaze run` keeps:
// - one force evaluation from the same state agrees to rounding on every backend;
// - pairs once with a thread a list entry (the GPU's small systems) and with a thread a particle
//   evaluate the same forces, and on the host the same trajectory bitwise (with contact history too);
// - on the host the whole trajectory is bitwise the same: the second side's force is the exact
//   negation of the first's, its torque the same expression, and both add in list order. On the
//   GPU the compiler contracts a*b + c into FMAs per kernel, and the pair and gather kernels
//   contract differently from the one-kernel path (measured on the H200: 976 of 1000 spheres
//   differ after 3000 chaotic steps), so there the trajectories are not compared.
#include <boost/test/unit_test.hpp>
#include <cmath>
#include <cstring>
#include <type_traits>
#include "verification/scenes.hpp"
#include "pipeline/gravity_packing.hpp"
#include "verification/cases/cube_bed.hpp"
#include "pipeline/polyhedron_packing.hpp"
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
Outcome run(const Scene& scene, const Laws& laws, const Shape& shape, PairEvaluation pairs, int steps,
            PairThreads threads = PairThreads::automatic) {
  auto params = scene.params;
  params.pairs = pairs;
  params.pair_threads = threads;
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
[[maybe_unused]] long differing_particles(const ParticleState<double>& a, const ParticleState<double>& b) {
  auto same = [](const auto& x, const auto& y) { return std::memcmp(&x, &y, sizeof x) == 0; };
  long n = 0;
  for (std::size_t i = 0; i < a.size(); ++i)
    n += !(same(a.position[i], b.position[i]) && same(a.velocity[i], b.velocity[i]) &&
           same(a.angular_velocity[i], b.angular_velocity[i]) && same(a.orientation[i], b.orientation[i]));
  return n;
}

// Largest difference of a per-particle vector between two snapshots (matched by id), and the
// largest magnitude in the first: force (fields 9-11 of the store's reals) or torque (12-14).
template <class Snapshot>
std::pair<double, double> field_difference(const Snapshot& a, const Snapshot& b, std::size_t first_field) {
  std::vector<std::size_t> at(b.id.size());
  for (std::size_t k = 0; k < b.id.size(); ++k) at[static_cast<std::size_t>(b.id[k])] = k;
  double diff = 0, scale = 0;
  for (std::size_t k = 0; k < a.id.size(); ++k) {
    const std::size_t m = at[static_cast<std::size_t>(a.id[k])];
    double d2 = 0, s2 = 0;
    for (std::size_t c = first_field; c < first_field + 3; ++c) {
      const double x = a.reals[c][k], y = b.reals[c][m];
      d2 += (x - y) * (x - y), s2 += x * x;
    }
    diff = std::max(diff, std::sqrt(d2)), scale = std::max(scale, std::sqrt(s2));
  }
  return {diff, scale};
}

// From one packed state (every body pressed on its neighbours), one step in each mode: the forces
// and torques it evaluated agree to rounding.
template <class Sim, class Scene, class Laws, class Shape>
void check_one_evaluation(const std::string& name, const Scene& scene, const Laws& laws, const Shape& shape, double tolerance) {
  auto params = scene.params;
  const auto snap = Sim(params, laws, scene.world, scene.particles, shape).snapshot();
  long contacts = 0;
  const auto evaluate = [&](PairEvaluation pairs) {
    params.pairs = pairs;
    Sim sim(params, laws, scene.world, snap, shape);
    sim.step();
    const auto c = sim.contact_counts();
    contacts = c.first + c.second;
    return sim.snapshot().store;
  };
  const auto both = evaluate(PairEvaluation::both_sides);
  const auto once = evaluate(PairEvaluation::once);
  const auto [df, sf] = field_difference(both, once, 9);
  const auto [dt, st] = field_difference(both, once, 12);
  BOOST_TEST_MESSAGE(name << ", one evaluation from the same state: " << contacts << " contacts; largest force difference "
                          << df << " N of the largest force " << sf << " N, torque " << dt << " of " << st << " N m");
  BOOST_TEST(contacts >= 2 * static_cast<long>(both.id.size()));
  BOOST_TEST(df <= tolerance * sf);
  BOOST_TEST(dt <= tolerance * st);
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

// Pairs once with a thread a list entry against a thread a particle (PairThreads; the GPU's
// choice below kEntryThreadsBelow particles): one evaluation from a packed state gives the same
// forces and torques (exactly on the host; to rounding on the GPU, whose two kernels may contract
// FMAs differently), and on the host the whole trajectory is bitwise the same.
template <class Sim, class Scene, class Laws, class Shape>
void check_entry_threads(const std::string& name, const Scene& packed, const Scene& falling, const Laws& laws, const Shape& shape,
                         double tolerance, int steps) {
  auto params = packed.params;
  params.pairs = PairEvaluation::once;
  const auto snap = Sim(params, laws, packed.world, packed.particles, shape).snapshot();
  const auto evaluate = [&](PairThreads threads) {
    params.pair_threads = threads;
    Sim sim(params, laws, packed.world, snap, shape);
    sim.step();
    return sim.snapshot().store;
  };
  const auto particle = evaluate(PairThreads::particle), entry = evaluate(PairThreads::entry);
  const auto [df, sf] = field_difference(particle, entry, 9);
  const auto [dt, st] = field_difference(particle, entry, 12);
  BOOST_TEST_MESSAGE(name << ", a thread a list entry against a thread a particle, one evaluation: largest force difference " << df
                          << " N of " << sf << " N, torque " << dt << " of " << st << " N m");
  BOOST_TEST(sf > 0);
  BOOST_TEST(df <= (std::is_same_v<DefaultSpace, Host> ? 0.0 : tolerance) * sf);
  BOOST_TEST(dt <= (std::is_same_v<DefaultSpace, Host> ? 0.0 : tolerance) * st);
  if constexpr (std::is_same_v<DefaultSpace, Host>) {
    const Outcome a = run<Sim>(falling, laws, shape, PairEvaluation::once, steps, PairThreads::particle);
    const Outcome b = run<Sim>(falling, laws, shape, PairEvaluation::once, steps, PairThreads::entry);
    BOOST_TEST_REQUIRE(a.state.size() == b.state.size());
    BOOST_TEST(a.builds > 2u);
    BOOST_TEST(differing_particles(a.state, b.state) == 0);
    BOOST_TEST(a.contacts.first == b.contacts.first);
    BOOST_TEST(a.contacts.second == b.contacts.second);
    BOOST_TEST(a.worst_penetration == b.worst_penetration);
  }
}

}  // namespace

BOOST_AUTO_TEST_SUITE(pair_evaluation)

BOOST_AUTO_TEST_CASE(spheres_once_equal_both_sides) {
  using Law = LinearLaw<double>;
  const double r = 2e-3, m = 2500 * 4.0 / 3.0 * kPi * r * r * r, k = 1e5;
  const auto scene = gravity_packing<double>(1000, r, 2024, kPi * std::sqrt(0.5 * m / k) / 25);
  const Law law{LinearSpringDashpot<double>::from_restitution(k, 0.5), HistoryFreeFriction<double>::make(0.4, 0.05)};
  using Sim = Simulation<DefaultSpace, SphereShape, Law, VelocityVerlet, ContactPointVelocity, MonitoredFeatures>;
  const auto packed = gravity_packing<double>(2000, r, 42, kPi * std::sqrt(0.5 * m / k) / 25, {Lattice::fcc, 1.98, 0.005, 0.01, true});
  check_one_evaluation<Sim>("spheres, double, fcc bed at 0.99 of the contact spacing", packed, one_law(law), SphereShape{},
                            tol::pair_evaluation_double);
  if constexpr (std::is_same_v<DefaultSpace, Host>)
    check_once_equals_both_sides<Sim>("spheres, double", scene, one_law(law), SphereShape{}, 3000);
}

BOOST_AUTO_TEST_CASE(cubes_once_equal_both_sides) {
  const cases::CubeBed bed = cases::cube_bed();
  using Sim = Simulation<DefaultSpace, PolyhedronShape<float>, LinearLaw<float>, VelocityVerlet, ContactPointVelocity,
                         MonitoredFeatures>;
  const auto packed = packed_polyhedra(bed.shape.table, 0, 512, 42, bed.dt, drawn_orientation(load_shape("data/shapes/cube.shape")));
  check_one_evaluation<Sim>("cubes, float, packed lattice", packed, one_law(bed.law), bed.shape, tol::pair_evaluation_float);
  if constexpr (std::is_same_v<DefaultSpace, Host>)
    check_once_equals_both_sides<Sim>("cubes, float", bed.scene, one_law(bed.law), bed.shape, 3000);
  check_entry_threads<Sim>("cubes, float", packed, bed.scene, one_law(bed.law), bed.shape, tol::pair_evaluation_float, 1500);
}

// The entry threads with contact history (the tangential spring read and written by the pair's
// entry) and spheres: the same as a thread a particle.
BOOST_AUTO_TEST_CASE(entry_threads_with_history_equal_particle_threads) {
  using Law = HertzMindlinLaw<double>;
  const double r = 2e-3, m = 2500 * 4.0 / 3.0 * kPi * r * r * r, k = 1e5;
  const double dt = kPi * std::sqrt(0.5 * m / k) / 25;
  const auto falling = gravity_packing<double>(800, r, 2024, dt);
  const auto packed = gravity_packing<double>(1000, r, 42, dt, {Lattice::fcc, 1.98, 0.005, 0.01, true});
  const Law law{Hertz<double>::from_restitution(5e7, 0.5), TangentialSpring<double>::mindlin(0.4, 5e7 / 1.5 / 2.5, 0.5)};  // (test_canonical_order.cpp)
  using Sim = Simulation<DefaultSpace, SphereShape, Law, VelocityVerlet, ContactPointVelocity, MonitoredFeatures>;
  check_entry_threads<Sim>("spheres, Hertz-Mindlin, double", packed, falling, one_law(law), SphereShape{}, tol::pair_evaluation_double, 1500);
}

BOOST_AUTO_TEST_SUITE_END()
