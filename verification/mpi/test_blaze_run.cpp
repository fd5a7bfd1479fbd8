// `blaze run` over ranks (issue 21; apps/blaze/run_scene.hpp's loop over a DistributedSimulation),
// on however many ranks mpirun starts (make test: 1 to 4), against the same scene on one rank:
// 200 glass beads on a jittered lattice and 400 more fed from a box above them over 40 ms (Hertz
// + Mindlin, contact history), falling into an open box whose floor reports its load; 60 ms.
// - The final state (the checkpoint's parts, one a rank) is bitwise the one-rank run's: every
//   position and velocity, the count, what was fed and removed.
// - The time series written by rank 0: the same rows (time, particles, removed, inserted) and the
//   energies, the floor's load and the contact counts as reduced over the ranks, to rounding (the
//   ranks' partial sums are added in another order than one rank's).
// - Each frame is one piece a rank (vtu/particles_NNNN_rK.vtu) and a .pvtu naming them all, whose
//   points add up to the particles of the time series at that time.
// - A run stopped at 45 ms (its checkpoint at 30 ms) and continued from that checkpoint on another
//   number of ranks (N - 1; one rank under mpirun -np 1) ends bitwise where the others end.
#include <boost/test/unit_test.hpp>
#include <unistd.h>

#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <map>
#include <sstream>
#include "apps/blaze/run_scene.hpp"
#include "blaze/scene/scene_file.hpp"
#include "verification/mpi/run_files.hpp"
#include "verification/report.hpp"
#include "verification/tolerances.hpp"

using namespace blaze;
using namespace blaze::test;

namespace {

const char* const kCase = "Runs over ranks (issue 21)";

const char* const kScene = R"(
[simulation]
law = "hertz"
tangential = "mindlin"
precision = "double"
dt = 1.25e-5
end_time = 0.06
gravity = [0, -9.81, 0]
domain_lo = [-0.05, -0.01, -0.05]
domain_hi = [0.05, 0.25, 0.05]
seed = 3
[output]
csv_interval = 0.005
vtu_interval = 0.02
checkpoint_interval = 0.03
[[material]]
name = "glass"
density = 2500
youngs_modulus = 5e7
poisson_ratio = 0.25
[[pair]]
materials = ["glass", "glass"]
restitution = 0.5
friction = 0.3
[[particle_type]]
name = "bead"
material = "glass"
radius = 3e-3
[[lattice]]
type = "bead"
origin = [-0.03, 0.01, -0.03]
count = [8, 3, 8]
spacing = 0.0075
jitter = 0.3
velocity = [0.0, -0.3, 0.0]
[[feed]]
name = "pour"
type = "bead"
region = { kind = "box", lo = [-0.035, 0.06, -0.035], hi = [0.035, 0.09, 0.035] }
rate = 10000
end_time = 0.04
velocity = [0.0, -0.5, 0.0]
[[wall]]
name = "floor"
material = "glass"
vertices = [[-0.04, 0.0, -0.04], [-0.04, 0.0, 0.04], [0.04, 0.0, 0.04], [0.04, 0.0, -0.04]]
rim = false
[[wall]]
material = "glass"
vertices = [[-0.04, 0.0, -0.04], [-0.04, 0.2, -0.04], [-0.04, 0.2, 0.04], [-0.04, 0.0, 0.04]]
rim = false
[[wall]]
material = "glass"
vertices = [[0.04, 0.0, 0.04], [0.04, 0.2, 0.04], [0.04, 0.2, -0.04], [0.04, 0.0, -0.04]]
rim = false
[[wall]]
material = "glass"
vertices = [[0.04, 0.0, -0.04], [0.04, 0.2, -0.04], [-0.04, 0.2, -0.04], [-0.04, 0.0, -0.04]]
rim = false
[[wall]]
material = "glass"
vertices = [[-0.04, 0.0, 0.04], [-0.04, 0.2, 0.04], [0.04, 0.2, 0.04], [0.04, 0.0, 0.04]]
rim = false
)";

