// The one launcher: for_each(space, n, f) calls f(i) for i in [0, n).
// Host: an OpenMP loop with static scheduling. Cuda: one thread per i.
// Functors are trivially copyable structs of views with a const BLAZE_HD operator()(Index).
#pragma once
#include <type_traits>
#include "blaze/exec/space.hpp"

namespace blaze {

template <class F>
void for_each(Host, Index n, const F& f) {
  static_assert(std::is_trivially_copyable_v<F>, "kernel functors are passed by value to the GPU");
#pragma omp parallel for schedule(static)
  for (Index i = 0; i < n; ++i) f(i);
}

#if BLAZE_DEVICE_CODE
constexpr int kBlockSize = 256;
// Blocks of kBlockSize per SM the compiler must fit, which caps registers at 65536 / (256 x 4) =
// 64 per thread. Measured on the H200 at 1e6 bodies (particle-steps/s, no cap -> cap 4): packed
// cubes 2.3e7 -> 3.8e7, packed dodecahedra 6.0e7 -> 8.1e7, falling cubes 2.5e8 -> 4.5e8; spheres
// unchanged (3.1e9). Without the cap the polyhedron contact kernel took 128 registers and ran at
// 25% occupancy. Override with -DBLAZE_MIN_BLOCKS=n to measure.
#ifndef BLAZE_MIN_BLOCKS
#define BLAZE_MIN_BLOCKS 4
#endif

template <class F>
__global__ void __launch_bounds__(kBlockSize, BLAZE_MIN_BLOCKS) for_each_kernel(Index n, F f) {
  const Index i = static_cast<Index>(blockIdx.x) * blockDim.x + threadIdx.x;
  if (i < n) f(i);
}

template <class F>
void for_each(Cuda, Index n, const F& f) {
  static_assert(std::is_trivially_copyable_v<F>, "kernel functors are passed by value to the GPU");
  if (n <= 0) return;
  for_each_kernel<<<(n + kBlockSize - 1) / kBlockSize, kBlockSize>>>(n, f);
  cuda_check(cudaGetLastError(), "kernel launch");
}
#endif

// data[i] = value for i in [0, n): for_each(space, n, Fill<T>{data, value}).
template <class T>
struct Fill {
  T* data;
  T value;
  BLAZE_HD void operator()(Index i) const { data[i] = value; }
};

}  // namespace blaze
