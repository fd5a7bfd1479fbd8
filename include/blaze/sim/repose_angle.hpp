// Angle of repose of a pile on a flat base, from the particles' positions (host code).
//
// The pile stands on the plane y = base_y around the vertical axis through (axis_x, axis_z). Its
// surface profile is sampled in radial bins of width `bin` (m): in each bin the highest sphere top
//   h_k = max over particles with r in [k bin, (k+1) bin) of (y + radius - base_y)         m
// with r = sqrt((x - axis_x)^2 + (z - axis_z)^2). A straight line h = h_0 - tan(theta) r is fitted
// by least squares to the (bin centre, h_k) of the non-empty bins whose centre lies between
// r_lo = inner R_p and r_hi = outer R_p, R_p being the pile's radius (the fixed base's, or the
// farthest particle's when none is given):
//   tan(theta) = -sum (r_k - r_mean)(h_k - h_mean) / sum (r_k - r_mean)^2
// The top (the apex's few grains) and the foot (the rounded toe, grains rolled out) are left
// out, as when the angle is read off a photograph of the flank. The highest grain of a bin sits
// at the bin's inner edge on a dense surface, so the profile is shifted by bin tan(theta) / 2
// against the bin centres; that moves h_0, not the slope. Reported: theta (deg), the root mean
// square of the fit's residuals (m), the bins used, and the profile itself. Fewer than three
// bins: theta is NaN.
#pragma once
#include <cmath>
#include <limits>
#include <vector>
#include "blaze/particles/particle_state.hpp"

namespace blaze {

struct ReposeProfile {
  double angle_deg = std::numeric_limits<double>::quiet_NaN();  // deg, atan of the fitted slope
  double intercept = 0;      // m, h_0 of the fit (height at r = 0)
  double rms = 0;            // m, root mean square of the fit's residuals
  int bins_used = 0;         // bins in [r_lo, r_hi] with a particle
  std::vector<double> r;     // m, bin centres (every bin, 0 .. R_p)
  std::vector<double> h;     // m, highest sphere top in the bin (NaN: empty bin)
  std::vector<bool> fitted;  // whether the bin took part in the fit
};

struct ReposeGeometry {
  double axis_x = 0, axis_z = 0;  // m, the pile's vertical axis
  double base_y = 0;              // m, the base plane
  double pile_radius = 0;         // m, R_p; 0: the farthest particle above the base
  double bin = 0;                 // m, radial bin width (> 0)
  double inner = 0.2, outer = 0.8;  // fraction of R_p fitted
};

// x, y, z (m) and radius (m) of every sphere; those below the base plane are ignored.
inline ReposeProfile measure_repose(const std::vector<double>& x, const std::vector<double>& y, const std::vector<double>& z,
                                    const std::vector<double>& radius, const ReposeGeometry& g) {
  ReposeProfile p;
  const std::size_t n = x.size();
  double r_p = g.pile_radius;
  if (!(r_p > 0))
    for (std::size_t i = 0; i < n; ++i)
      if (y[i] > g.base_y) r_p = std::max(r_p, std::hypot(x[i] - g.axis_x, z[i] - g.axis_z));
  if (!(g.bin > 0) || !(r_p > 0)) return p;
  const auto bins = static_cast<std::size_t>(std::ceil(r_p / g.bin));
  p.r.resize(bins);
  p.h.assign(bins, std::numeric_limits<double>::quiet_NaN());
  p.fitted.assign(bins, false);
  for (std::size_t k = 0; k < bins; ++k) p.r[k] = (static_cast<double>(k) + 0.5) * g.bin;
  for (std::size_t i = 0; i < n; ++i) {
    if (!(y[i] > g.base_y)) continue;
    const double r = std::hypot(x[i] - g.axis_x, z[i] - g.axis_z);
    const auto k = static_cast<std::size_t>(r / g.bin);
    if (k >= bins) continue;
    const double top = y[i] + radius[i] - g.base_y;
    if (!(p.h[k] >= top)) p.h[k] = top;  // NaN (empty) compares false
  }
  double sr = 0, sh = 0;
  for (std::size_t k = 0; k < bins; ++k)
    if (p.r[k] >= g.inner * r_p && p.r[k] <= g.outer * r_p && !std::isnan(p.h[k])) {
      p.fitted[k] = true;
      ++p.bins_used;
      sr += p.r[k], sh += p.h[k];
    }
  if (p.bins_used < 3) return p;
  const double rm = sr / p.bins_used, hm = sh / p.bins_used;
  double srr = 0, srh = 0;
  for (std::size_t k = 0; k < bins; ++k)
    if (p.fitted[k]) srr += (p.r[k] - rm) * (p.r[k] - rm), srh += (p.r[k] - rm) * (p.h[k] - hm);
  const double slope = srh / srr;  // dh/dr, negative on a pile
  p.intercept = hm - slope * rm;
  double ss = 0;
  for (std::size_t k = 0; k < bins; ++k)
    if (p.fitted[k]) {
      const double e = p.h[k] - (p.intercept + slope * p.r[k]);
      ss += e * e;
    }
  p.rms = std::sqrt(ss / p.bins_used);
  p.angle_deg = std::atan(-slope) * 180.0 / 3.14159265358979323846;
  return p;
}

template <class Real>
ReposeProfile measure_repose(const ParticleState<Real>& s, const ReposeGeometry& g) {
  std::vector<double> x, y, z, r;
  for (std::size_t i = 0; i < s.size(); ++i) {
    x.push_back(s.position[i].x), y.push_back(s.position[i].y), z.push_back(s.position[i].z);
    r.push_back(s.radius[i]);
  }
  return measure_repose(x, y, z, r, g);
}

}  // namespace blaze
