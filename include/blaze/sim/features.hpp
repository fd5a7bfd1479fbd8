// Compile-time feature switches: what a scene does not need compiles to nothing.
#pragma once

namespace blaze {

template <bool Rotation, bool Statistics = false, bool Monitor = false>
struct FeatureSet {
  static constexpr bool rotation = Rotation;      // torques, angular velocity, orientation
  static constexpr bool statistics = Statistics;  // contact counts by kind, every step
  static constexpr bool monitor = Monitor;        // per-particle deepest overlap / radius, every step
};
using FullFeatures = FeatureSet<true>;
using TranslationOnly = FeatureSet<false>;
using FullFeaturesWithStatistics = FeatureSet<true, true>;
// What `blaze run` uses: everything, plus the contact counts and penetration its output reports.
using MonitoredFeatures = FeatureSet<true, true, true>;

}  // namespace blaze
