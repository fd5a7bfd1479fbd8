// Tangential spring with a Coulomb limit: the contact's history (Cundall & Strack 1979 for the
// linear law; Mindlin & Deresiewicz 1953, no-slip stiffness, for Hertz, in the incremental force
// form of Thornton, Cummins & Cleary, Powder Technol. 210 (2011) 189). The state is the spring's
// elastic force F_e (N, on i). Per step, for a touching contact:
//
//   F_e <- |F_e| (F_e - (F_e.n) n) / |F_e - (F_e.n) n|   turned into the current tangent plane (the
//                                                    normal has turned), its size kept
//   unloading (v_n < 0):  F_e <- F_e k_t(delta) / k_t(delta - v_n dt)   the spring softens with the
//                                                    overlap (Mindlin: sqrt(delta / delta_prev))
//   F_e <- F_e - k_t(delta) v_t dt                   the increment of the elastic force
//   F   =  F_e - c_t v_t                             tangential force on i (N)
//   |F| > mu F_n:  F <- mu F_n F / |F|,  F_e <- F + c_t v_t   (sliding: the spring truncated)
//   F_n <= 0 (a pulling dashpot): F = 0, F_e = 0 (a contact that pulls transmits no friction)
//
//   k_t = k_0 + k_hat sqrt(R* delta)   N/m. Linear law: k_0 given (default 2/7 k_n, which gives a
//          sphere's tangential oscillation the normal one's period), k_hat = 0. Hertz (Mindlin):
//          k_0 = 0, k_hat = 8 G*, 1/G* = (2 - nu_1)/G_1 + (2 - nu_2)/G_2, G = E / (2 (1 + nu)) Pa.
//   c_t = beta_t sqrt(k_t m*)          kg/s, from the pair's restitution e: linear beta_t =
//          -2 ln e / sqrt(ln^2 e + pi^2) (the normal law's beta); Hertz beta_t = sqrt(5/6) times
//          that (LIGGGHTS: gamma_t = -2 sqrt(5/6) beta sqrt(S_t m*), S_t = k_t).
//   Stored elastic energy |F_e|^2 / (2 k_t) (J).
//
// Why the force and not the displacement s with F = -k_t(delta) s (LIGGGHTS): with k_t growing
// with the overlap, the total form raises the stored energy 1/2 k_t |s|^2 without work while the
// contact loads: an elastic (e = 1) sphere sticking in an oblique impact gained 40% of the
// spring's peak energy during the contact and kept 1.3% of it after (test_contact_history.cpp).
// The increments never create energy: the turning keeps |F_e|, a loading increment stores at most
// the work done (material entering the contact carries no tangential stress: Mindlin &
// Deresiewicz), and the softening on unloading gives up the stress of the area leaving the
// contact without work, which is dissipated (the same impact keeps E(t) <= E_0 throughout and
// loses most of the spring's peak energy at small angles; Chung & Ooi tests 4-8 compare the
// rebound with Maw, Barber & Fawcett's theory).
//
// v_t: tangential slip velocity at the contact point (m/s); v_n: normal approach speed (m/s,
// > 0 closing); n: contact normal; F_n: normal force (N, > 0 pushing); dt: the time step (s).
// Each side of a pair keeps its own copy of F_e, the exact negation of the other's (every
// operation above is odd in (F_e, v_t, n) together and even in v_n, so the two stay mirrored to
// the last bit). A contact is "sliding" when the Coulomb limit truncated it this step.
#pragma once
#include <cmath>
#include <stdexcept>
#include "blaze/contact/contact_geometry.hpp"
#include "blaze/laws/contact_state.hpp"

namespace blaze {

// What a tangential law is given: the slip, the normal force, the effective mass, the step.
template <class Real>
struct TangentialInput {
  Vec3<Real> normal;  // -, from i towards j
  Real overlap;       // m
  Real r_eff;         // m
  Vec3<Real> v_t;     // m/s
  Real v_n;           // m/s, approach speed (> 0 closing)
  Real f_n;           // N
  Real m_eff;         // kg
  Real dt;            // s
};

// What it gives back: the force on i and whether the Coulomb limit acted.
template <class Real>
struct TangentialForce {
  Vec3<Real> force;  // N
  bool sliding;
};

template <class Real>
struct TangentialSpring {
  static constexpr int kStateReals = 3;  // the spring's elastic force F_e, N
  Real mu;        // -, Coulomb coefficient
  Real k0;        // N/m
  Real k_hat;     // Pa (8 G*), times sqrt(R* delta)
  Real beta;      // -, damping factor beta_t

