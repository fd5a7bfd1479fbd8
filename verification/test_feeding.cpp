// Feeding (issue 20; pipeline/feeder.hpp, blaze/scene/size_distribution.hpp, insertion_region.hpp):
// - every size distribution (classes, uniform, normal, log-normal, Rosin-Rammler; by number and by
//   mass; several parameter sets) delivers sizes whose Kolmogorov-Smirnov distance from the
//   requested CDF stays below the 99% quantile 1.63 / sqrt(n_eff), and a wrong CDF is told apart;
// - box, cylinder and disc regions give centres that keep the particle inside, uniform in volume;
// - a feed into an empty box meets its due count exactly at every insertion (rate) or within one
//   particle's mass (mass_rate), for spheres and cubes, and no inserted particle overlaps another
//   or the floor; particle count is conserved (present + removed = inserted);
// - cubes (and the spheres of a polyhedron scene) fed with a scale distribution of one shape: the
//   delivered bounding radii pass the same KS test, each body is its type scaled (mass s^3,
//   moments s^5), apart at insertion;
// - a region too small for the rate reports its shortfall and what stayed undelivered;
// - a restart from a checkpoint continues the same feed bit for bit (particles, sizes, counts);
// - inserting a particle next to a bed does not disturb its contact histories: two spheres held
//   on a slope by their tangential springs move bitwise as without the insertion;
// - a pour settles to random loose packing (solid fraction >= 0.55 in the bulk);
// - elastic frictionless spheres fed into a closed box keep E(t) = E_inserted (the balance the
//   run's energy guard checks);
// - bad [[feed]] keys are refused naming the file, the table and the key.
#include <boost/test/unit_test.hpp>
#include <cmath>
#include <cstring>
#include <filesystem>
#include <map>
#include <random>
#include <omp.h>
#include "blaze/io/checkpoint.hpp"
#include "blaze/scene/scene_build.hpp"
#include "blaze/scene/scene_file.hpp"
#include "blaze/shapes/polyhedron_shape.hpp"
#include "blaze/shapes/sphere_shape.hpp"
#include "pipeline/feeder.hpp"
#include "pipeline/world_block_arrays.hpp"
#include "pipeline/scene_params.hpp"
#include "verification/report.hpp"
#include "verification/scenes.hpp"
#include "verification/tolerances.hpp"

using namespace blaze;
using namespace blaze::test;

