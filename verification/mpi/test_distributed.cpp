// One run over several ranks (issue 21; pipeline/parallel/distributed_simulation.hpp) against the
// same run in one Simulation, on however many ranks mpirun starts (make test: 1 to 4):
// - A bed of 10 000 spheres (Hertz-Mindlin, tangential springs carried across ranks with their
//   particles) falling into a box and settling, 1 000 steps in double: at every 50th step the set
//   of touching pairs is the one-process run's, and positions and velocities agree to rounding
//   (the ranks sum a particle's contact forces in another order: ~1e-16 a step, grown by the
//   bed's chaos); the particle count, mass and momentum are the one-process run's.
// - A run on two ranks writes its checkpoint (one part a rank) at step 300; three ranks read it
//   and go on to step 600: positions agree with the one-process run's to rounding, none lost
//   (fewer ranks under mpirun: 1 onto 1, 2 onto 2).
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
  const double r = 0.0025, half = 0.06;
  const Hertz<double> hertz = Hertz<double>::from_restitution(5e7, 0.5);
  const Law law{hertz, TangentialSpring<double>::mindlin(0.4, 5e7 / 1.5 / 2.5, 0.5)};
  auto prm = params<double>(2e-5, {0, -9.81, 0}, 0.2, 0.2 * r);
  prm.domain_lo = {-half - 0.01, -0.01, -half - 0.01}, prm.domain_hi = {half + 0.01, 0.45, half + 0.01};
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
  check_at_most({kCase, "max |x - x_one| / r over 1 000 steps (Hertz-Mindlin, double)" + ranks, "-", "the same forces summed in another order"},
                worst_x, tol::distributed_positions);
  BOOST_TEST(count_wrong == 0);
  BOOST_TEST(many.total() == static_cast<long>(start.size()));  // none escaped the box
  BOOST_TEST(one.state().size() == start.size());
  BOOST_TEST(worst_v < 1e-6);
}

BOOST_AUTO_TEST_CASE(a_checkpoint_of_two_ranks_restarts_on_three) {
  const Communicator world;
  const int writers = std::min(2, world.size()), readers = std::min(3, world.size());
  const double r = 0.0025, half = 0.06;
  const Hertz<double> hertz = Hertz<double>::from_restitution(5e7, 0.5);
  const Law law{hertz, TangentialSpring<double>::mindlin(0.4, 5e7 / 1.5 / 2.5, 0.5)};
  auto prm = params<double>(2e-5, {0, -9.81, 0}, 0.2, 0.2 * r);
  prm.domain_lo = {-half - 0.01, -0.01, -half - 0.01}, prm.domain_hi = {half + 0.01, 0.45, half + 0.01};
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
  check_at_most({kCase, "max |x - x_one| / r at step 600 after a checkpoint at 300" + label, "-", "parts read by any number of ranks"},
                worst, tol::distributed_positions);
  BOOST_TEST(count == static_cast<long>(start.size()));
}

BOOST_AUTO_TEST_SUITE_END()
