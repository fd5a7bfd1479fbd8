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

// rotation_sign: the sign of omega about `axis` (+1: right-handed about it).
template <class Real>
ChargeProfile charge_profile(const std::vector<Vec3<Real>>& x, const Vec3<double>& centre, const Vec3<double>& axis,
                             double shell_radius, double band, double rotation_sign, double bin_deg = 5) {
  const double pi = 3.14159265358979323846;
  const Vec3<double> a = axis * (1 / norm(axis));
  Vec3<double> down{0, -1, 0};
  if (std::fabs(dot(down, a)) > 0.99) down = {1, 0, 0};
  Vec3<double> e1 = down - a * dot(down, a);
  e1 = e1 * (1 / norm(e1));
  const Vec3<double> e2 = cross(a, e1);  // a right-handed turn about a carries e1 towards e2
  const int bins = std::max(4, static_cast<int>(std::lround(360 / bin_deg)));
  std::vector<int> count(static_cast<std::size_t>(bins), 0);
  ChargeProfile p;
  for (const auto& xi : x) {
    const Vec3<double> r = vec_cast<double>(xi) - centre;
    const Vec3<double> rho = r - a * dot(r, a);
    const double d = norm(rho);
    if (!(d > shell_radius - band && d <= shell_radius)) continue;
    double phi = std::atan2(dot(rho, e2), dot(rho, e1)) * (rotation_sign < 0 ? -1 : 1);  // (-pi, pi]
    int k = static_cast<int>(std::floor((phi + pi) / (2 * pi) * bins));
    k = std::min(std::max(k, 0), bins - 1);
    ++count[static_cast<std::size_t>(k)];
    ++p.band_particles;
  }
  const int fullest = *std::max_element(count.begin(), count.end());
  if (fullest == 0) return p;
  // the longest circular run of bins at or above half the fullest
  int best_start = 0, best_len = 0;
  for (int s = 0; s < bins; ++s) {
    const auto dense = [&](int k) { return 2 * count[static_cast<std::size_t>(((k % bins) + bins) % bins)] >= fullest; };
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

}  // namespace blaze
