// Tumbling-mill power draw (issue 19; thesis chapter 4), driven by a scene file with a [mill]:
//   study_mill [SCENE.toml] [--set key=value]...        (default studies/mill/lab_mill.toml)
//   mpirun -np N build/mpi/study_mill [SCENE.toml] ...  the same over N ranks (issue 21)
// What it measures and writes: studies/mill/mill_run.hpp.
#include <cstdio>
#include <string>
#include <vector>
#include "blaze/io/console.hpp"
#include "blaze/scene/run_size.hpp"
#include "blaze/scene/scene_file.hpp"
#include "pipeline/parallel/communicator.hpp"
#include "studies/mill/mill_run.hpp"

using namespace blaze;
using blaze::mill::run_mill;

namespace {

template <class Kinematics>
int dispatch(const Scene& s, const Communicator* c) {
  const bool spring = s.tangential != TangentialKind::history_free, linear = s.law == LawKind::linear;
  if (s.rolling != RollingKind::none)
    return linear ? run_mill<LinearSpringRollingLaw<double>, Kinematics>(s, c) : run_mill<HertzMindlinRollingLaw<double>, Kinematics>(s, c);
  if (linear) return spring ? run_mill<LinearSpringLaw<double>, Kinematics>(s, c) : run_mill<LinearLaw<double>, Kinematics>(s, c);
  return spring ? run_mill<HertzMindlinLaw<double>, Kinematics>(s, c) : run_mill<HertzLaw<double>, Kinematics>(s, c);
}

// In float, the two laws of make fig-mill-work-precision: the history-free linear law and
// Hertz-Mindlin, at the contact point (each float law is another instantiation of the whole step).
int dispatch_float(const Scene& s, const Communicator* c) {
  const bool spring = s.tangential != TangentialKind::history_free, linear = s.law == LawKind::linear;
  if (s.rolling == RollingKind::none && linear && !spring) return run_mill<LinearLaw<float>, ContactPointVelocity>(s, c);
  if (s.rolling == RollingKind::none && !linear && s.tangential == TangentialKind::mindlin)
    return run_mill<HertzMindlinLaw<float>, ContactPointVelocity>(s, c);
  throw SceneError(s.place("simulation.precision") +
                   " = \"float\": the mill study runs float for the history-free linear law and Hertz-Mindlin only "
                   "(no rolling resistance); use \"double\"");
}

}  // namespace

int main(int argc, char** argv) try {
  blaze::line_buffered_output();
  const Communicator* comm = study_ranks(&argc, &argv, "study_mill");  // an MPI build: its ranks (rank 0 prints)
  std::string path = "studies/mill/lab_mill.toml";
  std::vector<std::string> overrides;
  for (int k = 1; k < argc; ++k) {
    const std::string a = argv[k];
    if (a == "--set" && k + 1 < argc) overrides.push_back(argv[++k]);
    else if (a.rfind("--", 0) == 0) throw SceneError("unknown option '" + a + "'; usage: study_mill [SCENE.toml] [--set key=value]...");
    else path = a;
  }
  const Scene s = load_scene(path, overrides);
  refuse_feeds(s, "the mill study");
  if (!s.all_spheres()) throw SceneError(path + ": the mill study takes spheres only");
  for (const auto& note : s.notes) std::printf("%s\n", note.c_str());
  check_run_fits_here(s);
  // [study] thesis_kinematics = 1: the relative velocity with the thesis's mean angular velocity
  // (section 2.3.1, kinematics.hpp), as its mill runs had it; 0 (default): at the contact point.
  const bool mean_omega = s.study_value_or("thesis_kinematics", 0, 1, "(1: the thesis's mean-omega relative velocity)", 0) != 0;
  if (s.precision == PrecisionKind::float32) {
    if (mean_omega) throw SceneError(s.path + ": [study]: thesis_kinematics = 1 runs in double only (precision = \"double\")");
    return dispatch_float(s, comm);
  }
  return mean_omega ? dispatch<ThesisMeanOmegaVelocity>(s, comm) : dispatch<ContactPointVelocity>(s, comm);
} catch (const std::exception& ex) {
  std::fprintf(stderr, "error: %s%s\n", rank_label().c_str(), ex.what());
  return stop_ranks(1);
}
