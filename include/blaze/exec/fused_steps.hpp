// fused_steps(space, n, k, phases, flags): up to k time steps of a small system in one go. Each
// step runs the phases of Simulation::step() in order, each over i in [0, n):
//   pre(i);  code = max_i check(i), written to flags[s];  if code != 0: stop here;
//   contacts(i);  walls(i) (when has_walls);  post(i)
// A phase reads what the previous phase wrote for any i and writes only its own i, so the result
// is bitwise that of one kernel per phase. Cuda: one block runs all k steps, the phases separated
// by __syncthreads(): no kernel launch and no host round trip per step, which is what a step of a
// few hundred particles costs otherwise (issue 6: the 242-ball mill). Host: the same phases as
// for_each loops. A step whose check is nonzero stops the batch just after its pre phase, so the
// caller finishes that step (rebuild, or the NaN report) as step() would.
#pragma once
#include <cstdint>
#include <type_traits>
#include "blaze/exec/launch.hpp"
#include "blaze/exec/primitives.hpp"

namespace blaze {

// Up to this many particles the one-block path is used (16 particles per thread at most).
constexpr Index kFusedMaxParticles = 4096;

template <class Pre, class Check, class Contacts, class Walls, class Post>
void fused_steps(Host, Index n, std::uint64_t k, const Pre& pre, const Check& check, const Contacts& contacts,
                 const Walls& walls, bool has_walls, const Post& post, int* flags) {
  for (std::uint64_t s = 0; s < k; ++s) {
    for_each(Host{}, n, pre);
    flags[s] = reduce_max(Host{}, n, check, 0);
    if (flags[s] != 0) return;
    for_each(Host{}, n, contacts);
    if (has_walls) for_each(Host{}, n, walls);
    for_each(Host{}, n, post);
  }
}

#if BLAZE_DEVICE_CODE
constexpr int kFusedBlockSize = 256;

// The five functors, read from device memory: with a polyhedron shape table in each they exceed
// the kernel parameter space.
template <class Pre, class Check, class Contacts, class Walls, class Post>
struct FusedPhases {
  Pre pre;
  Check check;
  Contacts contacts;
  Walls walls;
  Post post;
};

template <class Phases>
__global__ void __launch_bounds__(kFusedBlockSize)
    fused_steps_kernel(Index n, std::uint64_t k, const Phases* ph, bool has_walls, int* flags) {
  __shared__ int code;
  for (std::uint64_t s = 0; s < k; ++s) {
    for (Index i = threadIdx.x; i < n; i += blockDim.x) ph->pre(i);
    if (threadIdx.x == 0) code = 0;
    __syncthreads();
    int c = 0;
    for (Index i = threadIdx.x; i < n; i += blockDim.x) c = max(c, ph->check(i));
    atomicMax(&code, c);
    __syncthreads();
    const int step_code = code;  // the same in every thread: the loop exits together
    if (threadIdx.x == 0) flags[s] = step_code;
    if (step_code != 0) return;
    for (Index i = threadIdx.x; i < n; i += blockDim.x) ph->contacts(i);
    __syncthreads();
    if (has_walls) {
      for (Index i = threadIdx.x; i < n; i += blockDim.x) ph->walls(i);
      __syncthreads();
    }
    for (Index i = threadIdx.x; i < n; i += blockDim.x) ph->post(i);
    __syncthreads();
  }
}

template <class Pre, class Check, class Contacts, class Walls, class Post>
void fused_steps(Cuda, Index n, std::uint64_t k, const Pre& pre, const Check& check, const Contacts& contacts,
                 const Walls& walls, bool has_walls, const Post& post, int* flags) {
  using Phases = FusedPhases<Pre, Check, Contacts, Walls, Post>;
  static_assert(std::is_trivially_copyable_v<Phases>, "kernel functors are copied to the GPU as bytes");
  if (n <= 0 || k == 0) return;
  static Buffer<Phases, Cuda> slot(1);  // one per instantiation, kept
  const Phases host{pre, check, contacts, walls, post};
  copy_n(&host, 1, slot.data(), Host{}, Cuda{});
  fused_steps_kernel<<<1, kFusedBlockSize>>>(n, k, slot.data(), has_walls, flags);
  cuda_check(cudaGetLastError(), "fused_steps launch");
}
#endif

}  // namespace blaze
