// One run over several ranks (issue 21; pipeline/parallel/distributed_simulation.hpp) against the
// same run in one Simulation with canonical order (a particle's contact forces summed by its
// neighbours' permanent ids, each pair formed from its lower id), on however many ranks mpirun
// starts (make test: 1 to 4). Every rank sums and forms the same terms in the same order, so the
// runs are bitwise the same, whatever the decomposition:
// - A bed of 10 000 spheres (Hertz-Mindlin, tangential springs carried across ranks with their
//   particles) pressed on its lattice neighbours, springing apart and falling, 1 000 steps in
//   double: at every 50th step the set of touching pairs is the one-process run's and every
//   position and velocity is bitwise its own (so the count, mass and momentum are too).
// - A run on two ranks writes its checkpoint (one part a rank) at step 300; three ranks read it
//   and go on to step 600: positions bitwise the one-process run's, none lost
//   (fewer ranks under mpirun: 1 onto 1, 2 onto 2).
// - 1 000 cubes (a linear spring law with history) dropped turned at random into the box: over
//   1 000 steps positions and orientations bitwise one process's. (Without canonical order the
//   ranks' sums round differently, and the cubes' contacts, switching features on differences of
//   rounding size, part the runs by 1e-3 r by step 800.)
// - A run that starts empty and is fed two batches of that bed: bitwise one process fed alike.
// - Particles cross the boxes' faces, edges and corners as the bed falls and spreads (bisection
//   on 4 ranks: four boxes meet along a vertical edge) and the ghosts are refreshed every step.
#include <boost/test/unit_test.hpp>
#include <algorithm>
#include <unistd.h>

#include <cmath>
#include <filesystem>
#include <map>
#include <random>
#include <set>
#include <sstream>
#include "blaze/shapes/polyhedron_shape.hpp"
#include "blaze/shapes/shape_io.hpp"
#include "pipeline/parallel/distributed_simulation.hpp"
#include "verification/report.hpp"
#include "verification/scenes.hpp"
#include "verification/tolerances.hpp"

using namespace blaze;
using namespace blaze::test;

