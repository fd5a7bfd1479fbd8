// Spatial decomposition of the domain into one box per rank (issue 21: several GPUs, MPI ranks).
//   slabs      cuts along the domain's longest axis that is not periodic: rank r holds
//              [c_r, c_r+1) there and the whole domain across;
//   bisection  recursive coordinate bisection: a box shared by P ranks is cut across its longest
//              non-periodic axis into floor(P/2) and P - floor(P/2) ranks (any P, not only powers
//              of two), each half recursively.
// Cuts are placed by particle count: where the weighted particles (every particle, or a sample
// each weighted by the particles it stands for) divide in the ranks' ratio, midway between the
// two particles on either side; with no particles, in that ratio of the length. Periodic axes are
// never cut: a box spans the whole period there, so its own grid wraps as a one-rank run does
// (grid/periodic_images.hpp); a domain periodic along all three axes is not divided.
// Boxes tile the domain: half-open [lo, hi) on each cut, so a point of the domain lies in exactly
// one box (owner()); a point outside it (a particle about to be removed) goes to the box nearest.
// A particle's ghosts (halo copies) go to every other rank whose box lies within `reach` of it
// (near(): reach = the neighbour list's cutoff, 2 r_max + skin, so every pair the list may hold
// has both particles on the rank owning either): across faces, edges and corners alike, and past a
// neighbour box thinner than the reach.
// Load balance: imbalance() = the most particles a rank holds over the mean; a run rebalances
// (builds the decomposition anew from the particles as they are) when it passes a threshold.
#pragma once
#include <algorithm>
#include <cmath>
#include <numeric>
#include <stdexcept>
#include <string>
#include <vector>
#include "blaze/core/vec3.hpp"

namespace blaze {

enum class DecompositionKind { slabs, bisection };

struct RankBox {
  Vec3<double> lo, hi;  // m, [lo, hi) along cut axes; the domain's extent along the others
};

class Decomposition {
 public:
  // The decomposition of [lo, hi) among `ranks` ranks, balanced on the points (m) with their
  // weights (particles each stands for; empty: 1 each). periodic: bit a set for a periodic axis a.
  static Decomposition make(DecompositionKind kind, const Vec3<double>& lo, const Vec3<double>& hi, int ranks, unsigned periodic,
                            const std::vector<Vec3<double>>& points, const std::vector<double>& weights = {}) {
    if (ranks < 1) throw std::invalid_argument("decomposition: at least 1 rank, got " + std::to_string(ranks));
    if (!(hi.x > lo.x && hi.y > lo.y && hi.z > lo.z)) throw std::invalid_argument("decomposition: the domain is empty");
    if (!weights.empty() && weights.size() != points.size())
      throw std::invalid_argument("decomposition: " + std::to_string(weights.size()) + " weights for " + std::to_string(points.size()) + " points");
    if (ranks > 1 && (periodic & 7u) == 7u)
      throw std::invalid_argument("decomposition: a domain periodic along x, y and z cannot be divided among " + std::to_string(ranks) +
                                  " ranks (cuts run across non-periodic axes only)");
    Decomposition d;
    d.lo_ = lo, d.hi_ = hi, d.periodic_ = periodic;
    std::vector<Weighted> w(points.size());
    for (std::size_t k = 0; k < points.size(); ++k) w[k] = {points[k], weights.empty() ? 1.0 : weights[k]};
    d.boxes_.resize(static_cast<std::size_t>(ranks));
    if (kind == DecompositionKind::slabs) {
      const int axis = d.longest_cut_axis(lo, hi);
      d.slabs(axis, lo, hi, 0, ranks, w.begin(), w.end());
    } else {
      d.bisect(lo, hi, 0, ranks, w.begin(), w.end());
    }
    return d;
  }

  int ranks() const { return static_cast<int>(boxes_.size()); }
  const RankBox& box(int rank) const { return boxes_.at(static_cast<std::size_t>(rank)); }
  const Vec3<double>& lo() const { return lo_; }
  const Vec3<double>& hi() const { return hi_; }

  // The rank whose box holds x (outside the domain: the box nearest).
  int owner(const Vec3<double>& x) const {
    int n = 0;
    while (nodes_[static_cast<std::size_t>(n)].rank < 0) {
      const Node& node = nodes_[static_cast<std::size_t>(n)];
      n = at(x, node.axis) < node.cut ? node.low : node.high;
    }
    return nodes_[static_cast<std::size_t>(n)].rank;
  }

  // f(rank) for every rank other than `self` whose box lies within `reach` (m) of x, in ascending
  // rank order.
  template <class F>
  void near(const Vec3<double>& x, double reach, int self, F&& f) const {
    for (int r = 0; r < ranks(); ++r)
      if (r != self && distance2(x, boxes_[static_cast<std::size_t>(r)]) <= reach * reach) f(r);
  }

  // The most particles a rank holds over the mean (1: perfectly balanced; no particles: 1).
  static double imbalance(const std::vector<long>& counts) {
    if (counts.empty()) return 1;
    const double total = std::accumulate(counts.begin(), counts.end(), 0.0);
    if (!(total > 0)) return 1;
    return static_cast<double>(*std::max_element(counts.begin(), counts.end())) / (total / static_cast<double>(counts.size()));
  }

