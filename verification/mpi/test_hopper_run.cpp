// The hopper study over ranks (issue 21; studies/hopper/hopper_run.hpp, build/mpi/study_hopper):
// the default hopper (studies/hopper/hopper.toml) made small: 3 x 60 beads placed, 60 more poured
// by a [[feed]] while the bed settles, the linear tangential spring (contact history across the
// ranks' boxes), the gate removed at 0.2 s and 0.15 s of discharge; on however many ranks mpirun
// starts, against the same on one rank:
// - timeseries.csv: the same rows; discharged mass and count and the particles present exactly;
//   energies, penetration and stored energy within tol::distributed_series of the column's largest
//   value (the ranks' sums are added in another order than one rank's);
// - discharge.csv (each particle's place at the opening and exit time) identical, and the manifest's
//   flow rate, residual and exit times the same (the trajectories are bitwise one rank's:
//   canonical order; the record is kept in id order);
// - beads do leave once the gate opens (the discharge is not empty);
// - with [study] arch_time (0.025 s) shorter than a bead's fall from the orifice out of the domain, every run
//   stops at the same row, "arched" (the decision rank 0 takes holds on every rank; no rank runs on);
// - stopped over the ranks at a wall-clock limit (twice, the first while the feed pours) and
//   restarted from its checkpoint parts, the run ends as the uninterrupted one.
#include <boost/test/unit_test.hpp>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <map>
#include <sstream>
#include "blaze/scene/scene_file.hpp"
#include "studies/hopper/hopper_run.hpp"
#include "verification/mpi/run_files.hpp"
#include "verification/report.hpp"
#include "verification/tolerances.hpp"

using namespace blaze;
using namespace blaze::test;

namespace {

const char* const kCase = "Runs over ranks (issue 21)";

// The default hopper with a feed that pours 60 medium beads over its first 0.1 s.
std::string hopper_scene() {
  std::ifstream in("studies/hopper/hopper.toml");
  std::stringstream text;
  for (std::string line; std::getline(in, line);)
    if (line.rfind("tangential_damping", 0) != 0) text << line << '\n';  // (the history-free law's key; the spring's run)
  text << "\n[[feed]]\nname = \"pour\"\ntype = \"medium\"\n"
          "region = { kind = \"box\", lo = [-0.07, 0.30, -0.03], hi = [0.07, 0.38, 0.03] }\n"
          "rate = 600\ncount = 60\nend_time = 0.1\nvelocity = [0.0, -0.5, 0.0]\n";
  return text.str();
}

// The study on `comm` (no run on a rank outside it), writing to `dir`; `status`: what it must end
// with (0, or hopper::kHopperStopped when `opt` stops it).
void run_study(const Communicator* comm, const std::string& scene, const std::string& dir, std::vector<std::string> extra,
               const hopper::HopperRunOptions& opt = {}, int status_wanted = 0) {
  if (!comm) return;
  std::vector<std::string> set = {"output.directory=\"" + dir + "\"", "simulation.end_time=0.35", "study.gate_open_time=0.2",
                                  "simulation.tangential=\"linear_spring\"", "fill[0].count=60", "fill[1].count=60", "fill[2].count=60",
                                  "output.vtu_interval=0.1"};
  set.insert(set.end(), extra.begin(), extra.end());
  const Scene s = load_scene(scene, set);
  const int status = hopper::run_hopper<LinearSpringLaw<double>, SphereShape>(s, set, comm, opt);
  BOOST_TEST(status == status_wanted);
}

std::map<std::string, std::string> manifest(const std::string& path) {
  std::map<std::string, std::string> m;
  std::ifstream in(path);
  std::string line;
  while (std::getline(in, line))
    if (const auto eq = line.find(" = "); eq != std::string::npos) m[line.substr(0, eq)] = line.substr(eq + 3);
  return m;
}

std::string text_of(const std::string& path) {
  std::ifstream in(path);
  std::stringstream s;
  s << in.rdbuf();
  return s.str();
}

}  // namespace

BOOST_AUTO_TEST_SUITE(distributed_hopper_study)

