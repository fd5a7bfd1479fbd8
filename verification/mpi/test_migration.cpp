// Particles moving between ranks (issue 21; pipeline/parallel/migration.hpp), on however many
// ranks mpirun starts (make test: 1 to 4):
// - Every rank starts with particles anywhere in the domain (not in its box); after migrate()
//   each is on the rank whose box holds it, none is lost or doubled, and each arrives bitwise as
//   it left (every array of the store's snapshot, and its contact states: pairs and walls).
// - Mirrored through the domain's centre, every particle crosses the point where four boxes meet
//   (four ranks; a face on two): a second migration puts each on its new owner, none lost.
// - Ghosts: each rank holds, owned or as a ghost, every particle within the reach of its box, and
//   no ghost beyond it (against the whole set, gathered); ghosts carry no contact states.
// - Gathered into a corner (imbalance > 2 on the old boxes), the particles are rebalanced from a
//   sample of each rank's and migrate to an imbalance within 15%.
// - Records survive pack / unpack bitwise; a cut or corrupt message is refused naming its source.
#include <boost/test/unit_test.hpp>
#include <algorithm>
#include <cmath>
#include <cstring>
#include <map>
#include <random>
#include <set>
#include "blaze/particles/particle_store.hpp"
#include "pipeline/parallel/migration.hpp"
#include "verification/report.hpp"
#include "verification/tolerances.hpp"

using namespace blaze;
using namespace blaze::test;