namespace {

const char* const kCase = "Runs over ranks (issue 21)";
using Law = HertzMindlinLaw<double>;
using Sim = Simulation<DefaultSpace, SphereShape, Law, VelocityVerlet>;

std::string ranks_label(const Communicator& comm) { return ", " + std::to_string(comm.size()) + " rank" + (comm.size() > 1 ? "s" : ""); }

// 20 x 25 x 20 spheres on a jittered lattice, each pressed on its six neighbours, with small
// random velocities, above the floor of a box: the lattice springs apart and falls.
ParticleState<double> falling_bed(double r) {
  ParticleState<double> s;
  std::mt19937_64 rng(17);
  std::uniform_real_distribution<double> u(-1, 1);
  const double h = 1.995 * r;  // each pressed on its six lattice neighbours: the bed is in contact from the start
  for (int k = 0; k < 20; ++k)
    for (int j = 0; j < 25; ++j)
      for (int i = 0; i < 20; ++i) {
        s.add_sphere({-0.5 * 19 * h + i * h + 0.01 * r * u(rng), 0.01 + j * h + 0.01 * r * u(rng), -0.5 * 19 * h + k * h + 0.01 * r * u(rng)},
                     r * (1 + 0.005 * u(rng)), 2500, 0);
        s.velocity.back() = {0.05 * u(rng), 0.05 * u(rng), 0.05 * u(rng)};
      }
  return s;
}

World<double> open_box(double half) {
  World<double> w;
  w.polygons.push_back(floor_square<double>(0, half));
  // side walls x = +-half, z = +-half, facing in
  w.polygons.push_back(PlanarPolygon<double>::make({{-half, 0, -half}, {-half, 0.4, -half}, {-half, 0.4, half}, {-half, 0, half}}, 1));
  w.polygons.push_back(PlanarPolygon<double>::make({{half, 0, -half}, {half, 0, half}, {half, 0.4, half}, {half, 0.4, -half}}, 1));
  w.polygons.push_back(PlanarPolygon<double>::make({{-half, 0, -half}, {half, 0, -half}, {half, 0.4, -half}, {-half, 0.4, -half}}, 1));
  w.polygons.push_back(PlanarPolygon<double>::make({{-half, 0, half}, {-half, 0.4, half}, {half, 0.4, half}, {half, 0, half}}, 1));
  return w;
}

// The spheres' bed: radius, the box's half width, its Hertz-Mindlin law and the run's parameters
// (canonical order: the one-process run sums in the ranks' order).
constexpr double kBedRadius = 0.0025, kBoxHalf = 0.06;
Law bed_law() { return {Hertz<double>::from_restitution(5e7, 0.5), TangentialSpring<double>::mindlin(0.4, 5e7 / 1.5 / 2.5, 0.5)}; }
SimulationParams<double> bed_params(double r, double half) {
  auto prm = params<double>(2e-5, {0, -9.81, 0}, 0.2, 0.2 * r);
  prm.canonical_order = true;
  prm.domain_lo = {-half - 0.01, -0.01, -half - 0.01}, prm.domain_hi = {half + 0.01, 0.45, half + 0.01};
  return prm;
}

// Every rank's owned particles, gathered, by id: position, velocity.
std::map<Index, std::pair<Vec3<double>, Vec3<double>>> gather_owned(const Communicator& comm, const ParticleState<double>& mine) {
  std::string bytes;
  std::vector<double> v;
  for (std::size_t k = 0; k < mine.size(); ++k)
    for (const auto& q : {mine.position[k], mine.velocity[k]}) v.push_back(q.x), v.push_back(q.y), v.push_back(q.z);
  put_array(bytes, mine.id), put_array(bytes, v);
  std::map<Index, std::pair<Vec3<double>, Vec3<double>>> all;
  long doubled = 0;
  for (const std::string& m : comm.all_gather_bytes(bytes)) {
    ByteReader<CommunicatorError> in(m, "owned particles: ");
    const auto ids = in.array<Index>();
    const auto vals = in.array<double>();
    for (std::size_t k = 0; k < ids.size(); ++k)
      doubled += !all.emplace(ids[k], std::make_pair(Vec3<double>{vals[6 * k], vals[6 * k + 1], vals[6 * k + 2]},
                                                     Vec3<double>{vals[6 * k + 3], vals[6 * k + 4], vals[6 * k + 5]}))
                      .second;
  }
  if (doubled) all.clear();  // a doubled particle fails the count check
  return all;
}

// Touching pairs (ids) of spheres at these positions and radii (cells of the largest diameter).
std::set<std::pair<Index, Index>> touching(const std::map<Index, std::pair<Vec3<double>, Vec3<double>>>& at, const std::map<Index, double>& radius) {
  double cell = 0;
  for (const auto& [id, r] : radius) cell = std::fmax(cell, 2 * r);
  std::map<std::tuple<long, long, long>, std::vector<Index>> cells;
  const auto key = [&](const Vec3<double>& x) {
    return std::make_tuple(static_cast<long>(std::floor(x.x / cell)), static_cast<long>(std::floor(x.y / cell)), static_cast<long>(std::floor(x.z / cell)));
  };
  for (const auto& [id, xv] : at) cells[key(xv.first)].push_back(id);
  std::set<std::pair<Index, Index>> out;
  for (const auto& [id, xv] : at) {
    const auto [cx, cy, cz] = key(xv.first);
    for (long dx = -1; dx <= 1; ++dx)
      for (long dy = -1; dy <= 1; ++dy)
        for (long dz = -1; dz <= 1; ++dz) {
          const auto c = cells.find({cx + dx, cy + dy, cz + dz});
          if (c == cells.end()) continue;
          for (Index other : c->second) {
            if (other <= id) continue;
            const double d = radius.at(id) + radius.at(other);
            if (norm2(at.at(other).first - xv.first) < d * d) out.insert({id, other});
          }
        }
  }
  return out;
}

}  // namespace

BOOST_AUTO_TEST_SUITE(distributed)