  // Cundall-Strack: constant k_t (N/m), beta_t from the normal law's.
  static TangentialSpring linear(double mu, double kt, double beta) {
    check(mu, beta);
    if (!(kt > 0)) throw std::invalid_argument("tangential spring: stiffness must be > 0 N/m");
    return {static_cast<Real>(mu), static_cast<Real>(kt), Real(0), static_cast<Real>(beta)};
  }
  // Mindlin: k_t = 8 G* sqrt(R* delta); beta_t = sqrt(5/6) * (-2 ln e / sqrt(ln^2 e + pi^2)).
  static TangentialSpring mindlin(double mu, double g_star, double restitution) {
    if (!(g_star > 0)) throw std::invalid_argument("tangential spring: effective shear modulus G* must be > 0 Pa");
    if (!(restitution > 0 && restitution <= 1)) throw std::invalid_argument("tangential spring: restitution must lie in (0, 1]");
    const double le = std::log(restitution), pi = 3.14159265358979323846;
    const double beta = std::sqrt(5.0 / 6.0) * (-2 * le / std::sqrt(le * le + pi * pi));
    check(mu, beta);
    return {static_cast<Real>(mu), Real(0), static_cast<Real>(8 * g_star), static_cast<Real>(beta)};
  }
  // 1/G* = (2 - nu_a)/G_a + (2 - nu_b)/G_b with G = E / (2 (1 + nu)); Pa.
  static double effective_shear_modulus(double e_a, double nu_a, double e_b, double nu_b) {
    const double g_a = e_a / (2 * (1 + nu_a)), g_b = e_b / (2 * (1 + nu_b));
    return 1 / ((2 - nu_a) / g_a + (2 - nu_b) / g_b);
  }

  BLAZE_HD Real stiffness(Real delta, Real r_eff) const {
    return k_hat == Real(0) ? k0 : k0 + k_hat * contact_radius(delta, r_eff);
  }

  // c_t (kg/s) at this overlap.
  BLAZE_HD Real damping(Real delta, Real r_eff, Real m_eff) const { return beta * sqrt_r(stiffness(delta, r_eff) * m_eff); }

  template <class State>
  BLAZE_HD TangentialForce<Real> force(const TangentialInput<Real>& in, State& state, int at) const {
    const Real cap = mu * in.f_n;
    if (!(cap > Real(0))) {  // pulling or frictionless: nothing transmitted, nothing kept
      state.set(at, {0, 0, 0});
      return {{0, 0, 0}, false};
    }
    Vec3<Real> fe = state.vec(at);
    const Real kt = stiffness(in.overlap, in.r_eff);
    const Real size2 = norm2(fe);
    if (size2 > Real(0)) {
      fe -= dot(fe, in.normal) * in.normal;
      const Real turned2 = norm2(fe);
      // |F_e|^2 kept, times (k_t(delta) / k_t(delta_prev))^2 when unloading: for Mindlin (k_0 = 0)
      // that is delta / delta_prev, one division with the turning's and no square root.
      Real num = size2, den = turned2 > Real(0) ? turned2 : size2;
      if (k_hat != Real(0) && in.v_n < Real(0)) {
        const Real prev = in.overlap - in.v_n * in.dt;
        if (k0 == Real(0)) {
          num *= in.overlap, den *= prev;
        } else {
          const Real before = stiffness(prev, in.r_eff);
          num *= kt * kt, den *= before * before;
        }
      }
      // A spring so weak that |F_e|^2 delta_prev underflows (float: |F_e| below ~1e-17 N at
      // micrometre overlaps) is dropped, not turned into 0/0 = NaN.
      if (den > Real(0)) fe *= sqrt_r(num / den);
      else fe = Vec3<Real>{0, 0, 0};
    }
    fe -= in.v_t * (kt * in.dt);
    const Vec3<Real> damping = in.v_t * (beta * sqrt_r(kt * in.m_eff));  // c_t v_t
    Vec3<Real> f = fe - damping;
    const Real f2 = norm2(f);
    const bool sliding = f2 > cap * cap;
    if (sliding) {
      f *= cap / sqrt_r(f2);
      fe = f + damping;
    }
    state.set(at, fe);
    return {f, sliding};
  }

  // |F_e|^2 / (2 k_t) (J), in double.
  template <class State>
  BLAZE_HD double stored_energy(Real delta, Real r_eff, const State& state, int at) const {
    const double kt = static_cast<double>(stiffness(delta, r_eff));
    const Vec3<Real> fe = state.vec(at);
    const double fx = fe.x, fy = fe.y, fz = fe.z;
    return kt > 0 ? 0.5 * (fx * fx + fy * fy + fz * fz) / kt : 0.0;
  }

 private:
  static void check(double mu, double beta) {
    if (!(mu >= 0)) throw std::invalid_argument("tangential spring: friction mu must be >= 0");
    if (!(beta >= 0)) throw std::invalid_argument("tangential spring: damping must be >= 0");
  }
};

}  // namespace blaze
