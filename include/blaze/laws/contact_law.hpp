// A contact law = a normal law + a tangential law, evaluated for one material pair.
// Given the geometry and the relative velocity at the contact point, it returns the force on
// body i (body j receives the opposite). Laws hold only derived coefficients; they are trivially
// copyable and live by value in the material-pair table that kernels receive as an argument.
#pragma once
#include <stdexcept>
#include <string>
#include <type_traits>
#include "blaze/contact/contact_geometry.hpp"

namespace blaze {

template <class Real, template <class> class NormalLaw, template <class> class TangentialLaw>
struct ContactLaw {
  using real_type = Real;
  NormalLaw<Real> normal;
  TangentialLaw<Real> tangential;

  BLAZE_HD Vec3<Real> force(const ContactGeometry<Real>& g, const Vec3<Real>& v_rel, Real m_eff) const {
    const Real v_n = dot(v_rel, g.normal);
    const Real f_n = normal.normal_force(g.overlap, v_n, m_eff, g.r_eff);
    const Vec3<Real> v_t = v_rel - v_n * g.normal;
    return g.normal * (-f_n) + tangential.tangential_force(v_t, f_n);
  }

  // Elastic energy the contact holds (J, double): the normal spring's potential
  // (NormalLaw::stored_energy, equation in its header). The tangential laws Blaze ships are
  // history-free (no spring, nothing stored); a tangential spring (the contact-history issue)
  // adds its 1/2 k_t |s|^2 here, and a rolling spring its 1/2 k_r |theta|^2, from the contact's
  // history: this is the one place Simulation::contact_energy() and the time series read.
  BLAZE_HD double stored_energy(const ContactGeometry<Real>& g) const { return normal.stored_energy(g.overlap, g.r_eff); }
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
