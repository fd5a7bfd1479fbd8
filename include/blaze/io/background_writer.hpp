// Output written while the run goes on: one task at a time on a background thread. A VTU frame
// of 10^6 particles (87 MB) took ~0.5 s to assemble and write, with the GPU idle meanwhile
// (bench/results/levers/history-bounds.md: output was 35% of a realistic run). start() waits for
// the previous task, rethrowing its error, before it starts the next, so frames are written in
// order and one at a time; wait() before the run reports what it wrote. A task owns (or shares
// ownership of) everything it reads.
#pragma once
#include <future>
#include <utility>

namespace blaze {

class BackgroundWriter {
 public:
  BackgroundWriter() = default;
  BackgroundWriter(const BackgroundWriter&) = delete;
  BackgroundWriter& operator=(const BackgroundWriter&) = delete;
  // A run that ends by an error leaves the task to finish, its own error unreported.
  ~BackgroundWriter() {
    if (pending_.valid()) pending_.wait();
  }

  template <class Task>
  void start(Task&& task) {
    wait();
    pending_ = std::async(std::launch::async, std::forward<Task>(task));
  }
  void wait() {
    if (pending_.valid()) pending_.get();
  }

 private:
  std::future<void> pending_;
};

}  // namespace blaze
