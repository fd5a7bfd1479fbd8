// The contact store: the state of every open contact of a law with history (tangential and
// rolling springs), on one memory space; kernels/contact_history.hpp has its views, kernels and
// layout. Pair states are aligned with the neighbour list (one per entry, each side its own copy);
// wall states sit in a few slots per particle keyed by the contact (WallKey). Both are carried over
// every rebuild by the contacts' identity: after the sort and the new list (after_rebuild), a pair
// state follows its two particles into their new entry, a wall slot follows its particle. A
// snapshot keys them by permanent particle ids (and the object), so a restart rebuilds them
// whatever the memory order.
//
// Memory per particle: the list's capacity x `used` reals (pairs) plus spare fields of the same
// size for the remap (one for large systems, all `used` while they fit in 32 MiB), and slots x
// (used reals + 4 B) for walls; none for a law without history.
#pragma once
#include <algorithm>
#include <cstdint>
#include <map>
#include <stdexcept>
#include <utility>
#include <vector>
#include "blaze/exec/buffer.hpp"
#include "blaze/exec/primitives.hpp"
#include "blaze/sim/snapshot.hpp"
#include "kernels/contact_history.hpp"

namespace blaze {

template <class Real, int N, class Space>
class ContactStore {
 public:
  static constexpr int kFields = N > 0 ? N : 1;

  // `used`: reals per contact (N, or fewer when a later part of the law is off); `objects`: the
  // most wall contacts a particle may hold (slots per particle: min(objects, 3) to begin with,
  // more on overflow).
  void configure(int used, int objects) {
    if (used < 0 || used > N) throw std::logic_error("contact store: more state reals than the law has");
    used_ = used;
    objects_ = objects;
    slots_ = std::min(objects, 3);
  }
  bool active() const { return N > 0 && used_ > 0; }

  PairHistoryView<Real, N> pairs() {
    PairHistoryView<Real, N> v{};
    for (int c = 0; c < kFields; ++c) v.field[c] = pair_[c].data();
    v.used = active() ? used_ : 0;
    return v;
  }
  WallHistoryView<Real, N> walls() {
    WallHistoryView<Real, N> v{};
    for (int c = 0; c < kFields; ++c) v.field[c] = wall_[c].data();
    v.used = active() ? used_ : 0;
    v.object = wall_object_.data();
    v.overflow = overflow_.data();
    v.stride = stride_;
    v.slots = active() ? slots_ : 0;
    return v;
  }

  // A new list with no history before it (the first build): every state zero, every slot free.
  void clear(const NeighbourView& list, Index n) {
    if (!active()) return;
    const std::size_t entries = static_cast<std::size_t>(list.capacity) * static_cast<std::size_t>(list.stride);
    for (int c = 0; c < used_; ++c) fill(pair_[c], entries, Real(0));
    lay_walls(n);
  }

  // The most bytes the remap's spare fields hold (one field at least): with room for all of them
  // the remap is one launch, without it a launch per field (kSpareBytes by default).
  void limit_spares(std::size_t bytes) { spare_bytes_ = bytes; }

  // After a rebuild (sort, removal, new list): carry every state to its contact's new place.
  // once: pairs evaluated once (the lower index's entry holds the state).
  void after_rebuild(const NeighbourView& list, const NeighbourView& previous, const Index* order, Index n, bool once) {
    if (!active()) return;
    const std::size_t entries = static_cast<std::size_t>(list.capacity) * static_cast<std::size_t>(list.stride);
    // As many fields a launch as spare_bytes_ of spare fields hold (all of them for small systems:
    // one search of the previous list per entry instead of one per field; one at a time for large).
    const int per_launch = static_cast<int>(
        arrays_per_launch(spare_bytes_, entries * sizeof(Real), static_cast<std::size_t>(used_), static_cast<std::size_t>(kFields)));
    if (static_cast<int>(scratch_.size()) < per_launch) scratch_.resize(static_cast<std::size_t>(per_launch));
    for (int c = 0; c < used_; c += per_launch) {
      RemapPairHistory<Real, kFields> remap{list, previous, order, {}, {}, std::min(per_launch, used_ - c), once};
      for (int f = 0; f < remap.fields; ++f) {
        auto& spare = scratch_[static_cast<std::size_t>(f)];
        spare.ensure(entries);
        remap.in[f] = pair_[c + f].data(), remap.out[f] = spare.data();
      }
      for_each(Space{}, n, remap);
      for (int f = 0; f < remap.fields; ++f) pair_[c + f].swap(scratch_[static_cast<std::size_t>(f)]);
    }
    // Wall slots: grown by one when a contact found none free since the last rebuild.
    const int grow = n > 0 && stride_ > 0 && reduce_max(Space{}, std::min(n, stride_), ValueOf<std::uint8_t>{overflow_.data()}, 0) > 0;
    const int slots = std::min(slots_ + grow, std::min(objects_, WallHistoryView<Real, N>::kMaxSlots));
    gather_rows(wall_object_, order, n, slots, WallKey(-1));
    for (int c = 0; c < used_; ++c) gather_rows(wall_[c], order, n, slots, Real(0));
    slots_ = slots;
    stride_ = n;
    fill(overflow_, static_cast<std::size_t>(n), std::uint8_t(0));
  }

