// Whole particles as one rank hands them to another (issue 21): a particle migrating to the rank
// whose box it entered takes everything it owns, as a restart would need it, and a ghost (a halo
// copy for a neighbour rank's contacts) the same arrays without its contact states.
// A record set is the store's snapshot layout (StoreSnapshot: every real array the store keeps,
// material, type, permanent id, image counts) for some particles, and their contact states
// (ContactSnapshot: pair states keyed (own id, partner id), the particle's own copy; wall states
// keyed (id, object or triangle)). pack() / unpack() turn it into bytes for MPI and back; unpack
// checks every length, so a short or corrupt message is an error naming its source.
#pragma once
#include <algorithm>
#include <stdexcept>
#include <string>
#include <unordered_map>
#include <vector>
#include "blaze/io/bytes.hpp"
#include "blaze/sim/snapshot.hpp"

namespace blaze {

struct RecordError : std::runtime_error {
  using std::runtime_error::runtime_error;
};

template <class Real>
struct ParticleRecords {
  StoreSnapshot<Real> store;
  ContactSnapshot<Real> contacts;
  std::size_t size() const { return store.id.size(); }
};

// The particles `which` (indices into s) with, when with_contacts, their contact states from c.
template <class Real>
ParticleRecords<Real> select_records(const StoreSnapshot<Real>& s, const ContactSnapshot<Real>& c, const std::vector<Index>& which,
                                     bool with_contacts = true) {
  ParticleRecords<Real> r;
  const std::size_t n = s.id.size();
  r.store.reals.resize(s.reals.size());
  for (std::size_t f = 0; f < s.reals.size(); ++f) {
    if (s.reals[f].empty()) continue;
    r.store.reals[f].reserve(which.size());
    for (Index k : which) r.store.reals[f].push_back(s.reals[f][static_cast<std::size_t>(k)]);
  }
  for (Index k : which) {
    if (k < 0 || static_cast<std::size_t>(k) >= n) throw RecordError("particle records: index " + std::to_string(k) + " of " + std::to_string(n));
    const auto u = static_cast<std::size_t>(k);
    r.store.material.push_back(s.material[u]);
    r.store.type.push_back(s.type[u]);
    r.store.id.push_back(s.id[u]);
    if (!s.image.empty())
      for (int a = 0; a < 3; ++a) r.store.image.push_back(s.image[3 * u + static_cast<std::size_t>(a)]);
  }
  r.contacts.used = c.used;
  if (!with_contacts || which.empty()) return r;
  std::unordered_map<Index, char> chosen;
  chosen.reserve(which.size());
  for (Index k : which) chosen[s.id[static_cast<std::size_t>(k)]] = 1;
  const auto per = static_cast<std::size_t>(c.used);
  for (std::size_t p = 0; 2 * p + 1 < c.pair_ids.size(); ++p)
    if (chosen.count(c.pair_ids[2 * p])) {
      r.contacts.pair_ids.push_back(c.pair_ids[2 * p]), r.contacts.pair_ids.push_back(c.pair_ids[2 * p + 1]);
      r.contacts.pair_values.insert(r.contacts.pair_values.end(), c.pair_values.begin() + static_cast<std::ptrdiff_t>(p * per),
                                    c.pair_values.begin() + static_cast<std::ptrdiff_t>((p + 1) * per));
    }
  for (std::size_t w = 0; w < c.wall_ids.size(); ++w)
    if (chosen.count(c.wall_ids[w])) {
      r.contacts.wall_ids.push_back(c.wall_ids[w]), r.contacts.wall_objects.push_back(c.wall_objects[w]);
      r.contacts.wall_values.insert(r.contacts.wall_values.end(), c.wall_values.begin() + static_cast<std::ptrdiff_t>(w * per),
                                    c.wall_values.begin() + static_cast<std::ptrdiff_t>((w + 1) * per));
    }
  return r;
}

// a += b: b's particles after a's (the same arrays kept: an empty `a` takes b's layout).
template <class Real>
void append_records(ParticleRecords<Real>& a, const ParticleRecords<Real>& b) {
  if (b.size() == 0 && b.contacts.pair_ids.empty() && b.contacts.wall_ids.empty()) return;
  if (a.size() == 0 && a.store.reals.empty()) {
    a.store.reals.resize(b.store.reals.size());
    a.contacts.used = b.contacts.used;
  }
  if (a.store.reals.size() != b.store.reals.size() || a.contacts.used != b.contacts.used)
    throw RecordError("particle records: appending records of another layout (" + std::to_string(b.store.reals.size()) + " arrays, " +
                      std::to_string(b.contacts.used) + " reals per contact; these have " + std::to_string(a.store.reals.size()) + ", " +
                      std::to_string(a.contacts.used) + ")");
  const auto cat = [](auto& to, const auto& from) { to.insert(to.end(), from.begin(), from.end()); };
  for (std::size_t f = 0; f < a.store.reals.size(); ++f) {
    if (a.store.reals[f].empty() != b.store.reals[f].empty() && a.size() > 0 && b.size() > 0)
      throw RecordError("particle records: array " + std::to_string(f) + " is kept by one side only");
    cat(a.store.reals[f], b.store.reals[f]);
  }
  cat(a.store.material, b.store.material), cat(a.store.type, b.store.type), cat(a.store.id, b.store.id), cat(a.store.image, b.store.image);
  cat(a.contacts.pair_ids, b.contacts.pair_ids), cat(a.contacts.pair_values, b.contacts.pair_values);
  cat(a.contacts.wall_ids, b.contacts.wall_ids), cat(a.contacts.wall_objects, b.contacts.wall_objects);
  cat(a.contacts.wall_values, b.contacts.wall_values);
}

template <class Real>
std::string pack_records(const ParticleRecords<Real>& r) {
  std::string out;
  put(out, static_cast<std::uint32_t>(sizeof(Real)));
  put(out, static_cast<std::uint32_t>(r.store.reals.size()));
  for (const auto& a : r.store.reals) put_array(out, a);
  put_array(out, r.store.material), put_array(out, r.store.type), put_array(out, r.store.id), put_array(out, r.store.image);
  put(out, static_cast<std::int32_t>(r.contacts.used));
  put_array(out, r.contacts.pair_ids), put_array(out, r.contacts.pair_values);
  put_array(out, r.contacts.wall_ids), put_array(out, r.contacts.wall_objects), put_array(out, r.contacts.wall_values);
  return out;
}

// What pack_records() wrote; `from` names the source in errors (e.g. "rank 3").
template <class Real>
ParticleRecords<Real> unpack_records(const std::string& bytes, const std::string& from) {
  ByteReader<RecordError> in(bytes, "particle records from " + from + ": ");
  ParticleRecords<Real> r;
  if (in.template get<std::uint32_t>() != sizeof(Real)) in.fail("written in another precision");
  const auto fields = in.template get<std::uint32_t>();
  if (fields > 64) in.fail("too many arrays");
  for (std::uint32_t f = 0; f < fields; ++f) r.store.reals.push_back(in.template array<Real>());
  r.store.material = in.template array<std::uint8_t>(), r.store.type = in.template array<std::uint8_t>();
  r.store.id = in.template array<Index>(), r.store.image = in.template array<Index>();
  r.contacts.used = in.template get<std::int32_t>();
  r.contacts.pair_ids = in.template array<Index>(), r.contacts.pair_values = in.template array<Real>();
  r.contacts.wall_ids = in.template array<Index>(), r.contacts.wall_objects = in.template array<WallKey>();
  r.contacts.wall_values = in.template array<Real>();
  if (!in.done()) in.fail("bytes after the end");
  const std::size_t n = r.store.id.size(), per = static_cast<std::size_t>(std::max(r.contacts.used, 0));
  for (const auto& a : r.store.reals)
    if (!a.empty() && a.size() != n) in.fail("an array's length differs from the particle count");
  if (r.store.material.size() != n || r.store.type.size() != n || (!r.store.image.empty() && r.store.image.size() != 3 * n))
    in.fail("the material, type or image arrays differ from the particle count");
  if (r.contacts.used < 0 || r.contacts.pair_ids.size() % 2 != 0 || r.contacts.pair_values.size() != r.contacts.pair_ids.size() / 2 * per ||
      r.contacts.wall_objects.size() != r.contacts.wall_ids.size() || r.contacts.wall_values.size() != r.contacts.wall_ids.size() * per)
    in.fail("the contact arrays disagree in length");
  return r;
}

}  // namespace blaze
