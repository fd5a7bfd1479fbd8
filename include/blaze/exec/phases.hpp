// A time step as a list of named phases over particles [0, n), run in order:
//   kernel_phase(name, f[, enabled])  f(i) for every i (a disabled phase is skipped); a functor
//                                     with items(n) runs over that many items instead (a thread
//                                     a neighbour-list entry, kernels/pair_forces.hpp)
//   check_phase(name, f)              code = max_i f(i); nonzero stops the step after this phase,
//                                     and the caller (the host) acts on it, then resumes the
//                                     phases after it (a rebuild; later, a feed or a migration)
//   check_phase(name, f, handler)     the same, but code kHandledCode is first handed to
//                                     `handler`, a phase list run in place (a rebuild without
//                                     leaving the batch: pipeline/in_block_rebuild.hpp); when
//                                     every check of the handler gives 0 the step goes on,
//                                     else it stops as without one (the host then does the
//                                     whole work, whatever the handler left). The one-block
//                                     kernel and the per-phase runner run handlers; a CUDA
//                                     graph's step hands the code to the host.
// A phase reads what earlier phases wrote for any i and writes only its own i, so the list runs
// the same way one launch per phase (run_phases: each phase timed by name) or many steps in one
// launch (fused_steps: small systems, where a launch and a host round trip per phase would cost
// more than the work). Adding a phase is adding it to the list: both runners take it as it is.
//
// fused_steps(space, n, k, phases, flags, one_block_max, from): up to k steps, the first from
// phase `from` on; flags (zero before the call) stay 0 for the steps that ran to the end, the
// stopped one's is check_flag(index of the check that stopped it, its code), and the batch ends
// there (just after that check): the caller acts on it and begins the next batch at the next
// phase, so the one-block kernel runs every phase of every step (a step's rounding does not
// depend on where batches stop: nvcc contracts a*b + c into FMAs per kernel). No path runs a
// step past the stop, so a batch may be as long as the caller likes. Cuda, up to
// kFusedMaxParticles: one block runs all k steps, the phases separated by __syncthreads(); no
// launch and no host round trip per step, which is what a step of a few hundred particles costs
// otherwise (issue 6: the 242-ball mill). Cuda, larger: the batch
// is one CUDA graph (graph_steps): a while node whose body is one step's phases, one kernel node
// each; a check reduces into device memory and, when it stops the step, raises a stop flag that
// the step's later kernels read first and return on, and the body's last kernel ends the loop.
// The host launches one graph per batch instead of a kernel per phase per step and reads the
// flags once (H100, against a read-back per step: 1.27x on a dense bed of 1e5 spheres, 1.06x at
// 1e6, 1.16x on the Los Bronces mill's 1.4e5; bench/results/levers/graph-steps.md). Host: the
// per-phase runner, step after step.
#pragma once
#include <algorithm>
#include <cstdint>
#include <cstdlib>
#include <tuple>
#include <type_traits>
#include <utility>
#include <vector>
#include "blaze/exec/launch.hpp"
#include "blaze/exec/primitives.hpp"

