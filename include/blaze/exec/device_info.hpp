// device_name() definitions (header-only: inline).
#pragma once
#include <fstream>
#include <string>
#include <thread>
#include "blaze/exec/space.hpp"
#if defined(_OPENMP)
#include <omp.h>
#endif

namespace blaze {

inline std::string device_name(Host) {
  std::string model = "unknown CPU";
  std::ifstream in("/proc/cpuinfo");
  for (std::string line; std::getline(in, line);) {
    if (line.rfind("model name", 0) == 0) {
      model = line.substr(line.find(':') + 2);
      break;
    }
  }
#if defined(_OPENMP)
  const int threads = omp_get_max_threads();
#else
  const int threads = 1;
#endif
  return model + " (" + std::to_string(threads) + " OpenMP threads)";
}

#if BLAZE_DEVICE_CODE
inline std::string device_name(Cuda) {
  int dev = 0;
  cuda_check(cudaGetDevice(&dev), "cudaGetDevice");
  cudaDeviceProp prop{};
  cuda_check(cudaGetDeviceProperties(&prop, dev), "cudaGetDeviceProperties");
  return std::string(prop.name) + " (sm_" + std::to_string(prop.major) + std::to_string(prop.minor) +
         ", " + std::to_string(prop.multiProcessorCount) + " SMs)";
}
#endif

}  // namespace blaze