  std::size_t bytes() const {
    std::size_t b = wall_object_.size() * sizeof(WallKey) + overflow_.size();
    for (const auto& f : scratch_) b += f.size() * sizeof(Real);
    for (int c = 0; c < kFields; ++c) b += (pair_[c].size() + wall_[c].size()) * sizeof(Real);
    return b + scratch_rows_.size() * sizeof(Real) + scratch_objects_.size() * sizeof(WallKey);
  }

  // On the host, keyed by ids (`id`: the store's particle ids in memory order; `list`: the current
  // neighbour list, on this space).
  ContactSnapshot<Real> snapshot(const std::vector<Index>& id, const NeighbourView& list) const {
    ContactSnapshot<Real> s;
    s.used = active() ? used_ : 0;
    if (!active()) return s;
    const Index n = static_cast<Index>(id.size());
    const auto count = host_copy(list.count, static_cast<std::size_t>(n));
    const std::size_t entries = static_cast<std::size_t>(list.capacity) * static_cast<std::size_t>(list.stride);
    const auto index = host_copy(list.index, entries);
    std::vector<std::vector<Real>> f(used_);
    for (int c = 0; c < used_; ++c) f[c] = host_copy(pair_[c].data(), entries);
    for (Index i = 0; i < n; ++i)
      for (Index k = 0; k < std::min(count[i], list.capacity); ++k) {
        const std::size_t e = list.offset(k, i);
        bool held = false;
        for (int c = 0; c < used_; ++c) held = held || f[c][e] != Real(0);
        if (!held) continue;
        s.pair_ids.push_back(id[i]);
        s.pair_ids.push_back(id[index[e]]);
        for (int c = 0; c < used_; ++c) s.pair_values.push_back(f[c][e]);
      }
    const std::size_t rows = static_cast<std::size_t>(slots_) * static_cast<std::size_t>(stride_);
    const auto objects = host_copy(wall_object_.data(), rows);
    std::vector<std::vector<Real>> w(used_);
    for (int c = 0; c < used_; ++c) w[c] = host_copy(wall_[c].data(), rows);
    for (int h = 0; h < slots_; ++h)
      for (Index i = 0; i < std::min(n, stride_); ++i) {
        const std::size_t e = static_cast<std::size_t>(h) * static_cast<std::size_t>(stride_) + static_cast<std::size_t>(i);
        if (objects[e] < 0) continue;
        s.wall_ids.push_back(id[i]);
        s.wall_objects.push_back(objects[e]);
        for (int c = 0; c < used_; ++c) s.wall_values.push_back(w[c][e]);
      }
    return s;
  }

