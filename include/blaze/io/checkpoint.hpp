// Checkpoint files: a SimulationSnapshot plus the driver's own text (run metadata), versioned and
// checksummed, written atomically.
//
// Layout (little-endian, version 6; versions 4 and 5, without the last lines, are read too):
//   "BLZCKPT" '\0' | u32 version | u32 bytes per real (4 or 8) | u64 payload bytes | payload |
//   u64 FNV-1a 64 of the payload
//   payload: u64 steps, i64 initial count, i64 removed count, f64 removed mass, f64 removed energy,
//            u32 real arrays, each u64 length + values; u64 n, n material bytes, n type bytes,
//            n ids (i32); contact store: u32 reals per contact, pair ids (u64 length + i32
//            pairs), pair values (u64 length + reals), wall ids, wall keys (i32), wall values;
//            u64 text length + text;
//            i64 inserted count, f64 inserted mass, energy and kinetic energy, i64 next id, u64 length +
//            the feeders' state (opaque bytes, pipeline/feeder.hpp);
//            u64 length + the image counts (i32, x y z per particle; periodic runs, else empty)
// Writing goes to <path>.tmp, is flushed and fsync'ed, then renamed over <path>: a run killed
// mid-write (even by SIGKILL) leaves the previous checkpoint whole. Reading rejects a wrong magic,
// version or precision, a truncated file and a checksum mismatch, each with a message naming the
// file.
#pragma once
#include <fcntl.h>
#include <unistd.h>

#include <algorithm>
#include <cstdint>
#include <cstdio>
#include <cstring>
#include <fstream>
#include <sstream>
#include <stdexcept>
#include <string>
#include "blaze/io/bytes.hpp"
#include "blaze/sim/snapshot.hpp"

