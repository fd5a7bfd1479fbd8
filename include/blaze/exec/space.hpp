// Execution/memory spaces. A space is a tag type; code is templated on it, so one binary built by
// nvcc can run the same kernels on the host (OpenMP) and on the GPU, and compare them.
#pragma once
#include <cstddef>
#include <cstdlib>
#include <cstring>
#include <new>
#include <stdexcept>
#include <string>
#include "blaze/config.hpp"
#if BLAZE_DEVICE_CODE
#include <cuda_runtime.h>
#endif

namespace blaze {

// An allocation that the memory space could not satisfy; what() names the space and the size.
// (The run's memory estimate, memory_estimate.hpp, is meant to refuse such a scene before.)
struct OutOfMemory : std::runtime_error {
  using std::runtime_error::runtime_error;
};

struct Host {
  static constexpr const char* name = "cpu";
  static void* allocate(std::size_t bytes) {
    if (bytes == 0) return nullptr;
    const std::size_t rounded = (bytes + 63) / 64 * 64;
    void* p = std::aligned_alloc(64, rounded);
    if (!p) throw OutOfMemory("out of host memory: an allocation of " + std::to_string(bytes) + " bytes failed");
#ifdef BLAZE_POISON_ALLOC
    // Debug builds (make poison): every byte 0xFF, so a read before the first write is a NaN
    // (float, double) or -1, as stale GPU memory from an earlier run can be, never a lucky zero.
    std::memset(p, 0xFF, rounded);
#endif
    return p;
  }
  static void deallocate(void* p) { std::free(p); }
};

#if BLAZE_DEVICE_CODE
inline void cuda_check(cudaError_t err, const char* what) {
  if (err != cudaSuccess)
    throw std::runtime_error(std::string("CUDA error in ") + what + ": " + cudaGetErrorString(err));
}

struct Cuda {
  static constexpr const char* name = "gpu";
  static void* allocate(std::size_t bytes) {
    if (bytes == 0) return nullptr;
    void* p = nullptr;
    const cudaError_t err = cudaMalloc(&p, bytes);
    if (err == cudaErrorMemoryAllocation) {
      (void)cudaGetLastError();  // clear it: the context stays usable for the report
      throw OutOfMemory("out of GPU memory: an allocation of " + std::to_string(bytes) + " bytes failed");
    }
    cuda_check(err, "cudaMalloc");
    return p;
  }
  static void deallocate(void* p) {
    if (p) cudaFree(p);
  }
};
using DefaultSpace = Cuda;
#else
using DefaultSpace = Host;
#endif

// Wait for all work queued in a space (timing, host reads).
inline void fence(Host) {}
#if BLAZE_DEVICE_CODE
inline void fence(Cuda) { cuda_check(cudaDeviceSynchronize(), "cudaDeviceSynchronize"); }
#endif

}  // namespace blaze
