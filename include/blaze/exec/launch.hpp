// The one launcher: for_each(space, n, f) calls f(i) for i in [0, n).
// Host: an OpenMP loop with static scheduling. Cuda: one thread per i.
// Functors are trivially copyable structs of views with a const BLAZE_HD operator()(Index).
#pragma once
#include <type_traits>
#include "blaze/exec/space.hpp"

namespace blaze {

// Blocks of 256 threads per SM that a functor's kernel must fit: its kMinBlocks, declared as
// __launch_bounds__(256, kMinBlocks); 0 (the default) declares nothing. 4 caps the registers at
// 65536 / (256 x 4) = 64 per thread. The polyhedron contact kernels ask for 4: uncapped they took
// 128 registers and ran at 25% occupancy; on the H200 at 1e6 bodies the cap took packed cubes
// from 2.3e7 to 3.8e7 particle-steps/s, packed dodecahedra 6.0e7 -> 8.1e7, falling cubes
// 2.5e8 -> 4.5e8. Declaring (256, 1) is not the same as declaring nothing: ptxas then allows
// other register counts. The bisection of stop 14 (H200, 1e7 frictionless non-rotating bed)
// found the lean sphere contact kernel at 0.97 ms per step without the attribute and 1.17 ms with
// (256, 1) or (256, 4), while the sphere wall kernel ran at 0.22 ms with (256, 1) and 0.29 ms
// without; so each kernel says what it wants (world_forces.hpp, contact_forces.hpp).
template <class F, class = void>
struct MinBlocks {
  static constexpr int value = 0;
};
template <class F>
struct MinBlocks<F, std::void_t<decltype(F::kMinBlocks)>> {
  static constexpr int value = F::kMinBlocks;
};
template <class F>
inline constexpr int min_blocks_v = MinBlocks<F>::value;

template <class F>
void for_each(Host, Index n, const F& f) {
  static_assert(std::is_trivially_copyable_v<F>, "kernel functors are passed by value to the GPU");
#pragma omp parallel for schedule(static)
  for (Index i = 0; i < n; ++i) f(i);
}

#if BLAZE_DEVICE_CODE
constexpr int kBlockSize = 256;
template <class F>
__device__ __forceinline__ void for_each_thread(Index n, const F& f) {
  const Index i = static_cast<Index>(blockIdx.x) * blockDim.x + threadIdx.x;
  if (i < n) f(i);
}
template <class F>
__global__ void for_each_kernel(Index n, F f) {
  for_each_thread(n, f);
}
template <class F>
__global__ void __launch_bounds__(kBlockSize, min_blocks_v<F>) for_each_bounded_kernel(Index n, F f) {
  for_each_thread(n, f);
}

template <class F>
void for_each(Cuda, Index n, const F& f) {
  static_assert(std::is_trivially_copyable_v<F>, "kernel functors are passed by value to the GPU");
  if (n <= 0) return;
  const unsigned blocks = static_cast<unsigned>((n + kBlockSize - 1) / kBlockSize);
  if constexpr (min_blocks_v<F> > 0)
    for_each_bounded_kernel<<<blocks, kBlockSize>>>(n, f);
  else
    for_each_kernel<<<blocks, kBlockSize>>>(n, f);
  cuda_check(cudaGetLastError(), "kernel launch");
}
#endif

// *p = v, returning what *p held, atomically among the threads of one for_each (a linked list
// built from many threads: kernels/placement.hpp).
BLAZE_HD inline int atomic_exchange(int* p, int v) {
#if defined(__CUDA_ARCH__)
  return atomicExch(p, v);
#else
  return __atomic_exchange_n(p, v, __ATOMIC_RELAXED);
#endif
}

// data[i] = value for i in [0, n): for_each(space, n, Fill<T>{data, value}).
template <class T>
struct Fill {
  T* data;
  T value;
  BLAZE_HD void operator()(Index i) const { data[i] = value; }
};

}  // namespace blaze
