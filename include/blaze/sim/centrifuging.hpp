// Balls that centrifuge in a tumbling mill (issue 19; thesis section 4.2.2, Figs 4.16-4.17: one
// layer at 100% and two at 160% of the critical speed), from their positions sampled K times over
// one revolution of the drum (K >= 8, so that a ball turning with the drum moves less than half a
// turn between samples). For each ball (by its permanent id), about the drum's axis:
//   turn   = sum over the samples of the change of its angle (wrapped to (-pi, pi]), times the
//            sign of the drum's rotation: 2 pi for a ball carried round with the drum
//   depth  = R - mean distance from the axis (m): r for a ball on the shell
// A ball centrifuges when turn >= 0.9 (2 pi) over the revolution and it never left the shell's
// neighbourhood: its largest depth stays below kMaxLayers ball diameters (a cataracting ball that
// flies past the axis turns by up to pi between two samples, which could count as a turn). Its layer is
// 1 + floor((depth - r) / (0.9 d)) (d = 2 r: the second layer's centres sit ~d further in, the
// 0.9 leaves room for the packing's offsets), and the layers counted are those holding at least
// `min_balls` of the centrifuging balls (a stray ball does not make a layer).
#pragma once
#include <cmath>
#include <map>
#include <vector>
#include "blaze/core/vec3.hpp"

namespace blaze {

struct CentrifugingReport {
  int balls = 0;   // centrifuging over the revolution
  int layers = 0;  // layers holding at least min_balls of them
  int tracked = 0; // balls seen in every sample
};

class CentrifugeTracker {
 public:
  CentrifugeTracker(const Vec3<double>& centre, const Vec3<double>& axis, double shell_radius, double rotation_sign)
      : c_(centre), a_(axis * (1 / norm(axis))), r_shell_(shell_radius), sign_(rotation_sign >= 0 ? 1.0 : -1.0) {
    Vec3<double> down{0, -1, 0};
    if (std::fabs(dot(down, a_)) > 0.99) down = {1, 0, 0};
    e1_ = down - a_ * dot(down, a_);
    e1_ = e1_ * (1 / norm(e1_));
    e2_ = cross(a_, e1_);
  }
  // One sample: positions, radii and permanent ids of the balls present.
  template <class Real, class Id>
  void add(const std::vector<Vec3<Real>>& x, const std::vector<Real>& radius, const std::vector<Id>& id) {
    ++samples_;
    for (std::size_t k = 0; k < x.size(); ++k) {
      const Vec3<double> p{static_cast<double>(x[k].x), static_cast<double>(x[k].y), static_cast<double>(x[k].z)};
      const Vec3<double> d = p - c_;
      const double u = dot(d, e1_), v = dot(d, e2_);
      const double phi = std::atan2(v, u), rho = std::hypot(u, v);
      Ball& b = balls_[static_cast<long>(id[k])];
      if (b.samples > 0) {
        double step = phi - b.phi;
        while (step > kPi) step -= 2 * kPi;
        while (step <= -kPi) step += 2 * kPi;
        b.turn += sign_ * step;
      }
      b.phi = phi, b.rho_sum += rho, b.radius = static_cast<double>(radius[k]), ++b.samples;
      b.max_depth = std::fmax(b.max_depth, r_shell_ - rho);
    }
  }
  CentrifugingReport report(int min_balls = 3) const {
    CentrifugingReport out;
    std::map<int, int> per_layer;
    for (const auto& [id, b] : balls_) {
      if (b.samples != samples_) continue;  // left or arrived during the revolution
      ++out.tracked;
      if (b.turn < 0.9 * 2 * kPi || b.max_depth > kMaxLayers * 2 * b.radius) continue;
      ++out.balls;
      const double depth = r_shell_ - b.rho_sum / b.samples;
      ++per_layer[1 + static_cast<int>(std::floor(std::fmax(depth - b.radius, 0.0) / (0.9 * 2 * b.radius)))];
    }
    for (const auto& [layer, n] : per_layer) out.layers += n >= min_balls;
    return out;
  }

 private:
  static constexpr double kPi = 3.14159265358979323846;
  static constexpr double kMaxLayers = 4;  // deeper than this many diameters: not carried by the shell
  struct Ball {
    double phi = 0, turn = 0, rho_sum = 0, radius = 0, max_depth = 0;
    int samples = 0;
  };
  Vec3<double> c_, a_, e1_, e2_;
  double r_shell_, sign_;
  int samples_ = 0;
  std::map<long, Ball> balls_;
};

}  // namespace blaze
