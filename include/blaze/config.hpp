// The one place that names host/device qualifiers.
// Every kernel body is written once: under nvcc it is compiled for host and device, under g++ for
// the host only (the OpenMP backend).
#pragma once
#include <cstdint>

// BLAZE_HD_INLINE: a helper that two kernels share and that must still be inlined into both
// (g++ -O2 does not inline a large function called from two places on its own: the pair
// arithmetic of kernels/contact_pair.hpp, out of line, made the CPU sphere step 1.4x slower).
#if defined(__CUDACC__)
#define BLAZE_HD __host__ __device__
#define BLAZE_HD_INLINE __host__ __device__ __forceinline__
#define BLAZE_DEVICE_CODE 1
#else
#define BLAZE_HD
#define BLAZE_HD_INLINE inline __attribute__((always_inline))
#define BLAZE_DEVICE_CODE 0
#endif

// BLAZE_UNROLL: before a loop of constant trip count whose index picks an array element, so that
// the array stays in registers (indexed at run time, nvcc puts it in local memory). g++ takes
// its own spelling; nvcc's host pass, which knows neither, none (its host code does not step).
#if defined(__CUDA_ARCH__)
#define BLAZE_UNROLL _Pragma("unroll")
#elif defined(__CUDACC__)
#define BLAZE_UNROLL
#else
#define BLAZE_UNROLL _Pragma("GCC unroll 16")
#endif

namespace blaze {
// Particle and neighbour indices: 32 bits reach 2.1e9 particles, far beyond one GPU's memory.
using Index = std::int32_t;
}  // namespace blaze
