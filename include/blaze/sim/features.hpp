// Compile-time feature switches: what a scene does not need compiles to nothing.
#pragma once

namespace blaze {

template <bool Rotation, bool Statistics = false>
struct FeatureSet {
  static constexpr bool rotation = Rotation;      // torques, angular velocity, orientation
  static constexpr bool statistics = Statistics;  // contact counts by kind, every step
};
using FullFeatures = FeatureSet<true>;
using TranslationOnly = FeatureSet<false>;
using FullFeaturesWithStatistics = FeatureSet<true, true>;

}  // namespace blaze