// The same bed periodic along x (thesis-style slice; grid/periodic_images.hpp): no walls across x,
// the floor and the z walls reaching past the period, everything moving in +x so that particles
// cross the periodic faces (and the ranks' boxes) with their contacts.
std::string periodic_scene() {
  std::string t = kScene;
  t = t.substr(0, t.find("[[wall]]"));  // the walls below instead
  const auto swap = [&](const std::string& from, const std::string& to) {
    const auto at = t.find(from);
    if (at == std::string::npos) throw std::logic_error("periodic scene: no '" + from + "'");
    t.replace(at, from.size(), to);
  };
  swap("domain_lo = [-0.05, -0.01, -0.05]", "domain_lo = [-0.04, -0.01, -0.05]");
  swap("domain_hi = [0.05, 0.25, 0.05]", "domain_hi = [0.04, 0.25, 0.05]\nperiodic = [\"x\"]");
  swap("velocity = [0.0, -0.3, 0.0]", "velocity = [0.6, -0.3, 0.0]");
  swap("velocity = [0.0, -0.5, 0.0]", "velocity = [0.4, -0.5, 0.0]");
  return t + R"([[wall]]
name = "floor"
material = "glass"
vertices = [[-0.05, 0.0, -0.04], [-0.05, 0.0, 0.04], [0.05, 0.0, 0.04], [0.05, 0.0, -0.04]]
rim = false
[[wall]]
material = "glass"
vertices = [[0.05, 0.0, -0.04], [0.05, 0.2, -0.04], [-0.05, 0.2, -0.04], [-0.05, 0.0, -0.04]]
rim = false
[[wall]]
material = "glass"
vertices = [[-0.05, 0.0, 0.04], [-0.05, 0.2, 0.04], [0.05, 0.2, 0.04], [0.05, 0.0, 0.04]]
rim = false
)";
}

// One `blaze run` of the scene on `comm`'s ranks (null: not a rank of it) into `dir`.
int run(const Communicator* comm, const std::string& scene, const std::string& dir, std::vector<std::string> overrides,
        const std::string& restart = "") {
  if (!comm) return 0;
  app::Options o;
  o.scene = scene, o.quiet = true, o.comm = comm, o.restart = restart;
  overrides.push_back("output.directory=\"" + dir + "\"");
  o.overrides = overrides;
  try {  // a rank that fails must still reach the test's barrier
    const Scene s = load_scene(scene, overrides);
    return app::run_spring<double>(s, o);
  } catch (const std::exception& e) {
    BOOST_TEST_MESSAGE("rank " << comm->rank() << ": " << dir << ": " << e.what());
    return 1;
  }
}

struct Final {
  std::map<Index, std::pair<Vec3<double>, Vec3<double>>> at;  // id: position, velocity
  Index removed = 0, inserted = 0;
  std::uint64_t steps = 0;
};
// The state a run's checkpoint holds (its parts, however many ranks wrote them).
Final final_state(const std::string& path) {
  Final f;
  using Run = DistributedSimulation<Simulation<DefaultSpace, SphereShape, HertzMindlinLaw<double>, VelocityVerlet>>;
  for (const std::string& part : Run::checkpoint_files(path)) {
    const Checkpoint<double> c = read_checkpoint<double>(part);
    const auto& st = c.snapshot.store;
    for (std::size_t i = 0; i < st.id.size(); ++i) {
      const auto& v = st.reals;
      const std::size_t kv = StoreSnapshot<double>::kVelocityField;
      f.at[st.id[i]] = {record_position(st, i), {v[kv][i], v[kv + 1][i], v[kv + 2][i]}};
    }
    f.removed += c.snapshot.removed_count, f.inserted += c.snapshot.inserted_count, f.steps = c.snapshot.steps;
  }
  return f;
}

long points_of(const std::string& vtu) {
  std::ifstream in(vtu, std::ios::binary);
  std::string head(4096, '\0');
  in.read(&head[0], static_cast<std::streamsize>(head.size()));
  const auto at = head.find("NumberOfPoints=\"");
  return at == std::string::npos ? -1 : std::stol(head.substr(at + 16));
}

}  // namespace