  // Puts a snapshot's states where the current list and memory order want them (after the first
  // build of a restored run).
  void restore(const ContactSnapshot<Real>& s, const std::vector<Index>& id, const NeighbourView& list) {
    if (!active()) return;
    if (s.used != used_) throw std::invalid_argument("contact store: the checkpoint's contact state has " + std::to_string(s.used) +
                                                     " reals per contact, this law " + std::to_string(used_));
    const Index n = static_cast<Index>(id.size());
    std::map<std::pair<Index, Index>, std::size_t> pairs;
    for (std::size_t k = 0; k < s.pair_ids.size() / 2; ++k) pairs[{s.pair_ids[2 * k], s.pair_ids[2 * k + 1]}] = k;
    const auto count = host_copy(list.count, static_cast<std::size_t>(n));
    const std::size_t entries = static_cast<std::size_t>(list.capacity) * static_cast<std::size_t>(list.stride);
    const auto index = host_copy(list.index, entries);
    std::vector<std::vector<Real>> f(used_, std::vector<Real>(entries, Real(0)));
    for (Index i = 0; i < n; ++i)
      for (Index k = 0; k < std::min(count[i], list.capacity); ++k) {
        const std::size_t e = list.offset(k, i);
        // i's own copy, or (pairs once, when the other particle held it) the other's negated
        auto it = pairs.find({id[i], id[index[e]]});
        Real sign = 1;
        if (it == pairs.end()) it = pairs.find({id[index[e]], id[i]}), sign = -1;
        if (it == pairs.end()) continue;
        for (int c = 0; c < used_; ++c) f[c][e] = sign * s.pair_values[it->second * used_ + c];
      }
    for (int c = 0; c < used_; ++c) from_host(pair_[c], f[c]);
    std::map<Index, Index> row;
    for (Index i = 0; i < n; ++i) row[id[i]] = i;
    std::vector<int> taken(static_cast<std::size_t>(n), 0);
    int slots = slots_;
    for (std::size_t k = 0; k < s.wall_ids.size(); ++k) {
      const auto it = row.find(s.wall_ids[k]);
      if (it != row.end()) slots = std::max(slots, ++taken[static_cast<std::size_t>(it->second)]);
    }
    slots_ = std::min(slots, WallHistoryView<Real, N>::kMaxSlots);
    stride_ = n;
    const std::size_t rows = static_cast<std::size_t>(slots_) * static_cast<std::size_t>(n);
    std::vector<WallKey> objects(rows, -1);
    std::vector<std::vector<Real>> w(used_, std::vector<Real>(rows, Real(0)));
    std::fill(taken.begin(), taken.end(), 0);
    for (std::size_t k = 0; k < s.wall_ids.size(); ++k) {
      const auto it = row.find(s.wall_ids[k]);
      if (it == row.end() || taken[static_cast<std::size_t>(it->second)] >= slots_) continue;
      const std::size_t e = static_cast<std::size_t>(taken[static_cast<std::size_t>(it->second)]++) * n + static_cast<std::size_t>(it->second);
      objects[e] = s.wall_objects[k];
      for (int c = 0; c < used_; ++c) w[c][e] = s.wall_values[k * used_ + c];
    }
    from_host(wall_object_, objects);
    for (int c = 0; c < used_; ++c) from_host(wall_[c], w[c]);
    fill(overflow_, static_cast<std::size_t>(n), std::uint8_t(0));
  }

 private:
  template <class T>
  static std::vector<T> host_copy(const T* src, std::size_t n) {
    std::vector<T> v(n);
    if (n) copy_n(src, n, v.data(), Space{}, Host{});
    return v;
  }
  template <class T>
  static void fill(Buffer<T, Space>& b, std::size_t n, T value) {
    b.ensure(n);
    for_each(Space{}, static_cast<Index>(b.size()), Fill<T>{b.data(), value});
  }
  void lay_walls(Index n) {
    stride_ = n;
    const std::size_t rows = static_cast<std::size_t>(slots_) * static_cast<std::size_t>(n);
    fill(wall_object_, rows, WallKey(-1));
    for (int c = 0; c < used_; ++c) fill(wall_[c], rows, Real(0));
    fill(overflow_, static_cast<std::size_t>(n), std::uint8_t(0));
  }
  template <class T>
  void gather_rows(Buffer<T, Space>& b, const Index* order, Index n, int slots, T empty) {
    auto& scratch = scratch_for(T{});
    scratch.ensure(static_cast<std::size_t>(slots) * n);
    for_each(Space{}, n, GatherRows<T>{b.data(), scratch.data(), order, n, stride_, slots_, slots, empty});
    b.swap(scratch);
  }
  Buffer<Real, Space>& scratch_for(Real) { return scratch_rows_; }
  Buffer<WallKey, Space>& scratch_for(WallKey) { return scratch_objects_; }

  int used_ = 0, objects_ = 0, slots_ = 0;
  Index stride_ = 0;  // the wall rows' stride (particles at the last rebuild)
  Buffer<Real, Space> pair_[kFields], wall_[kFields];
  std::size_t spare_bytes_ = kSpareBytes;     // limit_spares()
  std::vector<Buffer<Real, Space>> scratch_;  // the remap's spare fields
  Buffer<Real, Space> scratch_rows_;
  Buffer<WallKey, Space> wall_object_, scratch_objects_;
  Buffer<std::uint8_t, Space> overflow_;
};

}  // namespace blaze
