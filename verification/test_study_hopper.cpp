// study_hopper (studies/hopper) run as a user runs it, for the long studies that outlast a session
// (make fig-2.17: ~1e6 steps a run): a run stopped by its wall-clock limit (--stop-after) and
// continued from its checkpoint (--restart), twice, the first stop while the feeder still pours,
// ends with the uninterrupted run's time series, discharge record, frame list and frames byte for
// byte. Beads in an STL silo under Hertz-Mindlin (the tangential springs and the feeder's random
// streams travel in the checkpoint) at two checkpoint intervals, and corn polyhedra (random
// orientations, several contacts a pair) in an STL hopper. A checkpoint of another scene, a
// damaged one, one whose time series is gone and bad options are refused, naming what is wrong.
#include <boost/test/unit_test.hpp>

#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <regex>
#include <string>
#include <vector>
#include "verification/run_program.hpp"

namespace fs = std::filesystem;
using blaze::test::ProgramResult;
using blaze::test::slurp;

namespace {

struct HopperCase {
  const char* name;
  const char* stl;       // the geometry script's arguments (studies/hopper/*.py, studies/silo/*.py)
  const char* scene;     // the scene file, scaled down by `sets`
  const char* sets;      // --set overrides (single-quoted for the shell)
  int fed;               // particles the feeder pours
  double interval;       // s, [output] checkpoint_interval: the run stops at its first two multiples
};

// Small versions of the studies' scenes: 300 beads fed in 0.05 s into a 96-triangle silo, the gate
// opening at 0.2 s; 60 corn kernels fed in 0.1 s into a 16-triangle hopper, the gate at 0.2 s.
const char* const kSilo = "studies/silo/make_silo_stl.py --radius 0.04 --height 0.12 --orifice-radius 0.01 --segments 16";
const char* const kSiloSets =
    "--set study.orifice_half_width=0.01 --set simulation.end_time=0.4 --set study.gate_open_time=0.2 --set feed[0].count=300 "
    "--set feed[0].rate=6000 --set feed[0].end_time=0.05 "
    "--set 'feed[0].region={ kind = \"cylinder\", centre = [0.0, 0.06, 0.0], axis = [0.0, 1.0, 0.0], radius = 0.035, length = 0.04 }'";
const HopperCase kCases[] = {
    {"beads in a silo", kSilo, "studies/silo/beverloo.toml", kSiloSets, 300, 0.03},
    {"beads in a silo", kSilo, "studies/silo/beverloo.toml", kSiloSets, 300, 0.02},
    {"corn in a hopper", "studies/hopper/make_hopper_stl.py --width 0.08 --height 0.1 --angle 60 --orifice 0.03",
     "studies/hopper/corn.toml",
     "--set study.orifice_half_width=0.015 --set simulation.end_time=0.35 --set study.gate_open_time=0.2 --set feed[0].count=60 "
     "--set feed[0].rate=600 --set feed[0].end_time=0.1 --set simulation.domain_hi=[0.085,0.13,0.085] "
     "--set 'feed[0].region={ kind = \"box\", lo = [-0.035, 0.07, -0.035], hi = [0.035, 0.11, 0.035] }'",
     60, 0.04},
};

// The case's command line into output directory `dir` (plus `extra`).
std::string command(const HopperCase& c, const fs::path& stl, const fs::path& dir, const std::string& extra = "") {
  char interval[32];
  std::snprintf(interval, sizeof interval, "%.17g", c.interval);
  return blaze::test::program_binary("study_hopper") + " " + c.scene + " --no-plot --set 'mesh[0].file=\"" + stl.string() + "\"' " +
         c.sets + " --set output.checkpoint_interval=" + interval + " --set output.vtu_interval=0.1 --set 'output.directory=\"" +
         dir.string() + "\"' " + extra;
}

// The number in the first group of `pattern` in `text` (-1 when absent).
long number_after(const std::string& text, const std::string& pattern) {
  std::smatch m;
  return std::regex_search(text, m, std::regex(pattern)) ? std::stol(m[1]) : -1;
}

fs::path make_stl(const HopperCase& c, const fs::path& dir) {
  fs::create_directories(dir);
  const fs::path stl = dir / "walls.stl";
  const ProgramResult r = blaze::test::run_command(std::string("python3 ") + c.stl + " --out " + stl.string());
  BOOST_TEST_REQUIRE(r.status == 0, r.output);
  return stl;
}

}  // namespace

BOOST_AUTO_TEST_SUITE(study_hopper)

