// Checkpoint and restart (issue 5): a run continued from a checkpoint file is bit for bit the run
// that wrote it (spheres with both Verlet variants, with contact history, and polyhedra, through
// re-sorting and rebuilds); corrupt, truncated, foreign or wrong-precision files are rejected by name; a writer
// killed with SIGKILL mid-write leaves the previous checkpoint whole.
#include <boost/test/unit_test.hpp>
#include <signal.h>
#include <sys/wait.h>
#include <unistd.h>

#include <chrono>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <thread>
#include "blaze/io/checkpoint.hpp"
#include "verification/cases/cube_bed.hpp"
#include "verification/scenes.hpp"

using namespace blaze;
using namespace blaze::test;

namespace {

std::string temp(const std::string& name) { return (std::filesystem::temp_directory_path() / name).string(); }

template <class T>
bool same_bits(const std::vector<T>& a, const std::vector<T>& b) {
  return a.size() == b.size() && (a.empty() || std::memcmp(a.data(), b.data(), a.size() * sizeof(T)) == 0);
}

// Runs `before` steps, writes a checkpoint, runs `after` more; then restarts from the file and runs
// `after` steps. The two final states (in store order) must have the same bits.
template <class Sim, class Real, class Laws, class Make>
void restart_is_bitwise(Make make, const SimulationParams<Real>& prm, const Laws& laws,
                        const World<Real>& world, long before, long after, const char* label) {
  const std::string path = temp(std::string("blaze_ckpt_") + label + ".blz");
  Sim a = make();
  a.run(static_cast<std::uint64_t>(before));
  write_checkpoint(path, a.snapshot(), "label=" + std::string(label));
  const auto builds_at_checkpoint = a.neighbour_builds();
  a.run(static_cast<std::uint64_t>(after));
  const auto c = read_checkpoint<Real>(path);
  BOOST_TEST(c.text == "label=" + std::string(label));
  Sim b(prm, laws, world, c.snapshot, a.shape());
  b.run(static_cast<std::uint64_t>(after));
  const auto sa = a.state(), sb = b.state();
  BOOST_TEST_CONTEXT(label) {
    BOOST_TEST(a.neighbour_builds() > builds_at_checkpoint + 2);  // the continuation re-sorts
    BOOST_TEST(a.steps() == b.steps());
    BOOST_TEST(a.removed_count() == b.removed_count());
    BOOST_TEST(same_bits(sa.id, sb.id));
    BOOST_TEST(same_bits(sa.position, sb.position));
    BOOST_TEST(same_bits(sa.velocity, sb.velocity));
    BOOST_TEST(same_bits(sa.angular_velocity, sb.angular_velocity));
    BOOST_TEST(same_bits(sa.orientation, sb.orientation));
  }
  std::filesystem::remove(path);
}

template <class Law>
Law packing_law(double k) {
  using Real = typename Law::real_type;
  const auto normal = LinearSpringDashpot<Real>::from_restitution(k, 0.5);
  if constexpr (Law::kHistory) return {normal, TangentialSpring<Real>::linear(0.4, 2.0 / 7.0 * k, normal.beta)};
  else return {normal, HistoryFreeFriction<Real>::make(0.4, 0.05)};
}

// Law: the history-free linear law, or the linear spring (its contact store goes through the file).
template <class Real, class Integrator, class Law = LinearLaw<Real>>
void sphere_restart(const char* label, PairEvaluation pairs = PairEvaluation::both_sides) {
  const double r = 2e-3, m = 2500 * 4.0 / 3.0 * kPi * r * r * r, k = 1e5;
  const double dt = kPi * std::sqrt(0.5 * m / k) / 25;
  auto scene = gravity_packing<Real>(300, r, 77, dt);
  scene.params.pairs = pairs;
  const Law law = packing_law<Law>(k);
  using Sim = Simulation<DefaultSpace, SphereShape, Law, Integrator>;
  const auto laws = one_law(law);
  restart_is_bitwise<Sim, Real>([&] { return Sim(scene.params, laws, scene.world, scene.particles); }, scene.params, laws,
                                scene.world, 400, 600, label);
}

// Some truncation, corruption or mix-up of a good checkpoint, and what the rejection must say.
struct Damage {
  const char* name;
  void (*apply)(std::string&);
  const char* message;
};
const Damage kDamages[] = {
    {"one flipped byte", [](std::string& f) { f[f.size() / 2] ^= 0x10; }, "checksum mismatch"},
    {"truncated", [](std::string& f) { f.resize(f.size() - 100); }, "truncated"},
    {"empty", [](std::string& f) { f.clear(); }, "not a Blaze checkpoint"},
    {"foreign file", [](std::string& f) { f.replace(0, 7, "<?xml v"); }, "not a Blaze checkpoint"},
    {"future version", [](std::string& f) { f[8] = 9; }, "checkpoint version 9"},
};

}  // namespace