BOOST_AUTO_TEST_CASE(a_settling_bed_over_ranks_moves_as_in_one_process) {
  const Communicator comm;
  const double r = kBedRadius, half = kBoxHalf;
  const Law law = bed_law();
  const SimulationParams<double> prm = bed_params(r, half);
  const ParticleState<double> start = falling_bed(r);
  const World<double> world = open_box(half);
  Sim one(prm, one_law(law), world, start);
  DistributedSimulation<Sim> many(comm, prm, one_law(law), world, start, SphereShape{});
  std::map<Index, double> radius;
  for (std::size_t k = 0; k < start.size(); ++k) radius[start.id[k]] = start.radius[k];
  double worst_x = 0, worst_v = 0;
  long pairs_differ = 0, count_wrong = 0, pairs_seen = 0;
  for (int block = 0; block < 20; ++block) {
    one.run(50), many.run(50);
    const ParticleState<double> ref = one.state();
    std::map<Index, std::pair<Vec3<double>, Vec3<double>>> want;
    for (std::size_t k = 0; k < ref.size(); ++k) want[ref.id[k]] = {ref.position[k], ref.velocity[k]};
    const auto got = gather_owned(comm, many.owned_state());
    count_wrong += got.size() != want.size();
    for (const auto& [id, xv] : want) {
      const auto it = got.find(id);
      if (it == got.end()) continue;
      worst_x = std::fmax(worst_x, norm(it->second.first - xv.first) / r);
      worst_v = std::fmax(worst_v, norm(it->second.second - xv.second));
    }
    const auto a = touching(want, radius), b = touching(got, radius);
    pairs_seen += static_cast<long>(a.size());
    std::vector<std::pair<Index, Index>> diff;
    std::set_symmetric_difference(a.begin(), a.end(), b.begin(), b.end(), std::back_inserter(diff));
    pairs_differ += static_cast<long>(diff.size());
  }
  const std::string ranks = ranks_label(comm);
  BOOST_TEST_MESSAGE("distributed bed" << ranks << ": rank " << comm.rank() << " owns " << many.owned() << " of " << many.total() << "; "
                                       << many.rebuilds() << " rebuilds, " << many.rebalances() << " rebalances; worst |dx| / r "
                                       << worst_x << ", |dv| " << worst_v << " m/s; " << pairs_seen << " touching pairs seen, "
                                       << pairs_differ << " differ");
  BOOST_TEST(pairs_seen > 20000);  // the bed is in contact: over 1 000 touching pairs a sample
  check_at_most({kCase, "touching pairs that differ from one process's, 10 000 spheres, every 50th of 1 000 steps" + ranks, "-",
                 "ghosts within the cutoff of every box"},
                static_cast<double>(pairs_differ), 0);
  check_at_most({kCase, "max |x - x_one| / r over 1 000 steps (Hertz-Mindlin, double)" + ranks, "-", "canonical order: bitwise"},
                worst_x, tol::distributed_positions);
  BOOST_TEST(count_wrong == 0);
  BOOST_TEST(many.total() == static_cast<long>(start.size()));  // none escaped the box
  BOOST_TEST(one.state().size() == start.size());
  BOOST_TEST(worst_v == 0.0);
}

// A run that starts with no particles and takes them in batches (a scene of feeds alone, as the
// thesis's hoppers are filled): every rank's Simulation starts empty, and the first batch reloads
// a store larger than the one its broad phase last built (a reference position per particle it
// never had: the defect this case found, a null read on the CPU). Two batches of the settling
// bed's spheres, 150 steps apart, then 300 steps: bitwise one process fed alike.
BOOST_AUTO_TEST_CASE(a_run_that_starts_empty_and_is_fed_moves_as_in_one_process) {
  const Communicator comm;
  const double r = kBedRadius, half = kBoxHalf;
  const Law law = bed_law();
  SimulationParams<double> prm = bed_params(r, half);
  const ParticleState<double> bed = falling_bed(r);
  double r_max = 0;
  for (double q : bed.radius) r_max = std::fmax(r_max, q);
  prm.max_radius = r_max;  // (no particle at the start to size the grid by)
  const auto batch = [&](std::size_t from, std::size_t to) {
    ParticleState<double> b;
    for (std::size_t k = from; k < to; ++k) b.add_sphere(bed.position[k], bed.radius[k], 2500, 0), b.velocity.back() = bed.velocity[k];
    return b;
  };
  const World<double> world = open_box(half);
  Sim one(prm, one_law(law), world, ParticleState<double>{});
  DistributedSimulation<Sim> many(comm, prm, one_law(law), world, ParticleState<double>{}, SphereShape{});
  const std::size_t half_bed = bed.size() / 2;
  one.insert(batch(0, half_bed)), many.insert(batch(0, half_bed));
  one.run(150), many.run(150);
  one.insert(batch(half_bed, bed.size())), many.insert(batch(half_bed, bed.size()));
  one.run(300), many.run(300);
  const ParticleState<double> ref = one.state();
  const auto got = gather_owned(comm, many.owned_state());
  double worst_x = 0;
  long missing = 0;
  for (std::size_t k = 0; k < ref.size(); ++k) {
    const auto it = got.find(ref.id[k]);
    if (it == got.end()) ++missing;
    else worst_x = std::fmax(worst_x, norm(it->second.first - vec_cast<double>(ref.position[k])) / r);
  }
  BOOST_TEST_MESSAGE("fed from empty" << ranks_label(comm) << ": " << got.size() << " particles, worst |dx| / r " << worst_x);
  BOOST_TEST(ref.size() == bed.size());
  BOOST_TEST(got.size() == ref.size());
  BOOST_TEST(missing == 0);
  check_at_most({kCase, "max |x - x_one| / r, 10 000 spheres fed in two batches into an empty run, 450 steps" + ranks_label(comm), "-",
                 "canonical order: bitwise"},
                worst_x, tol::distributed_positions);
}

