// The contact store's views and kernels (the owner is pipeline/contact_store.hpp). A law with a
// state (laws/contact_state.hpp) keeps it per contact:
//   particle pairs   one state per neighbour-list entry, at the entry's own offset k * stride + i
//                    (PairHistoryView): each side of a pair keeps its own copy, the mirror of the
//                    other's, so a particle's thread reads and writes only its own entries (no
//                    atomics, the same order on every backend) and consecutive threads touch
//                    consecutive addresses. Pairs evaluated once keep only the lower index's copy.
//   world objects    a few slots per particle, each holding the contact's key (WallKey: the
//                    object's index, or a mesh triangle's key; -1: free) and its state, at
//                    h * stride + i (WallHistoryView); a contact finds its slot by the key, takes
//                    a free one when it closes and frees it when it opens. A mesh contact that
//                    rolled onto another triangle inherits the slot of the one it left (a
//                    triangle sharing a vertex with its new one that no contact of this step
//                    holds), so a tessellation does not reset the spring.
// A rebuild moves particles in memory and builds a new list, so the pair states are carried over
// by the pair's identity (RemapPairHistory: the entry of the same two particles in the previous
// list, through the sort's permutation), and the wall slots move with their particle (the
// store's permutation).
#pragma once
#include <cstdint>
#include "blaze/laws/contact_state.hpp"
#include "kernels/broad_phase_kernels.hpp"

namespace blaze {

// Blocks of 256 threads per SM that the contact and wall kernels of a law with history ask for
// (launch.hpp: 4 caps the registers at 64, no spills). Uncapped, the Mindlin sphere contact kernel
// took 72 registers (3 blocks, 37.5% occupancy; ncu: latency-bound, 18% of DRAM bandwidth) and
// the wall kernel 128 (25%, 12% achieved). H200, 1e7 spheres in float, dense bed, per step:
// contacts 4.23 -> 3.40 ms (Mindlin), 9.26 -> 5.58 ms (Mindlin + EPSD); walls 0.84 -> 0.39 ms;
// 1.62e9 -> 2.02e9 and 0.88e9 -> 1.39e9 particle-steps/s (bench/results/levers/history-bounds.md).
// The macros override them for lever measurements; 0 keeps the shape's own bound.
#ifndef BLAZE_HISTORY_CONTACT_MIN_BLOCKS
#define BLAZE_HISTORY_CONTACT_MIN_BLOCKS 4
#endif
#ifndef BLAZE_HISTORY_WALL_MIN_BLOCKS
#define BLAZE_HISTORY_WALL_MIN_BLOCKS 4
#endif
// A pair's state is loaded at the top of its list entry's iteration, before the collision: its
// address depends on the entry alone, so its memory latency overlaps that of the partner's
// position instead of following the collision (H100, 1e7 spheres: Mindlin contacts 3.59 -> 3.44 ms
// per step, Mindlin + EPSD 6.81 -> 5.93; bench/results/levers/early-loads.md). The entries
// that do not touch (a few in a dense bed) read their state anyway: forget() needs it. 0: loaded
// after the collision, for touching entries only (the lever's baseline).
#ifndef BLAZE_HISTORY_EARLY_LOAD
#define BLAZE_HISTORY_EARLY_LOAD 1
#endif
template <class Law>
constexpr int history_min_blocks(int shape_blocks, int history_blocks) {
  return Law::kHistory && history_blocks > shape_blocks ? history_blocks : shape_blocks;
}

template <class Real, int N>
struct PairHistoryView {
  using State = ContactState<Real, N>;
  Real* field[N > 0 ? N : 1];
  int used;  // fields held: N, or fewer when the law's later parts are off (no rolling spring)

  BLAZE_HD State load(std::size_t s) const {
    State st = State::zero();
    for (int c = 0; c < used; ++c) st.value[c] = field[c][s];
    return st;
  }
  BLAZE_HD void store(std::size_t s, const State& st) const {
    for (int c = 0; c < used; ++c) field[c][s] = st.value[c];
  }
  // The contact is open: forget its state (written only when it holds one).
  BLAZE_HD void forget(std::size_t s) const { forget(s, load(s)); }
  // The same, given the state already loaded from s.
  BLAZE_HD void forget(std::size_t s, const State& st) const {
    bool held = false;
    for (int c = 0; c < used; ++c) held = held || st.value[c] != Real(0);
    if (held)
      for (int c = 0; c < used; ++c) field[c][s] = Real(0);
  }
};

template <class Real, int N>
struct WallHistoryView {
  using State = ContactState<Real, N>;
  static constexpr int kMaxSlots = 8;  // the bit set of slots seen in one step
  Real* field[N > 0 ? N : 1];
  int used;
  WallKey* object;  // the contact's key per slot, -1: free
  std::uint8_t* overflow;  // per particle: 1 when a contact found no free slot (ran without state)
  Index stride;
  int slots;

