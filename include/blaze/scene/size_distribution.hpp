// Particle size distributions for feeders (pipeline/feeder.hpp): the radius r (m) of each
// inserted sphere, drawn from
//   classes:        r_k with fractions w_k (sum 1), by number, or by mass (number fraction
//                   proportional to w_k / r_k^3: one material, so mass ~ r^3);
//   uniform:        F(r) = (r - a) / (b - a) on [a, b] = [min, max];
//   normal:         F(r) = Phi((r - mu) / sigma);
//   log-normal:     F(r) = Phi((ln r - ln r_50) / sigma), r_50 the median (m), sigma of ln r (-);
//   Rosin-Rammler:  F(r) = 1 - exp(-(r / r_63)^k) (Rosin & Rammler 1933; r_63 the size with 63.2%
//                   finer, k the spread; the same as a Weibull distribution),
// each continuous one truncated to [min, max]: F_T(r) = (F(r) - F(min)) / (F(max) - F(min)).
// `by_mass` means F is the mass-weighted CDF (the fraction of the mass in particles of radius <= r,
// as a sieve analysis gives); particles are then drawn by number with density f(r) / r^3 (the
// draw from F is kept with probability (min / r)^3, rejection sampling).
// The delivered sizes are checked against F by the Kolmogorov-Smirnov distance
//   D = sup_r |F_delivered(r) - F(r)|,
// F_delivered in the same measure (by number, or mass-weighted) and, for classes, over the
// classes' sizes. Random draws use a fresh std:: distribution per call from the engine's state,
// so the engine alone carries the state (a restart continues the same sequence).
#pragma once
#include <algorithm>
#include <cmath>
#include <random>
#include <stdexcept>
#include <string>
#include <vector>

namespace blaze {

enum class SizeKind { constant, classes, uniform, normal, lognormal, rosin_rammler };

inline const char* to_string(SizeKind k) {
  switch (k) {
    case SizeKind::constant: return "constant";
    case SizeKind::classes: return "classes";
    case SizeKind::uniform: return "uniform";
    case SizeKind::normal: return "normal";
    case SizeKind::lognormal: return "lognormal";
    case SizeKind::rosin_rammler: return "rosin_rammler";
  }
  return "?";
}

struct SizeDistribution {
  // The narrowest spread a continuous kind may have, relative to its size (validate()).
  static constexpr double kMinRelativeSpread = 1e-9;
  SizeKind kind = SizeKind::constant;
  bool by_mass = false;
  double radius = 0;                    // m, constant
  std::vector<double> sizes, fractions;  // m, -; classes (fractions sum to 1)
  double mean = 0, deviation = 0;       // m, normal; log-normal: median r_50 (m) and sigma of ln r (-)
  double scale = 0, shape = 0;          // Rosin-Rammler: r_63 (m), k (-)
  double min = 0, max = 0;              // m, the truncation (continuous kinds)

  // The largest radius a draw can give (m).
  double largest() const {
    if (kind == SizeKind::constant) return radius;
    if (kind == SizeKind::classes) return *std::max_element(sizes.begin(), sizes.end());
    return max;
  }
  double smallest() const {
    if (kind == SizeKind::constant) return radius;
    if (kind == SizeKind::classes) return *std::min_element(sizes.begin(), sizes.end());
    return min;
  }

  // The untruncated CDF F(r) of the continuous kinds.
  double raw_cdf(double r) const {
    switch (kind) {
      case SizeKind::uniform: return std::clamp((r - min) / (max - min), 0.0, 1.0);
      case SizeKind::normal: return 0.5 * std::erfc(-(r - mean) / (deviation * std::sqrt(2.0)));
      case SizeKind::lognormal: return r <= 0 ? 0.0 : 0.5 * std::erfc(-(std::log(r) - std::log(mean)) / (deviation * std::sqrt(2.0)));
      case SizeKind::rosin_rammler: return r <= 0 ? 0.0 : 1 - std::exp(-std::pow(r / scale, shape));
      default: return 0;
    }
  }
  // The requested CDF F_T(r) in its own measure (by number, or mass-weighted when by_mass).
  double cdf(double r) const {
    if (kind == SizeKind::constant) return r >= radius ? 1.0 : 0.0;
    if (kind == SizeKind::classes) {
      double f = 0;
      for (std::size_t k = 0; k < sizes.size(); ++k)
        if (sizes[k] <= r) f += fractions[k];
      return std::min(f, 1.0);
    }
    if (r <= min) return 0;
    if (r >= max) return 1;
    return (raw_cdf(r) - raw_cdf(min)) / (raw_cdf(max) - raw_cdf(min));
  }