namespace {

const char* const kCase = "Particles across ranks (issue 21)";
const Vec3<double> kLo{0, 0, 0}, kHi{1, 1, 0.2};
constexpr unsigned kPeriodicZ = 4u;  // cuts run across x and y: four boxes meet at the centre

std::string ranks_label(const Communicator& comm) { return ", " + std::to_string(comm.size()) + " rank" + (comm.size() > 1 ? "s" : ""); }

// This rank's first particles: ids rank, rank + P, ..., anywhere in the domain; with contact states.
ParticleRecords<double> starting_particles(const Communicator& comm, int per_rank) {
  ParticleState<double> s;
  std::mt19937_64 rng(101 + static_cast<unsigned>(comm.rank()));
  std::uniform_real_distribution<double> u(0, 1);
  std::normal_distribution<double> g(0, 1);
  for (int k = 0; k < per_rank; ++k) {
    const Vec3<double> x{kLo.x + (kHi.x - kLo.x) * u(rng), kLo.y + (kHi.y - kLo.y) * u(rng), kLo.z + (kHi.z - kLo.z) * u(rng)};
    s.add_sphere(x, 0.004 + 0.002 * u(rng), 2500, static_cast<std::uint8_t>(k % 3));
    s.id.back() = comm.rank() + comm.size() * k;
    s.velocity.back() = {g(rng), g(rng), g(rng)};
    s.angular_velocity.back() = {g(rng), g(rng), g(rng)};
  }
  ParticleStore<double, Host> store;
  store.upload(s, true, true, true);
  ParticleRecords<double> r;
  r.store = store.snapshot();
  r.contacts.used = 3;
  for (std::size_t k = 0; k < s.size(); ++k) {
    const Index id = s.id[k];
    for (Index partner : {id + 1, id + 7}) {
      r.contacts.pair_ids.push_back(id), r.contacts.pair_ids.push_back(partner);
      for (int c = 0; c < 3; ++c) r.contacts.pair_values.push_back(1e-6 * id + 0.25 * c + 1e-3 * partner);
    }
    r.contacts.wall_ids.push_back(id), r.contacts.wall_objects.push_back(static_cast<WallKey>(id % 5));
    for (int c = 0; c < 3; ++c) r.contacts.wall_values.push_back(-1e-6 * id - c);
  }
  return r;
}

// Every rank's records, gathered (each rank sees all).
ParticleRecords<double> gather_all(const Communicator& comm, const ParticleRecords<double>& mine) {
  ParticleRecords<double> all;
  int r = 0;
  for (const std::string& m : comm.all_gather_bytes(pack_records(mine))) append_records(all, unpack_records<double>(m, "rank " + std::to_string(r++)));
  return all;
}

// Particles here not held by their box's rank, and ones whose arrays or contacts differ from
// `reference` (the whole set, any order), bitwise (memcmp: the raw store's previous-force arrays
// are unset until a Simulation primes them, and a NaN there is still carried bit for bit).
struct Audit {
  long misplaced = 0, changed = 0, contacts_changed = 0;
};
Audit audit(const Communicator& comm, const Decomposition& d, const ParticleRecords<double>& here, const ParticleRecords<double>& reference) {
  Audit a;
  std::map<Index, std::size_t> at;
  for (std::size_t k = 0; k < reference.size(); ++k) at[reference.store.id[k]] = k;
  for (std::size_t k = 0; k < here.size(); ++k) {
    a.misplaced += d.owner(record_position(here.store, k)) != comm.rank();
    const auto it = at.find(here.store.id[k]);
    if (it == at.end()) {
      ++a.changed;
      continue;
    }
    const std::size_t j = it->second;
    bool same = here.store.material[k] == reference.store.material[j] && here.store.type[k] == reference.store.type[j];
    for (std::size_t f = 0; f < here.store.reals.size(); ++f)
      same = same && here.store.reals[f].empty() == reference.store.reals[f].empty() &&
             (here.store.reals[f].empty() || std::memcmp(&here.store.reals[f][k], &reference.store.reals[f][j], sizeof(double)) == 0);
    a.changed += !same;
  }
  // contact states: the same set of (ids, values) as the reference's for the particles here
  std::vector<Index> which;
  for (std::size_t k = 0; k < here.size(); ++k)
    if (at.count(here.store.id[k])) which.push_back(static_cast<Index>(at[here.store.id[k]]));
  const ParticleRecords<double> expected = select_records(reference.store, reference.contacts, which);
  using PairRow = std::tuple<Index, Index, double, double, double>;
  std::multiset<PairRow> got, want;
  const auto rows = [](const ContactSnapshot<double>& c, std::multiset<PairRow>& out) {
    for (std::size_t p = 0; 2 * p + 1 < c.pair_ids.size(); ++p)
      out.insert({c.pair_ids[2 * p], c.pair_ids[2 * p + 1], c.pair_values[3 * p], c.pair_values[3 * p + 1], c.pair_values[3 * p + 2]});
    for (std::size_t w = 0; w < c.wall_ids.size(); ++w)
      out.insert({c.wall_ids[w], -1 - c.wall_objects[w], c.wall_values[3 * w], c.wall_values[3 * w + 1], c.wall_values[3 * w + 2]});
  };
  rows(here.contacts, got), rows(expected.contacts, want);
  a.contacts_changed = got == want ? 0 : 1 + static_cast<long>(std::max(got.size(), want.size()) - std::min(got.size(), want.size()));
  return a;
}

// Ids over all ranks: how many are missing from `all_ids` or held twice.
long lost_or_doubled(const ParticleRecords<double>& reference, const ParticleRecords<double>& all_now) {
  std::vector<Index> a = reference.store.id, b = all_now.store.id;
  std::sort(a.begin(), a.end()), std::sort(b.begin(), b.end());
  long bad = 0;
  for (std::size_t k = 1; k < b.size(); ++k) bad += b[k] == b[k - 1];
  std::vector<Index> missing;
  std::set_difference(a.begin(), a.end(), b.begin(), b.end(), std::back_inserter(missing));
  return bad + static_cast<long>(missing.size()) + std::labs(static_cast<long>(a.size()) - static_cast<long>(b.size()));
}

void mirror_through_centre(ParticleRecords<double>& r) {
  const std::size_t p = StoreSnapshot<double>::kPositionField;
  for (std::size_t k = 0; k < r.size(); ++k) {
    r.store.reals[p][k] = kLo.x + kHi.x - r.store.reals[p][k];
    r.store.reals[p + 1][k] = kLo.y + kHi.y - r.store.reals[p + 1][k];
  }
}

}  // namespace

BOOST_AUTO_TEST_SUITE(migration)

