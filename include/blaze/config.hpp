// The one place that names host/device qualifiers.
// Every kernel body is written once: under nvcc it is compiled for host and device, under g++ for
// the host only (the OpenMP backend).
#pragma once
#include <cstdint>

#if defined(__CUDACC__)
#define BLAZE_HD __host__ __device__
#define BLAZE_DEVICE_CODE 1
#else
#define BLAZE_HD
#define BLAZE_DEVICE_CODE 0
#endif

namespace blaze {
// Particle and neighbour indices: 32 bits reach 2.1e9 particles, far beyond one GPU's memory.
using Index = std::int32_t;
}  // namespace blaze
