// Restitution of the Hertzian contact with delta^(1/4) damping (host only, set-up time).
//
//   m x'' = -K_n x^(3/2) - eta sqrt(m K_n) x^(1/4) x'          (x: overlap, m: effective mass)
//
// With x = L y, t = (L / v0) s, L = (m v0^2 / K_n)^(2/5), this becomes the parameter-free
//   y'' = -y^(3/2) - eta y^(1/4) y',     y(0) = 0, y'(0) = 1,
// so the coefficient of restitution e = -y'(s_end) at the return to y = 0 depends on eta alone:
// not on the impact speed, the mass or the stiffness (Tsuji et al., Powder Technol. 71 (1992) 239
// chose the 1/4 power for this reason). The relation e(eta) has no closed form; it is integrated
// here (classical Runge-Kutta, fixed step) and inverted by bisection, so that a law built from a
// restitution coefficient gives exactly that coefficient (verified against GSL's adaptive
// Runge-Kutta-Prince-Dormand in the suite). The thesis's delta^(1/2) damping with constant K_D
// (eq. 3.7) has no such property: its e falls with impact speed as v^(1/5).
//
// With no_tension the total force is clamped at zero (a contact never pulls); near separation
// the damping would otherwise exceed the spring (y^(1/4) outlives y^(3/2)), and the clamp changes
// e, so the inversion accounts for it.
//
// Without the clamp a strongly damped contact never separates: the tensile damping holds the body
// and it creeps out ever more slowly. The equation is invariant under y -> l y, s -> l^(-1/4) s,
// so on unloading (v < 0) the ratio c = -v / y^(5/4) obeys the exact autonomous equation
//   dc/dtau = (5 c^2 - 4 eta c + 4) / c,     tau = -ln(y) / 4 (growing towards y = 0).
// For eta <= sqrt(5) the right side is positive: c grows without bound and the body separates.
// For eta > sqrt(5) it has roots c_- < c_+; once c < c_+ the body is trapped on the creeping
// solution v = -c_- y^(5/4), which reaches y = 0 only as v -> 0: e = 0 (the body sticks). The
// integration stops there rather than follow the creep (a time step proportional to y would
// need ~1e11 steps).
#pragma once
#include <cmath>
#include <stdexcept>

namespace blaze {

// e(eta), to ~1e-9. The step is h_max in the scaled time (the elastic contact lasts 3.2181),
// shrunk to a fraction of y near y = 0 where y^(1/4) has an unbounded derivative (a fixed step
// there converges only at order 5/4).
inline double hertz_restitution(double eta, bool no_tension, double h_max = 1e-4) {
  if (!(eta >= 0)) throw std::invalid_argument("hertz restitution: eta must be >= 0");
  const auto accel = [&](double y, double v) {
    const double yp = y > 0 ? y : 0;
    const double f = yp * std::sqrt(yp) + eta * std::sqrt(std::sqrt(yp)) * v;
    return -(no_tension && f < 0 ? 0 : f);
  };
  // Sticking threshold c_+ of the free contact (header comment); none with the clamp or eta^2 <= 5.
  const double c_stick = !no_tension && eta * eta > 5 ? (2 * eta + std::sqrt(4 * eta * eta - 20)) / 5 : 0;
  double y = 0, v = 1;
  for (long k = 0; k < 100000000L; ++k) {
    if (v < 0 && -v < c_stick * y * std::sqrt(std::sqrt(y))) return 0;  // trapped: creeps, never separates
    const double h = std::fmin(h_max, std::fmax(1e-12, 1e-2 * y));
    const double k1y = v, k1v = accel(y, v);
    const double k2y = v + 0.5 * h * k1v, k2v = accel(y + 0.5 * h * k1y, v + 0.5 * h * k1v);
    const double k3y = v + 0.5 * h * k2v, k3v = accel(y + 0.5 * h * k2y, v + 0.5 * h * k2v);
    const double k4y = v + h * k3v, k4v = accel(y + h * k3y, v + h * k3v);
    const double y1 = y + h / 6 * (k1y + 2 * k2y + 2 * k3y + k4y);
    const double v1 = v + h / 6 * (k1v + 2 * k2v + 2 * k3v + k4v);
    if (y1 <= 0 && k > 0) {
      // Separation inside this step: the velocity at y = 0 by linear interpolation in y.
      const double s = y / (y - y1);
      return -(v + s * (v1 - v));
    }
    if (v1 >= 0 && v < 0 && y1 > 0) return 0;  // turned back before separating: the contact sticks
    y = y1;
    v = v1;
  }
  return 0;
}

// The eta that gives restitution e in (0, 1].
inline double hertz_damping_for_restitution(double e, bool no_tension) {
  if (!(e > 0 && e <= 1)) throw std::invalid_argument("hertz: restitution must lie in (0, 1]");
  if (e == 1) return 0;
  double lo = 0, hi = 1;
  while (hertz_restitution(hi, no_tension) > e) {
    lo = hi;
    hi *= 2;
    if (hi > 1e6) throw std::invalid_argument("hertz: restitution too small to reach");
  }
  for (int it = 0; it < 50 && hi - lo > 1e-10 * hi; ++it) {
    const double mid = 0.5 * (lo + hi);
    (hertz_restitution(mid, no_tension) > e ? lo : hi) = mid;
  }
  return 0.5 * (lo + hi);
}

}  // namespace blaze