BOOST_AUTO_TEST_CASE(a_bed_of_cubes_over_ranks_moves_as_in_one_process) {
  const Communicator comm;
  using CubeLaw = LinearSpringLaw<double>;
  using CubeSim = Simulation<DefaultSpace, PolyhedronShape<double>, CubeLaw, VelocityVerlet>;
  std::istringstream text("vertices 8\n0 0 0\n0.008 0 0\n0.008 0.008 0\n0 0.008 0\n0 0 0.008\n0.008 0 0.008\n0.008 0.008 0.008\n"
                          "0 0.008 0.008\nfaces 6\n4 0 3 2 1\n4 4 5 6 7\n4 0 1 5 4\n4 1 2 6 5\n4 2 3 7 6\n4 3 0 4 7\n");
  PolyhedronShape<double> shape;
  shape.table.add(parse_blaze_shape(text, "cube-8mm"), 2500);
  ParticleState<double> cubes;
  std::mt19937_64 rng(23);
  std::uniform_real_distribution<double> u(-1, 1);
  const double h = 0.0105;  // the lattice's step: just over the cube's diagonal across a face
  for (int k = 0; k < 10; ++k)
    for (int j = 0; j < 10; ++j)
      for (int i = 0; i < 10; ++i) {
        const double a = 3.2 * u(rng);
        Vec3<double> axis{u(rng), u(rng), u(rng) + 1e-3};
        axis = axis * (1 / norm(axis));
        add_polyhedron(cubes, shape.table, 0, Vec3<double>{-4.5 * h + i * h, 0.01 + j * h, -4.5 * h + k * h},
                       Quat<double>{std::cos(a / 2), axis.x * std::sin(a / 2), axis.y * std::sin(a / 2), axis.z * std::sin(a / 2)}, 0,
                       Vec3<double>{0.2 * u(rng), 0.2 * u(rng), 0.2 * u(rng)});
      }
  const auto normal = LinearSpringDashpot<double>::from_restitution(2e4, 0.5);
  const CubeLaw law{normal, TangentialSpring<double>::linear(0.5, 2.0 / 7.0 * 2e4, normal.beta)};
  const double half = 0.06, r = shape.table.type[0].bounding_radius;
  auto prm = params<double>(2e-5, {0, -9.81, 0}, 0.2, 0.2 * r);
  prm.canonical_order = true;  // the one-process run sums in the ranks' order
  prm.domain_lo = {-half - 0.01, -0.01, -half - 0.01}, prm.domain_hi = {half + 0.01, 0.45, half + 0.01};
  const World<double> box = open_box(half);
  CubeSim one(prm, one_law(law), box, cubes, shape);
  DistributedSimulation<CubeSim> many(comm, prm, one_law(law), box, cubes, shape);
  double worst_x = 0, worst_q = 0;
  for (int block = 0; block < 4; ++block) {
    one.run(250), many.run(250);
    const ParticleState<double> ref = one.state(), mine = many.owned_state();
    std::string bytes;
    std::vector<double> v;
    for (std::size_t k = 0; k < mine.size(); ++k) {
      const auto& x = mine.position[k];
      const auto& q = mine.orientation[k];
      for (double c : {x.x, x.y, x.z, q.w, q.x, q.y, q.z}) v.push_back(c);
    }
    put_array(bytes, mine.id), put_array(bytes, v);
    std::map<Index, std::size_t> row;
    for (std::size_t k = 0; k < ref.size(); ++k) row[ref.id[k]] = k;
    long seen = 0;
    for (const std::string& m : comm.all_gather_bytes(bytes)) {
      ByteReader<CommunicatorError> in(m, "cubes: ");
      const auto ids = in.array<Index>();
      const auto vals = in.array<double>();
      for (std::size_t k = 0; k < ids.size(); ++k, ++seen) {
        const std::size_t j = row.at(ids[k]);
        const Vec3<double> x{vals[7 * k], vals[7 * k + 1], vals[7 * k + 2]};
        const Quat<double>& q = ref.orientation[j];
        worst_x = std::fmax(worst_x, norm(x - ref.position[j]) / r);
        worst_q = std::fmax(worst_q, std::fabs(vals[7 * k + 3] - q.w) + std::fabs(vals[7 * k + 4] - q.x) + std::fabs(vals[7 * k + 5] - q.y) +
                                         std::fabs(vals[7 * k + 6] - q.z));
      }
    }
    BOOST_TEST(seen == static_cast<long>(ref.size()));
  }
  const std::string ranks = ranks_label(comm);
  BOOST_TEST_MESSAGE("distributed cubes" << ranks << ": rank " << comm.rank() << " owns " << many.owned() << "; " << many.rebuilds()
                                         << " rebuilds; worst |dx| / r " << worst_x << ", |dq| " << worst_q);
  check_at_most({kCase, "max |x - x_one| / r, 1 000 cubes falling, 1 000 steps (linear spring, double)" + ranks, "-",
                 "canonical order: bitwise"},
                worst_x, tol::distributed_positions);
  check_at_most({kCase, "max |q - q_one| (sum of components), the same cubes" + ranks, "-", "canonical order: bitwise"},
                worst_q, tol::distributed_positions);
  BOOST_TEST(many.total() == 1000);
}