BOOST_AUTO_TEST_CASE(the_hopper_discharge_over_ranks_is_the_one_rank_discharge) {
  const Communicator comm;
  const int n = comm.size();
  const std::string base = scene_folder(comm, hopper_scene());
  BOOST_TEST_REQUIRE(!base.empty());
  const Communicator one = comm.first(1);
  const std::string ranks = std::to_string(n) + " rank" + (n > 1 ? "s" : "");
  for (const bool arch : {false, true}) {
    const std::string tag = arch ? "/arch" : "/flow";
    const std::vector<std::string> extra = arch ? std::vector<std::string>{"study.arch_time=0.025"} : std::vector<std::string>{};
    run_study(&comm, base + "/scene.toml", base + tag + "_many", extra);
    run_study(one.size() > 0 ? &one : nullptr, base + "/scene.toml", base + tag + "_one", extra);
    comm.barrier();
    if (comm.rank() != 0) continue;

    std::vector<std::string> ha, hb;
    const auto ra = csv_rows(base + tag + "_many/timeseries.csv", ha), rb = csv_rows(base + tag + "_one/timeseries.csv", hb);
    const SeriesComparison c = compare_series(ha, ra, hb, rb, {"t_s", "discharged_mass_kg", "discharged_count", "particles_in_hopper",
                                                              "contacts_wall"});
    BOOST_TEST(c.same_shape);
    BOOST_TEST(c.exact_wrong == 0);
    BOOST_TEST(text_of(base + tag + "_many/discharge.csv") == text_of(base + tag + "_one/discharge.csv"));
    auto ma = manifest(base + tag + "_many/manifest.txt"), mb = manifest(base + tag + "_one/manifest.txt");
    for (const char* key : {"particles_at_opening", "discharged_count", "residual_fraction", "flow_rate_kg_s", "exit_top_centre_s",
                            "arched", "last_exit_s"})
      BOOST_TEST(ma[key] == mb[key], key << ": " << ma[key] << " over ranks, " << mb[key] << " on one");
    const auto column = static_cast<std::size_t>(std::find(hb.begin(), hb.end(), "particles_in_hopper") - hb.begin());
    BOOST_TEST_REQUIRE((!rb.empty() && column < rb.front().size()));
    const double present_at_start = rb.front()[column];  // at t = -0.2 s, before the feed's first beads
    BOOST_TEST_MESSAGE("hopper study (" << tag.substr(1) << "), " << ranks << ": " << rb.size() << " rows, " << mb["discharged_count"]
                                        << " of " << mb["particles_at_opening"] << " discharged; worst column " << c.worst << " of its largest ("
                                        << c.worst_name << ")");
    BOOST_TEST(present_at_start == 180);
    if (arch) {
      BOOST_TEST(mb["arched"] == "yes");  // stopped 0.025 s after the first sample without an exit: before any bead fell out (~0.05 s)
      BOOST_TEST(rb.back()[0] < 0.1);
    } else {
      BOOST_TEST(mb["particles_at_opening"] == "240");  // 180 placed + 60 poured
      BOOST_TEST(std::stol(mb["discharged_count"]) > 0);
    }
    check_at_most({kCase, "the hopper's time series over ranks against one rank (" + tag.substr(1) + "): worst column, of its largest, " + ranks,
                   "-", "the ranks' sums in another order"},
                  c.worst, tol::distributed_series);
  }
  // Stopped over the ranks at once (--stop-after 0) at the first checkpoint step (0.06 s, while the
  // feed pours), again at the second, and continued to the end: the uninterrupted run's discharge
  // record and time series (its exact columns; the energies as the ranks' sums are), checkpoints
  // written one part a rank.
  const std::vector<std::string> every = {"output.checkpoint_interval=0.06"};
  const std::string stop = base + "/stop", checkpoint = stop + "/checkpoint.blz";
  const std::string part0 = n > 1 ? checkpoint + ".part0of" + std::to_string(n) : checkpoint;  // (one rank: one file)
  hopper::HopperRunOptions opt;
  opt.stop_after = 0;
  run_study(&comm, base + "/scene.toml", stop, every, opt, hopper::kHopperStopped);
  comm.barrier();
  if (comm.rank() == 0) std::filesystem::copy_file(part0, base + "/first_part0", std::filesystem::copy_options::overwrite_existing);
  opt.restart = checkpoint;
  run_study(&comm, base + "/scene.toml", stop, every, opt, hopper::kHopperStopped);
  opt.stop_after = -1;
  run_study(&comm, base + "/scene.toml", stop, every, opt);
  comm.barrier();
  if (comm.rank() == 0) {
    BOOST_TEST(text_of(base + "/first_part0") != text_of(part0));  // two stops, two checkpoints
    std::vector<std::string> ha, hb;
    const auto ra = csv_rows(stop + "/timeseries.csv", ha), rb = csv_rows(base + "/flow_many/timeseries.csv", hb);
    const SeriesComparison c = compare_series(ha, ra, hb, rb, {"t_s", "discharged_mass_kg", "discharged_count", "particles_in_hopper",
                                                              "contacts_wall"});
    BOOST_TEST(c.same_shape);
    BOOST_TEST(c.exact_wrong == 0);
    BOOST_TEST(text_of(stop + "/discharge.csv") == text_of(base + "/flow_many/discharge.csv"));
    check_at_most({kCase, "the hopper stopped twice and restarted over " + ranks + " against its uninterrupted run: worst column, of its largest",
                   "-", "the ranks' sums in another order"},
                  c.worst, tol::distributed_series);
  }
  comm.barrier();
  std::error_code ec;
  if (comm.rank() == 0) std::filesystem::remove_all(base, ec);
}

BOOST_AUTO_TEST_SUITE_END()
