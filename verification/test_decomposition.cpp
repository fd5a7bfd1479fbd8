// The domain's decomposition among ranks (issue 21; blaze/parallel/decomposition.hpp), checked
// without MPI: it is the same computation on every rank.
// - Tiling: for 1-9 ranks, slabs and bisection, uniform and clustered particles, periodic axes
//   none, x, and x and y: every probe point of the domain lies in exactly one box and owner()
//   names it; periodic axes are never cut; the boxes' volumes add up to the domain's.
// - Balance: cut on every particle, the ranks' counts differ by at most one (no ties); cut on a
//   1-in-16 sample weighted 16, the full set's imbalance stays within 10%.
// - Ghosts: every pair of particles closer than the reach has both on one rank, or the one's
//   owner among the other's near() ranks; a point by the corner of four boxes goes to the other
//   three, one by a face to one.
// - Bad input: no ranks, a domain periodic along all three axes divided, weights that do not
//   match the points.
#include <boost/test/unit_test.hpp>
#include <cmath>
#include <random>
#include <set>
#include "blaze/parallel/decomposition.hpp"
#include "verification/report.hpp"
#include "verification/tolerances.hpp"

using namespace blaze;
using namespace blaze::test;

namespace {

const char* const kCase = "Domain decomposition (issue 21)";

const Vec3<double> kLo{-0.5, 0, -0.2}, kHi{1.5, 0.6, 0.3};  // longest along x, then y

std::vector<Vec3<double>> particles(std::size_t n, bool clustered, unsigned seed) {
  std::mt19937_64 rng(seed);
  std::uniform_real_distribution<double> u(0, 1);
  std::normal_distribution<double> g(0, 0.08);
  std::vector<Vec3<double>> p(n);
  for (auto& x : p) {
    if (clustered && u(rng) < 0.7) {  // most in a heap at the low end, as a settled bed
      x = {std::clamp(-0.3 + g(rng), kLo.x, kHi.x - 1e-9), std::clamp(0.1 + std::fabs(g(rng)), kLo.y, kHi.y - 1e-9),
           std::clamp(g(rng), kLo.z, kHi.z - 1e-9)};
    } else {
      x = {kLo.x + (kHi.x - kLo.x) * u(rng), kLo.y + (kHi.y - kLo.y) * u(rng), kLo.z + (kHi.z - kLo.z) * u(rng)};
    }
  }
  return p;
}

bool inside(const Vec3<double>& x, const RankBox& b) {
  return x.x >= b.lo.x && x.x < b.hi.x && x.y >= b.lo.y && x.y < b.hi.y && x.z >= b.lo.z && x.z < b.hi.z;
}

}  // namespace

BOOST_AUTO_TEST_SUITE(decomposition)

BOOST_AUTO_TEST_CASE(boxes_tile_the_domain_and_balance_the_particles) {
  std::mt19937_64 rng(3);
  std::uniform_real_distribution<double> u(0, 1);
  long probes = 0, wrong_owner = 0, not_once = 0, cut_periodic = 0, unbalanced = 0;
  double worst_volume = 0;
  for (DecompositionKind kind : {DecompositionKind::slabs, DecompositionKind::bisection})
    for (unsigned periodic : {0u, 1u, 3u})
      for (bool clustered : {false, true})
        for (int ranks = 1; ranks <= 9; ++ranks) {
          const auto pts = particles(3000, clustered, 7 + static_cast<unsigned>(ranks));
          const Decomposition d = Decomposition::make(kind, kLo, kHi, ranks, periodic, pts);
          BOOST_TEST_REQUIRE(d.ranks() == ranks);
          double volume = 0;
          for (int r = 0; r < ranks; ++r) {
            const RankBox& b = d.box(r);
            volume += (b.hi.x - b.lo.x) * (b.hi.y - b.lo.y) * (b.hi.z - b.lo.z);
            if ((periodic & 1u) && (b.lo.x != kLo.x || b.hi.x != kHi.x)) ++cut_periodic;
            if ((periodic & 2u) && (b.lo.y != kLo.y || b.hi.y != kHi.y)) ++cut_periodic;
          }
          worst_volume = std::fmax(worst_volume, std::fabs(volume / ((kHi.x - kLo.x) * (kHi.y - kLo.y) * (kHi.z - kLo.z)) - 1));
          for (int k = 0; k < 2000; ++k, ++probes) {
            const Vec3<double> x{kLo.x + (kHi.x - kLo.x) * u(rng), kLo.y + (kHi.y - kLo.y) * u(rng), kLo.z + (kHi.z - kLo.z) * u(rng)};
            int holders = 0, holder = -1;
            for (int r = 0; r < ranks; ++r)
              if (inside(x, d.box(r))) ++holders, holder = r;
            not_once += holders != 1;
            wrong_owner += d.owner(x) != holder;
          }
          std::vector<long> count(static_cast<std::size_t>(ranks), 0);
          for (const auto& x : pts) ++count[static_cast<std::size_t>(d.owner(x))];
          unbalanced += *std::max_element(count.begin(), count.end()) - *std::min_element(count.begin(), count.end()) > 1;
        }
  BOOST_TEST_MESSAGE("decomposition: " << probes << " probes, " << not_once << " not in exactly one box, " << wrong_owner
                                       << " owner() elsewhere; box volumes off by " << worst_volume << "; " << unbalanced
                                       << " unbalanced, " << cut_periodic << " periodic cuts");
  check_at_most({kCase, "probe points not in exactly one box, or owner() naming another (1-9 ranks, slabs and bisection)", "-",
                 "half-open boxes tile the domain"},
                static_cast<double>(not_once + wrong_owner), 0);
  check_at_most({kCase, "the boxes' volumes over the domain's, - 1", "-", "a tiling"}, worst_volume, tol::decomposition_volume);
  check_at_most({kCase, "decompositions whose ranks' counts differ by more than one particle (cut on every particle)", "-",
                 "cuts at the count quantiles"},
                static_cast<double>(unbalanced), 0);
  BOOST_TEST(cut_periodic == 0);
}