BOOST_AUTO_TEST_CASE(particles_migrate_whole_and_cross_a_corner_of_four_boxes) {
  const Communicator comm;
  const ParticleRecords<double> start = starting_particles(comm, 1500);
  const ParticleRecords<double> reference = gather_all(comm, start);
  // cut by length (no particles given): with 2 and 4 ranks every box mirrors onto another
  const Decomposition d = Decomposition::make(DecompositionKind::bisection, kLo, kHi, comm.size(), kPeriodicZ, {});
  const ParticleRecords<double> here = migrate(comm, d, start);
  const Audit a = audit(comm, d, here, reference);
  const long lost = lost_or_doubled(reference, gather_all(comm, here));
  // every particle mirrored through the centre: it crosses into the opposite box
  ParticleRecords<double> moved = here, moved_reference = reference;
  mirror_through_centre(moved), mirror_through_centre(moved_reference);
  const ParticleRecords<double> again = migrate(comm, d, moved);
  const Audit b = audit(comm, d, again, moved_reference);
  const long lost_again = lost_or_doubled(reference, gather_all(comm, again));
  long stayed = 0;  // particles of this rank that stayed after the mirror (none on 2 or 4 ranks: the boxes mirror)
  for (Index id : again.store.id) stayed += std::binary_search(here.store.id.begin(), here.store.id.end(), id);
  const std::string ranks = ranks_label(comm);
  const double misplaced = static_cast<double>(comm.sum(a.misplaced + b.misplaced));
  const double changed = static_cast<double>(comm.sum(a.changed + a.contacts_changed + b.changed + b.contacts_changed));
  BOOST_TEST_MESSAGE("migration" << ranks << ": " << reference.size() << " particles; rank " << comm.rank() << " holds " << here.size()
                                 << ", after the mirror " << again.size() << " (" << stayed << " stayed)");
  check_at_most({kCase, "particles not on the rank whose box holds them, after migrating twice" + ranks, "-", "owner() by box"}, misplaced, 0);
  check_at_most({kCase, "particles or contact states changed by migrating (bitwise)" + ranks, "-", "records carry every array"}, changed, 0);
  check_at_most({kCase, "particles lost or doubled by migrating, through the centre where four boxes meet" + ranks, "-",
                 "each particle to exactly one owner"},
                static_cast<double>(lost + lost_again), 0);
  if (comm.size() == 2 || comm.size() == 4) BOOST_TEST(comm.sum(stayed) == 0);  // each particle to the opposite box
  BOOST_TEST(comm.sum(static_cast<long>(again.size())) == static_cast<long>(reference.size()));
}

BOOST_AUTO_TEST_CASE(each_rank_sees_every_particle_within_reach_of_its_box) {
  const Communicator comm;
  const double reach = 0.05;
  const ParticleRecords<double> start = starting_particles(comm, 1500);
  std::vector<Vec3<double>> x;
  for (std::size_t k = 0; k < start.size(); ++k) x.push_back(record_position(start.store, k));
  const Decomposition d = balanced_decomposition(comm, DecompositionKind::bisection, kLo, kHi, kPeriodicZ, x);
  const ParticleRecords<double> here = migrate(comm, d, start);
  const ParticleRecords<double> halo = ghosts(comm, d, here, reach);
  const ParticleRecords<double> all = gather_all(comm, here);
  std::set<Index> expected, got(halo.store.id.begin(), halo.store.id.end());
  const RankBox& box = d.box(comm.rank());
  for (std::size_t k = 0; k < all.size(); ++k)
    if (d.owner(record_position(all.store, k)) != comm.rank() && Decomposition::distance2(record_position(all.store, k), box) <= reach * reach)
      expected.insert(all.store.id[k]);
  long wrong = static_cast<long>(halo.size() - got.size());  // a ghost sent twice
  for (Index id : expected) wrong += !got.count(id);
  for (Index id : got) wrong += !expected.count(id);
  const long contacts = static_cast<long>(halo.contacts.pair_ids.size() + halo.contacts.wall_ids.size());
  const std::string ranks = ranks_label(comm);
  BOOST_TEST_MESSAGE("ghosts" << ranks << ": rank " << comm.rank() << " owns " << here.size() << ", holds " << halo.size() << " ghosts");
  check_at_most({kCase, "ghosts missing, doubled or beyond the reach of the box" + ranks, "-", "near() by box distance"},
                static_cast<double>(comm.sum(wrong)), 0);
  BOOST_TEST(comm.sum(contacts) == 0);
  if (comm.size() > 1) BOOST_TEST(comm.sum(static_cast<long>(halo.size())) > 0);
}

