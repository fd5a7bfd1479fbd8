// blaze: runs a scene file (README.md, "Scene files").
//   blaze run SCENE.toml [--set key=value]... [--quiet] [--check] [--phases]
//   blaze --help
// One binary per backend: build/cpu/blaze (OpenMP) and build/cuda/blaze (GPU). The scene picks
// the precision (float, double), the law (linear, hertz) and, through its particle types, the
// shape policy (spheres, or polyhedra with spheres); each combination is one instantiation of the
// same Simulation template, compiled in the law families' units apps/blaze/run_*.cpp (run_scene.hpp).
// An MPI build (build/mpi/blaze, BLAZE_MPI) run under mpirun -np N runs the scene over N ranks
// (issue 21; run_scene.hpp): rank 0 prints and writes the time series; errors come from any rank.
#include <cstdio>
#include <cstdlib>
#include <string>
#include "pipeline/scene_law.hpp"
#include "apps/blaze/run_families.hpp"
#include "blaze/exec/device_info.hpp"
#include "blaze/io/console.hpp"
#include "blaze/scene/run_size.hpp"
#include "blaze/scene/critical_step.hpp"
#include "blaze/scene/scene_build.hpp"
#include "blaze/scene/scene_file.hpp"
#include "pipeline/parallel/communicator.hpp"

using namespace blaze;
using blaze::app::Options;