namespace {

BOOST_AUTO_TEST_SUITE(feeding)

std::string temp(const std::string& name) { return (std::filesystem::temp_directory_path() / name).string(); }

// The Kolmogorov-Smirnov limit for n samples of weights w (99%: 1.63 / sqrt(n_eff), n_eff =
// (sum w)^2 / sum w^2, Kish's effective size of a weighted sample).
double ks_limit(const std::vector<double>& r, bool by_mass) {
  double s = 0, s2 = 0;
  for (double x : r) {
    const double w = by_mass ? x * x * x : 1.0;
    s += w, s2 += w * w;
  }
  return (by_mass ? tol::feed_ks_quantile_weighted : tol::feed_ks_quantile) / std::sqrt(s * s / s2);
}

SizeDistribution distribution(SizeKind kind, bool by_mass) {
  SizeDistribution d;
  d.kind = kind, d.by_mass = by_mass;
  return d;
}

BOOST_AUTO_TEST_CASE(size_distributions_match_their_cdf) {
  std::vector<std::pair<std::string, SizeDistribution>> cases;
  for (bool mass : {false, true}) {
    const std::string by = mass ? " by mass" : " by number";
    SizeDistribution c = distribution(SizeKind::classes, mass);
    c.sizes = {1e-3, 2e-3, 4e-3}, c.fractions = {0.2, 0.5, 0.3};
    cases.push_back({"classes" + by, c});
    SizeDistribution u = distribution(SizeKind::uniform, mass);
    u.min = 1e-3, u.max = 3e-3;
    cases.push_back({"uniform" + by, u});
    for (double sd : {0.2e-3, 1e-3}) {  // barely truncated, and cut at both ends
      SizeDistribution n = distribution(SizeKind::normal, mass);
      n.mean = 2e-3, n.deviation = sd, n.min = 1e-3, n.max = 3e-3;
      cases.push_back({"normal sd " + Scene::shortest(sd) + by, n});
    }
    for (double sigma : {0.1, 0.5}) {
      SizeDistribution l = distribution(SizeKind::lognormal, mass);
      l.mean = 2e-3, l.deviation = sigma, l.min = 0.8e-3, l.max = 5e-3;
      cases.push_back({"log-normal sigma " + Scene::shortest(sigma) + by, l});
    }
    for (double k : {1.5, 4.0}) {
      SizeDistribution w = distribution(SizeKind::rosin_rammler, mass);
      w.scale = 2e-3, w.shape = k, w.min = 0.5e-3, w.max = 4e-3;
      cases.push_back({"Rosin-Rammler k " + Scene::shortest(k) + by, w});
    }
  }
  for (const auto& [name, d] : cases) {
    d.validate();
    std::mt19937_64 rng(11);
    std::vector<double> r(20000);
    for (double& x : r) x = d.draw(rng);
    const auto [lo, hi] = std::minmax_element(r.begin(), r.end());
    BOOST_TEST((*lo >= d.smallest() && *hi <= d.largest()), name << ": a draw outside [min, max]");
    check_at_most({"Feed size distribution: " + name, "Kolmogorov-Smirnov distance of 20000 draws from the CDF", "-",
                   "Kolmogorov 1933; 99% quantile 1.63/sqrt(n_eff)"},
                  d.ks_distance(r), ks_limit(r, d.by_mass));
  }
  // the check can fail: uniform draws against a normal CDF, and by number against by mass
  SizeDistribution u = distribution(SizeKind::uniform, false), n = distribution(SizeKind::normal, false);
  u.min = n.min = 1e-3, u.max = n.max = 3e-3, n.mean = 2e-3, n.deviation = 0.5e-3;
  std::mt19937_64 rng(3);
  std::vector<double> r(20000);
  for (double& x : r) x = u.draw(rng);
  BOOST_TEST(n.ks_distance(r) > 5 * ks_limit(r, false));
  SizeDistribution um = u;
  um.by_mass = true;
  BOOST_TEST(um.ks_distance(r) > 5 * ks_limit(r, true));
}

// Narrow spreads: down to SizeDistribution::kMinRelativeSpread of the size the draws and the CDF
// are resolved (the check holds as for a wide spread); below it the spread is refused (the check
// read up to 0.5 for a distribution delivered exactly: double cannot tell the sizes apart).
BOOST_AUTO_TEST_CASE(narrow_size_spreads_resolved_or_refused) {
  const double floor = SizeDistribution::kMinRelativeSpread, r50 = 2e-3;
  for (double rel : {1e-3, 1e-6, floor}) {
    for (SizeKind kind : {SizeKind::uniform, SizeKind::normal, SizeKind::lognormal}) {
      SizeDistribution d = distribution(kind, false);
      d.mean = r50, d.deviation = kind == SizeKind::normal ? rel * r50 : rel;
      d.min = kind == SizeKind::uniform ? r50 : 0.5 * r50, d.max = kind == SizeKind::uniform ? r50 * (1 + 2 * rel) : 2 * r50;
      BOOST_REQUIRE_NO_THROW(d.validate());
      std::mt19937_64 rng(7);
      std::vector<double> r(5000);
      for (double& x : r) x = d.draw(rng);
      check_at_most({"Feed size distribution: " + std::string(to_string(kind)) + " of relative spread " + Scene::shortest(rel),
                     "Kolmogorov-Smirnov distance of 5000 draws from the CDF", "-", "Kolmogorov 1933; 99% quantile 1.63/sqrt(n)"},
                    d.ks_distance(r), ks_limit(r, false));
    }
  }
  for (double rel : {0.5 * floor, 1e-12, 1e-18}) {
    SizeDistribution u = distribution(SizeKind::uniform, false), n = distribution(SizeKind::normal, false),
                     l = distribution(SizeKind::lognormal, false);
    u.min = r50, u.max = r50 * (1 + rel);
    n.mean = l.mean = r50, n.deviation = rel * r50, l.deviation = rel;
    n.min = l.min = 0.5 * r50, n.max = l.max = 2 * r50;
    for (const SizeDistribution* d : {&u, &n, &l}) {
      bool refused = false;
      try {
        d->validate();
      } catch (const std::invalid_argument& e) {
        // (a spread below double's resolution leaves max == min: refused as an empty range)
        refused = std::string(e.what()).find(d->kind == SizeKind::uniform && rel < 1e-15 ? "min < max" : "one size") != std::string::npos;
      }
      BOOST_TEST(refused, to_string(d->kind) << " of relative spread " << rel << " accepted");
    }
  }
}

BOOST_AUTO_TEST_CASE(regions_keep_particles_inside_uniformly) {
  const double r = 0.01;
  InsertionRegion box, cyl, disc;
  box.kind = RegionKind::box, box.lo = {0, 0, 0}, box.hi = {0.2, 0.1, 0.3};
  cyl.kind = RegionKind::cylinder, cyl.centre = {1, 2, 3}, cyl.axis = {0.6, 0, 0.8}, cyl.radius = 0.1, cyl.length = 0.3;
  disc.kind = RegionKind::disc, disc.centre = {0, 0, 1}, disc.axis = {0, 1, 0}, disc.radius = 0.05;
  CounterEngine rng(5, 0);  // (draw runs where the particles live: its engine is the feeder's)
  for (const InsertionRegion* g : {&box, &cyl, &disc}) {
    double rho2 = 0, along = 0;
    const int n = 4000;
    for (int k = 0; k < n; ++k) {
      const Vec3<double> x = g->draw(rng, r);
      BOOST_TEST(g->admits(x, r, 1e-12), to_string(g->kind) << ": a centre outside the region");
      BOOST_TEST(!g->admits(x + Vec3<double>{0.5, 0.5, 0.5}, r, 1e-12));
      if (g->kind == RegionKind::box) {
        rho2 += (x.x - 0.1) / 0.08;  // uniform on [-1, 1]: mean 0
        along += (x.z - 0.15) / 0.13;
      } else {
        const Vec3<double> d = x - g->centre;
        const double s = dot(d, g->axis), reach = g->radius - r;
        rho2 += norm2(d - g->axis * s) / (reach * reach);  // uniform in area: mean 1/2
        along += g->kind == RegionKind::cylinder ? (s - 0.15) / 0.14 : s;
      }
    }
    const double expected = g->kind == RegionKind::box ? 0.0 : 0.5;
    // n = 4000 uniform draws: the means' standard errors are 0.29/sqrt(n) = 0.005 and below
    BOOST_TEST(std::fabs(rho2 / n - expected) < 0.03, to_string(g->kind) << ": mean " << rho2 / n);
    BOOST_TEST(std::fabs(along / n) < 0.03, to_string(g->kind) << ": mean along " << along / n);
  }
}

// An open-topped box (floor y = 0, four sides to y = 0.2) fed from a region near its top; no
// particles at the start. `feed` is the [[feed]] table's body, `types` extra [[particle_type]]s.
std::string feed_scene(const std::string& feed, const std::string& law_keys = "", const std::string& pair_keys = "",
                       const std::string& type = "name = \"bead\"\nmaterial = \"glass\"\nradius = 3e-3") {
  return R"(
[simulation]
law = "linear"
precision = "double"
dt = 2e-5
end_time = 0.3
gravity = [0, -9.81, 0]
domain_lo = [-0.05, -0.01, -0.05]
domain_hi = [0.05, 0.25, 0.05]
)" + law_keys + R"(
[[material]]
name = "glass"
density = 2500
[[pair]]
materials = ["glass", "glass"]
stiffness = 5e3
restitution = 0.5
friction = 0.3
)" + pair_keys + R"(
[[particle_type]]
)" + type + R"(
[[feed]]
)" + feed + R"(
[[wall]]
material = "glass"
vertices = [[-0.04, 0.0, -0.04], [-0.04, 0.0, 0.04], [0.04, 0.0, 0.04], [0.04, 0.0, -0.04]]
rim = false
[[wall]]
material = "glass"
vertices = [[-0.04, 0.0, -0.04], [-0.04, 0.2, -0.04], [-0.04, 0.2, 0.04], [-0.04, 0.0, 0.04]]
rim = false
[[wall]]
material = "glass"
vertices = [[0.04, 0.0, 0.04], [0.04, 0.2, 0.04], [0.04, 0.2, -0.04], [0.04, 0.0, -0.04]]
rim = false
[[wall]]
material = "glass"
vertices = [[0.04, 0.0, -0.04], [0.04, 0.2, -0.04], [-0.04, 0.2, -0.04], [-0.04, 0.0, -0.04]]
rim = false
[[wall]]
material = "glass"
vertices = [[-0.04, 0.0, 0.04], [-0.04, 0.2, 0.04], [0.04, 0.2, 0.04], [0.04, 0.0, 0.04]]
rim = false
)";
}

const char* kBoxRegion = "region = { kind = \"box\", lo = [-0.035, 0.12, -0.035], hi = [0.035, 0.18, 0.035] }\n";

// The smallest gap |x_i - x_j| - r_i - r_j between a particle of `fresh` ids and any other, and
// between it and the floor (y - r).
template <class Real>
double closest_gap(const ParticleState<Real>& s, Index fresh_from) {
  double gap = 1e300;
  for (std::size_t i = 0; i < s.size(); ++i) {
    if (s.id[i] < fresh_from) continue;
    gap = std::min(gap, static_cast<double>(s.position[i].y - s.radius[i]));
    for (std::size_t j = 0; j < s.size(); ++j)
      if (j != i) gap = std::min(gap, static_cast<double>(norm(s.position[i] - s.position[j]) - s.radius[i] - s.radius[j]));
  }
  return gap;
}