namespace {

// The scene run over all ranks, on one, stopped and continued on one rank fewer: see the top.
void check_over_ranks(const std::string& scene_text, const std::string& label) {
  const Communicator comm;
  const int n = comm.size();
  const std::string base = scene_folder(comm, scene_text);
  BOOST_TEST_REQUIRE(!base.empty());  // (the same on every rank)
  const std::string scene = base + "/scene.toml";
  const Communicator one = comm.first(1), fewer = comm.first(std::max(1, n - 1));
  const bool in_one = one.size() > 0, in_fewer = fewer.size() > 0;

  BOOST_TEST(run(&comm, scene, base + "/many", {}) == 0);
  BOOST_TEST(run(in_one ? &one : nullptr, scene, base + "/one", {}) == 0);
  BOOST_TEST(run(&comm, scene, base + "/stopped", {"simulation.end_time=0.045"}) == 0);
  BOOST_TEST(run(in_fewer ? &fewer : nullptr, scene, base + "/continued", {}, base + "/stopped/checkpoint.blz") == 0);
  comm.barrier();
  if (comm.rank() != 0) return;

  const std::string ranks = ", " + label + ", " + std::to_string(n) + " rank" + (n > 1 ? "s" : "");
  const Final a = final_state(base + "/many/checkpoint.blz"), b = final_state(base + "/one/checkpoint.blz"),
              c = final_state(base + "/continued/checkpoint.blz");
  double worst = 0, worst_continued = 0;
  long missing = 0;
  for (const auto& [id, xv] : b.at) {
    const auto ia = a.at.find(id), ic = c.at.find(id);
    if (ia == a.at.end() || ic == c.at.end()) {
      ++missing;
      continue;
    }
    worst = std::fmax(worst, std::fmax(norm(ia->second.first - xv.first), norm(ia->second.second - xv.second)));
    worst_continued = std::fmax(worst_continued, std::fmax(norm(ic->second.first - xv.first), norm(ic->second.second - xv.second)));
  }
  BOOST_TEST_MESSAGE("blaze run" << ranks << ": " << b.at.size() << " particles at the end (" << b.inserted << " fed, " << b.removed
                                 << " removed); worst |dx|, |dv| against one rank " << worst << ", continued on "
                                 << std::max(1, n - 1) << ": " << worst_continued);
  BOOST_TEST(b.at.size() > 550u);  // the feed delivered: 192 on the lattice, ~400 fed
  BOOST_TEST(b.inserted >= 390);
  BOOST_TEST(a.at.size() == b.at.size());
  BOOST_TEST(c.at.size() == b.at.size());
  BOOST_TEST(a.inserted == b.inserted);
  BOOST_TEST(a.removed == b.removed);
  BOOST_TEST(missing == 0);
  BOOST_TEST(a.steps == b.steps);
  check_at_most({kCase, "blaze run with a feeder: max |x - x_1|, |v - v_1| at 60 ms against one rank" + ranks, "-",
                 "canonical order: bitwise"},
                worst, tol::distributed_positions);
  check_at_most({kCase, "the same, continued from a checkpoint of " + std::to_string(n) + " onto " + std::to_string(std::max(1, n - 1)) +
                            " ranks",
                 "-", "canonical order: bitwise"},
                worst_continued, tol::distributed_positions);

  // the time series: the same rows; the reduced columns to rounding
  std::vector<std::string> ha, hb;
  const auto ra = csv_rows(base + "/many/timeseries.csv", ha), rb = csv_rows(base + "/one/timeseries.csv", hb);
  BOOST_TEST(ha == hb);
  BOOST_TEST(ra.size() == rb.size());
  BOOST_TEST(ra.size() == 13u);  // 0 to 60 ms every 5 ms (400 steps)
  double worst_column = 0;
  std::string worst_name;
  for (std::size_t r = 0; r < std::min(ra.size(), rb.size()); ++r)
    for (std::size_t k = 0; k < std::min(ra[r].size(), rb[r].size()); ++k) {
      const std::string& name = k < ha.size() ? ha[k] : std::string("?");
      // counts and ids: exactly
      if (name == "t_s" || name == "particles" || name == "removed" || name == "inserted" || name == "worst_penetration_id" ||
          name == "penetration_over_limit" || name.rfind("contacts_", 0) == 0) {
        BOOST_TEST(ra[r][k] == rb[r][k], name << " at row " << r);
        continue;
      }
      // J, N, N m, counts: against the column's largest magnitude (a sum that cancels)
      double scale = 0;
      for (const auto& row : rb) scale = std::fmax(scale, std::fabs(row[k]));
      const double d = scale > 0 ? std::fabs(ra[r][k] - rb[r][k]) / scale : std::fabs(ra[r][k] - rb[r][k]);
      if (d > worst_column) worst_column = d, worst_name = name;
    }
  BOOST_TEST_MESSAGE("time series" << ranks << ": worst column difference " << worst_column << " of its largest value (" << worst_name << ")");
  check_at_most({kCase, "blaze run's time series over ranks against one rank: worst column, of its largest value" + ranks, "-",
                 "the ranks' sums in another order"},
                worst_column, tol::distributed_series);
  const std::size_t loads = static_cast<std::size_t>(std::find(ha.begin(), ha.end(), "load_floor_Fy_N") - ha.begin());
  BOOST_TEST(loads < ha.size());
  if (loads < ha.size()) BOOST_TEST(rb.back()[loads] < 0);  // the bed presses on the floor (its load is -y)

  // the frames: a piece a rank and a .pvtu naming them; their points add up to the particles
  long frames_checked = 0, frames_wrong = 0;
  for (int f = 0; f < 4; ++f) {
    char name[64];
    std::snprintf(name, sizeof name, "%s/many/vtu/particles_%04d", base.c_str(), f);
    long points = 0;
    if (n > 1) {
      std::ifstream pv(std::string(name) + ".pvtu");
      std::stringstream text;
      text << pv.rdbuf();
      for (int r = 0; r < n; ++r) {
        char piece[64];
        std::snprintf(piece, sizeof piece, "particles_%04d_r%d.vtu", f, r);
        frames_wrong += text.str().find(piece) == std::string::npos;
        points += points_of(base + "/many/vtu/" + piece);
      }
    } else {
      points = points_of(std::string(name) + ".vtu");
    }
    const double t = 0.02 * f;  // every 1 600 steps
    for (const auto& row : rb)
      if (std::fabs(row[0] - t) < 1e-9) ++frames_checked, frames_wrong += points != static_cast<long>(row[1]);
  }
  BOOST_TEST(frames_checked == 4);
  BOOST_TEST(frames_wrong == 0);
  std::error_code ec;
  std::filesystem::remove_all(base, ec);
}

}  // namespace