BOOST_AUTO_TEST_SUITE(checkpoint)

BOOST_AUTO_TEST_CASE(sphere_restart_is_bitwise_velocity_verlet_double) { sphere_restart<double, VelocityVerlet>("vv_double"); }
BOOST_AUTO_TEST_CASE(sphere_restart_is_bitwise_half_step_float) { sphere_restart<float, HalfStepVerlet>("half_float"); }
BOOST_AUTO_TEST_CASE(sphere_restart_with_history_is_bitwise) {
  sphere_restart<double, VelocityVerlet, LinearSpringLaw<double>>("spring_double");
  sphere_restart<float, VelocityVerlet, LinearSpringLaw<float>>("spring_float");
  // pairs once: the state sits with the lower index only, and the restart finds it by ids
  sphere_restart<double, VelocityVerlet, LinearSpringLaw<double>>("spring_once", PairEvaluation::once);
}

BOOST_AUTO_TEST_CASE(polyhedron_restart_is_bitwise) {
  const cases::CubeBed bed = cases::cube_bed();
  using Sim = Simulation<DefaultSpace, PolyhedronShape<float>, LinearLaw<float>, VelocityVerlet>;
  const auto laws = one_law(bed.law);
  restart_is_bitwise<Sim, float>([&] { return Sim(bed.scene.params, laws, bed.scene.world, bed.scene.particles, bed.shape); },
                                 bed.scene.params, laws, bed.scene.world, 1500, 1500, "cubes");
}

BOOST_AUTO_TEST_CASE(damaged_checkpoints_are_rejected_by_name) {
  using Law = LinearLaw<double>;
  const auto scene = gravity_packing<double>(50, 2e-3, 3, 1e-5);
  const Law law{LinearSpringDashpot<double>::from_restitution(1e5, 0.5), HistoryFreeFriction<double>::make(0.4, 0.05)};
  SphereSim<Law> sim(scene.params, one_law(law), scene.world, scene.particles);
  sim.run(10);
  const std::string good = temp("blaze_ckpt_good.blz"), bad = temp("blaze_ckpt_bad.blz");
  write_checkpoint(good, sim.snapshot(), "");
  std::ifstream in(good, std::ios::binary);
  const std::string bytes((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  for (const Damage& d : kDamages) {
    std::string damaged = bytes;
    d.apply(damaged);
    std::ofstream(bad, std::ios::binary) << damaged;
    std::string message = "(accepted)";
    try {
      read_checkpoint<double>(bad);
    } catch (const CheckpointError& e) {
      message = e.what();
    }
    BOOST_TEST_CONTEXT(d.name << ": " << message) {
      BOOST_TEST(message.find(d.message) != std::string::npos);
      BOOST_TEST(message.rfind(bad, 0) == 0);  // names the file
    }
  }
  std::string message;
  try {
    read_checkpoint<float>(good);
  } catch (const CheckpointError& e) {
    message = e.what();
  }
  BOOST_TEST(message.find("written in double, the run is in float") != std::string::npos, message);
  std::filesystem::remove(good);
  std::filesystem::remove(bad);
}

// A child process rewrites a large checkpoint in a loop and is killed with SIGKILL; whatever
// moment the kill lands in, the file at the path is a whole checkpoint (the first one or one of
// the child's).
BOOST_AUTO_TEST_CASE(sigkill_mid_write_leaves_the_last_checkpoint_whole) {
  SimulationSnapshot<double> snap;
  const std::size_t n = 200000;  // ~40 MB per file: each write takes milliseconds
  for (int k = 0; k < 26; ++k) snap.store.reals.emplace_back(n, 1.0 * k);
  snap.store.material.assign(n, 0);
  snap.store.type.assign(n, 0);
  snap.store.id.assign(n, 1);
  snap.steps = 1;
  const std::string path = temp("blaze_ckpt_kill.blz");
  write_checkpoint(path, snap, "first");
  for (int trial = 0; trial < 3; ++trial) {
    const pid_t child = fork();
    BOOST_TEST_REQUIRE(child >= 0);
    if (child == 0) {
      for (std::uint64_t s = 2;; ++s) {
        snap.steps = s;
        write_checkpoint(path, snap, "child");
      }
    }
    std::this_thread::sleep_for(std::chrono::milliseconds(30 + 37 * trial));
    kill(child, SIGKILL);
    int status = 0;
    waitpid(child, &status, 0);
    BOOST_TEST(WIFSIGNALED(status));
    const auto c = read_checkpoint<double>(path);  // throws if the file were partial
    BOOST_TEST((c.text == "first" || c.text == "child"));
    BOOST_TEST(c.snapshot.store.reals[25][n - 1] == 25.0);
  }
  std::filesystem::remove(path);
  std::filesystem::remove(path + ".tmp");
}

BOOST_AUTO_TEST_SUITE_END()
