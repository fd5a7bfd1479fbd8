// Wall-clock time per pipeline phase. When enabled, each phase is fenced on both sides, so GPU
// work is attributed to the phase that queued it (at the cost of one synchronisation per phase:
// benchmarks enable it, production runs do not).
#pragma once
#include <chrono>
#include <map>
#include <string>
#include "blaze/exec/space.hpp"

namespace blaze {

template <class Space>
class PhaseTimer {
 public:
  bool enabled = false;

  template <class F>
  void time(const char* phase, F&& f) {
    if (!enabled) {
      f();
      return;
    }
    fence(Space{});
    const auto t0 = std::chrono::steady_clock::now();
    f();
    fence(Space{});
    seconds_[phase] += std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  }
  const std::map<std::string, double>& seconds() const { return seconds_; }
  void reset() { seconds_.clear(); }

 private:
  std::map<std::string, double> seconds_;
};

}  // namespace blaze