  BLAZE_HD std::size_t at(int h, Index i) const { return static_cast<std::size_t>(h) * static_cast<std::size_t>(stride) + static_cast<std::size_t>(i); }
  // The slot of `key` for particle i; else one not seen this step (bit h of `seen`) whose key
  // inherit(old key) accepts, re-keyed with its state kept; else a free one, claimed (zeroed);
  // -1 if all are taken.
  template <class Inherit>
  BLAZE_HD int slot(Index i, WallKey key, unsigned seen, const Inherit& inherit) const {
    int free = -1, heir = -1;
    for (int h = 0; h < slots; ++h) {
      const WallKey o = object[at(h, i)];
      if (o == key) return h;
      if (o < 0) {
        if (free < 0) free = h;
      } else if (heir < 0 && !((seen >> h) & 1u) && inherit(o)) {
        heir = h;
      }
    }
    if (heir >= 0) {
      object[at(heir, i)] = key;
      return heir;
    }
    if (free >= 0) {
      object[at(free, i)] = key;
      for (int c = 0; c < used; ++c) field[c][at(free, i)] = Real(0);
    }
    return free;
  }
  BLAZE_HD int slot(Index i, WallKey key) const {
    return slot(i, key, 0u, [](WallKey) { return false; });
  }
  // The slot holding `key` for particle i, or -1 (nothing claimed).
  BLAZE_HD int find(Index i, WallKey key) const {
    for (int h = 0; h < slots; ++h)
      if (object[at(h, i)] == key) return h;
    return -1;
  }
  BLAZE_HD State load(int h, Index i) const {
    State st = State::zero();
    for (int c = 0; c < used; ++c) st.value[c] = field[c][at(h, i)];
    return st;
  }
  BLAZE_HD void store(int h, Index i, const State& st) const {
    for (int c = 0; c < used; ++c) field[c][at(h, i)] = st.value[c];
  }
  // Frees the slots of i whose object it did not touch this step (bit h of `seen`).
  BLAZE_HD void release_unseen(Index i, unsigned seen) const {
    for (int h = 0; h < slots; ++h)
      if (!((seen >> h) & 1u) && object[at(h, i)] >= 0) object[at(h, i)] = -1;
  }
};

// After a rebuild: new entry (k, i) takes the state of the entry of the same pair in the previous
// list (row order[i], partner order[j]) or zero; fields in[f] (previous layout) to out[f], each
// found entry read for every field (the search, the costly part, once for them all).
// Pairs evaluated once (`once`) keep the state at the lower index's entry only, and a re-sort may
// swap which of the two is lower: the owner's entry then takes the other side's old state,
// negated (the two sides' states are exact negations), and the other entry is zero.
template <class Real, int N>
struct RemapPairHistory {
  NeighbourView list, previous;
  const Index* order;  // particle i of the new order was particle order[i] of the previous one
  const Real* in[N];   // fields in[0, fields) carried to out[0, fields): one search per entry for all
  Real* out[N];
  int fields;
  bool once;

  // The previous entry of row `row` for partner `partner`, or -1. The search starts at `from`
  // and wraps: a row rebuilt from the same cells lists its partners in the same order, so with
  // `from` just past the last match it takes one probe per entry (a full scan of the row each
  // took 12 x 12 index reads per particle in a dense bed).
  BLAZE_HD long find(Index row, Index partner, Index& from) const {
    const Index count = min_r(previous.count[row], previous.capacity);
    for (Index t = 0; t < count; ++t) {
      const Index m = from + t < count ? from + t : from + t - count;
      if (previous.at(m, row) == partner) {
        from = m + 1;
        return static_cast<long>(previous.offset(m, row));
      }
    }
    return -1;
  }
  // Particles inserted since the previous list (pipeline/feeder.hpp) sort from indices at or past
  // its stride: they had no contacts.
  BLAZE_HD void operator()(Index i) const {
    const Index o = order[i];
    const Index count = min_r(list.count[i], list.capacity);
    if (o >= previous.stride) {
      for (Index k = 0; k < count; ++k)
        for (int f = 0; f < fields; ++f) out[f][list.offset(k, i)] = Real(0);
      return;
    }
    Index from = 0;  // the cursor in i's own previous row
    for (Index k = 0; k < count; ++k) {
      const Index j = list.at(k, i);
      const Index was = order[j];
      long e = -1;     // the contact's previous entry
      bool flip = false;  // held by the other side before (pairs once): the state negated
      if (was >= previous.stride) {  // a new partner
      } else if (!once) {
        e = find(o, was, from);
      } else if (i < j) {  // the owner now; it was the owner before iff o < was
        Index elsewhere = 0;
        e = o < was ? find(o, was, from) : find(was, o, elsewhere);
        flip = !(o < was);
      }
      const std::size_t s = list.offset(k, i);
      for (int f = 0; f < fields; ++f) out[f][s] = e < 0 ? Real(0) : flip ? -in[f][e] : in[f][e];
    }
  }
};

// Per-particle rows (wall slots) after a rebuild: out[h * n + i] = in[h * stride + order[i]] for
// the old slots, `empty` for slots added.
template <class T>
struct GatherRows {
  const T* in;
  T* out;
  const Index* order;
  Index n, stride;
  int old_slots, slots;
  T empty;
  BLAZE_HD void operator()(Index i) const {
    for (int h = 0; h < slots; ++h)
      out[static_cast<std::size_t>(h) * n + i] =
          h < old_slots && order[i] < stride ? in[static_cast<std::size_t>(h) * stride + order[i]] : empty;  // past stride: inserted
  }
};

}  // namespace blaze
