// The feeders' states in a checkpoint (blaze run, the hopper study): one byte string for all of a
// run's feeders (pipeline/feeder.hpp Feeder::save), and back.
#pragma once
#include <cstdint>
#include <cstring>
#include <string>
#include <vector>
#include "blaze/io/checkpoint.hpp"
#include "pipeline/feeder.hpp"

namespace blaze {

// The feeders' states as one byte string for the checkpoint (u64 count, then u64 length + bytes
// each), and back.
template <class Real>
std::string save_feeders(const std::vector<Feeder<Real>>& feeders) {
  std::string out;
  auto put = [&](std::uint64_t v) { out.append(reinterpret_cast<const char*>(&v), sizeof v); };
  put(feeders.size());
  for (const auto& f : feeders) {
    const std::string b = f.save();
    put(b.size());
    out += b;
  }
  return out;
}
template <class Real>
void restore_feeders(std::vector<Feeder<Real>>& feeders, const std::string& bytes, const std::string& path) {
  std::size_t at = 0;
  auto get = [&]() {
    std::uint64_t v = 0;
    if (bytes.size() - at < sizeof v) throw CheckpointError(path + ": the feeders' state is truncated");
    std::memcpy(&v, bytes.data() + at, sizeof v);
    at += sizeof v;
    return v;
  };
  if (bytes.empty() && feeders.empty()) return;
  if (bytes.empty() || get() != feeders.size())
    throw CheckpointError(path + ": the checkpoint holds another number of feeders than the scene's [[feed]] tables");
  for (auto& f : feeders) {
    const std::uint64_t n = get();
    if (bytes.size() - at < n) throw CheckpointError(path + ": a feeder's state is truncated");
    f.restore(bytes.substr(at, n));
    at += n;
  }
}

}  // namespace blaze