template <class Shape, class Law>
struct FeedRun {
  using Real = typename Law::real_type;
  using Sim = Simulation<DefaultSpace, Shape, Law, VelocityVerlet>;
  Scene s;
  Shape shape;
  std::vector<ConvexShape> shapes;
  std::unique_ptr<Sim> sim;
  std::vector<Feeder<Real>> feeders;
  explicit FeedRun(const Scene& scene) : s(scene) {
    ParticleState<Real> particles;
    const PolyhedronTable<Real>* table = nullptr;
    if constexpr (!std::is_same_v<Shape, SphereShape>) {
      shapes = build_shapes(s);
      shape.table = build_shape_table<Real>(s, shapes);
      table = &shape.table;
      particles = build_particles<Real>(s, table);
    } else {
      particles = build_particles<Real>(s, nullptr);
    }
    sim = std::make_unique<Sim>(simulation_params<Real>(s, false), build_laws<Law>(s), build_world<Real>(s), particles, shape);
    for (std::size_t k = 0; k < s.feeds.size(); ++k) feeders.emplace_back(s, k, table);
  }
  // Steps [sim.steps(), until), feeding first at each step as blaze run does; after each
  // insertion, `check(feeder, ids before it)`.
  template <class Check>
  void run(std::uint64_t until, Check check) {
    for (std::uint64_t k = sim->steps(); k < until; ++k) {
      for (auto& f : feeders)
        if (f.inserts_at(k)) {
          const Index before = sim->inserted_count();
          f.feed(*sim);
          check(f, before);
        }
      sim->step();
    }
  }
  void run(std::uint64_t until) {
    run(until, [](const Feeder<Real>&, Index) {});
  }
};

BOOST_AUTO_TEST_CASE(feeds_meet_their_rate_without_overlaps) {
  using Run = FeedRun<SphereShape, LinearLaw<double>>;
  struct Case {
    const char* name;
    std::string feed;
  };
  const std::vector<Case> cases = {
      {"lognormal at 3000/s", std::string("type = \"bead\"\nrate = 3000\nend_time = 0.2\nvelocity = [0, -0.3, 0]\n") + kBoxRegion +
                                   "size = { kind = \"lognormal\", median = 2.5e-3, sigma = 0.2, min = 1.5e-3, max = 3e-3 }"},
      {"classes by mass at 0.02 kg/s", std::string("type = \"bead\"\nmass_rate = 0.02\nend_time = 0.2\n") + kBoxRegion +
                                            "size = { kind = \"classes\", radii = [1.5e-3, 3e-3], fractions = [0.5, 0.5], by = \"mass\" }"},
      {"uniform from a cylinder, count 150", "type = \"bead\"\nrate = 2000\ncount = 150\nstart_time = 0.02\n"
                                             "region = { kind = \"cylinder\", centre = [0, 0.12, 0], axis = [0, 1, 0], radius = 0.03, length = 0.05 }\n"
                                             "size = { kind = \"uniform\", min = 2e-3, max = 3e-3 }"},
      {"on a tilted disc, count 60", "type = \"bead\"\nrate = 600\ncount = 60\nvelocity = [0, -0.5, 0]\n"
                                     "region = { kind = \"disc\", centre = [0, 0.15, 0], normal = [0.3, 1, 0.2], radius = 0.035 }\n"},
  };
  for (const auto& c : cases) {
    const Scene s = parse_scene(feed_scene(c.feed), "feed.toml");
    Run run(s);
    const FeedSpec& f = s.feeds[0];
    double worst_gap = 1e300, worst_due = 0;
    int insertions = 0;
    run.run(static_cast<std::uint64_t>(std::llround(0.25 / s.dt)), [&](const Feeder<double>& feeder, Index before) {
      ++insertions;
      worst_gap = std::min(worst_gap, closest_gap(run.sim->state(), before));
      const double span = std::min(run.sim->time() + static_cast<double>(feeder.every()) * s.dt, f.end) - f.start;
      if (f.rate > 0) {
        double due = std::floor(f.rate * span + 1e-9);
        if (f.count > 0) due = std::min(due, static_cast<double>(f.count));
        worst_due = std::max(worst_due, std::fabs(static_cast<double>(feeder.inserted()) - due));
      } else {  // within one particle's mass of the due mass (the largest: 2500 kg/m^3, r = 3 mm)
        const double largest = 2500 * 4.0 / 3.0 * M_PI * 27e-9;
        worst_due = std::max(worst_due, std::fabs(feeder.inserted_mass() - f.mass_rate * span) / largest - 0.5);
      }
    });
    const std::string name = std::string("Feeding: ") + c.name;
    BOOST_TEST(insertions >= 2);
    BOOST_TEST(run.feeders[0].shortfall() == 0);
    check_at_most({name, "|delivered - due| at every insertion (particles; by mass: particle masses beyond one half)", "-",
                   "rate x (t + interval - start)"},
                  worst_due, 0);
    check_at_least({name, "smallest gap of an inserted particle to any other and to the floor (m)", "-", "no overlap at insertion"},
                   worst_gap, 0);
    BOOST_TEST(static_cast<long>(run.sim->size() + run.sim->removed_count()) == run.feeders[0].inserted());
    BOOST_TEST(run.sim->inserted_count() == run.feeders[0].inserted());
    check_at_most({name, "Kolmogorov-Smirnov distance of the delivered sizes", "-", "99% quantile 1.63/sqrt(n_eff)"},
                  run.feeders[0].ks_distance(), ks_limit(run.feeders[0].delivered(), f.size.by_mass));
  }
}

