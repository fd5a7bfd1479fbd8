// Particles moving between ranks (issue 21), collective calls over a Communicator:
//   balanced_decomposition  the decomposition of the domain balanced on every rank's particles
//                           (each rank sends at most `sample` positions, each weighted by the
//                           particles it stands for; every rank builds the same decomposition);
//   migrate                 each particle to the rank whose box holds it, with its contact states
//                           (particle_records.hpp); the rank's particles come back in permanent-id
//                           order, so the result does not depend on where they came from;
//   ghosts                  copies of each particle for every other rank whose box lies within
//                           `reach` of it (Decomposition::near), without contact states; in
//                           (source rank, id) order.
// A particle is never lost or doubled: each goes to exactly one owner (the boxes tile the domain;
// one outside goes to the nearest box).
#pragma once
#include <algorithm>
#include <numeric>
#include <string>
#include <vector>
#include "blaze/parallel/decomposition.hpp"
#include "blaze/parallel/particle_records.hpp"
#include "pipeline/parallel/communicator.hpp"

namespace blaze {

template <class Real>
Vec3<double> record_position(const StoreSnapshot<Real>& s, std::size_t k) {
  const std::size_t p = StoreSnapshot<Real>::kPositionField;
  return {static_cast<double>(s.reals[p][k]), static_cast<double>(s.reals[p + 1][k]), static_cast<double>(s.reals[p + 2][k])};
}

inline Decomposition balanced_decomposition(const Communicator& comm, DecompositionKind kind, const Vec3<double>& lo, const Vec3<double>& hi,
                                            unsigned periodic, const std::vector<Vec3<double>>& mine, std::size_t sample = 4096) {
  const std::size_t stride = mine.size() > sample ? (mine.size() + sample - 1) / sample : 1;
  std::string bytes;
  std::vector<double> picked;
  for (std::size_t k = 0; k < mine.size(); k += stride) picked.push_back(mine[k].x), picked.push_back(mine[k].y), picked.push_back(mine[k].z);
  const double weight = picked.empty() ? 0 : static_cast<double>(mine.size()) / static_cast<double>(picked.size() / 3);
  put(bytes, weight);
  put_array(bytes, picked);
  std::vector<Vec3<double>> points;
  std::vector<double> weights;
  int from = 0;
  for (const std::string& m : comm.all_gather_bytes(bytes)) {
    ByteReader<CommunicatorError> in(m, "decomposition sample from rank " + std::to_string(from++) + ": ");
    const auto w = in.get<double>();
    const auto xyz = in.array<double>();
    for (std::size_t k = 0; k + 2 < xyz.size(); k += 3) points.push_back({xyz[k], xyz[k + 1], xyz[k + 2]}), weights.push_back(w);
  }
  return Decomposition::make(kind, lo, hi, comm.size(), periodic, points, weights);
}

// The records in permanent-id order.
template <class Real>
ParticleRecords<Real> in_id_order(const ParticleRecords<Real>& r) {
  std::vector<Index> order(r.size());
  std::iota(order.begin(), order.end(), Index{0});
  std::sort(order.begin(), order.end(), [&](Index a, Index b) { return r.store.id[static_cast<std::size_t>(a)] < r.store.id[static_cast<std::size_t>(b)]; });
  return select_records(r.store, r.contacts, order);
}

template <class Real>
ParticleRecords<Real> migrate(const Communicator& comm, const Decomposition& d, const ParticleRecords<Real>& mine) {
  if (d.ranks() != comm.size())
    throw CommunicatorError("migrate: a decomposition of " + std::to_string(d.ranks()) + " ranks on " + std::to_string(comm.size()));
  std::vector<std::vector<Index>> to(static_cast<std::size_t>(comm.size()));
  for (std::size_t k = 0; k < mine.size(); ++k) to[static_cast<std::size_t>(d.owner(record_position(mine.store, k)))].push_back(static_cast<Index>(k));
  std::vector<std::string> out(to.size());
  for (std::size_t r = 0; r < to.size(); ++r) out[r] = pack_records(select_records(mine.store, mine.contacts, to[r]));
  ParticleRecords<Real> here;
  const std::vector<std::string> in = comm.exchange(out);
  for (std::size_t r = 0; r < in.size(); ++r) append_records(here, unpack_records<Real>(in[r], "rank " + std::to_string(r)));
  if (here.store.reals.empty()) here.store.reals.resize(mine.store.reals.size()), here.contacts.used = mine.contacts.used;
  return in_id_order(here);
}

template <class Real>
ParticleRecords<Real> ghosts(const Communicator& comm, const Decomposition& d, const ParticleRecords<Real>& mine, double reach) {
  std::vector<std::vector<Index>> to(static_cast<std::size_t>(comm.size()));
  for (std::size_t k = 0; k < mine.size(); ++k)
    d.near(record_position(mine.store, k), reach, comm.rank(), [&](int r) { to[static_cast<std::size_t>(r)].push_back(static_cast<Index>(k)); });
  std::vector<std::string> out(to.size());
  for (std::size_t r = 0; r < to.size(); ++r) out[r] = pack_records(select_records(mine.store, mine.contacts, to[r], false));
  ParticleRecords<Real> here;
  const std::vector<std::string> in = comm.exchange(out);
  for (std::size_t r = 0; r < in.size(); ++r) append_records(here, unpack_records<Real>(in[r], "rank " + std::to_string(r)));
  return here;
}

}  // namespace blaze
