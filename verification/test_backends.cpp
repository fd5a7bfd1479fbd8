// Backends agree. Acceptance (issue 2, point 5): CPU and GPU trajectories of a 10^4-sphere
// packing over 1,000 steps agree in double precision (GPU build only: it holds both backends).
// On every build: the host backend is deterministic, bitwise, whatever the thread count (no
// atomics, fixed summation order), which is what makes the CPU-GPU comparison meaningful.
#include <boost/test/unit_test.hpp>
#include <boost/test/data/test_case.hpp>
#include <boost/test/data/monomorphic.hpp>
#include <algorithm>
#include <cmath>
#include <random>
#include <sstream>
#include <type_traits>
#if defined(_OPENMP)
#include <omp.h>
#endif
#include "blaze/shapes/polyhedron_shape.hpp"
#include "blaze/shapes/shape_io.hpp"
#include "verification/scenes.hpp"

using namespace blaze;
using namespace blaze::test;
namespace bdata = boost::unit_test::data;

namespace {

using Law = LinearLaw<double>;
constexpr double kRadius = 2e-3;

// How the steps are taken: run(steps) (small systems: batches of fused steps), step() one at a
// time (a small system: a batch of one), or step() with the phase timer on (one launch per phase).
enum class Stepping { run, single, per_phase };
template <class Space>
ParticleState<double> run_packing(int n, int steps, std::uint64_t* builds = nullptr, Stepping how = Stepping::run) {
  const double m = 2500 * 4.0 / 3.0 * kPi * std::pow(kRadius, 3), k = 1e5;
  const double dt = kPi * std::sqrt(0.5 * m / k) / 25;
  const auto scene = gravity_packing<double>(n, kRadius, 2024, dt);
  const Law law{LinearSpringDashpot<double>::from_restitution(k, 0.5), HistoryFreeFriction<double>::make(0.4, 0.05)};
  Simulation<Space, SphereShape, Law, VelocityVerlet> sim(scene.params, one_law(law), scene.world, scene.particles);
  sim.timer().enabled = how == Stepping::per_phase;
  if (how == Stepping::run) sim.run(static_cast<std::uint64_t>(steps));
  else
    for (int s = 0; s < steps; ++s) sim.step();
  if (builds) *builds = sim.neighbour_builds();
  auto s = sim.state();
  // Back to id order, to compare particle by particle.
  std::vector<Index> order(s.size());
  for (std::size_t i = 0; i < s.size(); ++i) order[s.id[i]] = static_cast<Index>(i);
  ParticleState<double> sorted;
  for (Index i : order) {
    sorted.position.push_back(s.position[i]);
    sorted.velocity.push_back(s.velocity[i]);
    sorted.angular_velocity.push_back(s.angular_velocity[i]);
    sorted.id.push_back(s.id[i]);
  }
  return sorted;
}

struct Difference {
  double position = 0, velocity = 0, angular_velocity = 0, speed_scale = 0;
};

Difference compare(const ParticleState<double>& a, const ParticleState<double>& b) {
  Difference d;
  for (std::size_t i = 0; i < a.position.size(); ++i) {
    d.position = std::max(d.position, norm(a.position[i] - b.position[i]));
    d.velocity = std::max(d.velocity, norm(a.velocity[i] - b.velocity[i]));
    d.angular_velocity = std::max(d.angular_velocity, norm(a.angular_velocity[i] - b.angular_velocity[i]));
    d.speed_scale = std::max(d.speed_scale, norm(a.velocity[i]));
  }
  return d;
}

}  // namespace

BOOST_AUTO_TEST_SUITE(backends)

bool bitwise_equal(const ParticleState<double>& a, const ParticleState<double>& b) {
  bool same = a.position.size() == b.position.size();
  for (std::size_t i = 0; same && i < a.position.size(); ++i)
    same = a.position[i].x == b.position[i].x && a.position[i].y == b.position[i].y && a.position[i].z == b.position[i].z &&
           a.velocity[i].x == b.velocity[i].x && a.velocity[i].y == b.velocity[i].y && a.velocity[i].z == b.velocity[i].z &&
           a.angular_velocity[i].z == b.angular_velocity[i].z;
  return same;
}

