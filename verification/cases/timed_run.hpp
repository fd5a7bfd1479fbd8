// Runs a simulation for `steps` steps in chunks of `per_sample`, calling sample() before the first
// chunk and after each one; returns the wall time (s) of the stepping alone, each chunk fenced so
// device work is counted and sampling (a device-to-host copy) is not. Used by the cases that feed
// the work-precision study.
#pragma once
#include <algorithm>
#include <chrono>
#include <cstdint>
#include "blaze/exec/space.hpp"

namespace blaze::test::cases {

template <class Sim, class Sample>
double run_sampled(Sim& sim, long steps, long per_sample, Sample&& sample) {
  double wall_s = 0;
  sample();
  for (long done = 0; done < steps;) {
    const long n = std::min(per_sample, steps - done);
    const auto t0 = std::chrono::steady_clock::now();
    sim.run(static_cast<std::uint64_t>(n));
    fence(DefaultSpace{});
    wall_s += std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    done += n;
    sample();
  }
  return wall_s;
}

}  // namespace blaze::test::cases
