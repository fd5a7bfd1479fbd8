// Hopper discharge study (default `make run`; make fig-2.15 / fig-2.16), driven by a scene file:
//   study_hopper [SCENE.toml] [--set key=value]... [--restart CHECKPOINT] [--stop-after SECONDS] [--no-plot] [--phases]
//                                                       (default studies/hopper/hopper.toml)
//   --stop-after S: after S seconds of wall time, write <output directory>/checkpoint.blz (at the
//   next checkpoint step when [output] checkpoint_interval is set) and stop with status 3;
//   --restart continues from it (hopper_run.hpp). --no-plot: no plots/hopper.png. --phases: each
//   phase's time per step at the end (one synchronisation per phase: slower).
//   mpirun -np N build/mpi/study_hopper [SCENE.toml] ... the same over N ranks (issue 21)
// What it runs, measures and writes: studies/hopper/hopper_run.hpp; here also plots/hopper.png.
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <string>
#include <vector>
#if __has_include(<gnuplot-iostream.h>)
#include <gnuplot-iostream.h>
#define BLAZE_HAVE_GNUPLOT 1
#endif
#include "blaze/io/console.hpp"
#include "blaze/scene/run_size.hpp"
#include "blaze/scene/scene_file.hpp"
#include "pipeline/parallel/communicator.hpp"
#include "studies/hopper/hopper_run.hpp"

using namespace blaze;
using blaze::hopper::run_hopper;
using Real = double;

namespace {

bool plot(const std::string& csv, const std::string& png) {
#if !defined(BLAZE_HAVE_GNUPLOT)
  std::printf("plot skipped: built without gnuplot-iostream (tools/ensure_deps.sh installs it); %s has the data\n",
              csv.c_str());
  (void)png;
  return false;
#else
  Gnuplot gp;
  gp << "set terminal pngcairo size 1000,800 font ',11'\nset output '" << png << "'\n"
     << "set datafile separator ','\nset key autotitle columnhead\nset grid\nset format y '%g'\nset multiplot layout 2,1\n"
     << "set title 'Hopper discharge (gate opens at t = 0)'\nset xlabel 't (s)'\nset ylabel 'discharged mass (kg)'\n"
     << "plot '" << csv << "' using 1:2 with lines lw 2 notitle\n"
     << "set title 'Energy'\nset ylabel 'J'\nset logscale y\n"
     << "plot '" << csv << "' using 1:5 with lines lw 2 title 'translational KE', "
     << "'' using 1:6 with lines lw 2 title 'rotational KE'\nunset multiplot\n";
  return true;
#endif
}

}  // namespace

int main(int argc, char** argv) try {
  blaze::line_buffered_output();
  const Communicator* comm = study_ranks(&argc, &argv, "study_hopper");  // an MPI build: its ranks (rank 0 prints)
  std::string path = "studies/hopper/hopper.toml";
  std::vector<std::string> overrides;
  hopper::HopperRunOptions opt;
  bool plot_png = true;
  const char* const usage =
      "usage: study_hopper [SCENE.toml] [--set key=value]... [--restart CHECKPOINT] [--stop-after SECONDS] [--no-plot] [--phases]";
  for (int k = 1; k < argc; ++k) {
    const std::string a = argv[k];
    if (a == "--set" && k + 1 < argc) overrides.push_back(argv[++k]);
    else if (a == "--restart" && k + 1 < argc) opt.restart = argv[++k];
    else if (a == "--no-plot") plot_png = false;
    else if (a == "--phases") opt.phases = true;
    else if (a == "--stop-after" && k + 1 < argc) {
      const std::string v = argv[++k];
      char* end = nullptr;
      opt.stop_after = std::strtod(v.c_str(), &end);
      if (v.empty() || *end || !(opt.stop_after >= 0) || !(opt.stop_after < 1e9))
        throw SceneError("--stop-after " + v + ": a wall time in seconds, from 0 to 1e9, is wanted; " + usage);
    } else if (a.rfind("--", 0) == 0) throw SceneError("unknown option '" + a + "' (or its value missing); " + usage);
    else path = a;
  }
  const Scene s = load_scene(path, overrides);
  if (s.precision != PrecisionKind::float64) throw SceneError(path + ": the hopper study runs in double: precision = \"double\"");
  for (const auto& note : s.notes) std::printf("%s\n", note.c_str());
  check_run_fits_here(s);
  // the scene's law, tangential and rolling keys, all of them (pipeline/scene_law.hpp)
  const int status =
      s.all_spheres()
          ? with_scene_law<Real, true>(s, [&](auto law) { return run_hopper<typename decltype(law)::type, SphereShape>(s, overrides, comm, opt); })
          : with_scene_law<Real, false>(
                s, [&](auto law) { return run_hopper<typename decltype(law)::type, PolyhedronShape<Real>>(s, overrides, comm, opt); });
  if ((!comm || comm->rank() == 0) && status != hopper::kHopperStopped && plot_png) {
    std::filesystem::create_directories("plots");
    if (plot(s.output.directory + "/timeseries.csv", "plots/hopper.png")) std::printf("plotted plots/hopper.png\n");
  }
  return status;
} catch (const std::exception& ex) {
  std::fprintf(stderr, "error: %s%s\n", rank_label().c_str(), ex.what());
  return stop_ranks(1);
}