namespace {

const char* kUsage =
    "usage: blaze run SCENE.toml [options]\n"
    "       blaze --help\n"
    "\n"
    "Runs the scene described by SCENE.toml (TOML, SI units; README.md documents every key).\n"
    "\n"
    "options:\n"
    "  --set KEY=VALUE  override a scene value, for example --set simulation.dt=1e-5,\n"
    "                   --set dt=1e-5 (keys of [simulation] and [output] may drop the table),\n"
    "                   --set material[0].density=2600; repeatable; validated like the file\n"
    "  --restart FILE   continue the run from a checkpoint written by it (same scene; the time\n"
    "                   series and frames after the checkpoint's time are replaced)\n"
    "  --quiet          no progress line (on a terminal it is redrawn twice a second; into a\n"
    "                   file or pipe a line is written every minute)\n"
    "  --phases         time every phase of the step (one synchronisation per phase: a few\n"
    "                   percent slower) and print the split per step at the end\n"
    "  --check          validate the scene, print the critical time step, the sizes and the\n"
    "                   memory estimate (host and GPU) against this machine, and stop\n"
    "  --help, -h       this text\n"
    "\n"
    "Writes to [output] directory: timeseries.csv (every csv_interval), particles.pvd with\n"
    "vtu/particles_NNNN.vtu (every vtu_interval; polyhedral scenes also polyhedra.pvd with their\n"
    "faces), walls.vtu, checkpoint.blz (every checkpoint_interval, atomically). A state that turns\n"
    "NaN or Inf stops the run (exit status 3), naming the step and particle, and leaves the last\n"
    "sampled state in last_good.vtu; so does a sampled energy above the initial one by more than\n"
    "[output] energy_gain_limit (an unstable time step). Exit status 0 on success, 1 on a rejected\n"
    "scene or a failed run, 2 on a usage error, 3 when a guard stopped the run.\n";

Options parse_args(int argc, char** argv) {
  Options o;
  if (argc >= 2 && (std::string(argv[1]) == "--help" || std::string(argv[1]) == "-h")) {
    std::fputs(kUsage, stdout);
    std::exit(0);
  }
  if (argc < 3 || std::string(argv[1]) != "run") {
    std::fputs(kUsage, stderr);
    std::exit(2);
  }
  o.scene = argv[2];
  for (int k = 3; k < argc; ++k) {
    const std::string a = argv[k];
    if (a == "--set" && k + 1 < argc) o.overrides.push_back(argv[++k]);
    else if (a.rfind("--set=", 0) == 0) o.overrides.push_back(a.substr(6));
    else if (a == "--restart" && k + 1 < argc) o.restart = argv[++k];
    else if (a == "--quiet") o.quiet = true;
    else if (a == "--check") o.check = true;
    else if (a == "--phases") o.phases = true;
    else if (a == "--help" || a == "-h") {
      std::fputs(kUsage, stdout);
      std::exit(0);
    } else {
      std::fprintf(stderr, "blaze: unknown option '%s'\n\n%s", a.c_str(), kUsage);
      std::exit(2);
    }
  }
  return o;
}

// The scene's law family and precision (apps/blaze/run_*.cpp).
template <class Real>
int run_precision(const Scene& s, const Options& o) {
  switch (law_family(s)) {
    case LawFamily::history_free:
      return app::run_history_free<Real>(s, o);
    case LawFamily::spring:
      return app::run_spring<Real>(s, o);
    case LawFamily::rolling:
      break;
  }
  if (!s.all_spheres()) throw SceneError(s.place("simulation.rolling") + " = \"" + to_string(s.rolling) + "\": rolling resistance is for spheres");
  return app::run_rolling<Real>(s, o);
}

}  // namespace
int main(int argc, char** argv) try {
  blaze::line_buffered_output();
  Options o = parse_args(argc, argv);
#if defined(BLAZE_MPI)
  static MpiSession mpi(&argc, &argv);  // before anything else can fail: MPI_Finalize at exit
  static const Communicator comm;
  o.comm = &comm;
  if (comm.rank() != 0 && !std::freopen("/dev/null", "w", stdout)) return 1;  // one voice; errors still on stderr
  if (comm.size() > 1) std::printf("blaze: over %d ranks (MPI)\n", comm.size());
#endif
  const Scene s = load_scene(o.scene, o.overrides);
  const bool gpu_build = std::string(DefaultSpace::name) == "gpu";
  if (s.backend == BackendKind::gpu && !gpu_build)
    throw SceneError(s.place("simulation.backend") + " = \"gpu\": this is the CPU build (build/cpu/blaze); run build/cuda/blaze");
  if (s.backend == BackendKind::cpu && gpu_build)
    throw SceneError(s.place("simulation.backend") + " = \"cpu\": this is the GPU build (build/cuda/blaze); run build/cpu/blaze");
  std::printf("blaze: %s, %s law%s%s, %s, %s (%s)\n", s.path.c_str(), to_string(s.law),
              s.tangential == TangentialKind::mindlin         ? " + Mindlin tangential spring"
              : s.tangential == TangentialKind::linear_spring ? " + linear tangential spring"
                                                              : "",
              s.rolling == RollingKind::cdt    ? " + rolling resistance (constant torque)"
              : s.rolling == RollingKind::epsd ? " + rolling resistance (spring-dashpot)"
                                               : "",
              to_string(s.precision), DefaultSpace::name, device_name(DefaultSpace{}).c_str());
  std::printf("dt = %.4g s = %.3f of the critical step %.4g s (%s)%s\n", s.dt, s.dt / s.dt_critical, s.dt_critical,
              s.dt_governing.c_str(), s.dt > kSafeStepFraction * s.dt_critical ? ", ABOVE the safe fraction: forced" : "");
  std::printf("impact at %.3g m/s: deepest elastic overlap %.3g%% of the radius (%s)%s\n", s.impact_speed,
              100 * s.impact_overlap, s.overlap_governing.c_str(),
              s.impact_overlap > s.output.penetration_warning ? ", above penetration_warning" : "");
  for (const auto& note : s.notes) std::printf("%s\n", note.c_str());
  if (!s.study.empty()) {  // read by the study programs (study_mill, study_hopper), not here
    std::string keys;
    for (const auto& v : s.study) keys += (keys.empty() ? "" : ", ") + v.key;
    std::printf("note: %s: [study] (%s) is for the study programs (study_mill, study_hopper: the power averaged over "
                "revolutions, the gate, the discharge); blaze run does not read it\n", s.study.front().where.c_str(), keys.c_str());
  }
  // Derived sizes against this machine, before anything is allocated (run_size.hpp).
  const RunSize size = run_size(s, gpu_build);
  const double host_free = available_memory(Host{});
  std::printf("size: %.4g particles, %.4g steps, %.3g x %.3g x %.3g grid cells; memory estimate %s of host memory (%s "
              "available)", size.particles, size.steps, size.cells[0], size.cells[1], size.cells[2],
              gigabytes(size.host_bytes).c_str(), host_free > 0 ? gigabytes(host_free).c_str() : "unknown");
  double device_free = 0;
  if (gpu_build) {
    device_free = available_memory(DefaultSpace{});
    std::printf(", %s of GPU memory (%s free)", gigabytes(size.device_bytes).c_str(), gigabytes(device_free).c_str());
  }
  const double seconds = estimated_seconds(size, gpu_build, host_threads());
  std::printf("; at least %.3g s of wall time\n", seconds);
  check_run_fits(s, size, gpu_build, host_free > 0 ? host_free : INFINITY, device_free, host_threads());
  if (o.check) {
    std::printf("placements: %zu particles, none overlapping another or a world object\n", check_placements(s));
    return 0;
  }
  return s.precision == PrecisionKind::float32 ? run_precision<float>(s, o) : run_precision<double>(s, o);
} catch (const SceneError& e) {  // over ranks: naming the rank, stopping every rank (communicator.hpp)
  std::fprintf(stderr, "blaze: %sscene rejected: %s\n", rank_label().c_str(), e.what());
  return stop_ranks(1);
} catch (const std::exception& e) {
  std::fprintf(stderr, "blaze: %serror: %s\n", rank_label().c_str(), e.what());
  return stop_ranks(1);
}
