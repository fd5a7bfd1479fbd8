// device_name() definitions (header-only: inline).
#pragma once
#include <sys/resource.h>

#include <algorithm>
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

// Host memory a run can take (bytes): MemAvailable of /proc/meminfo, capped by the address-space
// limit (ulimit -v) when one is set; 0 when unknown (not Linux).
inline double available_memory(Host) {
  double available = 0;
  std::ifstream in("/proc/meminfo");
  for (std::string key; in >> key;) {
    double kb = 0;
    in >> kb;
    if (key == "MemAvailable:") available = kb * 1024;
    std::string unit;
    std::getline(in, unit);
  }
  rlimit lim{};
  if (getrlimit(RLIMIT_AS, &lim) == 0 && lim.rlim_cur != RLIM_INFINITY)
    available = available > 0 ? std::min(available, static_cast<double>(lim.rlim_cur)) : static_cast<double>(lim.rlim_cur);
  return available;
}

inline int host_threads() {
#if defined(_OPENMP)
  return omp_get_max_threads();
#else
  return 1;
#endif
}

#if BLAZE_DEVICE_CODE
// Free memory of the current GPU (bytes).
inline double available_memory(Cuda) {
  std::size_t free = 0, total = 0;
  cuda_check(cudaMemGetInfo(&free, &total), "cudaMemGetInfo");
  return static_cast<double>(free);
}

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
