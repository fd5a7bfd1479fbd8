// Each particle's energy accounts (J, since the last sample), kept when the world moves or a run
// asks for them (SimulationParams::energy_ledger); the sample (kernels/sample_tally.hpp) adds them
// up and resets them. Columns:
//   drive        W = sum F . v_w(p) dt + M . omega_w dt: the work moving world objects do on the
//                particle (F, M: the contact's force on the particle and its moment about the
//                contact point p; v_w, omega_w: the object's velocity at p and its spin)
//   pair         D = -sum P dt over the particle's particle-particle contacts, where
//                P = F . (v_i - v_j) + (r_i x F + M) . w_i - (r_j x F + M) . w_j   [W]
//                is the power of the contact's force and moment on both bodies (r = p - x):
//                what the contact takes out of the bodies' motion. Over a contact's life the
//                elastic part integrates to zero (its stored energy is zero when it opens), so D
//                is what the dashpots, friction and rolling resistance dissipated, plus the elastic
//                energy the contact holds at the sample (StoredContactEnergy reports it).
//   wall classes D for the particle-world contacts, the same P with the object as body j
//                (v_j = v_w(p), w_j = omega_w), split by the object's contact class (world.hpp):
//                wall, shell, lifter, end plate.
// This is the energy method of mill power (the thesis's section 4.1.4 sums |F_diss| |v| dt over
// the dissipative forces; the power P above is the exact rate of the same work for any law,
// history included). A pair's account goes to the lower index when each pair is evaluated once,
// half to each side otherwise: the totals agree, per-particle values need not.
#pragma once
#include <cstdint>
#include "blaze/config.hpp"

namespace blaze {

// A world object's contact class, for the split of the dissipated energy (mill power).
enum class ContactClass : std::uint8_t { wall = 0, shell = 1, lifter = 2, end_plate = 3 };
inline constexpr int kContactClasses = 4;
inline const char* contact_class_name(int c) {
  static const char* const names[kContactClasses] = {"wall", "shell", "lifter", "end_plate"};
  return c >= 0 && c < kContactClasses ? names[c] : "?";
}

enum LedgerColumn : int { kLedgerDrive = 0, kLedgerPair = 1, kLedgerWalls = 2 };
inline constexpr int kLedgerColumns = kLedgerWalls + kContactClasses;
inline constexpr int ledger_column(ContactClass c) { return kLedgerWalls + static_cast<int>(c); }

template <class Real>
struct EnergyLedger {
  Real* column[kLedgerColumns];  // null: not kept
  BLAZE_HD bool on() const { return column[0] != nullptr; }
};

}  // namespace blaze