namespace blaze {

// Up to this many particles the one-block path is used (16 particles per thread at most), unless
// the caller gives fused_steps a lower limit (a shape whose particles each cost a long chain of
// work: Simulation passes the shape's kOneBlockParticles).
constexpr Index kFusedMaxParticles = 4096;
// A shape's kOneBlockParticles where it declares one, else kFusedMaxParticles.
template <class Shape, class = void>
struct OneBlockParticles {
  static constexpr Index value = kFusedMaxParticles;
};
template <class Shape>
struct OneBlockParticles<Shape, std::void_t<decltype(Shape::kOneBlockParticles)>> {
  static constexpr Index value = Shape::kOneBlockParticles;
};
template <class Shape>
constexpr Index one_block_particles() {
  return OneBlockParticles<Shape>::value;
}

// The items a kernel phase runs over for n particles: f.items(n) where the functor declares it (a
// thread a list entry: kernels/pair_forces.hpp), else n. Checks run over the particles.
template <class F, class = void>
struct HasItems : std::false_type {};
template <class F>
struct HasItems<F, std::void_t<decltype(std::declval<const F&>().items(Index{}))>> : std::true_type {};
template <class F>
BLAZE_HD Index phase_items(const F& f, Index n) {
  if constexpr (HasItems<F>::value) return f.items(n);
  else return n;
}

template <class F>
struct KernelPhase {
  const char* name;
  F f;
  bool enabled;
};
template <class... P>
struct Phases;
// The code a check's handler is given (any other nonzero code goes to the host).
constexpr int kHandledCode = 1;
template <class F, class Handler = Phases<>>
struct CheckPhase {
  const char* name;
  F f;
  Handler handler;
  static constexpr bool handled = Handler::size > 0;
};
template <class F>
KernelPhase<F> kernel_phase(const char* name, const F& f, bool enabled = true) {
  return {name, f, enabled};
}
template <class F>
CheckPhase<F> check_phase(const char* name, const F& f) {
  return {name, f, {}};
}
template <class F, class Handler>
CheckPhase<F, Handler> check_phase(const char* name, const F& f, const Handler& handler) {
  return {name, f, handler};
}
// A kernel phase and the check after it in one pass over the particles: f(i), then the check's
// code for i. For a check that reads only what f wrote for the same i (the rebuild check after
// the drift): one launch and one read of the particles fewer per step.
template <class F, class C>
struct ThenCheck {
  F f;
  C check;
  BLAZE_HD int operator()(Index i) const {
    f(i);
    return check(i);
  }
};
template <class F, class C>
ThenCheck<F, C> then_check(const F& f, const C& check) {
  return {f, check};
}
template <class P>
struct is_check_phase : std::false_type {};
template <class F, class Handler>
struct is_check_phase<CheckPhase<F, Handler>> : std::true_type {};

// The list: a trivially copyable recursive aggregate (std::tuple is not trivially copyable).
template <class... P>
struct Phases {
  static constexpr int size = 0;
};
template <class H, class... T>
struct Phases<H, T...> {
  static constexpr int size = 1 + sizeof...(T);
  H head;
  Phases<T...> tail;
};
inline Phases<> make_phases() { return {}; }
template <class H, class... T>
Phases<H, T...> make_phases(const H& head, const T&... tail) {
  return {head, make_phases(tail...)};
}

// A check's code (1..255) and its place in the list, as one flag.
BLAZE_HD constexpr int check_flag(int index, int code) { return index * 256 + code; }
struct PhaseStop {
  int index = -1;  // the check that stopped the step; -1: the phases ran to the end
  int code = 0;
  static PhaseStop of_flag(int flag) { return flag ? PhaseStop{flag / 256, flag % 256} : PhaseStop{}; }
};

// A timer that only runs (the fused host path; PhaseTimer's interface).
struct Untimed {
  template <class F>
  void time(const char*, F&& f) {
    f();
  }
};

// Phases with from <= index < to, one launch each, each timed under its name.
template <class Space, class Timer>
PhaseStop run_phases(Space, Index, const Phases<>&, int, int, Timer&, int = 0) {
  return {};
}
template <class Space, class Timer, class H, class... T>
PhaseStop run_phases(Space space, Index n, const Phases<H, T...>& p, int from, int to, Timer& timer, int index = 0) {
  if (index >= to) return {};
  if (index >= from) {
    if constexpr (is_check_phase<H>::value) {
      int code = 0;
      timer.time(p.head.name, [&] { code = reduce_max(space, n, p.head.f, 0); });
      if constexpr (H::handled)
        if (code == kHandledCode && run_phases(space, n, p.head.handler, 0, decltype(p.head.handler)::size, timer).index < 0) code = 0;
      if (code != 0) return {index, code};
    } else if (p.head.enabled) {
      timer.time(p.head.name, [&] { for_each(space, phase_items(p.head.f, n), p.head.f); });
    }
  }
  return run_phases(space, n, p.tail, from, to, timer, index + 1);
}

// Up to k steps, each through the per-phase runner (a check read back on the host every step);
// the flag of the step a check stopped is written to `flags` (in Space's memory, zero before).
// The first step begins at phase `from`.
template <class Space, class... P>
void stepwise_steps(Space, Index n, std::uint64_t k, const Phases<P...>& phases, int* flags, int from = 0) {
  Untimed untimed;
  for (std::uint64_t s = 0; s < k; ++s) {
    const PhaseStop stop = run_phases(Space{}, n, phases, s == 0 ? from : 0, Phases<P...>::size, untimed);
    if (stop.index < 0) continue;
    const int flag = check_flag(stop.index, stop.code);
    copy_n(&flag, 1, flags + s, Host{}, Space{});
    return;
  }
}

template <class... P>
void fused_steps(Host, Index n, std::uint64_t k, const Phases<P...>& phases, int* flags, Index /*one_block_max*/ = kFusedMaxParticles,
                 int from = 0) {
  stepwise_steps(Host{}, n, k, phases, flags, from);
}

#if BLAZE_DEVICE_CODE
// The one-block kernel's threads (BLAZE_FUSED_BLOCK_SIZE overrides it for lever builds).
#ifndef BLAZE_FUSED_BLOCK_SIZE
#define BLAZE_FUSED_BLOCK_SIZE 256
#endif
constexpr int kFusedBlockSize = BLAZE_FUSED_BLOCK_SIZE;

#ifdef BLAZE_FUSED_CLOCKS
// A profiling build (make NVCC_EXTRA=-DBLAZE_FUSED_CLOCKS; never the default): the one-block
// kernel counts, per phase index, the cycles from the phase's start to the barrier after it
// (thread 0: the slowest warp's time plus the barrier's) and each warp's own cycles until it
// reaches that barrier (its work), summed over the steps; fused_clock_counts() reads and clears
// them. What a phase costs and how evenly its warps share it, without a profiler.
constexpr int kFusedClockPhases = 16, kFusedClockWarps = kFusedBlockSize / 32;
__device__ unsigned long long fused_phase_cycles[kFusedClockPhases];
__device__ unsigned long long fused_warp_cycles[kFusedClockPhases * kFusedClockWarps];
__device__ unsigned long long fused_clock_steps;  // steps begun
__device__ inline void fused_clock_work(int index, long long t0) {
  if (index < kFusedClockPhases && (threadIdx.x & 31) == 0)
    fused_warp_cycles[index * kFusedClockWarps + threadIdx.x / 32] += static_cast<unsigned long long>(clock64() - t0);
}
__device__ inline void fused_clock_phase(int index, long long t0) {
  if (index < kFusedClockPhases && threadIdx.x == 0) fused_phase_cycles[index] += static_cast<unsigned long long>(clock64() - t0);
}
struct FusedClocks {
  unsigned long long steps = 0;
  std::vector<std::vector<unsigned long long>> phase;  // [index][0]: the phase's cycles, [index][1 + w]: warp w's work
};
inline FusedClocks fused_clock_counts() {
  unsigned long long ph[kFusedClockPhases], wa[kFusedClockPhases * kFusedClockWarps];
  FusedClocks out;
  cuda_check(cudaMemcpyFromSymbol(ph, fused_phase_cycles, sizeof ph), "fused clocks");
  cuda_check(cudaMemcpyFromSymbol(wa, fused_warp_cycles, sizeof wa), "fused clocks");
  cuda_check(cudaMemcpyFromSymbol(&out.steps, fused_clock_steps, sizeof out.steps), "fused clocks");
  out.phase.resize(kFusedClockPhases);
  for (int k = 0; k < kFusedClockPhases; ++k) {
    out.phase[k].push_back(ph[k]);
    for (int w = 0; w < kFusedClockWarps; ++w) out.phase[k].push_back(wa[k * kFusedClockWarps + w]);
  }
  const unsigned long long zero_ph[kFusedClockPhases] = {}, zero_wa[kFusedClockPhases * kFusedClockWarps] = {}, zero = 0;
  cuda_check(cudaMemcpyToSymbol(fused_phase_cycles, zero_ph, sizeof zero_ph), "fused clocks");
  cuda_check(cudaMemcpyToSymbol(fused_warp_cycles, zero_wa, sizeof zero_wa), "fused clocks");
  cuda_check(cudaMemcpyToSymbol(fused_clock_steps, &zero, sizeof zero), "fused clocks");
  return out;
}
#define BLAZE_FUSED_CLOCK_START const long long clock_t0 = clock64()
#define BLAZE_FUSED_CLOCK_WORK(index) fused_clock_work(index, clock_t0)
#define BLAZE_FUSED_CLOCK_PHASE(index) fused_clock_phase(index, clock_t0)
#else
#define BLAZE_FUSED_CLOCK_START
#define BLAZE_FUSED_CLOCK_WORK(index)
#define BLAZE_FUSED_CLOCK_PHASE(index)
#endif

// A check's handler's phases are counted from this index on (BLAZE_FUSED_CLOCKS).
constexpr int kFusedHandlerClock = 8;

// One phase of one step in the block (none before phase `from`); false: a check stopped the step
// (flag written).
__device__ inline bool fused_phase(const Phases<>&, Index, int, int*, int*, int = 0) { return true; }
template <class H, class... T>
__device__ bool fused_phase(const Phases<H, T...>& p, Index n, int index, int* flag, int* code, int from = 0) {
  if (index < from) {
  } else if constexpr (is_check_phase<H>::value) {
    BLAZE_FUSED_CLOCK_START;
    if (threadIdx.x == 0) *code = 0;
    __syncthreads();
    int c = 0;
    for (Index i = threadIdx.x; i < n; i += blockDim.x) c = max(c, p.head.f(i));
    atomicMax(code, c);
    BLAZE_FUSED_CLOCK_WORK(index);
    __syncthreads();
    int step_code = *code;  // the same in every thread: they stop together
    __syncthreads();        // every thread has read it before a later check resets it
    BLAZE_FUSED_CLOCK_PHASE(index);
    if constexpr (H::handled) {
      __shared__ int handler_flag;  // (a stopped handler's flag: not the step's)
      if (step_code == kHandledCode && fused_phase(p.head.handler, n, kFusedHandlerClock, &handler_flag, code)) step_code = 0;
    }
    if (step_code != 0) {
      if (threadIdx.x == 0) *flag = check_flag(index, step_code);
      return false;
    }
  } else if (p.head.enabled) {
    BLAZE_FUSED_CLOCK_START;
    const Index items = phase_items(p.head.f, n);
    for (Index i = threadIdx.x; i < items; i += blockDim.x) p.head.f(i);
    BLAZE_FUSED_CLOCK_WORK(index);
    __syncthreads();
    BLAZE_FUSED_CLOCK_PHASE(index);
  }
  return fused_phase(p.tail, n, index + 1, flag, code, from);
}

template <class Phases>
__global__ void __launch_bounds__(kFusedBlockSize) fused_steps_kernel(Index n, std::uint64_t k, const Phases* ph, int* flags, int from) {
  __shared__ int code;
  for (std::uint64_t s = 0; s < k; ++s) {
    if (threadIdx.x == 0) flags[s] = 0;
#ifdef BLAZE_FUSED_CLOCKS
    if (threadIdx.x == 0) ++fused_clock_steps;
#endif
    if (!fused_phase(*ph, n, 0, flags + s, &code, s == 0 ? from : 0)) return;
  }
}

// A phase of a graph's step: nothing once the batch has stopped (*stop != 0); the kernel keeps
// the phase's own launch bounds.
template <class F>
struct UnlessStopped {
  static constexpr int kMinBlocks = min_blocks_v<F>;
  F f;
  const int* stop;
  __device__ void operator()(Index i) const {
    if (*stop == 0) f(i);
  }
};
// A check of a graph's step: max of f(i) into *code (zero before), unless stopped.
template <class F>
__global__ void graph_check_kernel(Index n, F f, const int* stop, int* code) {
  if (*stop != 0) return;
  int v = 0;
  for (Index i = blockIdx.x * blockDim.x + threadIdx.x; i < n; i += gridDim.x * blockDim.x) v = max(v, f(i));
  for (int o = 16; o > 0; o /= 2) v = max(v, __shfl_down_sync(0xffffffffu, v, o));
  if ((threadIdx.x & 31) == 0 && v != 0) atomicMax(code, v);
}
// A CUDA graph's body as a chain of kernel nodes, each after the one before.
struct GraphChain {
  cudaGraph_t graph;
  cudaGraphNode_t last = nullptr;