BOOST_AUTO_TEST_CASE(gathered_particles_are_rebalanced) {
  const Communicator comm;
  ParticleRecords<double> start = starting_particles(comm, 1500);
  std::vector<Vec3<double>> x;
  for (std::size_t k = 0; k < start.size(); ++k) x.push_back(record_position(start.store, k));
  const Decomposition before = balanced_decomposition(comm, DecompositionKind::bisection, kLo, kHi, kPeriodicZ, x);
  // every particle squeezed into the corner [0, 0.3)^2
  const std::size_t p = StoreSnapshot<double>::kPositionField;
  for (std::size_t k = 0; k < start.size(); ++k) start.store.reals[p][k] *= 0.3, start.store.reals[p + 1][k] *= 0.3;
  const ParticleRecords<double> crowded = migrate(comm, before, start);
  const std::vector<long> counts_before = comm.all_gather(static_cast<long>(crowded.size()));
  x.clear();
  for (std::size_t k = 0; k < crowded.size(); ++k) x.push_back(record_position(crowded.store, k));
  const Decomposition after = balanced_decomposition(comm, DecompositionKind::bisection, kLo, kHi, kPeriodicZ, x, 512);
  const ParticleRecords<double> balanced = migrate(comm, after, crowded);
  const std::vector<long> counts_after = comm.all_gather(static_cast<long>(balanced.size()));
  const std::string ranks = ranks_label(comm);
  if (comm.size() >= 2) BOOST_TEST(Decomposition::imbalance(counts_before) > 1.5);
  check_at_most({kCase, "imbalance - 1 after rebalancing particles gathered in a corner (512 sampled a rank)" + ranks, "-",
                 "sampled quantiles"},
                Decomposition::imbalance(counts_after) - 1, tol::decomposition_sampled_imbalance);
  BOOST_TEST(comm.sum(static_cast<long>(balanced.size())) == comm.sum(static_cast<long>(start.size())));
}

BOOST_AUTO_TEST_CASE(records_survive_packing_and_bad_messages_are_refused) {
  const Communicator comm;
  const ParticleRecords<double> r = starting_particles(comm, 50);
  const std::string bytes = pack_records(r);
  const ParticleRecords<double> back = unpack_records<double>(bytes, "itself");
  BOOST_TEST(pack_records(back) == bytes);
  BOOST_TEST((back.store.id == r.store.id && back.contacts.pair_values == r.contacts.pair_values));
  BOOST_CHECK_THROW(unpack_records<double>(bytes.substr(0, bytes.size() - 5), "rank 9"), RecordError);
  BOOST_CHECK_THROW(unpack_records<float>(bytes, "rank 9"), RecordError);
  std::string bad = bytes;
  bad[8] = 127;  // the first array's length runs past the end
  try {
    unpack_records<double>(bad, "rank 9");
    BOOST_ERROR("a corrupt message was taken");
  } catch (const RecordError& e) {
    BOOST_TEST(std::string(e.what()).find("rank 9") != std::string::npos);
  }
}

// A gather to one rank (frames, a guard's last good state, the mill study's charge): every rank's
// bytes arrive on the root in rank order, whichever rank it is, and nothing on the others.
BOOST_AUTO_TEST_CASE(a_gather_brings_every_ranks_bytes_to_the_root_alone) {
  const Communicator comm;
  const std::string mine(static_cast<std::size_t>(comm.rank() + 1) * 1000, static_cast<char>('a' + comm.rank()));
  for (int root = 0; root < comm.size(); ++root) {
    const std::vector<std::string> got = comm.gather_bytes(mine, root);
    BOOST_TEST_REQUIRE(got.size() == static_cast<std::size_t>(comm.size()));
    for (int r = 0; r < comm.size(); ++r) {
      const std::string want = comm.rank() == root ? std::string(static_cast<std::size_t>(r + 1) * 1000, static_cast<char>('a' + r)) : "";
      BOOST_TEST(got[static_cast<std::size_t>(r)] == want, "root " << root << ", from rank " << r);
    }
  }
  BOOST_CHECK_THROW(comm.gather_bytes(mine, comm.size()), CommunicatorError);  // (every rank alike)
}

BOOST_AUTO_TEST_SUITE_END()