BOOST_AUTO_TEST_CASE(a_weighted_sample_balances_the_whole_set) {
  double worst = 1;
  for (DecompositionKind kind : {DecompositionKind::slabs, DecompositionKind::bisection})
    for (int ranks : {2, 3, 4, 8}) {
      const auto all = particles(64000, true, 21);
      std::vector<Vec3<double>> sample;
      for (std::size_t k = 0; k < all.size(); k += 16) sample.push_back(all[k]);
      const Decomposition d = Decomposition::make(kind, kLo, kHi, ranks, 0, sample, std::vector<double>(sample.size(), 16.0));
      std::vector<long> count(static_cast<std::size_t>(ranks), 0);
      for (const auto& x : all) ++count[static_cast<std::size_t>(d.owner(x))];
      worst = std::fmax(worst, Decomposition::imbalance(count));
    }
  check_at_most({kCase, "imbalance (most / mean) of 64 000 clustered particles cut on a 1-in-16 sample", "-", "sampled quantiles"},
                worst - 1, tol::decomposition_sampled_imbalance);
  BOOST_TEST(Decomposition::imbalance({10, 10, 10}) == 1.0);
  BOOST_TEST(Decomposition::imbalance({30, 0, 0}) == 3.0);
}

BOOST_AUTO_TEST_CASE(every_close_pair_meets_on_one_rank) {
  const double reach = 0.06;
  long pairs = 0, unmet = 0;
  for (DecompositionKind kind : {DecompositionKind::slabs, DecompositionKind::bisection})
    for (int ranks : {2, 4, 5, 8}) {
      const auto pts = particles(2500, true, 5 + static_cast<unsigned>(ranks));
      const Decomposition d = Decomposition::make(kind, kLo, kHi, ranks, 0, pts);
      std::vector<std::set<int>> ghosts_of(pts.size());
      for (std::size_t i = 0; i < pts.size(); ++i) d.near(pts[i], reach, d.owner(pts[i]), [&](int r) { ghosts_of[i].insert(r); });
      for (std::size_t i = 0; i < pts.size(); ++i)
        for (std::size_t j = i + 1; j < pts.size(); ++j) {
          if (norm2(pts[i] - pts[j]) > reach * reach) continue;
          ++pairs;
          const int oi = d.owner(pts[i]), oj = d.owner(pts[j]);
          // i's rank must see j (j's ghost there), and j's rank must see i
          unmet += oi != oj && (!ghosts_of[j].count(oi) || !ghosts_of[i].count(oj));
        }
    }
  BOOST_TEST_MESSAGE("decomposition: " << pairs << " close pairs, " << unmet << " with a particle missing from the other's rank");
  BOOST_TEST_REQUIRE(pairs > 10000);
  check_at_most({kCase, "close pairs whose particles do not meet on a rank (ghosts within the reach)", "-", "near() by box distance"},
                static_cast<double>(unmet), 0);

  // four boxes meeting at one edge (bisection of a square slab, periodic along z)
  const Decomposition d = Decomposition::make(DecompositionKind::bisection, {0, 0, 0}, {1, 1, 0.1}, 4, 4u, {});
  const Vec3<double> corner{0.5 - 0.01, 0.5 + 0.01, 0.05}, face{0.5 - 0.01, 0.25, 0.05};
  std::vector<int> at_corner, at_face;
  d.near(corner, reach, d.owner(corner), [&](int r) { at_corner.push_back(r); });
  d.near(face, reach, d.owner(face), [&](int r) { at_face.push_back(r); });
  BOOST_TEST(at_corner.size() == 3u);
  BOOST_TEST(at_face.size() == 1u);
}

BOOST_AUTO_TEST_CASE(bad_decompositions_are_refused) {
  BOOST_CHECK_THROW(Decomposition::make(DecompositionKind::bisection, kLo, kHi, 0, 0, {}), std::invalid_argument);
  BOOST_CHECK_THROW(Decomposition::make(DecompositionKind::slabs, kLo, kHi, 2, 7u, {}), std::invalid_argument);
  BOOST_CHECK_NO_THROW(Decomposition::make(DecompositionKind::slabs, kLo, kHi, 1, 7u, {}));
  BOOST_CHECK_THROW(Decomposition::make(DecompositionKind::slabs, kLo, kHi, 2, 0, {{0, 0, 0}}, {1.0, 2.0}), std::invalid_argument);
  BOOST_CHECK_THROW(Decomposition::make(DecompositionKind::slabs, kHi, kLo, 2, 0, {}), std::invalid_argument);
}

BOOST_AUTO_TEST_SUITE_END()
