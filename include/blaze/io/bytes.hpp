// Plain values and arrays to and from a byte string (native byte order: little-endian on every
// machine Blaze runs on): the checkpoint's payload (checkpoint.hpp) and the particle records ranks
// send each other (blaze/parallel/particle_records.hpp). A reader fails, never overruns, at the end.
#pragma once
#include <cstdint>
#include <cstring>
#include <string>
#include <utility>
#include <vector>

namespace blaze {

template <class T>
void put(std::string& out, const T& v) {
  out.append(reinterpret_cast<const char*>(&v), sizeof v);
}
template <class T>
void put_array(std::string& out, const std::vector<T>& v) {
  put(out, static_cast<std::uint64_t>(v.size()));
  out.append(reinterpret_cast<const char*>(v.data()), v.size() * sizeof(T));
}

// Reads what put() and put_array() wrote; a read past the end throws Error(prefix + what).
template <class Error>
class ByteReader {
 public:
  ByteReader(const std::string& bytes, std::string prefix) : b_(bytes), prefix_(std::move(prefix)) {}
  template <class T>
  T get() {
    T v;
    need(sizeof v);
    std::memcpy(&v, b_.data() + at_, sizeof v);
    at_ += sizeof v;
    return v;
  }
  template <class T>
  std::vector<T> array(std::uint64_t n) {
    if (n > (b_.size() - at_) / sizeof(T)) fail("an array runs past the end of the payload");
    std::vector<T> v(n);
    if (n) std::memcpy(v.data(), b_.data() + at_, n * sizeof(T));
    at_ += n * sizeof(T);
    return v;
  }
  template <class T>
  std::vector<T> array() { return array<T>(get<std::uint64_t>()); }
  bool done() const { return at_ == b_.size(); }
  [[noreturn]] void fail(const std::string& what) const { throw Error(prefix_ + what); }

 private:
  void need(std::size_t n) const {
    if (b_.size() - at_ < n) fail("the payload ends early");
  }
  const std::string& b_;
  std::string prefix_;
  std::size_t at_ = 0;
};

}  // namespace blaze
