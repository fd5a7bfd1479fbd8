// A contact law = a normal law + a tangential law (+ a rolling law), evaluated for one material
// pair. Given the geometry, the relative motion at the contact and the contact's state (its
// history, contact_state.hpp), it returns the force on body i and a moment on i about the contact
// point (body j receives the opposite of both), and updates the state:
//   evaluate(geometry, motion, state, dt) -> ContactForce
//   F = -F_n n + F_t,   F_n = normal.normal_force(delta, v_n, m*, R*),  v_n = v_rel . n,
//   F_t = tangential.force(v_t = v_rel - v_n n, F_n, state),  M = rolling.moment(w_rel, F_n, state)
// Laws hold only derived coefficients; they are trivially copyable and live by value in the
// material-pair table that kernels receive as an argument. A law whose parts keep no state
// (history-free friction, thesis eq. 2.3) has State::kReals = 0: the kernels store nothing for
// it and compile the same code as before history existed; force() is its stateless shorthand.
#pragma once
#include <stdexcept>
#include <string>
#include <type_traits>
#include "blaze/contact/contact_geometry.hpp"
#include "blaze/laws/contact_state.hpp"
#include "blaze/laws/rolling_resistance.hpp"
#include "blaze/laws/tangential_spring.hpp"

namespace blaze {

// Relative motion of i with respect to j at the contact.
template <class Real>
struct ContactMotion {
  Vec3<Real> v_rel;  // m/s, at the contact point (kinematics.hpp)
  Vec3<Real> w_rel;  // rad/s, w_i - w_j (rolling laws)
  Real m_eff;        // kg, 1 / (1/m_i + 1/m_j)
  Real inv_rolling_inertia = 0;  // 1/(kg m^2), 1 / I_r (rolling laws; rolling_resistance.hpp)
};

template <class Real>
struct ContactForce {
  Vec3<Real> force;   // N, on i
  Vec3<Real> moment;  // N m, on i beyond (point - x_i) x force (rolling resistance)
  bool sliding;       // the Coulomb limit acted this step
};

// No rolling resistance: no moment, no state.
template <class Real>
struct NoRolling {
  static constexpr int kStateReals = 0;
};

template <class Real, template <class> class NormalLaw, template <class> class TangentialLaw,
          template <class> class RollingLaw = NoRolling>
struct ContactLaw {
  using real_type = Real;
  using State = ContactState<Real, TangentialLaw<Real>::kStateReals + RollingLaw<Real>::kStateReals>;
  static constexpr bool kHistory = State::kReals > 0;
  static constexpr int kRollingAt = TangentialLaw<Real>::kStateReals;  // the rolling law's offset in State
  static constexpr bool kRolling = !std::is_same_v<RollingLaw<Real>, NoRolling<Real>>;
  NormalLaw<Real> normal;
  TangentialLaw<Real> tangential;
  RollingLaw<Real> rolling{};  // (a default: two-part laws are written {normal, tangential})

  BLAZE_HD ContactForce<Real> evaluate(const ContactGeometry<Real>& g, const ContactMotion<Real>& m, State& state,
                                       Real dt) const {
    const Real v_n = dot(m.v_rel, g.normal);
    const Real f_n = normal.normal_force(g.overlap, v_n, m.m_eff, g.r_eff);
    const TangentialInput<Real> in{g.normal, g.overlap, g.r_eff, m.v_rel - v_n * g.normal, v_n, f_n, m.m_eff, dt};
    const TangentialForce<Real> t = tangential.force(in, state, 0);
    ContactForce<Real> out{g.normal * (-f_n) + t.force, {0, 0, 0}, t.sliding};
    if constexpr (kRolling)
      out.moment = rolling.moment({g.normal, g.r_eff, m.w_rel, f_n, normal.tangent_stiffness(g.overlap, g.r_eff),
                                   m.inv_rolling_inertia, dt},
                                  state, kRollingAt);
    return out;
  }
  // Reals of state in use (the contact store holds these): the rolling spring only under model C.
  int state_reals() const {
    if constexpr (kRolling) return TangentialLaw<Real>::kStateReals + rolling.state_reals();
    return State::kReals;
  }

  // The stateless law's force on i (laws without history only).
  template <bool Stateless = !kHistory, std::enable_if_t<Stateless, int> = 0>
  BLAZE_HD Vec3<Real> force(const ContactGeometry<Real>& g, const Vec3<Real>& v_rel, Real m_eff) const {
    State none{};
    return evaluate(g, {v_rel, {0, 0, 0}, m_eff}, none, Real(0)).force;
  }

  // Elastic energy the contact holds (J, double): the normal spring's potential
  // (NormalLaw::stored_energy, equation in its header) plus a tangential spring's |F_e|^2 / (2 k_t)
  // from the contact's state: the one place Simulation::contact_energy() and the time series read.
  BLAZE_HD double stored_energy(const ContactGeometry<Real>& g, const State& state = State::zero()) const {
    double e = normal.stored_energy(g.overlap, g.r_eff);
    if constexpr (TangentialLaw<Real>::kStateReals > 0) e += tangential.stored_energy(g.overlap, g.r_eff, state, 0);
    if constexpr (kRolling)
      if (rolling.model == RollingModel::epsd && rolling.mu_r > Real(0)) {  // 1/2 |M_k|^2 / k_r
        const double k_r = 2.25 * static_cast<double>(normal.tangent_stiffness(g.overlap, g.r_eff)) *
                           static_cast<double>(rolling.mu_r) * static_cast<double>(rolling.mu_r) *
                           static_cast<double>(g.r_eff) * static_cast<double>(g.r_eff);
        const Vec3<Real> mk = state.vec(kRollingAt);
        const double m2 = static_cast<double>(mk.x) * mk.x + static_cast<double>(mk.y) * mk.y + static_cast<double>(mk.z) * mk.z;
        if (k_r > 0) e += 0.5 * m2 / k_r;
      }
    return e;
  }
};

// Laws per material pair, symmetric, with a compile-time cap so the table fits in a kernel's
// parameter space (constant memory: the thesis kept its per-type data there too, section 2.2.1).
template <class Law>
struct PairTable {
  PairTable() : entries{}, defined{} {}
  static constexpr int kMaxMaterials = 8;
  Law entries[kMaxMaterials * kMaxMaterials];
  bool defined[kMaxMaterials * kMaxMaterials];

  BLAZE_HD const Law& operator()(int a, int b) const { return entries[a * kMaxMaterials + b]; }
  bool has(int a, int b) const {
    return a >= 0 && b >= 0 && a < kMaxMaterials && b < kMaxMaterials && defined[a * kMaxMaterials + b];
  }
  void set(int a, int b, const Law& law) {
    if (a < 0 || b < 0 || a >= kMaxMaterials || b >= kMaxMaterials)
      throw std::invalid_argument("material index outside [0, " + std::to_string(kMaxMaterials) + ")");
    entries[a * kMaxMaterials + b] = entries[b * kMaxMaterials + a] = law;
    defined[a * kMaxMaterials + b] = defined[b * kMaxMaterials + a] = true;
  }
};

}  // namespace blaze
