// Prescribed motion of a world object (issue 19): the object keeps its reference geometry x_ref
// and is placed at time t (s) by a rigid map x(t) = R(t) (x_ref - p) + p + u(t); a point x of it
// moves at v(x) = omega(t) x (x - o(t)) + u'(t), o(t) = p + u(t). Every motion starts at t_0 and
// may ramp up linearly over T_r (T_r = 0: at once): r(s) = clamp(s / T_r, 0, 1), s = t - t_0, and
// R(s) = int_0^s r = s^2 / (2 T_r) during the ramp, s - T_r / 2 after it (0 before t_0).
// One kind per object:
//   rotation     about the unit axis a through p at the final speed omega_f (rad/s; a scene may
//                give rpm): omega(t) = omega_f r(s) a, angle theta(t) = omega_f R(s)
//   translation  at the final velocity V (m/s): u(t) = V R(s), u'(t) = V r(s)
//   vibration    along the unit direction d, amplitude A (m), frequency f (Hz), w = 2 pi f:
//                u(t) = A r(s) sin(w s) d, u'(t) = A (r'(s) sin(w s) + r(s) w cos(w s)) d (a ramp
//                starts the plate without a jump in its velocity)
// and, for any kind (none included), removal: from t_remove on the object is gone (the hopper's
// gate). Poses are formed in double from t = step x dt (no accumulated angle), then rounded to the
// simulation's precision. A moving wall does work on the particles: the world kernel adds
// F . v(x) dt per contact to the particle's account (the energy balance's drive work).
#pragma once
#include <cmath>
#include <cstdint>
#include <limits>
#include <vector>
#include "blaze/core/mat3.hpp"
#include "blaze/core/quat.hpp"

namespace blaze {

enum class MotionKind : std::uint8_t { none, rotation, translation, vibration };

struct Motion {
  MotionKind kind = MotionKind::none;
  Vec3<double> axis{0, 0, 1};       // unit (rotation)
  Vec3<double> point{0, 0, 0};      // m, on the axis (rotation)
  double omega = 0;                 // rad/s, final angular speed about `axis` (rotation)
  double ramp = 0;                  // s, T_r: the motion's linear ramp from t_0 (every kind)
  Vec3<double> velocity{0, 0, 0};   // m/s (translation)
  double amplitude = 0;             // m (vibration)
  double frequency = 0;             // Hz (vibration)
  Vec3<double> direction{0, 1, 0};  // unit (vibration)
  double start = 0;                 // s, t_0: the motion begins
  double remove = std::numeric_limits<double>::infinity();  // s: the object is gone from then on

  bool moves() const { return kind != MotionKind::none; }
  bool is_static() const { return kind == MotionKind::none && !(remove < std::numeric_limits<double>::infinity()); }
};

// Where an object is at one time, in the simulation's precision: x = rotation x_ref + shift.
template <class Real>
struct Pose {
  Mat3<Real> rotation;
  Vec3<Real> shift;     // m
  Vec3<Real> omega;     // rad/s, world frame
  Vec3<Real> origin;    // m, o(t): the point the rotation turns about, where it is now
  Vec3<Real> velocity;  // m/s, u'(t)
  bool active;          // false from t_remove on

  BLAZE_HD Vec3<Real> place(const Vec3<Real>& x_ref) const { return rotation * x_ref + shift; }
  BLAZE_HD Vec3<Real> turn(const Vec3<Real>& v_ref) const { return rotation * v_ref; }
  // The reference point that the pose places at x: x_ref = R^T (x - shift).
  BLAZE_HD Vec3<Real> to_reference(const Vec3<Real>& x) const { return rotation.transpose_times(x - shift); }
  // Velocity of the object's material point now at x (m/s).
  BLAZE_HD Vec3<Real> velocity_at(const Vec3<Real>& x) const { return cross(omega, x - origin) + velocity; }
};

// The ramp at s = t - t_0: r(s), r'(s) (1/s) and R(s) = int_0^s r (s).
struct Ramp {
  double r, dr, integral;
};
BLAZE_HD inline Ramp ramp_at(const Motion& m, double t) {
  const double s = t - m.start;
  if (!(s > 0)) return {0, 0, 0};
  if (s < m.ramp) return {s / m.ramp, 1 / m.ramp, s * s / (2 * m.ramp)};
  return {1, 0, s - 0.5 * m.ramp};
}

template <class Real>
BLAZE_HD Pose<Real> pose_at(const Motion& m, double t) {
  Mat3<double> r = Mat3<double>::rotation(Quat<double>::identity());
  Vec3<double> u{0, 0, 0}, du{0, 0, 0}, w{0, 0, 0};
  const double s = t - m.start;
  const Ramp q = ramp_at(m, t);
  switch (m.kind) {
    case MotionKind::rotation: {
      const double h = 0.5 * m.omega * q.integral, c = cos(h), sn = sin(h);
      r = Mat3<double>::rotation(Quat<double>{c, sn * m.axis.x, sn * m.axis.y, sn * m.axis.z});
      w = m.axis * (m.omega * q.r);
      break;
    }
    case MotionKind::translation:
      u = m.velocity * q.integral, du = m.velocity * q.r;
      break;
    case MotionKind::vibration:
      if (s > 0) {
        const double omega = 2 * 3.14159265358979323846 * m.frequency, phase = omega * s;
        u = m.direction * (m.amplitude * q.r * sin(phase));
        du = m.direction * (m.amplitude * (q.dr * sin(phase) + q.r * omega * cos(phase)));
      }
      break;
    case MotionKind::none:
      break;
  }
  // x = R (x_ref - p) + p + u = R x_ref + (p - R p + u)
  const Vec3<double> shift = m.point - r * m.point + u;
  Pose<Real> p;
  for (int a = 0; a < 3; ++a)
    for (int b = 0; b < 3; ++b) p.rotation.m[a][b] = static_cast<Real>(r.m[a][b]);
  p.shift = vec_cast<Real>(shift);
  p.omega = vec_cast<Real>(w);
  p.origin = vec_cast<Real>(m.point + u);
  p.velocity = vec_cast<Real>(du);
  p.active = !(t >= m.remove);
  return p;
}

// The fastest a point of an object moves (m/s), over `points` of it (its vertices; a cylinder's
// rim): |omega| times the farthest from the axis, |V| (the ramps only approach these), or
// A (2 pi f + 1 / T_r) for a vibration (its ramp adds A r'(s) sin to u'; 2 pi f A without one).
inline double peak_speed(const Motion& m, const std::vector<Vec3<double>>& points) {
  switch (m.kind) {
    case MotionKind::rotation: {
      double reach = 0;
      for (const auto& x : points) {
        const Vec3<double> r = x - m.point;
        reach = std::fmax(reach, norm(r - m.axis * dot(r, m.axis)));
      }
      return std::fabs(m.omega) * reach;
    }
    case MotionKind::translation: return norm(m.velocity);
    case MotionKind::vibration:
      return m.amplitude * (2 * 3.14159265358979323846 * m.frequency + (m.ramp > 0 ? 1 / m.ramp : 0));
    case MotionKind::none: return 0;
  }
  return 0;
}

}  // namespace blaze