// A feed into a moving world places against the world where it is now (stop 50: the world at its
// initial pose was tested, so particles were put across a wall that had moved into the region, as
// a lifter turns into a mill's feed): a plate rising at 0.5 m/s from y = 0.05 m, through the
// region (y 0.12-0.18 m) by the insertions at 0.14-0.26 s, has no particle across it or within a
// radius above it; one removed at 0.2 s refuses nothing from then on.
BOOST_AUTO_TEST_CASE(feeds_place_against_moving_walls_where_they_are) {
  using Run = FeedRun<SphereShape, LinearLaw<double>>;
  for (const char* removal : {"", "remove_time = 0.2\n"}) {
    const std::string plate = std::string("[[wall]]\nmaterial = \"glass\"\nrim = false\n") + removal +
                              "vertices = [[-0.04, 0.05, -0.04], [-0.04, 0.05, 0.04], [0.04, 0.05, 0.04], [0.04, 0.05, -0.04]]\n"
                              "motion = { kind = \"translation\", velocity = [0, 0.5, 0] }\n";
    const Scene s = parse_scene(feed_scene(std::string("type = \"bead\"\nrate = 4000\nstart_time = 0.14\nend_time = 0.26\n") + kBoxRegion) +
                                    plate,
                                "feed.toml");
    Run run(s);
    const double r = 2.5e-3;
    long across = 0, placed = 0, above_reach = 0;
    run.run(static_cast<std::uint64_t>(std::llround(0.27 / s.dt)), [&](const Feeder<double>&, Index before) {
      const double t = run.sim->time(), plate_y = 0.05 + 0.5 * t;
      const auto& st = run.sim->state();
      for (std::size_t i = 0; i < st.size(); ++i) {
        if (st.id[i] < before) continue;
        ++placed;
        const double d = static_cast<double>(st.position[i].y) - plate_y;
        const bool gone = *removal && t >= 0.2 - 0.5 * s.dt;
        if (!gone && d > -r && d < r - tol::feed_wall_clearance) ++across;
        if (gone && std::fabs(d) < r) ++above_reach;  // the removed plate's place: free again
      }
    });
    BOOST_TEST_REQUIRE(placed > 100);
    BOOST_TEST(across == 0, (*removal ? "removed at 0.2 s: " : "") << across << " of " << placed << " placed across the plate or within r of it");
    if (*removal) BOOST_TEST(above_reach > 0, "nothing placed where the removed plate was");
  }
  // A paddle turning about y at 2 pi rad/s through the region (50-94 degrees from where it
  // started over the insertions): nothing placed within r of its plane over its outline.
  const std::string paddle = "[[wall]]\nmaterial = \"glass\"\nrim = false\n"
                             "vertices = [[0, 0.11, -0.03], [0, 0.19, -0.03], [0, 0.19, 0.03], [0, 0.11, 0.03]]\n"
                             "motion = { kind = \"rotation\", axis = [0, 1, 0], point = [0, 0, 0], omega = 6.283185307179586 }\n";
  const Scene s = parse_scene(feed_scene(std::string("type = \"bead\"\nrate = 4000\nstart_time = 0.14\nend_time = 0.26\n") + kBoxRegion) + paddle,
                              "feed.toml");
  Run run(s);
  const double r = 2.5e-3;
  long near = 0, placed = 0;
  run.run(static_cast<std::uint64_t>(std::llround(0.27 / s.dt)), [&](const Feeder<double>&, Index before) {
    const double a = 2 * M_PI * run.sim->time();
    const Vec3<double> n{std::cos(a), 0, -std::sin(a)}, along{std::sin(a), 0, std::cos(a)};  // e_x, e_z turned about y
    const auto& st = run.sim->state();
    for (std::size_t i = 0; i < st.size(); ++i) {
      if (st.id[i] < before) continue;
      ++placed;
      const Vec3<double> x = vec_cast<double>(st.position[i]);
      const bool over = std::fabs(dot(x, along)) <= 0.03 && x.y >= 0.11 && x.y <= 0.19;
      if (over && std::fabs(dot(x, n)) < r - tol::feed_wall_clearance) ++near;
    }
  });
  BOOST_TEST_REQUIRE(placed > 100);
  BOOST_TEST(near == 0, near << " of " << placed << " placed within r of the turning paddle");
}

BOOST_AUTO_TEST_CASE(cubes_are_fed_turned_and_apart) {
  using Run = FeedRun<PolyhedronShape<double>, LinearLaw<double>>;
  const Scene s = parse_scene(feed_scene(std::string("type = \"cube\"\nrate = 1500\nend_time = 0.1\n") + kBoxRegion, "", "",
                                         "name = \"cube\"\nmaterial = \"glass\"\nshape = \"data/shapes/cube.shape\"\nbounding_radius = 4e-3"),
                              "cubes.toml");
  Run run(s);
  double worst_gap = 1e300;
  run.run(static_cast<std::uint64_t>(std::llround(0.12 / s.dt)),
          [&](const Feeder<double>&, Index before) { worst_gap = std::min(worst_gap, closest_gap(run.sim->state(), before)); });
  const auto st = run.sim->state();
  BOOST_TEST(run.feeders[0].inserted() == 150);
  // bounding spheres apart at insertion, and every cube turned its own way
  check_at_least({"Feeding: cubes at 1500/s", "smallest bounding-sphere gap at insertion (m)", "-", "no overlap at insertion"}, worst_gap, 0);
  int identity = 0;
  for (const auto& q : st.orientation) identity += std::fabs(q.w) > 0.999999;
  BOOST_TEST(identity == 0);
}

