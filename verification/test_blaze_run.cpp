// The blaze program (apps/blaze), run as a user would: --help lists every option, a bad scene or
// option fails with its exit status and a message naming the place, and a run restarted from its
// checkpoint rewrites exactly the time series the uninterrupted run wrote.
#include <boost/test/unit_test.hpp>

#include <filesystem>
#include <string>
#include "verification/run_program.hpp"

namespace fs = std::filesystem;
using blaze::test::blaze_binary;
using blaze::test::slurp;
using Result = blaze::test::ProgramResult;

namespace {
Result run(const std::string& args) { return blaze::test::run_blaze(args); }
}  // namespace

BOOST_AUTO_TEST_SUITE(blaze_run)

BOOST_AUTO_TEST_CASE(help_lists_every_option) {
  BOOST_TEST_REQUIRE(fs::exists(blaze_binary()), blaze_binary() << " is missing: make test builds it");
  const Result r = run("--help");
  BOOST_TEST(r.status == 0);
  for (const char* option : {"run SCENE.toml", "--set KEY=VALUE", "--restart FILE", "--quiet", "--check", "--help"})
    BOOST_TEST(r.output.find(option) != std::string::npos, option);
  BOOST_TEST(run("run data/scenes/box_fill.toml --frobnicate").status == 2);
}

// README.md's annotated example is the shipped scene itself, and that scene runs.
BOOST_AUTO_TEST_CASE(readme_example_is_the_shipped_scene) {
  const std::string readme = slurp("README.md"), scene = slurp("data/scenes/box_fill.toml");
  const auto start = readme.find("```toml\n");
  BOOST_TEST_REQUIRE(start != std::string::npos);
  const auto end = readme.find("```", start + 8);
  BOOST_TEST(readme.substr(start + 8, end - start - 8) == scene);
  BOOST_TEST(run("run data/scenes/box_fill.toml --check").status == 0);
  BOOST_TEST(run("run data/scenes/cubes_in_drum.toml --check").status == 0);
}

// The progress line is for a terminal: with stderr in a pipe (as here) a run prints none, even
// without --quiet, and still reports its summary.
BOOST_AUTO_TEST_CASE(no_progress_line_when_not_a_terminal) {
  const fs::path dir = fs::temp_directory_path() / "blaze_run_progress";
  const Result r = run("run data/scenes/box_fill.toml --set end_time=0.002 --set output.directory=" + dir.string());
  BOOST_TEST(r.status == 0, r.output);
  BOOST_TEST(r.output.find("ETA") == std::string::npos, r.output);
  BOOST_TEST(r.output.find("done: ") != std::string::npos, r.output);
  fs::remove_all(dir);
}

BOOST_AUTO_TEST_CASE(rejected_scene_exits_1_naming_the_place) {
  const Result r = run("run data/scenes/box_fill.toml --check --set pair[0].restitution=0");
  BOOST_TEST(r.status == 1);
  BOOST_TEST(r.output.find("[[pair]] #1: key 'restitution' = 0: must be in (0, 1]") != std::string::npos, r.output);
  const Result missing = run("run no/such/scene.toml");
  BOOST_TEST(missing.status == 1);
  BOOST_TEST(missing.output.find("no/such/scene.toml: cannot open scene file") != std::string::npos, missing.output);
}

// The uninterrupted run writes checkpoints; a copy of its output directory, restarted from its
// last checkpoint, must end with byte-identical time series and frames.
BOOST_AUTO_TEST_CASE(restart_rewrites_the_same_time_series) {
  const fs::path a = fs::temp_directory_path() / "blaze_run_a", b = fs::temp_directory_path() / "blaze_run_b";
  fs::remove_all(a);
  fs::remove_all(b);
  const std::string common = "run data/scenes/box_fill.toml --quiet --set end_time=0.03 --set output.csv_interval=0.001 "
                             "--set output.vtu_interval=0.01 --set output.checkpoint_interval=0.008 ";
  const Result first = run(common + "--set output.directory=" + a.string());
  BOOST_TEST_REQUIRE(first.status == 0, first.output);
  fs::copy(a, b, fs::copy_options::recursive);
  const Result again = run(common + "--set output.directory=" + b.string() + " --restart " + (a / "checkpoint.blz").string());
  BOOST_TEST_REQUIRE(again.status == 0, again.output);
  BOOST_TEST(again.output.find("restarted from") != std::string::npos);
  BOOST_TEST(slurp(a / "timeseries.csv") == slurp(b / "timeseries.csv"));
  BOOST_TEST(slurp(a / "particles.pvd") == slurp(b / "particles.pvd"));
  BOOST_TEST(slurp(a / "vtu/particles_0003.vtu") == slurp(b / "vtu/particles_0003.vtu"));
  // the guards' summary covers the whole run, not the restarted part only (stop 50: the deepest
  // penetration and the largest energy gain were those after the checkpoint)
  auto summary = [](const std::string& out) {
    const auto at = out.find("deepest penetration");
    return at == std::string::npos ? std::string("none") : out.substr(at, out.find('\n', at) - at);
  };
  BOOST_TEST(summary(first.output) != "none", first.output);
  BOOST_TEST(summary(again.output) == summary(first.output));
  // A checkpoint of another run is refused.
  const Result other = run(common + "--set output.directory=" + b.string() + " --set dt=5e-6 --restart " +
                           (a / "checkpoint.blz").string());
  BOOST_TEST(other.status == 1);
  BOOST_TEST(other.output.find("cannot continue this scene") != std::string::npos, other.output);
  BOOST_TEST(other.output.find("key 'dt'") != std::string::npos, other.output);
  fs::remove_all(a);
  fs::remove_all(b);
}

