// The in-block rebuild (issue 19; pipeline/in_block_rebuild.hpp): a small system's neighbour and
// world lists rebuilt inside the batch, as the rebuild check's handler, instead of by the host.
// It runs by default on the GPU (the one-block path); here InBlockRebuild::on runs it on any
// backend and InBlockRebuild::off gives the host's rebuilds to compare with.
// - The lists it leaves: after every batch, every pair of spheres that touches is listed, both
//   ways, and no listed pair lies beyond the reach a list may have aged to (r_i + r_j + 2 skin).
// - The same run: 1000 steps in (the mill 2000, past its ramp), bodies within tol::in_block_rebuild_double_over_radius (double)
//   or _float_ of where host rebuilds put them, and as many builds: the same pairs are listed,
//   but in another order, the particles lie in another memory order and a pair is formed from its
//   lower index, so sums round differently. Scenes: a bed of 343 spheres falling into a box (float and double,
//   skins of 0.1 r and 0.3 r), the turning mill of test_world_lists.cpp with its world lists
//   (15 objects, float and double, skins of 0.2 r and r), 64 cubes with each pair once (its
//   reverse index).
// - What stays with the host: balls falling out of the domain are removed and counted as with
//   host rebuilds.
#include <boost/test/unit_test.hpp>
#include <cmath>
#include <type_traits>
#include "verification/cases/cube_bed.hpp"
#include "verification/mill_scenes.hpp"
#include "verification/report.hpp"
#include "verification/scenes.hpp"

using namespace blaze;
using namespace blaze::test;