// A scale distribution of one shape file: cubes whose bounding radii follow the requested
// distribution, each its type's cube scaled (mass s^3, moments s^5), apart at insertion, the
// distribution's extremes sizing the run; and a sphere type of a polyhedron scene likewise.
BOOST_AUTO_TEST_CASE(cubes_are_fed_with_a_scale_distribution) {
  using Run = FeedRun<PolyhedronShape<double>, LinearLaw<double>>;
  const std::string cube = "name = \"cube\"\nmaterial = \"glass\"\nshape = \"data/shapes/cube.shape\"\nbounding_radius = 4e-3";
  struct Case {
    const char* name;
    std::string size;
    bool by_mass;
  };
  const std::vector<Case> cases = {
      {"uniform 2.5-5 mm by number", "size = { kind = \"uniform\", min = 2.5e-3, max = 5e-3 }", false},
      {"Rosin-Rammler by mass", "size = { kind = \"rosin_rammler\", r63 = 4e-3, k = 4, min = 2e-3, max = 5e-3, by = \"mass\" }", true},
      {"two classes by mass", "size = { kind = \"classes\", radii = [3e-3, 4.5e-3], fractions = [0.3, 0.7], by = \"mass\" }", true},
  };
  for (const auto& c : cases) {
    const std::string rate = c.by_mass ? "mass_rate = 0.3\n" : "rate = 1500\n";
    const Scene s = parse_scene(feed_scene("type = \"cube\"\n" + rate + "end_time = 0.1\n" + kBoxRegion + c.size, "", "", cube), "cubes.toml");
    BOOST_TEST(s.types.size() == 3u);  // the cube and its feed's smallest and largest
    BOOST_TEST(s.types[1].volume < s.types[0].volume);  // the smallest cube, scaled: (r / R)^3 of the volume
    BOOST_TEST(s.types[1].volume == s.types[0].volume * std::pow(s.types[1].bounding_radius / s.types[0].bounding_radius, 3),
               boost::test_tools::tolerance(tol::scaled_mass_properties));
    Run run(s);
    BOOST_TEST(run.shape.table.count == 1);  // one shape: the sizes are scales of it
    double worst_gap = 1e300;
    run.run(static_cast<std::uint64_t>(std::llround(0.12 / s.dt)),
            [&](const Feeder<double>&, Index before) { worst_gap = std::min(worst_gap, closest_gap(run.sim->state(), before)); });
    const Feeder<double>& f = run.feeders[0];
    const auto st = run.sim->state();
    const auto& type = run.shape.table.type[0];
    double worst_mass = 0, worst_inertia = 0, smallest = 1, largest = 0;
    for (std::size_t i = 0; i < st.size(); ++i) {
      const double k = st.radius[i] / type.bounding_radius;
      smallest = std::min(smallest, st.radius[i]), largest = std::max(largest, st.radius[i]);
      worst_mass = std::max(worst_mass, std::fabs(st.mass[i] / (type.mass * k * k * k) - 1));
      worst_inertia = std::max(worst_inertia, std::fabs(st.inertia[i].x * type.inv_inertia.x / std::pow(k, 5) - 1));
    }
    const std::string name = std::string("Feeding: cubes, ") + c.name;
    BOOST_TEST(f.inserted() > 100);
    BOOST_TEST(f.shortfall() == 0);
    BOOST_TEST(smallest >= f.spec().size.smallest() * (1 - 1e-12));
    BOOST_TEST(largest <= f.spec().size.largest() * (1 + 1e-12));
    BOOST_TEST(largest > 1.2 * smallest);
    check_at_most({name, "|m / (m_type s^3) - 1| and |I / (I_type s^5) - 1| of every cube", "-", "a scaled cube (rounding)"},
                  std::max(worst_mass, worst_inertia), tol::scaled_mass_properties);
    check_at_least({name, "smallest bounding-sphere gap at insertion (m)", "-", "no overlap at insertion"}, worst_gap, 0);
    check_at_most({name, "Kolmogorov-Smirnov distance of the delivered bounding radii", "-", "99% quantile 1.63/sqrt(n_eff)"},
                  f.ks_distance(), ks_limit(f.delivered(), c.by_mass));
    if (c.by_mass)  // within one largest particle's mass of the due mass
      BOOST_TEST(std::fabs(f.inserted_mass() - 0.3 * 0.1) < type.mass * std::pow(f.spec().size.largest() / type.bounding_radius, 3));
  }
  // a sphere type in a polyhedron scene: the table's sphere, scaled
  const std::string both = "name = \"bead\"\nmaterial = \"glass\"\nradius = 3e-3\n[[particle_type]]\n" + cube;
  const Scene mixed = parse_scene(feed_scene(std::string("type = \"bead\"\nrate = 1000\nend_time = 0.05\n") + kBoxRegion +
                                                 "size = { kind = \"uniform\", min = 2e-3, max = 4e-3 }",
                                             "", "", both),
                                  "mixed.toml");
  Run run(mixed);
  run.run(static_cast<std::uint64_t>(std::llround(0.06 / mixed.dt)));
  const auto st = run.sim->state();
  BOOST_TEST_REQUIRE(st.size() > 20u);
  double worst = 0;
  for (std::size_t i = 0; i < st.size(); ++i) {
    const double r = st.radius[i], m = 2500 * 4.0 / 3.0 * M_PI * r * r * r;
    worst = std::max({worst, std::fabs(st.mass[i] / m - 1), std::fabs(st.inertia[i].y / (0.4 * m * r * r) - 1)});
  }
  check_at_most({"Feeding: spheres of a polyhedron scene, uniform 2-4 mm", "|m / (rho 4/3 pi r^3) - 1|, |I / (2/5 m r^2) - 1|", "-",
                 "a scaled sphere type (rounding)"},
                worst, tol::scaled_mass_properties);
}

BOOST_AUTO_TEST_CASE(a_full_region_reports_its_shortfall) {
  using Run = FeedRun<SphereShape, LinearLaw<double>>;
  // a slab one particle high, at 20000/s: each insertion owes more than the slab holds
  const Scene s = parse_scene(feed_scene("type = \"bead\"\nrate = 20000\nend_time = 0.05\n"
                                         "region = { kind = \"box\", lo = [-0.012, 0.15, -0.012], hi = [0.012, 0.156, 0.012] }"),
                              "full.toml");
  Run run(s);
  long short_seen = 0;
  double worst_gap = 1e300;
  run.run(static_cast<std::uint64_t>(std::llround(0.06 / s.dt)), [&](const Feeder<double>& f, Index before) {
    short_seen = std::max(short_seen, f.shortfall());
    worst_gap = std::min(worst_gap, closest_gap(run.sim->state(), before));
  });
  const Feeder<double>& f = run.feeders[0];
  BOOST_TEST(short_seen > 0);
  BOOST_TEST(f.short_insertions() > 0);
  BOOST_TEST(f.undelivered() == 1000 - f.inserted());  // 20000/s over 0.05 s, all accounted for
  BOOST_TEST(f.undelivered() > 0);
  BOOST_TEST(worst_gap >= 0);
}

template <class T>
bool same_bits(const std::vector<T>& a, const std::vector<T>& b) {
  return a.size() == b.size() && (a.empty() || std::memcmp(a.data(), b.data(), a.size() * sizeof(T)) == 0);
}

BOOST_AUTO_TEST_CASE(a_feed_restarts_bitwise) {
  using Run = FeedRun<SphereShape, LinearSpringLaw<double>>;
  const Scene s = parse_scene(feed_scene(std::string("type = \"bead\"\nrate = 2000\nend_time = 0.2\nvelocity_spread = 0.1\n") + kBoxRegion +
                                             "size = { kind = \"rosin_rammler\", r63 = 2.5e-3, k = 3, min = 1.5e-3, max = 3e-3 }",
                                         "tangential = \"linear_spring\""),
                              "restart.toml");
  const std::string path = temp("blaze_feed_restart.blz");
  Run a(s);
  const auto before = static_cast<std::uint64_t>(std::llround(0.1 / s.dt)), end = static_cast<std::uint64_t>(std::llround(0.15 / s.dt));
  a.run(before);
  write_checkpoint(path, a.sim->snapshot(), "feed", a.feeders[0].save());
  a.run(end);
  const auto c = read_checkpoint<double>(path);
  Run b(s);
  b.sim = std::make_unique<Run::Sim>(simulation_params<double>(s, false), build_laws<LinearSpringLaw<double>>(s), build_world<double>(s),
                                     c.snapshot, b.shape);
  b.feeders[0].restore(c.feeders);
  b.run(end);
  const auto sa = a.sim->state(), sb = b.sim->state();
  BOOST_TEST(a.feeders[0].inserted() > b.sim->state().size() / 2);
  BOOST_TEST(a.feeders[0].inserted() == b.feeders[0].inserted());
  BOOST_TEST(same_bits(a.feeders[0].delivered(), b.feeders[0].delivered()));
  BOOST_TEST(same_bits(sa.id, sb.id));
  BOOST_TEST(same_bits(sa.radius, sb.radius));
  BOOST_TEST(same_bits(sa.position, sb.position));
  BOOST_TEST(same_bits(sa.velocity, sb.velocity));
  BOOST_TEST(a.sim->inserted_energy() == b.sim->inserted_energy());
  std::filesystem::remove(path);
}

