// Output cadences of a run driver (blaze run, the studies): the steps between two events run as
// one stretch, so the GPU can batch them (Simulation::run).
#pragma once
#include <algorithm>
#include <cstdint>
#include <initializer_list>

namespace blaze {

// The first step after k at which one of the cadences falls (a multiple of `every`; 0: never),
// or `end` if none comes before it.
inline std::uint64_t next_event(std::uint64_t k, std::uint64_t end, std::initializer_list<std::uint64_t> every) {
  std::uint64_t next = end;
  for (std::uint64_t e : every)
    if (e) next = std::min(next, (k / e + 1) * e);
  return next;
}

}  // namespace blaze