// Steps run in batches (exec/phases.hpp: on the GPU one launch per batch for small systems, one
// CUDA graph per batch, its steps' phases behind a stop flag, for larger ones), stopping at a step that needs a rebuild: the
// trajectory is bitwise that of single steps, through a loose bed's frequent rebuilds, on both
// sides of kFusedMaxParticles. On the host it is also bitwise that of one launch per phase (the
// phase timer's path; on the GPU the two compiled kernels may contract a*b + c into FMAs
// differently).
BOOST_DATA_TEST_CASE(batched_steps_equal_single_steps, bdata::make({1000, 6000}), n) {
  static_assert(kFusedMaxParticles > 1000 && kFusedMaxParticles < 6000, "one bed on each side of the one-launch size");
  const int steps = 3000;
  std::uint64_t builds_run = 0, builds_single = 0, builds_phases = 0;
  const auto run = run_packing<DefaultSpace>(n, steps, &builds_run, Stepping::run);
  const auto single = run_packing<DefaultSpace>(n, steps, &builds_single, Stepping::single);
  const auto phases = run_packing<DefaultSpace>(n, steps, &builds_phases, Stepping::per_phase);
  BOOST_TEST(builds_run > 10u);  // rebuilds fall inside batches
  BOOST_TEST(builds_run == builds_single);
  BOOST_TEST(bitwise_equal(run, single));
  if (std::is_same_v<DefaultSpace, Host>) {
    BOOST_TEST(builds_run == builds_phases);
    BOOST_TEST(bitwise_equal(run, phases));
  }
}

