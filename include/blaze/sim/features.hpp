// Compile-time feature switches: what a scene does not need compiles to nothing.
#pragma once

namespace blaze {

template <bool Rotation>
struct FeatureSet {
  static constexpr bool rotation = Rotation;  // torques, angular velocity, orientation
};
using FullFeatures = FeatureSet<true>;
using TranslationOnly = FeatureSet<false>;

}  // namespace blaze