// Placement runs on all host threads on the CPU (feeder.hpp: every candidate draws from its own counter-based
// stream, conflicts go to the earlier candidate): one thread and three give the same particles,
// bit for bit, in a region crowded enough that candidates of one round meet.
BOOST_AUTO_TEST_CASE(placement_does_not_depend_on_the_thread_count) {
  using Run = FeedRun<SphereShape, LinearLaw<double>>;
  const Scene s = parse_scene(feed_scene("type = \"bead\"\nrate = 6000\nend_time = 0.04\nvelocity_spread = 0.2\n"
                                         "region = { kind = \"box\", lo = [-0.02, 0.15, -0.02], hi = [0.02, 0.16, 0.02] }\n"
                                         "size = { kind = \"uniform\", min = 1.5e-3, max = 3e-3 }"),
                              "threads.toml");
  const int threads = omp_get_max_threads();
  std::vector<std::unique_ptr<Run>> runs;
  for (const int n : {1, 3}) {
    omp_set_num_threads(n);
    runs.push_back(std::make_unique<Run>(s));
    runs.back()->feeders[0].parallel_from(0);  // every round on the team, however small
    runs.back()->run(static_cast<std::uint64_t>(std::llround(0.045 / s.dt)));
  }
  omp_set_num_threads(threads);
  const auto a = runs[0]->sim->state(), b = runs[1]->sim->state();
  BOOST_TEST(runs[0]->feeders[0].inserted() > 100);
  BOOST_TEST(runs[0]->feeders[0].short_insertions() > 0);  // crowded: some insertions fell short
  BOOST_TEST(runs[0]->feeders[0].inserted() == runs[1]->feeders[0].inserted());
  BOOST_TEST(same_bits(a.radius, b.radius));
  BOOST_TEST(same_bits(a.position, b.position));
  BOOST_TEST(same_bits(a.velocity, b.velocity));
}

// The rounds' cells (kernels/placement.hpp: spheres linked into hashed cells where the particles
// live, 27 cells a query) find an overlap exactly when a search of every sphere below `before`
// does: 1500 spheres of three sizes put from many threads, a third of them outside the box the
// cells start from (negative cell numbers), queried by 3000 spheres of every size up to the
// largest, with and without a slack, seeing all or the first half; with a table of 64 heads
// (long shared chains) and of 4096.
struct QueryCells {
  SphereCellsView cells;
  const double* query;  // x, y, z, r, slack a query
  const int* before;
  std::uint8_t* hit;
  BLAZE_HD void operator()(Index q) const {
    const double* v = query + 5 * q;
    hit[q] = cells.overlapping({v[0], v[1], v[2]}, v[3], v[4], before[q]) ? 1 : 0;
  }
};
BOOST_AUTO_TEST_CASE(hashed_cells_find_what_a_search_of_every_sphere_finds) {
  using Space = DefaultSpace;
  using V = Vec3<double>;
  const double r_max = 0.05;
  std::mt19937_64 rng(11);
  std::uniform_real_distribution<double> u(-0.3, 1.3), size(0.2, 1.0);
  const int n = 1500, queries = 3000;
  std::vector<double> centre(3 * n), radius(n);
  for (int k = 0; k < n; ++k) centre[3 * k] = u(rng), centre[3 * k + 1] = u(rng), centre[3 * k + 2] = u(rng), radius[k] = r_max * size(rng);
  std::vector<double> query(5 * queries);
  std::vector<int> before(queries);
  for (int q = 0; q < queries; ++q) {
    const double r = r_max * size(rng);
    query[5 * q] = u(rng), query[5 * q + 1] = u(rng), query[5 * q + 2] = u(rng), query[5 * q + 3] = r, query[5 * q + 4] = q % 3 == 0 ? 0.2 * r : 0.0;
    before[q] = q % 2 == 0 ? 0x7fffffff : n / 2;
  }
  for (const std::uint32_t heads : {64u, 4096u}) {
    Buffer<int, Space> head(heads), next(n), before_d(queries);
    Buffer<double, Space> sphere(4 * n), centre_d(3 * n), radius_d(n), query_d(5 * queries);
    Buffer<std::uint8_t, Space> hit(queries), all(n);
    from_host(centre_d, centre), from_host(radius_d, radius);
    for_each(Space{}, n, Fill<std::uint8_t>{all.data(), 1});
    from_host(query_d, query), from_host(before_d, before);
    for_each(Space{}, static_cast<Index>(heads), Fill<int>{head.data(), -1});
    const SphereCellsView cells{V{0, 0, 0}, 1 / (2 * r_max), r_max, heads - 1, head.data(), next.data(), sphere.data()};
    for_each(Space{}, n, PutCandidates{cells, radius_d.data(), centre_d.data(), all.data()});
    for_each(Space{}, queries, QueryCells{cells, query_d.data(), before_d.data(), hit.data()});
    const std::vector<std::uint8_t> got = to_host(hit, queries);
    long found = 0, wrong = 0;
    for (int q = 0; q < queries; ++q) {
      const V x{query[5 * q], query[5 * q + 1], query[5 * q + 2]};
      bool expected = false;
      for (int j = 0; j < n && j < before[q] && !expected; ++j)
        expected = norm(x - V{centre[3 * j], centre[3 * j + 1], centre[3 * j + 2]}) < query[5 * q + 3] + radius[j] - query[5 * q + 4];
      wrong += (got[q] != 0) != expected;
      found += expected;
    }
    BOOST_TEST(wrong == 0, heads << " heads: " << wrong << " of " << queries << " queries answered unlike the search");
    BOOST_TEST(found > queries / 20);  // the queries met spheres often, inside the box and out
  }
}

