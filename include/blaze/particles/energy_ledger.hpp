// Each particle's energy accounts (J, since the last sample), kept when the world moves or a run
// asks for them (SimulationParams::energy_ledger); the sample (kernels/sample_tally.hpp) adds them
// up and resets them. Columns:
//   drive        W = sum (F . v_w(p) + M . omega_w) dt over the particle's contacts with moving
//                world objects (F, M: the contact's force on the particle and its moment about the
//                contact point p; v_w, omega_w: the object's velocity at p and its spin): the work
//                the drive does on the charge
//   pair         D = -sum (F_i . v_i + T_i . w_i) dt, F_i and T_i the particle's summed
//                particle-particle contact force and torque (about its centre): summed over all
//                particles, the energy the particle-particle contacts took out of the motion
//   wall classes D_c = -sum (F_c . v_i + T_c . w_i - W_c) dt, F_c, T_c and W_c the particle's
//                force, torque and drive power from its contacts with objects of class c (world.hpp:
//                wall, shell, lifter, end plate)
// Over a contact's life the elastic part of -P dt integrates to zero (its stored energy is zero
// when it opens), so D is what the dashpots, friction and rolling resistance dissipated, plus the
// elastic energy the contacts hold at the sample (StoredContactEnergy reports it).
// Exact booking: velocity Verlet changes a particle's kinetic energy between the half steps
// n - 1/2 and n + 1/2 by exactly F_n . v_n dt (v_n = (v_{n-1/2} + v_{n+1/2}) / 2, the velocity
// after the step's second kick), so the accounts are booked after that kick
// (kernels/integrate.hpp, book_energy) with v_n, w_n, not at the forces' evaluation (whose
// predicted velocity differs by (a_n - a_{n-1}) dt / 2: booked there, a mill's accounts were 28%
// off with the thesis's eq. 4.3 friction at mu = 0.5). The world kernel leaves the wall classes'
// F_c, T_c per particle in `class_sums` for it (6 reals per class, 24 per particle; pairs are the
// rest of the particle's force and torque), and in `class_mask` (bit c) the classes it wrote this
// step: only those are read, the others are zero. A particle that touches no wall (most) costs a
// byte written and read per step instead of 24 reals each way (the 242-ball lab mill on an H100:
// the last kick's phase, which reads them, went from 3 419 to 2 250 cycles a step).
// The thesis's own estimate (section 4.1.4.1), kept beside them when the kernels are compiled with
// Features::thesis_power (study_mill): E = sum over contacts and steps of |F_diss| |V| dt, F_diss
// the contact's damping force (its normal force less the elastic part) plus its tangential force,
// V the relative velocity at the contact point (a pair booked half to each side when it is
// evaluated from both). Not checkpointed: a restored run starts it from zero.
// This is the energy method of mill power (the thesis's section 4.1.4 sums |F_diss| |v| dt over
// the dissipative forces, an upper bound of their work: |F . v| <= |F| |v|; the power above is the
// rate of the same work for any law, history included).
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
BLAZE_HD inline constexpr int ledger_column(ContactClass c) { return kLedgerWalls + static_cast<int>(c); }

inline constexpr int kClassSumReals = 6 * kContactClasses;  // F_c (3), T_c (3) per wall class

template <class Real>
struct EnergyLedger {
  Real* column[kLedgerColumns];  // null: not kept
  Real* class_sums;              // [(6 c + k) n + i]: F_c then T_c of particle i (k = 0..5)
  std::uint8_t* class_mask;      // [i]: bit c set when class c's sums of particle i are this step's
  Index n;                       // the stride of class_sums
  Real* thesis_estimate;         // J per particle, the thesis's sum |F_diss| |V| dt; null: not kept
  BLAZE_HD bool on() const { return column[0] != nullptr; }
  BLAZE_HD Real& sum(int c, int k, Index i) const { return class_sums[static_cast<std::size_t>(6 * c + k) * n + i]; }
};

}  // namespace blaze
