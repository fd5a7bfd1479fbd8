// Where a feeder (pipeline/feeder.hpp) places particles: a region whose every point a particle's
// centre may take, given the particle's bounding radius r (m), so that the particle lies wholly
// inside the region (a disc: on its plane, within its rim):
//   box:       lo + r <= x <= hi - r per axis                                  (lo, hi: m)
//   cylinder:  x = c + s a + rho (cos t e1 + sin t e2), r <= s <= L - r, rho <= R - r
//              (c: centre of its first end, a: unit axis, L: length, R: radius; m)
//   disc:      the cylinder with L = 0 and s = 0 (c: centre, a: the disc's normal)
// Uniform in volume (area for a disc): rho = (R - r) sqrt(u). A dimension under 2 r puts the
// centre on that dimension's middle.
#pragma once
#include <algorithm>
#include <cmath>
#include <random>
#include "blaze/config.hpp"
#include "blaze/core/vec3.hpp"

namespace blaze {

enum class RegionKind { box, cylinder, disc };

inline const char* to_string(RegionKind k) { return k == RegionKind::box ? "box" : k == RegionKind::cylinder ? "cylinder" : "disc"; }

struct InsertionRegion {
  RegionKind kind = RegionKind::box;
  Vec3<double> lo{0, 0, 0}, hi{0, 0, 0};  // m, box
  Vec3<double> centre{0, 0, 0}, axis{0, 0, 1};  // m, unit; cylinder and disc (zero otherwise: the identity text prints them)
  double radius = 0, length = 0;        // m

  // A number uniform in [0, 1) from a 64-bit engine of full range (CounterEngine, mt19937_64):
  // the draw over 2^64, below 1 (std::generate_canonical<double, 53> of libstdc++, which
  // std::uniform_real_distribution<double>(0, 1) returns, bit for bit), on host and device.
  template <class Rng>
  BLAZE_HD static double unit(Rng& rng) {
    // (the engines' min() and max(), 0 and 2^64 - 1, are host functions: the size stands in)
    static_assert(sizeof(typename Rng::result_type) == 8, "a 64-bit engine of full range");
    const double u = static_cast<double>(rng()) * 0x1p-64;
    return u < 1 ? u : 0x1.fffffffffffffp-1;
  }
  // A centre for a particle of bounding radius r (m). Host and device: the engine's operator()
  // must be callable on both (CounterEngine; nvcc refuses a host-only engine such as mt19937_64).
  template <class Rng>
  BLAZE_HD Vec3<double> draw(Rng& rng, double r) const {
    if (kind == RegionKind::box) {
      auto along = [&](double a, double b) { return b - a > 2 * r ? a + r + (b - a - 2 * r) * unit(rng) : 0.5 * (a + b); };
      const double x = along(lo.x, hi.x), y = along(lo.y, hi.y), z = along(lo.z, hi.z);
      return {x, y, z};
    }
    const double s = kind == RegionKind::disc ? 0.0 : length > 2 * r ? r + (length - 2 * r) * unit(rng) : 0.5 * length;
    const double rho = ::fmax(radius - r, 0.0) * ::sqrt(unit(rng)), t = 2 * M_PI * unit(rng);
    Vec3<double> e1, e2;
    basis(e1, e2);
    return centre + axis * s + (e1 * ::cos(t) + e2 * ::sin(t)) * rho;
  }

  // The region's bounding box (m).
  void bounds(Vec3<double>& out_lo, Vec3<double>& out_hi) const {
    if (kind == RegionKind::box) {
      out_lo = lo, out_hi = hi;
      return;
    }
    const Vec3<double> end = centre + axis * (kind == RegionKind::disc ? 0.0 : length);
    const double a[3] = {axis.x, axis.y, axis.z};
    double lo_[3], hi_[3];
    const double c0[3] = {centre.x, centre.y, centre.z}, c1[3] = {end.x, end.y, end.z};
    for (int d = 0; d < 3; ++d) {
      const double spread = radius * std::sqrt(std::max(0.0, 1 - a[d] * a[d]));  // a circle's extent
      lo_[d] = std::min(c0[d], c1[d]) - spread, hi_[d] = std::max(c0[d], c1[d]) + spread;
    }
    out_lo = {lo_[0], lo_[1], lo_[2]}, out_hi = {hi_[0], hi_[1], hi_[2]};
  }

  // m^3 (a disc: 0).
  double volume() const {
    if (kind == RegionKind::box) return (hi.x - lo.x) * (hi.y - lo.y) * (hi.z - lo.z);
    return kind == RegionKind::disc ? 0.0 : M_PI * radius * radius * length;
  }

  // Is x (m) a centre draw() can give for radius r (to `slack` m)?
  bool admits(const Vec3<double>& x, double r, double slack) const {
    if (kind == RegionKind::box) {
      auto in = [&](double v, double a, double b) {
        return b - a > 2 * r ? v >= a + r - slack && v <= b - r + slack : std::fabs(v - 0.5 * (a + b)) <= slack;
      };
      return in(x.x, lo.x, hi.x) && in(x.y, lo.y, hi.y) && in(x.z, lo.z, hi.z);
    }
    const Vec3<double> d = x - centre;
    const double s = dot(d, axis), rho = norm(d - axis * s);
    const bool along = kind == RegionKind::disc ? std::fabs(s) <= slack
                       : length > 2 * r         ? s >= r - slack && s <= length - r + slack
                                                : std::fabs(s - 0.5 * length) <= slack;
    return along && rho <= std::max(radius - r, 0.0) + slack;
  }

 private:
  BLAZE_HD void basis(Vec3<double>& e1, Vec3<double>& e2) const {
    const Vec3<double> helper = ::fabs(axis.x) < 0.9 ? Vec3<double>{1, 0, 0} : Vec3<double>{0, 1, 0};
    e1 = cross(axis, helper);
    e1 = e1 * (1 / norm(e1));
    e2 = cross(axis, e1);
  }
};

}  // namespace blaze