// The world's test of a draw (blaze/scene/world_block.hpp) answers where the particles live as
// WorldOverlapCheck does on the host: walls with and without rims (one a [mill]'s), a drum and a
// mesh of 200 triangles (a bumpy floor), for 20 000 spheres of two sizes all over them.
struct BlockedAt {
  WorldBlockView world;
  const double* sphere;  // x, y, z, r
  std::uint8_t* out;
  BLAZE_HD void operator()(Index k) const {
    const double* v = sphere + 4 * k;
    out[k] = world.blocked({v[0], v[1], v[2]}, v[3]) ? 1 : 0;
  }
};
BOOST_AUTO_TEST_CASE(the_world_test_answers_alike_where_the_particles_live) {
  using V = Vec3<double>;
  Scene s;
  s.path = "world.toml";
  ParticleTypeSpec bead;
  bead.name = "bead", bead.radius = 0.01;
  s.types.push_back(bead);
  WallSpec side, rimless, mill;
  side.vertices = {{0.3, -0.2, -0.2}, {0.3, 0.2, -0.2}, {0.3, 0.2, 0.2}, {0.3, -0.2, 0.2}};
  rimless.vertices = {{-0.2, -0.2, -0.3}, {0.2, -0.2, -0.3}, {0.2, 0.2, -0.3}, {-0.2, 0.2, -0.3}}, rimless.rim_edges = 0;
  mill.name = "mill lifter", mill.vertices = {{-0.3, 0.25, -0.1}, {-0.3, 0.25, 0.1}, {-0.1, 0.25, 0.1}, {-0.1, 0.25, -0.1}};
  s.walls = {side, rimless, mill};
  CylinderSpec drum;
  drum.origin = {0, 0, -0.35}, drum.axis = {0, 0, 1}, drum.radius = 0.4, drum.length = 0.7;
  s.cylinders = {drum};
  MeshSpec floor;
  floor.name = "floor";
  const int cells = 10;
  for (int i = 0; i <= cells; ++i)
    for (int k = 0; k <= cells; ++k)
      floor.mesh.vertices.push_back({-0.25 + 0.05 * i, -0.15 + 0.01 * ((i * 7 + k * 3) % 5), -0.25 + 0.05 * k});
  for (int i = 0; i < cells; ++i)
    for (int k = 0; k < cells; ++k) {
      const int a = i * (cells + 1) + k, b = a + cells + 1;
      floor.mesh.triangles.push_back({a, a + 1, b}), floor.mesh.triangles.push_back({a + 1, b + 1, b});
    }
  floor.mesh.file_index.resize(floor.mesh.triangles.size());
  s.meshes = {floor};
  const WorldOverlapCheck check(s, 1e-9 * 0.01);
  const WorldBlockArrays<DefaultSpace> arrays(check);
  std::mt19937_64 rng(3);
  std::uniform_real_distribution<double> u(-0.45, 0.45);
  const int n = 20000;
  std::vector<double> sphere(4 * n);
  for (int k = 0; k < n; ++k) sphere[4 * k] = u(rng), sphere[4 * k + 1] = u(rng), sphere[4 * k + 2] = u(rng), sphere[4 * k + 3] = k % 2 ? 0.01 : 0.004;
  Buffer<double, DefaultSpace> sphere_d(sphere.size());
  Buffer<std::uint8_t, DefaultSpace> out(n);
  from_host(sphere_d, sphere);
  for_each(DefaultSpace{}, n, BlockedAt{arrays.view(), sphere_d.data(), out.data()});
  const std::vector<std::uint8_t> got = to_host(out, n);
  const std::vector<V> no_vertices;
  long blocked = 0, wrong = 0;
  for (int k = 0; k < n; ++k) {
    const bool expected = check.blocked({sphere[4 * k], sphere[4 * k + 1], sphere[4 * k + 2]}, sphere[4 * k + 3], no_vertices);
    wrong += (got[k] != 0) != expected;
    blocked += expected;
  }
  BOOST_TEST(wrong == 0, wrong << " of " << n << " spheres answered unlike the host");
  BOOST_TEST(blocked > n / 10);  // every kind of object refused some, and some were let through
  BOOST_TEST(blocked < n - n / 10);
}

// The contact store through an insertion: a bed fed for 0.1 s, at 0.3 s (linear springs on every contact,
// pairs and walls), then one more particle inserted far from it. The stored states, keyed by
// particle ids (and the wall contact's key), are the same before and after, bit for bit: the
// insertion re-sorts the store, and every spring follows its contact.
std::map<std::vector<long>, std::vector<double>> stored_states(const ContactSnapshot<double>& c) {
  std::map<std::vector<long>, std::vector<double>> out;
  const std::size_t per = static_cast<std::size_t>(c.used);
  for (std::size_t k = 0; k < c.pair_ids.size() / 2; ++k)
    out[{0, c.pair_ids[2 * k], c.pair_ids[2 * k + 1]}] = {c.pair_values.begin() + k * per, c.pair_values.begin() + (k + 1) * per};
  for (std::size_t k = 0; k < c.wall_ids.size(); ++k)
    out[{1, c.wall_ids[k], c.wall_objects[k]}] = {c.wall_values.begin() + k * per, c.wall_values.begin() + (k + 1) * per};
  return out;
}

BOOST_AUTO_TEST_CASE(insertion_keeps_contact_history) {
  using Run = FeedRun<SphereShape, LinearSpringLaw<double>>;
  for (const char* pairs : {"both_sides", "once"}) {
    const Scene s = parse_scene(feed_scene(std::string("type = \"bead\"\nrate = 3000\nend_time = 0.1\n") + kBoxRegion,
                                           std::string("tangential = \"linear_spring\"\npair_evaluation = \"") + pairs + "\""),
                                "history.toml");
    Run run(s);
    run.run(static_cast<std::uint64_t>(std::llround(0.3 / s.dt)));  // landed and settling
    const auto before = stored_states(run.sim->snapshot().contacts);
    ParticleState<double> far;
    far.add_sphere({0.03, 0.22, 0.03}, 2e-3, 2500, 0);
    run.sim->insert(far);
    const auto after = stored_states(run.sim->snapshot().contacts);
    long walls = 0, pair_states = 0;
    for (const auto& [key, v] : before) (key[0] ? walls : pair_states) += 1;
    BOOST_TEST_CONTEXT(pairs) {
      BOOST_TEST(walls > 20);  // the bed holds springs on the floor and between the beads
      BOOST_TEST(pair_states > 100);
      BOOST_TEST((before == after));
      BOOST_TEST(run.sim->size() == 301u);
    }
  }
}

BOOST_AUTO_TEST_CASE(energy_is_balanced_through_insertion) {
  using Run = FeedRun<SphereShape, LinearLaw<double>>;
  // elastic, frictionless: E(t) = E_inserted up to Verlet's wobble during contacts
  const Scene s = parse_scene(feed_scene(std::string("type = \"bead\"\nrate = 2000\nend_time = 0.15\nvelocity = [0.2, -0.5, 0.1]\n") +
                                             kBoxRegion),
                              "elastic.toml");
  Scene elastic = s;
  for (auto& p : elastic.pairs) p.restitution = 1, p.friction = 0, p.tangential_damping = 0, p.tangential_rate = 0;
  Run run(elastic);
  double worst = 0;
  for (double t = 0.05; t <= 0.2001; t += 0.05) {
    run.run(static_cast<std::uint64_t>(std::llround(t / s.dt)));
    const auto smp = run.sim->sample(1);
    const double e = smp.energies.total() + smp.stored.total();
    worst = std::max(worst, std::fabs(e - run.sim->inserted_energy()) / run.sim->inserted_kinetic());
  }
  BOOST_TEST(run.sim->inserted_count() == 300);
  check_at_most({"Feeding: energy balance", "|E(t) - E_inserted| / inserted kinetic energy, elastic frictionless spheres", "-",
                 "energy conservation"},
                worst, tol::feed_energy_balance);
}