  // Squared distance from x to the box (0 inside), m^2.
  static double distance2(const Vec3<double>& x, const RankBox& b) {
    double s = 0;
    for (int a = 0; a < 3; ++a) {
      const double d = std::fmax(std::fmax(at(b.lo, a) - at(x, a), 0.0), at(x, a) - at(b.hi, a));
      s += d * d;
    }
    return s;
  }

 private:
  struct Weighted {
    Vec3<double> x;
    double w;
  };
  struct Node {
    int axis = 0;
    double cut = 0;
    int low = -1, high = -1;  // children (nodes)
    int rank = -1;            // a leaf's rank
  };
  using It = std::vector<Weighted>::iterator;

  static double at(const Vec3<double>& v, int a) { return a == 0 ? v.x : a == 1 ? v.y : v.z; }
  static void set(Vec3<double>& v, int a, double value) { (a == 0 ? v.x : a == 1 ? v.y : v.z) = value; }

  // The longest axis of [lo, hi) that may be cut (not periodic).
  int longest_cut_axis(const Vec3<double>& lo, const Vec3<double>& hi) const {
    int best = -1;
    for (int a = 0; a < 3; ++a)
      if (!((periodic_ >> a) & 1u) && (best < 0 || at(hi, a) - at(lo, a) > at(hi, best) - at(lo, best))) best = a;
    return best;
  }

  // Where [lo, hi) along `axis` divides the points in [first, last) as low : high ranks; the points
  // are reordered, those below the cut first. Returns the cut (m) and the split point.
  double cut(int axis, const Vec3<double>& lo, const Vec3<double>& hi, int low, int high, It first, It last, It& split) const {
    const double a = at(lo, axis), b = at(hi, axis), share = static_cast<double>(low) / static_cast<double>(low + high);
    double total = 0;
    for (It p = first; p != last; ++p) total += p->w;
    double c = a + share * (b - a);
    if (total > 0) {
      std::sort(first, last, [&](const Weighted& u, const Weighted& v) { return at(u.x, axis) < at(v.x, axis); });
      // the first point past the low ranks' share: the cut lies midway between it and the one before
      const double want = share * total;
      double sum = 0;
      It p = first;
      while (p != last && sum + 0.5 * p->w <= want) sum += p->w, ++p;
      if (p == first) c = std::fmin(c, at(p->x, axis));
      else if (p == last) c = std::fmax(c, at((p - 1)->x, axis));
      else c = 0.5 * (at((p - 1)->x, axis) + at(p->x, axis));
      c = std::fmin(std::fmax(c, a), b);
    }
    split = std::partition(first, last, [&](const Weighted& u) { return at(u.x, axis) < c; });
    return c;
  }

  int leaf(int rank, const Vec3<double>& lo, const Vec3<double>& hi) {
    boxes_[static_cast<std::size_t>(rank)] = {lo, hi};
    Node n;
    n.rank = rank;
    nodes_.push_back(n);
    return static_cast<int>(nodes_.size()) - 1;
  }

  // Ranks [first_rank, first_rank + count) share [lo, hi); returns the subtree's node.
  int bisect(const Vec3<double>& lo, const Vec3<double>& hi, int first_rank, int count, It first, It last) {
    if (count == 1) return leaf(first_rank, lo, hi);
    const int axis = longest_cut_axis(lo, hi), low = count / 2, high = count - low;
    return divide(axis, lo, hi, first_rank, low, high, first, last, [&](const Vec3<double>& l, const Vec3<double>& h, int r, int c, It f, It e) {
      return bisect(l, h, r, c, f, e);
    });
  }
  // Slabs: the first rank's slab is cut off, the rest divided the same way.
  int slabs(int axis, const Vec3<double>& lo, const Vec3<double>& hi, int first_rank, int count, It first, It last) {
    if (count == 1) return leaf(first_rank, lo, hi);
    return divide(axis, lo, hi, first_rank, 1, count - 1, first, last, [&](const Vec3<double>& l, const Vec3<double>& h, int r, int c, It f, It e) {
      return slabs(axis, l, h, r, c, f, e);
    });
  }
  template <class Recurse>
  int divide(int axis, const Vec3<double>& lo, const Vec3<double>& hi, int first_rank, int low, int high, It first, It last, Recurse&& recurse) {
    It split = first;
    const double c = cut(axis, lo, hi, low, high, first, last, split);
    const int node = static_cast<int>(nodes_.size());
    nodes_.push_back(Node{axis, c, -1, -1, -1});
    Vec3<double> low_hi = hi, high_lo = lo;
    set(low_hi, axis, c), set(high_lo, axis, c);
    const int l = recurse(lo, low_hi, first_rank, low, first, split);
    const int h = recurse(high_lo, hi, first_rank + low, high, split, last);
    nodes_[static_cast<std::size_t>(node)].low = l, nodes_[static_cast<std::size_t>(node)].high = h;
    return node;
  }

  Vec3<double> lo_, hi_;
  unsigned periodic_ = 0;
  std::vector<RankBox> boxes_;
  std::vector<Node> nodes_;  // nodes_[0]: the root
};

}  // namespace blaze