  // Adds func<<<grid, block>>>(args...); the arguments are copied into the node.
  template <class... A, class... B>
  void kernel(void (*func)(A...), unsigned grid, unsigned block, const B&... b) {
    std::tuple<A...> args{static_cast<A>(b)...};
    add(reinterpret_cast<void*>(func), grid, block, args, std::index_sequence_for<A...>{});
  }
  template <class F>
  void for_each(Index n, const F& f) {
    const unsigned blocks = static_cast<unsigned>((n + kBlockSize - 1) / kBlockSize);
    if constexpr (min_blocks_v<F> > 0)
      kernel(for_each_bounded_kernel<F>, blocks, kBlockSize, n, f);
    else
      kernel(for_each_kernel<F>, blocks, kBlockSize, n, f);
  }

 private:
  template <class Tuple, std::size_t... I>
  void add(void* func, unsigned grid, unsigned block, Tuple& args, std::index_sequence<I...>) {
    void* params[] = {static_cast<void*>(&std::get<I>(args))...};
    cudaKernelNodeParams kp{};
    kp.func = func;
    kp.gridDim = dim3(grid);
    kp.blockDim = dim3(block);
    kp.kernelParams = params;
    cudaGraphNode_t node;
    cuda_check(cudaGraphAddKernelNode(&node, graph, last ? &last : nullptr, last ? 1 : 0, &kp), "graph kernel node");
    last = node;
  }
};

// The graph's state: [0] stop, [1] the check's code, [2] the step the loop is in.
// After a check: a nonzero code stops the batch at this step (its flag written); code back to 0.
template <int = 0>
__global__ void graph_settle_kernel(int* state, int* flags, int index) {
  if (state[0] == 0 && state[1] != 0) {
    flags[state[2]] = check_flag(index, state[1]);
    state[0] = 1;
  }
  state[1] = 0;
}
// The body's last node: the next step, or the loop's end (stopped, or k steps run).
template <int = 0>
__global__ void graph_step_end_kernel(int* state, cudaGraphConditionalHandle loop, int k) {
  const int s = ++state[2];
  if (state[0] != 0 || s >= k) cudaGraphSetConditional(loop, 0);
}

inline void graph_phases(const Phases<>&, Index, int, GraphChain&, int*, int*) {}
template <class H, class... T>
void graph_phases(const Phases<H, T...>& p, Index n, int index, GraphChain& chain, int* state, int* flags) {
  if constexpr (is_check_phase<H>::value) {
    const auto blocks = static_cast<unsigned>(std::min<Index>((n + kBlockSize - 1) / kBlockSize, 4096));
    chain.kernel(graph_check_kernel<decltype(p.head.f)>, blocks, kBlockSize, n, p.head.f, state, state + 1);
    chain.kernel(graph_settle_kernel<0>, 1, 1, state, flags, index);
  } else if (p.head.enabled) {
    chain.for_each(phase_items(p.head.f, n), UnlessStopped<decltype(p.head.f)>{p.head.f, state});
  }
  graph_phases(p.tail, n, index + 1, chain, state, flags);
}

// k steps as one CUDA graph: a while node whose body is one step's phases (each after the one
// before) and a last kernel that ends the loop after the step a check stopped or after k steps.
// The device decides: nothing is launched for the steps after a stop, and the host launches one
// graph per batch instead of a kernel per phase per step. The graph is built and instantiated
// for every batch (the views move at rebuilds); its cost was not measured apart. flags[s] as
// fused_steps's (zero before the call).
template <class... P>
void graph_steps(Cuda, Index n, std::uint64_t k, const Phases<P...>& phases, int* flags) {
  static Buffer<int, Cuda> state(3);
  cudaGraph_t graph;
  cuda_check(cudaGraphCreate(&graph, 0), "graph create");
  cudaGraphConditionalHandle loop;
  cuda_check(cudaGraphConditionalHandleCreate(&loop, graph, 1, cudaGraphCondAssignDefault), "graph loop handle");
  cudaGraphNodeParams cp{};
  cp.type = cudaGraphNodeTypeConditional;
  cp.conditional.handle = loop;
  cp.conditional.type = cudaGraphCondTypeWhile;
  cp.conditional.size = 1;
  cudaGraphNode_t node;
  cuda_check(cudaGraphAddNode(&node, graph, nullptr, nullptr, 0, &cp), "graph loop node");
  GraphChain body{cp.conditional.phGraph_out[0]};
  graph_phases(phases, n, 0, body, state.data(), flags);
  body.kernel(graph_step_end_kernel<0>, 1, 1, state.data(), loop, static_cast<int>(k));
  cudaGraphExec_t exec;
  cuda_check(cudaGraphInstantiate(&exec, graph, 0), "graph instantiate");
  cuda_check(cudaMemsetAsync(state.data(), 0, 3 * sizeof(int)), "graph steps reset");
  cuda_check(cudaGraphLaunch(exec, 0), "graph launch");
  cuda_check(cudaGraphExecDestroy(exec), "graph exec destroy");  // freed once it has run
  cuda_check(cudaGraphDestroy(graph), "graph destroy");
}

// The list is read from device memory: with a polyhedron shape table in several phases it
// exceeds the kernel parameter space.
// one_block_max: the most particles the one-block kernel takes (at most kFusedMaxParticles).
template <class... P>
void fused_steps(Cuda, Index n, std::uint64_t k, const Phases<P...>& phases, int* flags, Index one_block_max = kFusedMaxParticles,
                 int from = 0) {
  using List = Phases<P...>;
  static_assert(std::is_trivially_copyable_v<List>, "kernel functors are copied to the GPU as bytes");
  if (n <= 0 || k == 0) return;
  if (n > std::min(one_block_max, kFusedMaxParticles)) {
    // BLAZE_STEPWISE=1 (the lever's baseline, bench/results/levers/graph-steps.md): a host round
    // trip per step, each step's phases in turn and the check read back.
    static const bool stepwise = std::getenv("BLAZE_STEPWISE") != nullptr;
    if (stepwise) return stepwise_steps(Cuda{}, n, k, phases, flags, from);
    if (from > 0) {  // the rest of a stopped step by the per-phase kernels, then the graph
      stepwise_steps(Cuda{}, n, 1, phases, flags, from);
      if (read_one(flags, Cuda{}) != 0 || k == 1) return;
      ++flags, --k;
    }
    return graph_steps(Cuda{}, n, k, phases, flags);
  }
  static Buffer<List, Cuda> slot(1);  // one per instantiation, kept
  copy_n(&phases, 1, slot.data(), Host{}, Cuda{});
  fused_steps_kernel<<<1, kFusedBlockSize>>>(n, k, slot.data(), flags, from);
  cuda_check(cudaGetLastError(), "fused_steps launch");
}
#endif

}  // namespace blaze