namespace {

const char* const kCase = "In-block rebuild (issue 19)";

struct Outcome {
  ParticleState<double> state;  // by id, at the step compared
  std::uint64_t builds = 0, in_block = 0, world_list_builds = 0;
  Index removed = 0;
  long missed = 0, stale = 0;  // over the batches: touching pairs not listed, listed pairs beyond reach
  long touching = 0;           // touching pairs seen over the batches
};

// Spheres only: the list against the pairs as they lie now.
template <class Real>
void check_lists(const ParticleState<Real>& s, const std::vector<std::vector<Index>>& lists, double skin, Outcome& out) {
  std::vector<std::size_t> at(lists.size());
  for (std::size_t k = 0; k < s.size(); ++k) at[static_cast<std::size_t>(s.id[k])] = k;
  for (std::size_t a = 0; a < s.size(); ++a) {
    const auto& listed = lists[static_cast<std::size_t>(s.id[a])];
    for (std::size_t b = 0; b < s.size(); ++b) {
      if (a == b) continue;
      const double d = norm(vec_cast<double>(s.position[a]) - vec_cast<double>(s.position[b]));
      const double rr = static_cast<double>(s.radius[a]) + static_cast<double>(s.radius[b]);
      const bool in = std::find(listed.begin(), listed.end(), s.id[b]) != listed.end();
      if (d < rr) ++out.touching, out.missed += in ? 0 : 1;
      if (in && d > rr + 2 * skin * (1 + 1e-6)) ++out.stale;
    }
  }
}

template <class Sim, class Real, class Laws, class Shape>
Outcome run(SimulationParams<Real> prm, const Laws& laws, const World<Real>& world, const ParticleState<Real>& s, const Shape& shape,
            InBlockRebuild mode, int steps, int compare_at, int batch, bool spheres) {
  prm.in_block_rebuild = mode;
  Sim sim(prm, laws, world, s, shape);
  Outcome out;
  const auto keep = [&] {
    const ParticleState<Real> now = sim.state();
    Index top = 0;
    for (Index id : now.id) top = std::max(top, id);
    out.state.position.assign(static_cast<std::size_t>(top) + 1, {0, 0, 0});
    out.state.velocity = out.state.angular_velocity = out.state.position;
    for (std::size_t k = 0; k < now.size(); ++k) {
      const auto i = static_cast<std::size_t>(now.id[k]);
      out.state.position[i] = vec_cast<double>(now.position[k]);
      out.state.velocity[i] = vec_cast<double>(now.velocity[k]);
      out.state.angular_velocity[i] = vec_cast<double>(now.angular_velocity[k]);
    }
  };
  for (int done = 0; done < steps; done += batch) {
    sim.run(static_cast<std::uint64_t>(batch));
    if (spheres) check_lists(sim.state(), sim.neighbour_ids(), static_cast<double>(prm.skin), out);
    if (done + batch == compare_at) keep();
  }
  out.builds = sim.neighbour_builds();
  out.in_block = sim.in_block_builds();
  out.world_list_builds = sim.world_lists().builds();
  out.removed = sim.removed_count();
  return out;
}

// In place against host rebuilds, for one scene.
template <class Sim, class Real, class Laws, class Shape = SphereShape>
void check_scene(const std::string& name, const SimulationParams<Real>& prm, const Laws& laws, const World<Real>& world,
                 const ParticleState<Real>& s, double r, int steps, int compare_at, const Shape& shape = Shape{},
                 Index removed_at_least = 0, bool contacts = true) {
  constexpr bool spheres = std::is_same_v<Shape, SphereShape>;
  const int batch = 50;
  const Outcome host = run<Sim>(prm, laws, world, s, shape, InBlockRebuild::off, steps, compare_at, batch, spheres);
  const Outcome in = run<Sim>(prm, laws, world, s, shape, InBlockRebuild::on, steps, compare_at, batch, spheres);
  double worst = 0, moved = 0;
  BOOST_TEST_REQUIRE(host.state.size() == in.state.size());
  for (std::size_t i = 0; i < host.state.size(); ++i) {
    worst = std::fmax(worst, norm(host.state.position[i] - in.state.position[i]));
    if (i < s.size()) moved = std::fmax(moved, norm(host.state.position[i] - vec_cast<double>(s.position[i])));
  }
  BOOST_TEST_MESSAGE(name << ": " << s.size() << " bodies, " << steps << " steps; builds " << host.builds << " by the host, "
                          << in.builds << " with " << in.in_block << " in place (world lists " << host.world_list_builds << ", "
                          << in.world_list_builds << "); removed " << host.removed << ", " << in.removed << "; " << in.touching
                          << " touching pairs checked, " << in.missed << " not listed, " << in.stale << " listed beyond reach; at step "
                          << compare_at << " bodies " << worst / r << " r apart (moved up to " << moved / r << " r)");
  BOOST_TEST(host.in_block == 0u);
  BOOST_TEST(in.in_block >= 3u);                 // the lists were rebuilt in place ...
  BOOST_TEST(2 * in.in_block >= in.builds - 1);  // ... most of the time
  BOOST_TEST(moved > static_cast<double>(prm.skin));  // (the bodies did move past the skin by then)
  if (spheres)
    check_at_most({kCase, name + ": pairs touching but not listed, and listed beyond r_i + r_j + 2 skin, after every batch", "-",
                   "a list holds every pair within reach"},
                  static_cast<double>(in.missed + in.stale), 0);
  if (spheres && contacts) BOOST_TEST(in.touching > 100);
  BOOST_TEST(in.removed == host.removed);
  BOOST_TEST(in.removed >= removed_at_least);
  if (host.world_list_builds > 0) BOOST_TEST(in.world_list_builds == in.builds);  // the world lists with every list
  // as many builds (a chaotic run's may shift by one now and then)
  BOOST_TEST(std::labs(static_cast<long>(in.builds) - static_cast<long>(host.builds)) <= 1 + static_cast<long>(host.builds) / 50);
  check_at_most({kCase, name + ": max |x_in place - x_host| / r at step " + std::to_string(compare_at), "-",
                 "host rebuilds: the same pairs, summed in another order"},
                worst / r, sizeof(Real) == 8 ? tol::in_block_rebuild_double_over_radius : tol::in_block_rebuild_float_over_radius);
}

template <class Real>
void falling_bed(double skin_fraction) {
  using Law = LinearLaw<Real>;
  const double r = 2e-3, m = 2500 * 4.0 / 3.0 * kPi * r * r * r, k = 1e5;
  const auto scene = gravity_packing<Real>(343, r, 11, kPi * std::sqrt(0.5 * m / k) / 25);
  auto prm = scene.params;
  prm.skin = static_cast<Real>(skin_fraction * r);
  const Law law{LinearSpringDashpot<Real>::from_restitution(static_cast<Real>(k), Real(0.5)), HistoryFreeFriction<Real>::make(Real(0.4), Real(0.05))};
  using Sim = Simulation<DefaultSpace, SphereShape, Law, VelocityVerlet, ContactPointVelocity, FullFeatures>;
  const std::string name = std::string("falling bed, ") + (sizeof(Real) == 8 ? "double" : "float") + ", skin " +
                           std::to_string(skin_fraction).substr(0, 3) + " r";
  check_scene<Sim>(name, prm, one_law(law), scene.world, scene.particles, r, 3000, 1000);
}

template <class Real>
void turning_mill(double skin_fraction) {
  using Law = LinearLaw<Real>;
  const double r = 0.01, kn = 1e5, m = 7800 * 4.0 / 3.0 * kPi * r * r * r;
  const double dt = kPi * std::sqrt(0.5 * m / kn) / 25;
  const Law law{LinearSpringDashpot<Real>::from_restitution(static_cast<Real>(kn), Real(0.6)), HistoryFreeFriction<Real>::make(Real(0.5), Real(0))};
  auto prm = params<Real>(dt, {0, -9.81, 0}, 0.2, skin_fraction * r);
  prm.world_lists = WorldLists::on;
  using Sim = Simulation<DefaultSpace, SphereShape, Law, VelocityVerlet, ContactPointVelocity, FullFeatures>;
  const std::string name = std::string("turning mill, ") + (sizeof(Real) == 8 ? "double" : "float") + ", skin " +
                           std::to_string(skin_fraction).substr(0, 3) + " r";
  check_scene<Sim>(name, prm, one_law(law), small_mill<Real>(40, 0.1), mill_balls<Real>(r), r, 3000, 2000);
}

}  // namespace