// A run stopped at its end off the CSV schedule and continued to a later end_time (stop 49: the
// stopped run's last row stayed, which the uninterrupted run never wrote) writes the uninterrupted
// run's time series; a restart past end_time is refused before any file is touched.
BOOST_AUTO_TEST_CASE(restart_to_a_later_end_drops_the_stopped_run_s_last_row) {
  const fs::path a = fs::temp_directory_path() / "blaze_run_later_a", b = fs::temp_directory_path() / "blaze_run_later_b";
  fs::remove_all(a);
  fs::remove_all(b);
  // checkpoints at the same step in both runs (a checkpoint rebuilds the lists: the trajectory
  // depends on where they are)
  const std::string common = "run data/scenes/box_fill.toml --quiet --set output.csv_interval=0.002 --set output.vtu_interval=0.01 "
                             "--set output.checkpoint_interval=0.0251 ";
  const Result whole = run(common + "--set end_time=0.03 --set output.directory=" + a.string());
  BOOST_TEST_REQUIRE(whole.status == 0, whole.output);
  const Result stopped = run(common + "--set end_time=0.0251 --set output.directory=" + b.string());
  BOOST_TEST_REQUIRE(stopped.status == 0, stopped.output);
  const std::string before = slurp(b / "timeseries.csv");
  const Result past = run(common + "--set end_time=0.02 --set output.directory=" + b.string() + " --restart " + (b / "checkpoint.blz").string());
  BOOST_TEST(past.status == 1);
  BOOST_TEST(past.output.find("past this run's end_time = 0.02 s") != std::string::npos, past.output);
  BOOST_TEST(slurp(b / "timeseries.csv") == before);
  const Result later = run(common + "--set end_time=0.03 --set output.directory=" + b.string() + " --restart " + (b / "checkpoint.blz").string());
  BOOST_TEST_REQUIRE(later.status == 0, later.output);
  BOOST_TEST(slurp(a / "timeseries.csv") == slurp(b / "timeseries.csv"));
  BOOST_TEST(slurp(a / "particles.pvd") == slurp(b / "particles.pvd"));
  fs::remove_all(a);
  fs::remove_all(b);
}

// Without csv_interval the guards still sample (stop 49: such a run blew up and ended with status
// 0, every particle gone): a time step far above the critical one stops with status 3.
BOOST_AUTO_TEST_CASE(guards_sample_without_a_csv) {
  const fs::path dir = fs::temp_directory_path() / "blaze_run_nocsv";
  fs::remove_all(dir);
  for (const char* dt : {"1e-3", "3e-4"}) {
    const Result r = run(std::string("run data/scenes/box_fill.toml --quiet --set end_time=0.05 --set force_dt=true --set dt=") + dt +
                         " --set output.csv_interval=0 --set output.vtu_interval=0 --set output.checkpoint_interval=0 "
                         "--set output.directory=" + dir.string());
    BOOST_TEST(r.status == 3, dt << ": " << r.output);
    BOOST_TEST(r.output.find("the energy rose") != std::string::npos, r.output);
  }
  const Result fine = run("run data/scenes/box_fill.toml --quiet --set end_time=0.01 --set output.csv_interval=0 --set output.vtu_interval=0 "
                          "--set output.checkpoint_interval=0 --set output.directory=" + dir.string());
  BOOST_TEST(fine.status == 0, fine.output);
  BOOST_TEST(fine.output.find("the guards sampled without rows") != std::string::npos, fine.output);
  fs::remove_all(dir);
}

// An output interval of the run's whole length comes at its end, once: a checkpoint_interval equal
// to end_time writes the checkpoint that make bench-compare restarts from (an interval rounding to
// the run's step count was taken for "never" from stop 22 to 24), and one just past it writes none.
BOOST_AUTO_TEST_CASE(interval_of_the_run_length_comes_at_its_end) {
  for (const char* end_time : {"0.002", "0.0021", "0.0034"}) {  // dt = 3.4e-5 s x 40 steps per contact
    const fs::path dir = fs::temp_directory_path() / "blaze_run_interval";
    fs::remove_all(dir);
    const std::string set = std::string(" --set end_time=") + end_time + " --set output.checkpoint_interval=" + end_time;
    const Result r = run("run data/scenes/box_fill.toml --quiet --set output.directory=" + dir.string() + set);
    BOOST_TEST_REQUIRE(r.status == 0, r.output);
    BOOST_TEST(fs::exists(dir / "checkpoint.blz"), "end_time = checkpoint_interval = " << end_time);
    fs::remove_all(dir);
    const Result past = run("run data/scenes/box_fill.toml --quiet --set output.directory=" + dir.string() + set +
                            " --set end_time=" + std::to_string(0.5 * std::stod(end_time)));
    BOOST_TEST_REQUIRE(past.status == 0, past.output);
    BOOST_TEST(!fs::exists(dir / "checkpoint.blz"), "checkpoint_interval twice end_time: none written");
    fs::remove_all(dir);
  }
}

BOOST_AUTO_TEST_SUITE_END()
