// Data-parallel primitives the pipeline needs beyond for_each:
//   RadixSorter<Space>::sort_pairs  stable sort of (uint32 key, Index value) pairs by key
//   reduce_max(space, n, f)         max over i of an int-valued functor f(i)
//   reduce_in_order(space, n, f, p) a deterministic reduction of values f(i) (sums in double)
// Cuda uses CUB (from the CUDA toolkit's CCCL) with scratch kept between calls, so the time-step
// loop does not allocate. Host uses our own OpenMP LSD radix sort: CCCL is not a Debian package,
// and a radix sort over bounded cell keys is O(N) where std::stable_sort is O(N log N).
#pragma once
#include <algorithm>
#include <cstdint>
#include <type_traits>
#include <vector>
#include "blaze/exec/buffer.hpp"
#include "blaze/exec/launch.hpp"
#if defined(_OPENMP)
#include <omp.h>
#endif
#if BLAZE_DEVICE_CODE
#include <cub/device/device_radix_sort.cuh>
#endif

namespace blaze {

template <class Space>
class RadixSorter;

template <>
class RadixSorter<Host> {
 public:
  // Sorts keys[0,n) ascending, carrying values along; equal keys keep their order.
  // Only bits [0, end_bit) of the keys are examined.
  void sort_pairs(std::uint32_t* keys, Index* values, Index n, int end_bit) {
    if (n <= 1) return;
    keys_alt_.resize(static_cast<std::size_t>(n));
    values_alt_.resize(static_cast<std::size_t>(n));
    std::uint32_t* k_in = keys;
    Index* v_in = values;
    std::uint32_t* k_out = keys_alt_.data();
    Index* v_out = values_alt_.data();
    for (int shift = 0; shift < end_bit; shift += kDigitBits) {
      pass(k_in, v_in, k_out, v_out, n, shift);
      std::swap(k_in, k_out);
      std::swap(v_in, v_out);
    }
    if (k_in != keys) {
      std::copy(k_in, k_in + n, keys);
      std::copy(v_in, v_in + n, values);
    }
  }

 private:
  static constexpr int kDigitBits = 11;
  static constexpr int kBuckets = 1 << kDigitBits;

  void pass(const std::uint32_t* k_in, const Index* v_in, std::uint32_t* k_out, Index* v_out, Index n,
            int shift) {
#if defined(_OPENMP)
    const int threads = omp_get_max_threads();
#else
    const int threads = 1;
#endif
    counts_.assign(static_cast<std::size_t>(threads) * kBuckets, 0);
    const Index chunk = (n + threads - 1) / threads;
#pragma omp parallel num_threads(threads)
    {
#if defined(_OPENMP)
      const int t = omp_get_thread_num();
#else
      const int t = 0;
#endif
      const Index lo = std::min<Index>(n, t * chunk), hi = std::min<Index>(n, lo + chunk);
      Index* c = counts_.data() + static_cast<std::size_t>(t) * kBuckets;
      for (Index i = lo; i < hi; ++i) ++c[(k_in[i] >> shift) & (kBuckets - 1)];
#pragma omp barrier
#pragma omp single
      {
        // Exclusive scan in (bucket, thread) order keeps the sort stable.
        Index sum = 0;
        for (int b = 0; b < kBuckets; ++b)
          for (int tt = 0; tt < threads; ++tt) {
            Index& x = counts_[static_cast<std::size_t>(tt) * kBuckets + b];
            const Index v = x;
            x = sum;
            sum += v;
          }
      }
      for (Index i = lo; i < hi; ++i) {
        const Index dst = c[(k_in[i] >> shift) & (kBuckets - 1)]++;
        k_out[dst] = k_in[i];
        v_out[dst] = v_in[i];
      }
    }
  }