// Polyhedra take the one-block path only up to PolyhedronShape::kOneBlockParticles (256; their
// contacts are too long a chain for a thread to take several particles), spheres up to
// kFusedMaxParticles. Cubes of 6 mm, randomly turned, dropped as a loose lattice into an open box:
// batched steps give single steps' trajectory bitwise on both sides of the polyhedra's limit (on
// the GPU: one block at 200 cubes, a graph a batch at 600).
BOOST_DATA_TEST_CASE(polyhedra_batched_steps_equal_single_steps, bdata::make({200, 600}), n) {
  static_assert(one_block_particles<PolyhedronShape<double>>() == 256 && one_block_particles<SphereShape>() == kFusedMaxParticles);
  static_assert(200 < 256 && 600 > 256, "one bed on each side of the polyhedra's one-block size");
  std::istringstream text("vertices 8\n0 0 0\n0.006 0 0\n0.006 0.006 0\n0 0.006 0\n0 0 0.006\n0.006 0 0.006\n0.006 0.006 0.006\n"
                          "0 0.006 0.006\nfaces 6\n4 0 3 2 1\n4 4 5 6 7\n4 0 1 5 4\n4 1 2 6 5\n4 2 3 7 6\n4 3 0 4 7\n");
  PolyhedronShape<double> shape;
  shape.table.add(parse_blaze_shape(text, "cube-6mm"), 2500);
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> u(-1, 1);
  ParticleState<double> cubes;
  const int side = 10;  // 10 x 10 cubes a layer, 9.5 mm apart
  for (int k = 0; k < n; ++k) {
    const double a = 3 * u(rng);
    add_polyhedron(cubes, shape.table, 0, Vec3<double>{-0.045 + (k % side) * 0.0095, 0.008 + (k / (side * side)) * 0.0095, -0.045 + (k / side % side) * 0.0095},
                   Quat<double>{std::cos(a / 2), 0.6 * std::sin(a / 2), 0, 0.8 * std::sin(a / 2)}, 0, Vec3<double>{0.2 * u(rng), -0.3, 0.2 * u(rng)});
  }
  const double half = 0.052;
  World<double> box;
  box.polygons.push_back(floor_square<double>(0, half));
  for (const double sx : {-1.0, 1.0}) {  // the four sides, each facing the box's inside
    const double x = sx * half;
    for (std::vector<Vec3<double>> v : {std::vector<Vec3<double>>{{x, 0, -half}, {x, 0.2, -half}, {x, 0.2, half}, {x, 0, half}},
                                        std::vector<Vec3<double>>{{-half, 0, x}, {-half, 0.2, x}, {half, 0.2, x}, {half, 0, x}}}) {
      auto wall = PlanarPolygon<double>::make(v, 1);
      if (dot(wall.normal, v[0]) > 0) wall = PlanarPolygon<double>::make({v[3], v[2], v[1], v[0]}, 1);
      box.polygons.push_back(wall);
    }
  }
  using Law = LinearSpringLaw<double>;
  const auto normal = LinearSpringDashpot<double>::from_restitution(2e4, 0.5);
  const Law law{normal, TangentialSpring<double>::linear(0.5, 2.0 / 7.0 * 2e4, normal.beta)};
  using CubeSim = Simulation<DefaultSpace, PolyhedronShape<double>, Law, VelocityVerlet>;
  const auto prm = params<double>(2e-5, {0, -9.81, 0}, 0.2, 0.2 * shape.table.type[0].bounding_radius);
  CubeSim batched(prm, one_law(law), box, cubes, shape), single(prm, one_law(law), box, cubes, shape);
  const int steps = 1500;
  batched.run(steps);
  for (int s = 0; s < steps; ++s) single.step();
  BOOST_TEST(batched.neighbour_builds() > 3u);  // rebuilds fall inside batches
  BOOST_TEST(batched.neighbour_builds() == single.neighbour_builds());
  const auto a = batched.state(), b = single.state();
  bool same = a.size() == b.size() && a.size() == static_cast<std::size_t>(n);
  for (std::size_t i = 0; same && i < a.size(); ++i)
    same = a.id[i] == b.id[i] && a.position[i].x == b.position[i].x && a.position[i].y == b.position[i].y && a.position[i].z == b.position[i].z &&
           a.orientation[i].w == b.orientation[i].w && a.angular_velocity[i].x == b.angular_velocity[i].x;
  BOOST_TEST(same, "particles " << a.size() << " batched, " << b.size() << " single, of " << n);
}

#if defined(_OPENMP)
BOOST_AUTO_TEST_CASE(host_results_do_not_depend_on_thread_count) {
  const int threads = omp_get_max_threads();
  omp_set_num_threads(1);
  const auto one = run_packing<Host>(3000, 500);
  omp_set_num_threads(std::max(2, threads));
  const auto many = run_packing<Host>(3000, 500);
  omp_set_num_threads(threads);
  const auto d = compare(one, many);
  BOOST_TEST(d.position == 0.0);
  BOOST_TEST(d.velocity == 0.0);
  BOOST_TEST(d.angular_velocity == 0.0);
}
#endif

#if BLAZE_DEVICE_CODE
BOOST_AUTO_TEST_CASE(cpu_and_gpu_trajectories_agree) {
  std::uint64_t builds = 0;
  const auto cpu = run_packing<Host>(10000, 1000, &builds);
  const auto gpu = run_packing<Cuda>(10000, 1000);
  BOOST_TEST_REQUIRE(cpu.position.size() == gpu.position.size());
  const auto d = compare(cpu, gpu);
  BOOST_TEST_MESSAGE("CPU vs GPU after 1000 steps: max |dx| = " << d.position << " m, max |dv| = " << d.velocity
                     << " m/s, max |dw| = " << d.angular_velocity << " rad/s, neighbour builds " << builds);
  BOOST_TEST(builds > 1u);  // particles moved: the comparison covers re-sorting
  BOOST_TEST(d.position <= tol::cpu_gpu_position_over_radius * kRadius);
  BOOST_TEST(d.velocity <= tol::cpu_gpu_velocity_over_scale * d.speed_scale);
}
#endif

BOOST_AUTO_TEST_SUITE_END()
