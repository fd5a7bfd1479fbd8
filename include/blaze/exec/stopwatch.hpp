// Elapsed time of work queued in a space. Host: wall clock around the work (OpenMP loops return
// when done). GPU: CUDA events recorded in the stream before and after the work, so the time is
// the GPU's own (launch latency and host gaps before the first kernel excluded); reading it waits
// for the second event.
#pragma once
#include <chrono>
#include "blaze/exec/space.hpp"

namespace blaze {

template <class Space>
class Stopwatch {
 public:
  void start() { t0_ = std::chrono::steady_clock::now(); }
  double stop_seconds() { return std::chrono::duration<double>(std::chrono::steady_clock::now() - t0_).count(); }

 private:
  std::chrono::steady_clock::time_point t0_;
};

#if BLAZE_DEVICE_CODE
template <>
class Stopwatch<Cuda> {
 public:
  Stopwatch() {
    cuda_check(cudaEventCreate(&begin_), "cudaEventCreate");
    cuda_check(cudaEventCreate(&end_), "cudaEventCreate");
  }
  ~Stopwatch() {
    cudaEventDestroy(begin_);
    cudaEventDestroy(end_);
  }
  Stopwatch(const Stopwatch&) = delete;
  Stopwatch& operator=(const Stopwatch&) = delete;
  void start() { cuda_check(cudaEventRecord(begin_), "cudaEventRecord"); }
  double stop_seconds() {
    cuda_check(cudaEventRecord(end_), "cudaEventRecord");
    cuda_check(cudaEventSynchronize(end_), "cudaEventSynchronize");
    float ms = 0;
    cuda_check(cudaEventElapsedTime(&ms, begin_, end_), "cudaEventElapsedTime");
    return 1e-3 * ms;
  }

 private:
  cudaEvent_t begin_{}, end_{};
};
#endif

}  // namespace blaze