  std::vector<std::uint32_t> keys_alt_;
  std::vector<Index> values_alt_;
  std::vector<Index> counts_;
};

template <class F>
int reduce_max(Host, Index n, const F& f, int init) {
  int result = init;
#pragma omp parallel for reduction(max : result) schedule(static)
  for (Index i = 0; i < n; ++i) result = std::max(result, f(i));
  return result;
}

// reduce_in_order: V is trivially copyable, V{} the identity, v.combine(w) folds w into v
// (BLAZE_HD). The n values are cut into a fixed number of parts for the space, each part folded
// in index order by one thread, the parts folded in order on the host: the same n gives the same
// result bit for bit on any thread count, with no atomics. Host: contiguous chunks (cache order);
// Cuda: part t takes i = t, t + parts, ... (coalesced reads). The two backends therefore add in
// different orders (a few ulps apart in a sum of ~n terms). `parts`: scratch kept by the caller.
template <class Space>
inline constexpr Index kReduceParts = 256;
#if BLAZE_DEVICE_CODE
template <>
inline constexpr Index kReduceParts<Cuda> = 16384;
#endif

template <class V, class F>
struct ReducePart {
  F f;
  V* out;
  Index n, parts;
  bool strided;
  BLAZE_HD void operator()(Index t) const {
    V v{};
    if (strided) {
      for (Index i = t; i < n; i += parts) v.combine(f(i));
    } else {
      const Index lo = static_cast<Index>(static_cast<long long>(n) * t / parts);
      const Index hi = static_cast<Index>(static_cast<long long>(n) * (t + 1) / parts);
      for (Index i = lo; i < hi; ++i) v.combine(f(i));
    }
    out[t] = v;
  }
};

template <class V, class F, class Space>
V reduce_in_order(Space, Index n, const F& f, Buffer<V, Space>& parts) {
  V v{};
  if (n <= 0) return v;
  const Index p = std::min(n, kReduceParts<Space>);
  if (parts.size() < static_cast<std::size_t>(p)) parts.resize(static_cast<std::size_t>(kReduceParts<Space>));
  for_each(Space{}, p, ReducePart<V, F>{f, parts.data(), n, p, !std::is_same_v<Space, Host>});
  for (const V& w : to_host(parts, static_cast<std::size_t>(p))) v.combine(w);
  return v;
}

#if BLAZE_DEVICE_CODE
template <>
class RadixSorter<Cuda> {
 public:
  void sort_pairs(std::uint32_t* keys, Index* values, Index n, int end_bit) {
    if (n <= 1) return;
    keys_alt_.ensure(static_cast<std::size_t>(n));
    values_alt_.ensure(static_cast<std::size_t>(n));
    cub::DoubleBuffer<std::uint32_t> k(keys, keys_alt_.data());
    cub::DoubleBuffer<Index> v(values, values_alt_.data());
    std::size_t bytes = 0;
    cuda_check(cub::DeviceRadixSort::SortPairs(nullptr, bytes, k, v, n, 0, end_bit), "cub sort size");
    temp_.ensure(bytes);
    cuda_check(cub::DeviceRadixSort::SortPairs(temp_.data(), bytes, k, v, n, 0, end_bit), "cub sort");
    if (k.Current() != keys) {
      cuda_check(cudaMemcpyAsync(keys, k.Current(), n * sizeof(std::uint32_t), cudaMemcpyDeviceToDevice), "copy");
      cuda_check(cudaMemcpyAsync(values, v.Current(), n * sizeof(Index), cudaMemcpyDeviceToDevice), "copy");
    }
  }

 private:
  Buffer<std::uint32_t, Cuda> keys_alt_;
  Buffer<Index, Cuda> values_alt_;
  Buffer<unsigned char, Cuda> temp_;
};

template <class F>
__global__ void reduce_max_kernel(Index n, F f, int* out) {
  int v = INT_MIN;
  for (Index i = blockIdx.x * blockDim.x + threadIdx.x; i < n; i += gridDim.x * blockDim.x) v = max(v, f(i));
  for (int o = 16; o > 0; o /= 2) v = max(v, __shfl_down_sync(0xffffffffu, v, o));
  if ((threadIdx.x & 31) == 0) atomicMax(out, v);
}

// Max is order-independent, so the atomic combine is deterministic.
template <class F>
int reduce_max(Cuda, Index n, const F& f, int init) {
  static Buffer<int, Cuda> slot(1);
  cuda_check(cudaMemcpy(slot.data(), &init, sizeof(int), cudaMemcpyHostToDevice), "reduce init");
  if (n > 0) {
    const int blocks = std::min<Index>((n + kBlockSize - 1) / kBlockSize, 4096);
    reduce_max_kernel<<<blocks, kBlockSize>>>(n, f, slot.data());
    cuda_check(cudaGetLastError(), "reduce_max launch");
  }
  return read_one(slot.data(), Cuda{});
}

#endif

}  // namespace blaze