namespace blaze {

struct CheckpointError : std::runtime_error {
  using std::runtime_error::runtime_error;
};

namespace checkpoint_detail {

constexpr char kMagic[8] = {'B', 'L', 'Z', 'C', 'K', 'P', 'T', '\0'};
constexpr std::uint32_t kVersion = 6;  // 2: the removed particles' energy; 3: the contact store; 4: 32-bit wall keys (meshes); 5: feeders; 6: image counts (periodic axes)

inline std::uint64_t fnv1a(const std::string& bytes) {
  std::uint64_t h = 1469598103934665603ull;
  for (unsigned char c : bytes) h = (h ^ c) * 1099511628211ull;
  return h;
}

// Reads the payload; fails naming the file.
class Reader : public ByteReader<CheckpointError> {
 public:
  Reader(const std::string& bytes, const std::string& path) : ByteReader<CheckpointError>(bytes, path + ": corrupt checkpoint: ") {}
};

}  // namespace checkpoint_detail

template <class Real>
void write_checkpoint(const std::string& path, const SimulationSnapshot<Real>& s, const std::string& text,
                      const std::string& feeders = "") {
  using namespace checkpoint_detail;
  std::string payload;
  put(payload, s.steps);
  put(payload, static_cast<std::int64_t>(s.initial_count));
  put(payload, static_cast<std::int64_t>(s.removed_count));
  put(payload, s.removed_mass);
  put(payload, s.removed_energy);
  put(payload, static_cast<std::uint32_t>(s.store.reals.size()));
  for (const auto& a : s.store.reals) put_array(payload, a);
  put(payload, static_cast<std::uint64_t>(s.store.id.size()));
  payload.append(reinterpret_cast<const char*>(s.store.material.data()), s.store.material.size());
  payload.append(reinterpret_cast<const char*>(s.store.type.data()), s.store.type.size());
  payload.append(reinterpret_cast<const char*>(s.store.id.data()), s.store.id.size() * sizeof(Index));
  put(payload, static_cast<std::uint32_t>(s.contacts.used));
  put_array(payload, s.contacts.pair_ids);
  put_array(payload, s.contacts.pair_values);
  put_array(payload, s.contacts.wall_ids);
  put_array(payload, s.contacts.wall_objects);
  put_array(payload, s.contacts.wall_values);
  put(payload, static_cast<std::uint64_t>(text.size()));
  payload += text;
  put(payload, static_cast<std::int64_t>(s.inserted_count));
  put(payload, s.inserted_mass);
  put(payload, s.inserted_energy);
  put(payload, s.inserted_kinetic);
  put(payload, static_cast<std::int64_t>(s.next_id));
  put(payload, static_cast<std::uint64_t>(feeders.size()));
  payload += feeders;
  put_array(payload, s.store.image);

  std::string file(kMagic, sizeof kMagic);
  put(file, kVersion);
  put(file, static_cast<std::uint32_t>(sizeof(Real)));
  put(file, static_cast<std::uint64_t>(payload.size()));
  file += payload;
  put(file, fnv1a(payload));

  const std::string tmp = path + ".tmp";
  const int fd = ::open(tmp.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
  if (fd < 0) throw CheckpointError(tmp + ": cannot create: " + std::strerror(errno));
  std::size_t done = 0;
  while (done < file.size()) {
    const ssize_t w = ::write(fd, file.data() + done, file.size() - done);
    if (w <= 0) {
      ::close(fd);
      throw CheckpointError(tmp + ": write failed: " + std::strerror(errno));
    }
    done += static_cast<std::size_t>(w);
  }
  if (::fsync(fd) != 0 || ::close(fd) != 0) throw CheckpointError(tmp + ": cannot flush: " + std::strerror(errno));
  if (std::rename(tmp.c_str(), path.c_str()) != 0)
    throw CheckpointError(tmp + ": cannot rename to " + path + ": " + std::strerror(errno));
}

template <class Real>
struct Checkpoint {
  SimulationSnapshot<Real> snapshot;
  std::string text;
  std::string feeders;  // the feeders' state (pipeline/feeder.hpp); empty before version 5
};

template <class Real>
Checkpoint<Real> read_checkpoint(const std::string& path) {
  using namespace checkpoint_detail;
  std::ifstream in(path, std::ios::binary);
  if (!in) throw CheckpointError(path + ": cannot open checkpoint");
  std::ostringstream buf;
  buf << in.rdbuf();
  const std::string file = buf.str();
  const std::size_t header = sizeof kMagic + 2 * sizeof(std::uint32_t) + sizeof(std::uint64_t);
  if (file.size() < header || std::memcmp(file.data(), kMagic, sizeof kMagic) != 0)
    throw CheckpointError(path + ": not a Blaze checkpoint (no BLZCKPT header)");
  Reader head(file, path);
  (void)head.array<char>(sizeof kMagic);
  const auto version = head.get<std::uint32_t>();
  const auto real_bytes = head.get<std::uint32_t>();
  const auto payload_bytes = head.get<std::uint64_t>();
  if (version != kVersion && version != 4 && version != 5)
    throw CheckpointError(path + ": checkpoint version " + std::to_string(version) + ", this Blaze reads versions 4 to " +
                          std::to_string(kVersion));
  if (real_bytes != sizeof(Real))
    throw CheckpointError(path + ": written in " + (real_bytes == 4 ? "float" : "double") + ", the run is in " +
                          (sizeof(Real) == 4 ? "float" : "double"));
  if (file.size() != header + payload_bytes + sizeof(std::uint64_t))
    throw CheckpointError(path + ": truncated or padded: " + std::to_string(file.size()) + " bytes, the header promises " +
                          std::to_string(header + payload_bytes + sizeof(std::uint64_t)));
  const std::string payload = file.substr(header, payload_bytes);
  std::uint64_t stored;
  std::memcpy(&stored, file.data() + header + payload_bytes, sizeof stored);
  if (stored != fnv1a(payload)) throw CheckpointError(path + ": checksum mismatch: the file is corrupt");

  Reader r(payload, path);
  Checkpoint<Real> c;
  auto& s = c.snapshot;
  s.steps = r.get<std::uint64_t>();
  s.initial_count = static_cast<Index>(r.get<std::int64_t>());
  s.removed_count = static_cast<Index>(r.get<std::int64_t>());
  s.removed_mass = r.get<double>();
  s.removed_energy = r.get<double>();
  const auto fields = r.get<std::uint32_t>();
  if (fields > 64) r.fail("too many arrays");
  for (std::uint32_t k = 0; k < fields; ++k) s.store.reals.push_back(r.array<Real>());
  const auto n = r.get<std::uint64_t>();
  s.store.material = r.array<std::uint8_t>(n);
  s.store.type = r.array<std::uint8_t>(n);
  s.store.id = r.array<Index>(n);
  auto& ct = s.contacts;
  ct.used = static_cast<int>(r.get<std::uint32_t>());
  if (ct.used > 64) r.fail("too many reals per contact");
  ct.pair_ids = r.array<Index>();
  ct.pair_values = r.array<Real>();
  ct.wall_ids = r.array<Index>();
  ct.wall_objects = r.array<WallKey>();
  ct.wall_values = r.array<Real>();
  const auto per = static_cast<std::size_t>(ct.used);
  if (ct.pair_ids.size() % 2 != 0 || ct.pair_values.size() != ct.pair_ids.size() / 2 * per ||
      ct.wall_objects.size() != ct.wall_ids.size() || ct.wall_values.size() != ct.wall_ids.size() * per)
    r.fail("the contact store's arrays disagree in length");
  const auto text = r.array<char>();
  c.text.assign(text.begin(), text.end());
  if (version >= 5) {
    s.inserted_count = static_cast<Index>(r.get<std::int64_t>());
    s.inserted_mass = r.get<double>();
    s.inserted_energy = r.get<double>();
    s.inserted_kinetic = r.get<double>();
    s.next_id = static_cast<Index>(r.get<std::int64_t>());
    const auto feeders = r.array<char>();
    c.feeders.assign(feeders.begin(), feeders.end());
    if (version >= 6) {
      s.store.image = r.array<Index>();
      if (!s.store.image.empty() && s.store.image.size() != 3 * n) r.fail("the image counts' length differs from 3 x the particle count");
    }
  } else {
    for (Index id : s.store.id) s.next_id = std::max(s.next_id, id + 1);
  }
  if (!r.done()) r.fail("bytes after the end");
  for (const auto& a : s.store.reals)
    if (!a.empty() && a.size() != n) r.fail("an array's length differs from the particle count");
  return c;
}

}  // namespace blaze
