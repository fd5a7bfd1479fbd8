// An owning, uninitialised array in one memory space (move-only). Kernels never see it: they get
// raw pointers through views.
#pragma once
#include <algorithm>
#include <cstring>
#include <string>
#include <type_traits>
#include <utility>
#include <vector>
#include "blaze/exec/space.hpp"

namespace blaze {

template <class T, class Space>
class Buffer {
  static_assert(std::is_trivially_copyable_v<T>, "buffers hold plain data");

 public:
  Buffer() = default;
  explicit Buffer(std::size_t n) { resize(n); }
  ~Buffer() { Space::deallocate(data_); }
  Buffer(const Buffer&) = delete;
  Buffer& operator=(const Buffer&) = delete;
  Buffer(Buffer&& o) noexcept : data_(std::exchange(o.data_, nullptr)), size_(std::exchange(o.size_, 0)) {}
  Buffer& operator=(Buffer&& o) noexcept {
    swap(o);
    return *this;
  }
  void swap(Buffer& o) noexcept {
    std::swap(data_, o.data_);
    std::swap(size_, o.size_);
  }

  // Contents are discarded when the size changes.
  void resize(std::size_t n) {
    if (n == size_) return;
    if (n > static_cast<std::size_t>(-1) / sizeof(T)) throw OutOfMemory("buffer: " + std::to_string(n) + " elements overflow the address space");
    Space::deallocate(data_);
    data_ = nullptr, size_ = 0;  // an allocation that throws leaves an empty buffer, not a dangling one
    data_ = static_cast<T*>(Space::allocate(n * sizeof(T)));
    size_ = n;
  }
  // Grows to at least n elements keeping the first `keep` (a store that takes in particles;
  // capacity grows by half again, so appends allocate O(log n) times). Never shrinks.
  void grow_keep(std::size_t n, std::size_t keep);
  // At least n elements, contents discarded when it grows, by half again at least: scratch sized
  // by the particle count reallocates O(log n) times while a feed adds particles, not at every
  // insertion (each cudaMalloc/cudaFree pair synchronises the device). A first sizing is exact.
  void ensure(std::size_t n) {
    if (n > size_) resize(std::max(n, size_ + size_ / 2));
  }
  T* data() { return data_; }
  const T* data() const { return data_; }
  std::size_t size() const { return size_; }

 private:
  T* data_ = nullptr;
  std::size_t size_ = 0;
};

// Copies between any two spaces.
template <class T>
void copy_n(const T* src, std::size_t n, T* dst, Host, Host) {
  if (n) std::memcpy(dst, src, n * sizeof(T));
}
#if BLAZE_DEVICE_CODE
template <class T, class S1, class S2>
void copy_n(const T* src, std::size_t n, T* dst, S1, S2) {
  if (n) cuda_check(cudaMemcpy(dst, src, n * sizeof(T), cudaMemcpyDefault), "cudaMemcpy");
}
#endif

template <class T, class Space>
void Buffer<T, Space>::grow_keep(std::size_t n, std::size_t keep) {
  if (n <= size_) return;
  Buffer bigger(std::max(n, size_ + size_ / 2));
  copy_n(data_, std::min(keep, size_), bigger.data(), Space{}, Space{});
  swap(bigger);
}

template <class T, class Space>
std::vector<T> to_host(const Buffer<T, Space>& b, std::size_t n) {
  std::vector<T> out(n);
  copy_n(b.data(), n, out.data(), Space{}, Host{});
  return out;
}
// n values from the host into b's first n, growing it by ensure() (no reallocation while it is
// large enough: scratch refilled at every insertion of a feed).
template <class T, class Space>
void copy_in(Buffer<T, Space>& b, const T* v, std::size_t n) {
  b.ensure(n);
  copy_n(v, n, b.data(), Host{}, Space{});
}
template <class T, class Space>
void copy_in(Buffer<T, Space>& b, const std::vector<T>& v) {
  copy_in(b, v.data(), v.size());
}
template <class T, class Space>
void from_host(Buffer<T, Space>& b, const std::vector<T>& v) {
  b.resize(v.size());
  copy_n(v.data(), v.size(), b.data(), Host{}, Space{});
}
// Arrays moved a launch when a rebuild reorders `count` arrays of `bytes_each` each into spare
// arrays that may hold `spare_bytes` together (one at least, `most` at most): the particle store's
// reorder and the contact store's remap. Small systems take all in one launch, large ones one at
// a time (no more memory than one spare array).
inline constexpr std::size_t kSpareBytes = std::size_t{32} << 20;
inline std::size_t arrays_per_launch(std::size_t spare_bytes, std::size_t bytes_each, std::size_t count, std::size_t most) {
  return std::clamp<std::size_t>(spare_bytes / std::max<std::size_t>(1, bytes_each), 1, std::max<std::size_t>(1, std::min(count, most)));
}

template <class T, class Space>
T read_one(const T* p, Space) {
  T v;
  copy_n(p, 1, &v, Space{}, Host{});
  return v;
}

}  // namespace blaze