  // Throws std::invalid_argument saying what is wrong (the scene parser adds file, line and key).
  void validate() const {
    auto need = [](bool ok, const std::string& what) {
      if (!ok) throw std::invalid_argument(what);
    };
    switch (kind) {
      case SizeKind::constant: need(radius > 0, "the radius must be > 0 m"); return;
      case SizeKind::classes: {
        need(!sizes.empty() && sizes.size() == fractions.size(), "radii and fractions must be non-empty lists of one length");
        double sum = 0;
        for (std::size_t k = 0; k < sizes.size(); ++k) {
          need(sizes[k] > 0 && std::isfinite(sizes[k]), "every radius must be > 0 m");
          need(fractions[k] >= 0 && std::isfinite(fractions[k]), "every fraction must be >= 0");
          sum += fractions[k];
        }
        need(std::fabs(sum - 1) <= 1e-6, "the fractions must sum to 1 (they sum to " + std::to_string(sum) + ")");
        return;
      }
      default: break;
    }
    need(min > 0 && max > min && std::isfinite(max), "min and max must satisfy 0 < min < max (m)");
    if (kind == SizeKind::normal) need(deviation > 0, "deviation must be > 0 m");
    if (kind == SizeKind::lognormal) need(mean > 0 && deviation > 0, "median must be > 0 m and sigma > 0");
    // A spread below kMinRelativeSpread of the size is one size: double resolves the draws and
    // the CDF no better than ~1e-13 of it (the Kolmogorov-Smirnov check then reports up to 0.5
    // for a distribution delivered exactly), and no feeder needs sizes closer than that.
    const std::string one_size = ": sizes closer than that are one size (leave size out for the type's radius, or "
                                 "give kind = \"classes\" with one radius)";
    need(max - min >= kMinRelativeSpread * max, "max - min must be >= 1e-9 x max" + one_size);
    if (kind == SizeKind::normal)
      need(deviation >= kMinRelativeSpread * std::fabs(mean), "deviation must be >= 1e-9 x mean" + one_size);
    if (kind == SizeKind::lognormal) need(deviation >= kMinRelativeSpread, "sigma must be >= 1e-9" + one_size);
    if (kind == SizeKind::rosin_rammler) need(scale > 0 && shape > 0, "r63 must be > 0 m and k > 0");
    // a range the distribution barely reaches would make the rejection draws loop for ever
    need(raw_cdf(max) - raw_cdf(min) >= 1e-6, "[min, max] holds less than 1e-6 of the distribution");
  }

  // One radius (m).
  template <class Rng>
  double draw(Rng& rng) const {
    if (kind == SizeKind::constant) return radius;
    std::uniform_real_distribution<double> u(0, 1);
    if (kind == SizeKind::classes) {
      // number fractions: w_k, or w_k / r_k^3 normalised (by mass)
      double total = 0;
      for (std::size_t k = 0; k < sizes.size(); ++k) total += weight(k);
      double pick = u(rng) * total;
      for (std::size_t k = 0; k < sizes.size(); ++k) {
        pick -= weight(k);
        if (pick < 0) return sizes[k];
      }
      for (std::size_t k = sizes.size(); k-- > 0;)  // rounding at the top end
        if (fractions[k] > 0) return sizes[k];
    }
    for (;;) {
      const double r = draw_truncated(rng);
      if (!by_mass || u(rng) * r * r * r <= min * min * min) return r;
    }
  }

  // The Kolmogorov-Smirnov distance of `delivered` radii (m) from this distribution, in its
  // measure: over the jumps of the empirical CDF (continuous kinds), or at the classes' sizes.
  double ks_distance(std::vector<double> delivered) const {
    if (delivered.empty()) return 0;
    std::sort(delivered.begin(), delivered.end());
    auto w = [&](double r) { return by_mass ? r * r * r : 1.0; };
    double total = 0;
    for (double r : delivered) total += w(r);
    // F_delivered(r): the share at or below r
    auto empirical = [&](double r) {
      double below = 0;
      for (double x : delivered) {
        if (x > r) break;
        below += w(x);
      }
      return below / total;
    };
    double d = 0;
    if (kind == SizeKind::constant || kind == SizeKind::classes) {
      const std::vector<double> at = kind == SizeKind::constant ? std::vector<double>{radius} : sizes;
      for (double r : at) d = std::max(d, std::fabs(empirical(r) - cdf(r)));
      return std::max(d, empirical(smallest() * (1 - 1e-12)));  // any delivered below every class
    }
    double before = 0;
    for (std::size_t k = 0; k < delivered.size();) {
      double after = before;
      std::size_t j = k;
      for (; j < delivered.size() && delivered[j] == delivered[k]; ++j) after += w(delivered[j]) / total;
      const double f = cdf(delivered[k]);
      d = std::max({d, std::fabs(after - f), std::fabs(before - f)});
      before = after, k = j;
    }
    return d;
  }

 private:
  double weight(std::size_t k) const { return by_mass ? fractions[k] / (sizes[k] * sizes[k] * sizes[k]) : fractions[k]; }
  template <class Rng>
  double draw_truncated(Rng& rng) const {
    std::uniform_real_distribution<double> u(0, 1);
    switch (kind) {
      case SizeKind::uniform: return min + (max - min) * u(rng);
      case SizeKind::rosin_rammler: {  // inverse CDF over [F(min), F(max)]
        const double f = raw_cdf(min) + (raw_cdf(max) - raw_cdf(min)) * u(rng);
        return std::clamp(scale * std::pow(-std::log1p(-f), 1 / shape), min, max);
      }
      default: break;
    }
    for (;;) {  // normal and log-normal: redraw until inside [min, max] (validate(): >= 1e-6 of the mass)
      std::normal_distribution<double> g(0, 1);
      const double z = g(rng);
      const double r = kind == SizeKind::normal ? mean + deviation * z : mean * std::exp(deviation * z);
      if (r >= min && r <= max) return r;
    }
  }
};

}  // namespace blaze
