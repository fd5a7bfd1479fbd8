// Time per pipeline phase. When enabled, each phase is measured by the space's Stopwatch: on the
// GPU by CUDA events around the phase's kernels (the GPU's time, not the host's), waiting for the
// phase to finish before the next is queued, so work is attributed to the phase that queued it
// (at the cost of one synchronisation per phase: benchmarks enable it, production runs do not).
#pragma once
#include <memory>
#include <string>
#include <utility>
#include <vector>
#include "blaze/exec/stopwatch.hpp"

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
    if (!watch_) watch_ = std::make_shared<Stopwatch<Space>>();
    fence(Space{});
    watch_->start();
    f();
    const double t = watch_->stop_seconds();
    for (auto& [name, total] : seconds_)
      if (name == phase) {
        total += t;
        return;
      }
    seconds_.emplace_back(phase, t);
  }
  // Seconds per phase, in the order the phases first ran (the pipeline's order).
  const std::vector<std::pair<std::string, double>>& seconds() const { return seconds_; }
  double seconds(const std::string& phase) const {
    for (const auto& [name, total] : seconds_)
      if (name == phase) return total;
    return 0;
  }
  void reset() { seconds_.clear(); }

 private:
  std::vector<std::pair<std::string, double>> seconds_;
  std::shared_ptr<Stopwatch<Space>> watch_;  // created on first use (no CUDA call before then)
};

}  // namespace blaze