BOOST_AUTO_TEST_SUITE(in_block_rebuild)

BOOST_AUTO_TEST_CASE(falling_beds_rebuild_in_place_as_the_host_does) {
  for (double skin : {0.1, 0.3}) {
    falling_bed<float>(skin);
    falling_bed<double>(skin);
  }
}

BOOST_AUTO_TEST_CASE(turning_mills_rebuild_their_world_lists_in_place) {
  for (double skin : {0.2, 1.0}) {
    turning_mill<float>(skin);
    turning_mill<double>(skin);
  }
}

BOOST_AUTO_TEST_CASE(cubes_with_pairs_once_rebuild_in_place) {
  const cases::CubeBed bed = cases::cube_bed();
  using Sim = Simulation<DefaultSpace, PolyhedronShape<float>, LinearLaw<float>, VelocityVerlet, ContactPointVelocity, FullFeatures>;
  auto prm = bed.scene.params;
  prm.pairs = PairEvaluation::once;
  check_scene<Sim>("64 cubes, pairs once", prm, one_law(bed.law), bed.scene.world, bed.scene.particles, 0.005,
                   1500, 1000, bed.shape);
}

// Balls dropped through a floorless domain: each leaves it at a rebuild, which the host does.
BOOST_AUTO_TEST_CASE(balls_leaving_the_domain_are_removed_by_the_host) {
  using Law = LinearLaw<double>;
  const double r = 0.01, kn = 1e5, m = 7800 * 4.0 / 3.0 * kPi * r * r * r;
  const Law law{LinearSpringDashpot<double>::from_restitution(kn, 0.6), HistoryFreeFriction<double>::make(0.5, 0)};
  const double dt = kPi * std::sqrt(0.5 * m / kn) / 25;
  using Sim = Simulation<DefaultSpace, SphereShape, Law, VelocityVerlet, ContactPointVelocity, FullFeatures>;
  const auto balls = mill_balls<double>(r);
  check_scene<Sim>("balls falling out of the domain", params<double>(dt, {0, -9.81, 0}, 0.13, 0.3 * r), one_law(law), World<double>{},
                   balls, r, 4000, 1000, SphereShape{}, static_cast<Index>(balls.size()) / 2, false);
}

BOOST_AUTO_TEST_SUITE_END()
