// Shoulder and toe of a tumbling mill's charge (issue 19; the positions the thesis's figures 4.3-
// 4.12 compare), from the particles' positions. In the drum's cross-section (axis a through the
// centre c), an angle phi is measured about a from the bottom of the drum (phi = 0: the direction
// -y projected, the frame of mill_geometry.hpp), positive in the drum's direction of rotation.
//   1. the liner band: particles whose centres lie within `band` of the shell (R - band < rho <= R);
//   2. their angles binned at `bin` degrees around the circle;
//   3. the en-masse region: the longest circular run of bins holding at least half the fullest
//      bin's count (the charge packed against the shell; the cataracting and cascading balls
//      cross the band sparsely);
//   4. the toe is the region's trailing end (where the charge, falling back, lands on the shell
//      and is carried up again), the shoulder its leading end (where the lifted charge leaves the
//      shell): toe < shoulder in phi. Both in degrees in (-180, 180], to the bins' resolution.
// This is the shell-contact definition the mill literature uses for measured profiles (the angular
// extent of the charge in contact with the liner; e.g. Venugopal & Rajamani 2001 read toe and
// shoulder off photographs of the charge against the shell). `found` is false when no bin holds
// a particle.
#pragma once
#include <algorithm>
#include <cmath>
#include <vector>
#include "blaze/core/vec3.hpp"

namespace blaze {

struct ChargeProfile {
  bool found = false;
  double toe_deg = 0, shoulder_deg = 0;  // from the bottom, positive in the direction of rotation
  int band_particles = 0;
};

// The band's angular histogram summed over any number of samples (a revolution's: the profile of
// the time-averaged charge, steadier than one snapshot's); profile() reads the toe and shoulder
// off it. rotation_sign: the sign of omega about `axis` (+1: right-handed about it).
class ChargeProfileSampler {
 public:
  ChargeProfileSampler(const Vec3<double>& centre, const Vec3<double>& axis, double shell_radius, double band,
                       double rotation_sign, double bin_deg = 5)
      : c_(centre), R_(shell_radius), band_(band), sign_(rotation_sign < 0 ? -1 : 1) {
    a_ = axis * (1 / norm(axis));
    Vec3<double> down{0, -1, 0};
    if (std::fabs(dot(down, a_)) > 0.99) down = {1, 0, 0};
    e1_ = down - a_ * dot(down, a_);
    e1_ = e1_ * (1 / norm(e1_));
    e2_ = cross(a_, e1_);  // a right-handed turn about a carries e1 towards e2
    count_.assign(static_cast<std::size_t>(std::max(4, static_cast<int>(std::lround(360 / bin_deg)))), 0);
  }

  template <class Real>
  void add(const std::vector<Vec3<Real>>& x) {
    const double pi = 3.14159265358979323846;
    const int bins = static_cast<int>(count_.size());
    for (const auto& xi : x) {
      const Vec3<double> r = vec_cast<double>(xi) - c_;
      const Vec3<double> rho = r - a_ * dot(r, a_);
      const double d = norm(rho);
      if (!(d > R_ - band_ && d <= R_)) continue;
      const double phi = std::atan2(dot(rho, e2_), dot(rho, e1_)) * sign_;  // (-pi, pi]
      int k = static_cast<int>(std::floor((phi + pi) / (2 * pi) * bins));
      k = std::min(std::max(k, 0), bins - 1);
      ++count_[static_cast<std::size_t>(k)];
      ++band_particles_;
    }
  }

  ChargeProfile profile() const {
    const int bins = static_cast<int>(count_.size());
    ChargeProfile p;
    p.band_particles = band_particles_;
    const long fullest = *std::max_element(count_.begin(), count_.end());
    if (fullest == 0) return p;
    // the longest circular run of bins at or above half the fullest
    int best_start = 0, best_len = 0;
    for (int s = 0; s < bins; ++s) {
      const auto dense = [&](int k) { return 2 * count_[static_cast<std::size_t>(((k % bins) + bins) % bins)] >= fullest; };
      if (!dense(s) || dense(s - 1)) continue;  // runs start after a sparse bin
      int len = 0;
      while (len < bins && dense(s + len)) ++len;
      if (len > best_len) best_len = len, best_start = s;
    }
    if (best_len == 0) best_start = 0, best_len = bins;  // every bin dense: no edges
    const auto angle = [&](int edge) {  // the bin boundary `edge`, in degrees in (-180, 180]
      double deg = -180 + 360.0 * edge / bins;
      while (deg <= -180) deg += 360;
      while (deg > 180) deg -= 360;
      return deg;
    };
    p.found = true;
    p.toe_deg = angle(best_start);
    p.shoulder_deg = angle(best_start + best_len);
    return p;
  }

 private:
  Vec3<double> c_, a_, e1_, e2_;
  double R_, band_, sign_;
  std::vector<long> count_;
  int band_particles_ = 0;
};

// The profile of one sample.
template <class Real>
ChargeProfile charge_profile(const std::vector<Vec3<Real>>& x, const Vec3<double>& centre, const Vec3<double>& axis,
                             double shell_radius, double band, double rotation_sign, double bin_deg = 5) {
  ChargeProfileSampler sampler(centre, axis, shell_radius, band, rotation_sign, bin_deg);
  sampler.add(x);
  return sampler.profile();
}

}  // namespace blaze
