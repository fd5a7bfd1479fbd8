// A counter-based random engine: the numbers of draw k of a stream depend on (key, k) only, so
// draws can be made in any order and on any number of threads with the same result, and a stream's
// state is one counter (what a checkpoint keeps).
//
// Each engine is SplitMix64 (Steele, Lea & Flood, "Fast splittable pseudorandom number
// generators", OOPSLA 2014: state += 0x9e3779b97f4a7c15, output = the state through the MurmurHash3
// finalizer variant "Mix13"), started from mix(key ^ mix(k)): distinct (key, k) start far apart in
// its period of 2^64. It meets the standard's UniformRandomBitGenerator, so std:: distributions
// take it. Not for cryptography; for placing particles and jittering velocities.
#pragma once
#include <cstdint>
#include "blaze/config.hpp"

namespace blaze {

class CounterEngine {
 public:
  using result_type = std::uint64_t;
  BLAZE_HD static constexpr result_type min() { return 0; }
  BLAZE_HD static constexpr result_type max() { return ~result_type{0}; }
  BLAZE_HD static constexpr std::uint64_t mix(std::uint64_t z) {
    z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9ull;
    z = (z ^ (z >> 27)) * 0x94d049bb133111ebull;
    return z ^ (z >> 31);
  }
  // Draw k of the stream `key`.
  BLAZE_HD CounterEngine(std::uint64_t key, std::uint64_t k) : state_(mix(key ^ mix(k + 0x9e3779b97f4a7c15ull))) {}
  BLAZE_HD result_type operator()() { return mix(state_ += 0x9e3779b97f4a7c15ull); }

 private:
  std::uint64_t state_;
};

}  // namespace blaze