BOOST_AUTO_TEST_CASE(a_checkpoint_of_two_ranks_restarts_on_three) {
  const Communicator world;
  const int writers = std::min(2, world.size()), readers = std::min(3, world.size());
  const double r = kBedRadius, half = kBoxHalf;
  const Law law = bed_law();
  const SimulationParams<double> prm = bed_params(r, half);
  const ParticleState<double> start = falling_bed(r);
  const World<double> box = open_box(half);
  Sim one(prm, one_law(law), box, start);
  one.run(600);
  const ParticleState<double> ref = one.state();
  const std::string path = (std::filesystem::temp_directory_path() / ("blaze_restart_" + std::to_string(world.all_gather(static_cast<long>(getpid()))[0]))).string();
  const Communicator first = world.first(writers);
  if (world.rank() < writers) {
    DistributedSimulation<Sim> run(first, prm, one_law(law), box, start, SphereShape{});
    run.run(300);
    run.write_checkpoint(path, "test");
  }
  world.barrier();
  const Communicator second = world.first(readers);
  double worst = 0;
  long count = 0;
  if (world.rank() < readers) {
    DistributedSimulation<Sim> resumed(second, prm, one_law(law), box, path, SphereShape{});
    BOOST_TEST(resumed.steps() == 300u);
    resumed.run(300);
    const auto got = gather_owned(second, resumed.owned_state());
    count = static_cast<long>(got.size());
    for (std::size_t k = 0; k < ref.size(); ++k) {
      const auto it = got.find(ref.id[k]);
      worst = it == got.end() ? 1.0 : std::fmax(worst, norm(it->second.first - ref.position[k]) / r);
    }
  }
  worst = world.max(worst), count = world.max(count);
  world.barrier();
  if (world.rank() == 0)
    for (int k = 0; k < writers; ++k) std::filesystem::remove(DistributedSimulation<Sim>::part_path(path, k, writers));
  const std::string label = ", " + std::to_string(writers) + " onto " + std::to_string(readers) + " ranks";
  BOOST_TEST_MESSAGE("restart" << label << ": worst |x - x_one| / r " << worst << " at step 600, " << count << " particles");
  check_at_most({kCase, "max |x - x_one| / r at step 600 after a checkpoint at 300" + label, "-", "parts read by any number of ranks; canonical order: bitwise"},
                worst, tol::distributed_positions);
  BOOST_TEST(count == static_cast<long>(start.size()));
}

BOOST_AUTO_TEST_SUITE_END()