// A dense fill by pouring: 3000 beads fed in 0.15 s settle in the box; the solid fraction in its
// bulk (a box 1.7 diameters from the side walls, 2 from the floor, below the bed's top) reaches
// random loose packing (the issue's 0.55; frictional spheres settle at 0.55-0.60: Onoda & Liniger
// 1990, Scott 1960), where a [[fill]] stops at 0.3.
BOOST_AUTO_TEST_CASE(a_pour_settles_to_random_loose_packing) {
  using Run = FeedRun<SphereShape, LinearLaw<double>>;
  const Scene s = parse_scene(feed_scene("type = \"bead\"\nrate = 20000\ncount = 3000\nvelocity = [0, -0.3, 0]\n"
                                         "region = { kind = \"box\", lo = [-0.037, 0.12, -0.037], hi = [0.037, 0.19, 0.037] }"),
                              "pour.toml");
  Run run(s);
  run.run(static_cast<std::uint64_t>(std::llround(0.45 / s.dt)));
  const auto st = run.sim->state();
  double top = 0, solid = 0;
  for (std::size_t k = 0; k < st.size(); ++k) top = std::max(top, static_cast<double>(st.position[k].y));
  const double lo_y = 0.012, hi_y = top - 0.015, half = 0.03;  // m
  for (std::size_t k = 0; k < st.size(); ++k) {
    const auto& x = st.position[k];
    if (std::fabs(x.x) < half && std::fabs(x.z) < half && x.y > lo_y && x.y < hi_y)
      solid += 4.0 / 3.0 * M_PI * std::pow(static_cast<double>(st.radius[k]), 3);  // centres in the box: unbiased
  }
  BOOST_TEST(run.feeders[0].inserted() == 3000);
  BOOST_TEST(hi_y - lo_y > 0.03);  // a bulk many diameters deep
  check_at_least({"Feeding: poured fill", "solid fraction in the bulk of 3000 settled beads (mu = 0.3)", "0.3 (random fill)",
                  "random loose packing 0.55-0.60 (Onoda & Liniger 1990)"},
                 solid / (4 * half * half * (hi_y - lo_y)), tol::feed_poured_fraction);
}

template <class F>
std::string rejection(F f) {
  try {
    f();
  } catch (const SceneError& e) {
    return e.what();
  }
  return "(accepted)";
}

BOOST_AUTO_TEST_CASE(bad_feeds_are_refused_by_name) {
  const auto refused = [&](const std::string& feed, std::initializer_list<const char*> parts) {
    const std::string msg = rejection([&] { parse_scene(feed_scene(feed), "bad.toml"); });
    for (const char* p : parts) BOOST_TEST(msg.find(p) != std::string::npos, "message '" << msg << "' lacks '" << p << "'");
  };
  const std::string region = kBoxRegion;
  refused("type = \"bead\"\n" + region, {"bad.toml:", "[[feed]] #1", "missing key 'rate' (or mass_rate"});
  refused("type = \"bead\"\nrate = 10\nmass_rate = 1\n" + region, {"[[feed]] #1", "key 'mass_rate' = 1", "not both"});
  refused("type = \"bead\"\nrate = -1\n" + region, {"[[feed]] #1", "key 'rate'"});
  refused("type = \"grain\"\nrate = 10\n" + region, {"[[feed]] #1", "key 'type'"});
  refused("type = \"bead\"\nrate = 10", {"[[feed]] #1", "missing key 'region'"});
  refused("type = \"bead\"\nrate = 10\nregion = { kind = \"box\", lo = [-0.1, 0, 0], hi = [0.01, 0.1, 0.1] }", {"key 'region'", "inside the domain"});
  refused("type = \"bead\"\nrate = 10\nregion = { kind = \"sphere\", radius = 0.01 }", {"region", "key 'kind'", "\"box\""});
  refused("type = \"bead\"\nrate = 10\nregion = { kind = \"box\", lo = [0, 0.1, 0], hi = [0.001, 0.11, 0.01] }", {"key 'hi'", "diameter"});
  refused("type = \"bead\"\nrate = 10\nregion = { kind = \"disc\", centre = [0, 0.1, 0], axis = [0, 1, 0], radius = 0.01 }",
          {"key 'axis'", "not a key of kind = \"disc\""});
  refused("type = \"bead\"\nrate = 10\n" + region + "size = { kind = \"classes\", radii = [1e-3, 2e-3], fractions = [0.5, 0.6] }",
          {"key 'size'", "sum to 1"});
  refused("type = \"bead\"\nrate = 10\n" + region + "size = { kind = \"normal\", mean = 2e-3, deviation = 1e-4, min = 3e-3, max = 2e-3 }",
          {"key 'size'", "min < max"});
  refused("type = \"bead\"\nrate = 10\n" + region + "size = { kind = \"normal\", mean = 1e-3, deviation = 1e-5, min = 2e-3, max = 3e-3 }",
          {"key 'size'", "1e-6"});
  refused("type = \"bead\"\nrate = 10\n" + region + "size = { kind = \"uniform\", min = 1e-3, max = 3e-3, mean = 2e-3 }",
          {"key 'mean'", "not a key"});
  refused("type = \"bead\"\nrate = 10\nspeed = 3\n" + region, {"[[feed]] #1", "unknown key 'speed'"});
  refused("type = \"bead\"\nrate = 10\nend_time = 0\n" + region, {"key 'end_time'", "after start_time"});
  // a study that places its own particles refuses a scene with feeds rather than run without them
  const std::string msg = rejection([&] { refuse_feeds(parse_scene(feed_scene("type = \"bead\"\nrate = 10\n" + region), "s.toml"), "the x study"); });
  BOOST_TEST(msg.find("s.toml:") != std::string::npos);
  BOOST_TEST(msg.find("[[feed]] #1") != std::string::npos);
  BOOST_TEST(msg.find("the x study does not run") != std::string::npos);
}

BOOST_AUTO_TEST_CASE(a_distribution_sizes_the_run) {
  // the derived types: the critical step and the grid see the smallest and the largest bead
  const std::string feed = std::string("type = \"bead\"\nrate = 100\n") + kBoxRegion +
                           "size = { kind = \"uniform\", min = 0.5e-3, max = 4e-3 }";
  const Scene s = parse_scene(feed_scene(feed, "force_dt = true"), "sizes.toml");
  const Scene plain = parse_scene(feed_scene(std::string("type = \"bead\"\nrate = 100\n") + kBoxRegion, "force_dt = true"), "plain.toml");
  BOOST_TEST(s.types.size() == 3u);
  BOOST_TEST(simulation_params<double>(s).max_radius == 4e-3);
  // the lightest pair (0.5 mm beads, 512 x lighter) sets a shorter critical step
  BOOST_TEST(s.dt_critical < 0.1 * plain.dt_critical);
}

BOOST_AUTO_TEST_SUITE_END()

}  // namespace