BOOST_AUTO_TEST_CASE(a_stopped_and_restarted_run_is_the_uninterrupted_one) {
  BOOST_TEST_REQUIRE(fs::exists(blaze::test::program_binary("study_hopper")), "study_hopper is missing: make test builds it");
  int k = 0;
  for (const HopperCase& c : kCases) {
    BOOST_TEST_CONTEXT(c.name << ", checkpoints every " << c.interval << " s") {
      const fs::path root = fs::temp_directory_path() / ("blaze_study_hopper_" + std::to_string(k++));
      fs::remove_all(root);
      const fs::path stl = make_stl(c, root), a = root / "a", b = root / "b";
      const ProgramResult whole = blaze::test::run_command(command(c, stl, a));
      BOOST_TEST_REQUIRE(whole.status == 0, whole.output);
      // The physics ran: the feeder placed every particle and some left through the orifice.
      BOOST_TEST(number_after(whole.output, R"(feed pour: (\d+) inserted, 0 due not placed)") == c.fed, whole.output);
      BOOST_TEST(number_after(whole.output, R"(discharged (\d+) of)") > 0, whole.output);

      // Stopped at once (--stop-after 0): at the first checkpoint step, while the feeder pours.
      const ProgramResult first = blaze::test::run_command(command(c, stl, b, "--stop-after 0"));
      BOOST_TEST_REQUIRE(first.status == 3, first.output);
      BOOST_TEST(first.output.find("stopped at t = ") != std::string::npos, first.output);
      fs::copy_file(b / "checkpoint.blz", root / "first.blz");
      const ProgramResult second =
          blaze::test::run_command(command(c, stl, b, "--stop-after 0 --restart " + (root / "first.blz").string()));
      BOOST_TEST_REQUIRE(second.status == 3, second.output);
      const long present = number_after(second.output, R"(restarted from .* \(step \d+\): (\d+) particles)");
      BOOST_TEST((present > 0 && present < c.fed), "the first stop falls in the feed: " << present << " particles of " << c.fed);
      fs::copy_file(b / "checkpoint.blz", root / "second.blz");
      const ProgramResult rest = blaze::test::run_command(command(c, stl, b, "--restart " + (root / "second.blz").string()));
      BOOST_TEST_REQUIRE(rest.status == 0, rest.output);

      for (const char* file : {"timeseries.csv", "discharge.csv", "particles.pvd", "walls.vtu"})
        BOOST_TEST((slurp(a / file) == slurp(b / file)), file << " differs from the uninterrupted run's");
      int frames = 0;
      for (const auto& e : fs::directory_iterator(a / "vtu")) {
        ++frames;
        BOOST_TEST((slurp(e.path()) == slurp(b / "vtu" / e.path().filename())), e.path().filename() << " differs");
      }
      BOOST_TEST(frames >= 4);
      BOOST_TEST(std::distance(fs::directory_iterator(b / "vtu"), fs::directory_iterator{}) == frames);
      BOOST_TEST(number_after(rest.output, R"(discharged (\d+) of)") == number_after(whole.output, R"(discharged (\d+) of)"));
      fs::remove_all(root);
    }
  }
}

BOOST_AUTO_TEST_CASE(a_checkpoint_that_cannot_continue_is_refused) {
  const HopperCase& c = kCases[0];
  const fs::path root = fs::temp_directory_path() / "blaze_study_hopper_refused";
  fs::remove_all(root);
  const fs::path stl = make_stl(c, root), a = root / "a";
  const ProgramResult stopped = blaze::test::run_command(command(c, stl, a, "--stop-after 0"));
  BOOST_TEST_REQUIRE(stopped.status == 3, stopped.output);
  const fs::path cp = root / "cp.blz";
  fs::copy_file(a / "checkpoint.blz", cp);
  const auto refused = [&](const std::string& extra, const fs::path& dir, const std::vector<std::string>& says) {
    const ProgramResult r = blaze::test::run_command(command(c, stl, dir, extra));
    BOOST_TEST(r.status == 1, extra << ": " << r.output);
    for (const auto& s : says) BOOST_TEST(r.output.find(s) != std::string::npos, extra << ": '" << s << "' not in " << r.output);
  };
  // another scene: the friction changed
  refused("--set pair[0].friction=0.3 --restart " + cp.string(), a, {"cannot continue this scene", "friction"});
  // a damaged checkpoint: cut in half
  const std::string bytes = slurp(cp);
  std::ofstream(root / "half.blz", std::ios::binary) << bytes.substr(0, bytes.size() / 2);
  refused("--restart " + (root / "half.blz").string(), a, {(root / "half.blz").string()});
  // its time series gone (a fresh output directory): nothing to continue the rows of
  refused("--restart " + cp.string(), root / "fresh", {"timeseries.csv", "shorter than when the checkpoint was written (or gone)"});
  // bad options
  for (const char* bad : {"--stop-after -1", "--stop-after soon", "--stop-after"}) refused(bad, a, {"--stop-after", "usage: study_hopper"});
  fs::remove_all(root);
}

BOOST_AUTO_TEST_SUITE_END()
