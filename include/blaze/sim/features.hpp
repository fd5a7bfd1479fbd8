// Compile-time feature switches: what a scene does not need compiles to nothing.
#pragma once

namespace blaze {

template <bool Rotation, bool Statistics = false, bool Monitor = false, bool ThesisPower = false>
struct FeatureSet {
  static constexpr bool rotation = Rotation;      // torques, angular velocity, orientation
  static constexpr bool statistics = Statistics;  // contact counts by kind, every step
  static constexpr bool monitor = Monitor;        // per-particle deepest overlap / radius, every step
  // the thesis's mill-power estimate sum |F_diss| |V| dt per contact, every step, with the energy
  // accounts (blaze/particles/energy_ledger.hpp, EnergyLedger::thesis_estimate; study_mill)
  static constexpr bool thesis_power = ThesisPower;
};
using FullFeatures = FeatureSet<true>;
using TranslationOnly = FeatureSet<false>;
using FullFeaturesWithStatistics = FeatureSet<true, true>;
// What `blaze run` uses: everything, plus the contact counts and penetration its output reports.
using MonitoredFeatures = FeatureSet<true, true, true>;
// study_mill: what `blaze run` uses, plus the thesis's power estimate beside the exact methods.
using MillStudyFeatures = FeatureSet<true, true, true, true>;

}  // namespace blaze