BOOST_AUTO_TEST_SUITE(distributed_blaze_run)

BOOST_AUTO_TEST_CASE(a_fed_scene_over_ranks_is_the_one_rank_run) { check_over_ranks(kScene, "box"); }

BOOST_AUTO_TEST_CASE(a_fed_periodic_slice_over_ranks_is_the_one_rank_run) { check_over_ranks(periodic_scene(), "periodic along x"); }

// What a run over ranks refuses, on every rank alike (none is left waiting): pairs evaluated once,
// a checkpoint that is not there, parts of two checkpoints in one folder.
BOOST_AUTO_TEST_CASE(a_run_over_ranks_refuses_what_it_cannot_do) {
  const Communicator comm;
  const std::string base = scene_folder(comm, kScene);
  BOOST_TEST_REQUIRE(!base.empty());
  const std::string scene = base + "/scene.toml";
  const auto message = [&](std::vector<std::string> overrides, const std::string& restart) {
    overrides.push_back("output.directory=\"" + base + "/out\"");
    try {
      app::Options o;
      o.scene = scene, o.quiet = true, o.comm = &comm, o.restart = restart, o.overrides = overrides;
      app::run_spring<double>(load_scene(scene, overrides), o);
    } catch (const std::exception& e) {
      return std::string(e.what());
    }
    return std::string();
  };
  const std::string once = message({"simulation.pair_evaluation=\"once\"", "simulation.end_time=0.001"}, "");
  BOOST_TEST(once.find("key 'pair_evaluation'") != std::string::npos, once);
  BOOST_TEST(once.find("both_sides") != std::string::npos, once);
  const std::string missing = message({}, base + "/nowhere/checkpoint.blz");
  BOOST_TEST(missing.find("nowhere/checkpoint.blz") != std::string::npos, missing);
  BOOST_TEST(missing.find("no checkpoint parts") != std::string::npos, missing);
  if (comm.rank() == 0) {  // parts of a 2-rank and a 3-rank checkpoint side by side
    for (const char* part : {"/two.blz.part0of2", "/two.blz.part0of3"}) std::ofstream(base + part) << "x";
  }
  comm.barrier();
  const std::string mixed = message({}, base + "/two.blz");
  BOOST_TEST(mixed.find("more than one checkpoint") != std::string::npos, mixed);
  comm.barrier();
  std::error_code ec;
  if (comm.rank() == 0) std::filesystem::remove_all(base, ec);
}

BOOST_AUTO_TEST_SUITE_END()
