// The mill study's run (studies/mill/main.cpp: study_mill; issue 19, and over ranks issue 21).
// The charge starts as the scene's placements, the drum turns at the [mill]'s speed, and after
// every revolution the study writes the power the drum delivered over it:
//   P_rev = (W(t_k) - W(t_{k-1})) / T,   T = 2 pi / |omega|,  W: the drive work (J)
// W is the work the moving walls (shell, end plates, lifters) do on the balls, F . v_wall dt per
// contact and step (kernels/world_forces.hpp): this is the torque method, P = omega . sum (r x F)
// over the drum's contacts, summed in time (for a rigid rotation F . (omega x r) = omega . (r x F)).
// The mean over the revolutions after [study] skip_revolutions (the charge settles into its
// profile over the first) is the mill's power. The energy method measures the same power from the
// other end: what the contacts took out of the charge's motion per revolution, contact by contact
// (blaze/particles/energy_ledger.hpp), split by class: ball-ball, ball-shell, ball-lifter,
// ball-end plate (the thesis's Table 4.7 split). At steady state the two agree (the charge's energy
// returns each revolution); both go to the CSV with their ratio. Each revolution also gives the
// charge's toe and shoulder (include/blaze/sim/charge_profile.hpp: degrees from the bottom of
// the drum, positive in its direction of rotation; from the revolution's 72 samples together) and the balls centrifuging over it, with the
// layers they make (include/blaze/sim/centrifuging.hpp; positions sampled 72 times a revolution).
// The samples of the averaged revolutions also give the time-averaged charge in the cross-section
// (include/blaze/sim/charge_field.hpp: occupancy and mean velocity per cell of one ball radius),
// written to charge_field.csv for plots/mill_profile.gp, and the mean toe and shoulder.
// Beside them, the thesis's own estimate (section 4.1.4.1): sum |F_diss| |V| dt over contacts and
// steps per revolution (MillStudyFeatures; energy_ledger.hpp), an upper bound of the dissipated
// work, to show what its Table 4.4 measured.
// Any sphere law of the scene file: the history-free law (the thesis's) or Hertz-Mindlin / the
// linear spring, with rolling resistance.
// Writes <output directory>/{power.csv, manifest.txt, charge_field.csv}; the scene's [output] rows and frames as
// `blaze run` would are not written (use blaze run for those).
// Over ranks (build/mpi/study_mill under mpirun): every rank runs the loop; the samples (energies,
// drive work, the dissipation accounts) are sums over the ranks' own particles, the same on every
// rank; the charge's positions come to rank 0, which writes the files.
#pragma once
#include <chrono>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <map>
#include <type_traits>
#include "blaze/exec/device_info.hpp"
#include "blaze/io/manifest.hpp"
#include "blaze/scene/scene_build.hpp"
#include "blaze/scene/scene_file.hpp"
#include "blaze/shapes/sphere_shape.hpp"
#include "blaze/sim/centrifuging.hpp"
#include "blaze/sim/charge_field.hpp"
#include "blaze/sim/charge_profile.hpp"
#include "pipeline/parallel/communicator.hpp"
#include "pipeline/scene_params.hpp"
#include "pipeline/simulation.hpp"
#if defined(BLAZE_MPI)
#include "pipeline/parallel/distributed_simulation.hpp"
#endif

namespace blaze::mill {

// The charge's particles: the simulation's; over ranks all of them on rank 0 (none elsewhere).
template <class Sim>
auto charge_state(Sim& sim) { return sim.state(); }
#if defined(BLAZE_MPI)
template <class Sim>
auto charge_state(DistributedSimulation<Sim>& sim) { return sim.gathered_state(); }
#endif

// The revolutions the study averages: the drum reaches full speed at `first` (its start plus its
// ramp, s), `skip` revolutions of `period` (s) settle the charge, and every whole revolution
// after them up to end_time is averaged.
struct MillSpan {
  double period = 0, first = 0, skip = 0;
  double first_averaged_end() const { return first + (skip + 1) * period; }  // s
};

// The scene's span; refuses a mill that does not turn and an end_time that ends before the first
// averaged revolution (which would write a power of 0 W from no revolution at all), naming the
// key and the least end_time that holds one.
inline MillSpan mill_span(const Scene& s) {
  if (!s.mill.present || s.mill.omega == 0) throw SceneError(s.path + ": the mill study needs a [mill] that turns");
  MillSpan m;
  m.skip = s.study_value("skip_revolutions", 0, 1000, "revolutions settled before the power is averaged");
  for (const auto& v : s.study)
    if (v.key == "skip_revolutions" && m.skip != std::floor(m.skip))
      throw SceneError(v.where + ": [study]: key 'skip_revolutions' = " + Scene::shortest(m.skip) + ": must be a whole number of revolutions");
  m.period = 2 * 3.14159265358979323846 / std::fabs(s.mill.omega);
  m.first = s.mill.start + s.mill.ramp;  // revolutions count from full speed
  if (s.end_time + 1e-12 < m.first_averaged_end()) {
    char buf[400];
    std::snprintf(buf, sizeof buf,
                  " = %.6g s holds no revolution to average: the drum reaches full speed at %.6g s, a revolution takes "
                  "%.6g s and [study] skip_revolutions = %.0f settle the charge; end_time must be at least %.6g s",
                  s.end_time, m.first, m.period, m.skip, m.first_averaged_end());
    throw SceneError(s.place("simulation.end_time") + buf);
  }
  return m;
}

// The study on a Simulation, or over ranks on a DistributedSimulation (`span`: mill_span's;
// `root`: the rank that writes; every rank runs the same loop, whose samples and counts are collective).
template <class Real, class Kinematics, class Run>
int drive_mill(Run& sim, const Scene& s, const MillSpan& span, Index balls, bool root) {
  s.check_study_used();
  const double period = span.period, first = span.first, skip = span.skip;
  double r_max = 0;
  for (const auto& t : s.types) r_max = std::max(r_max, t.size());
  std::printf("mill: %zu balls, D = %.3g m, L = %.3g m, %.4g rpm (T = %.4g s), dt = %.3g s (%.3f of the critical step)\n"
              "backend: %s, %s\n",
              static_cast<std::size_t>(balls), s.mill.diameter, s.mill.length, s.mill.omega * 60 / (2 * 3.14159265358979323846), period, s.dt,
              s.dt / s.dt_critical, DefaultSpace::name, device_name(DefaultSpace{}).c_str());
  const std::string dir = s.output.directory;
  if (root) make_output_directory(s);
  std::ofstream csv(root ? dir + "/power.csv" : std::string("/dev/null"));  // (every rank runs the loop)
  csv << "revolution,t_end_s,power_W,energy_method_W,thesis_estimate_W,pair_W,shell_W,lifter_W,end_plate_W,wall_W,kinetic_J,dissipated_J,"
         "drive_work_J,balls,toe_deg,shoulder_deg,centrifuging_balls,centrifuging_layers,wall_s\n";
  const auto steps_to = [&](double t) { return static_cast<std::uint64_t>(std::llround(t / s.dt)); };
  const auto wall0 = std::chrono::steady_clock::now();
  const auto e0_sample = sim.sample(s.output.penetration_warning);  // E(0), the balance's start
  const double e0 = e0_sample.energies.total() + e0_sample.stored.total();
  double work = 0, work_at = 0, sum = 0, sum_energy = 0, sum_thesis = 0, worst = 0;
  double by_class[1 + kContactClasses] = {}, class_sum[1 + kContactClasses] = {};  // J: pairs, then the walls' classes
  int averaged = 0, rev = 0;
  double toe_sum = 0, shoulder_sum = 0;
  int profiles = 0;
  CentrifugingReport spun;  // the last revolution's (centrifuging.hpp)
  ChargeField field(s.mill.centre, s.mill.axis, s.gravity, 0.5 * s.mill.diameter, r_max);
  for (double t_end = first; t_end <= s.end_time + 1e-12; t_end += period, ++rev) {
    // the revolution in kSamples parts, the balls' positions sampled at each (centrifuging)
    constexpr int kSamples = 72;
    CentrifugeTracker tracker(s.mill.centre, s.mill.axis, 0.5 * s.mill.diameter, s.mill.omega);
    // the charge against the shell over the revolution: a band of 1.5 ball diameters (charge_profile.hpp)
    ChargeProfileSampler band(s.mill.centre, s.mill.axis, 0.5 * s.mill.diameter, 3 * r_max, s.mill.omega > 0 ? 1 : -1);
    const auto track = [&] {  // (over ranks the positions come to the root)
      const auto st = charge_state(sim);
      if (!root) return;
      tracker.add(st.position, st.radius, st.id);
      band.add(st.position);
      if (rev > skip) field.add(st.position, st.velocity);
    };
    const double t_start = rev > 0 ? t_end - period : sim.time();
    const auto rev_wall0 = std::chrono::steady_clock::now();  // the revolution's wall time (its steps and samples)
    if (rev > 0) track();
    for (int k = 1; k <= kSamples; ++k) {
      sim.run(steps_to(t_start + (t_end - t_start) * k / kSamples) - sim.steps());
      if (rev > 0) track();
    }
    if (rev > 0) spun = tracker.report();
    const auto smp = sim.sample(s.output.penetration_warning);
    const double rev_wall = std::chrono::duration<double>(std::chrono::steady_clock::now() - rev_wall0).count();
    work += smp.drive_work;
    by_class[0] = smp.dissipated_pair;  // this revolution's (the sample resets the accounts)
    for (int c = 0; c < kContactClasses; ++c) by_class[1 + c] = smp.dissipated_walls[c];
    const double e = smp.energies.total() + smp.stored.total();
    worst = std::max(worst, smp.penetration.worst);
    if (rev > 0) {
      const double power = (work - work_at) / period;
      const double dissipated = e0 + work - e - sim.removed_energy();
      const ChargeProfile cp = band.profile();
      const double energy_method = smp.dissipated() / period, thesis = smp.thesis_estimate / period;
      csv << rev << ',' << sim.time() << ',' << power << ',' << energy_method << ',' << thesis;
      for (int c : {0, 1 + static_cast<int>(ContactClass::shell), 1 + static_cast<int>(ContactClass::lifter),
                    1 + static_cast<int>(ContactClass::end_plate), 1 + static_cast<int>(ContactClass::wall)})
        csv << ',' << by_class[c] / period;
      csv << ',' << smp.energies.kinetic() << ',' << dissipated << ',' << work << ',' << sim.size() << ',' << cp.toe_deg << ','
          << cp.shoulder_deg << ',' << spun.balls << ',' << spun.layers << ',' << rev_wall << '\n';
      std::printf("  revolution %3d (t = %6.2f s): %8.2f W (energy method %8.2f W, thesis's estimate %8.2f W), toe %6.1f deg, "
                  "shoulder %6.1f deg, %d balls centrifuging in %d layers; %.1f s wall time\n",
                  rev, sim.time(), power, energy_method, thesis, cp.toe_deg, cp.shoulder_deg, spun.balls, spun.layers, rev_wall);
      if (rev > skip) {
        sum += power, sum_energy += energy_method, sum_thesis += thesis, ++averaged;
        if (cp.found) toe_sum += cp.toe_deg, shoulder_sum += cp.shoulder_deg, ++profiles;
        for (int c = 0; c <= kContactClasses; ++c) class_sum[c] += by_class[c];
      }
    }
    work_at = work;
  }
  csv.close();
  const double wall = std::chrono::duration<double>(std::chrono::steady_clock::now() - wall0).count();
  const double mean = averaged ? sum / averaged : 0, mean_energy = averaged ? sum_energy / averaged : 0,
               mean_thesis = averaged ? sum_thesis / averaged : 0;
  double taken = 0;
  for (double d : class_sum) taken += d;
  const auto share = [&](int c) { return taken > 0 ? 100 * class_sum[c] / taken : 0.0; };
  const int shell = 1 + static_cast<int>(ContactClass::shell), lifter = 1 + static_cast<int>(ContactClass::lifter),
            plate = 1 + static_cast<int>(ContactClass::end_plate), other = 1 + static_cast<int>(ContactClass::wall);
  std::printf("power %.2f W by the torque method, %.2f W by the energy method (mean of %d revolutions after %g; ratio %.4f); "
              "the thesis's estimate %.2f W\n"
              "dissipated: ball-ball %.1f%%, ball-shell %.1f%%, ball-lifter %.1f%%, ball-end plate %.1f%%, other walls %.1f%%\n"
              "deepest penetration %.3g%% of the radius%s; %d balls left; wall time %.1f s, %.4g steps/s\n",
              mean, mean_energy, averaged, skip, mean > 0 ? mean_energy / mean : 0.0, mean_thesis, share(0), share(shell), share(lifter),
              share(plate), share(other), 100 * worst,
              worst > s.output.penetration_warning ? " (ABOVE output.penetration_warning: the contacts are soft for these impacts)" : "",
              static_cast<int>(sim.size()), wall,
              static_cast<double>(sim.steps()) / wall);
  std::map<std::string, std::string> m;
  char b[64];
  const auto num = [&](double v) { return std::snprintf(b, sizeof b, "%.10g", v), std::string(b); };
  m["scene"] = s.path, m["backend"] = DefaultSpace::name, m["device"] = device_name(DefaultSpace{});
  m["power_W"] = num(mean), m["energy_method_W"] = num(mean_energy), m["thesis_estimate_W"] = num(mean_thesis);
  m["share_pair"] = num(share(0)), m["share_shell"] = num(share(shell)), m["share_lifter"] = num(share(lifter));
  m["share_end_plate"] = num(share(plate)), m["share_other_walls"] = num(share(other));
  m["law"] = std::string(to_string(s.law)) + (s.tangential == TangentialKind::history_free ? " history-free" : " + spring") +
             (s.rolling == RollingKind::none ? "" : " + rolling");
  m["kinematics"] = std::is_same_v<Kinematics, ThesisMeanOmegaVelocity> ? "thesis mean omega" : "contact point";
  m["revolutions_averaged"] = std::to_string(averaged), m["rpm"] = num(s.mill.omega * 60 / (2 * 3.14159265358979323846));
  m["balls"] = std::to_string(balls), m["dt_s"] = num(s.dt), m["wall_time_s"] = num(wall);
  m["deepest_penetration"] = num(worst), m["penetration_warning"] = num(s.output.penetration_warning);  // overlap / radius
  m["steps_per_s"] = num(static_cast<double>(sim.steps()) / wall);
  m["centrifuging_balls"] = std::to_string(spun.balls), m["centrifuging_layers"] = std::to_string(spun.layers);
  m["toe_deg"] = num(profiles ? toe_sum / profiles : 0), m["shoulder_deg"] = num(profiles ? shoulder_sum / profiles : 0);
  if (root) field.write_csv(dir + "/charge_field.csv"), write_manifest(dir + "/manifest.txt", m);
  std::printf("wrote %s/power.csv, %s/manifest.txt, %s/charge_field.csv\n", dir.c_str(), dir.c_str(), dir.c_str());
  return sim.removed_count() ? 2 : 0;
}

// The mill study of one law: over the ranks of `comm` when it has more than one (an MPI build),
// else one Simulation; in an MPI build (comm given) pairs from both sides in canonical order, so
// one rank and many give the same run (pipeline/parallel/distributed_simulation.hpp).
template <class Law, class Kinematics>
int run_mill(const Scene& s, const Communicator* comm = nullptr) {
  using Real = typename Law::real_type;  // the study's own sums are double
  const MillSpan span = mill_span(s);  // before the charge is built: a run too short to average a revolution is refused
  using Sim = Simulation<DefaultSpace, SphereShape, Law, VelocityVerlet, Kinematics, MillStudyFeatures>;
  SimulationParams<Real> sp = simulation_params<Real>(s);
  if (comm) sp.pairs = PairEvaluation::both_sides, sp.canonical_order = true;
  const ParticleState<Real> balls = build_particles<Real>(s, nullptr);
  const Index n = static_cast<Index>(balls.size());
#if defined(BLAZE_MPI)
  if (comm && comm->size() > 1) {
    DistributedSimulation<Sim> run(*comm, sp, build_laws<Law>(s), build_world<Real>(s), balls, SphereShape{});
    return drive_mill<Real, Kinematics>(run, s, span, n, comm->rank() == 0);
  }
#endif
  Sim sim(sp, build_laws<Law>(s), build_world<Real>(s), balls);
  return drive_mill<Real, Kinematics>(sim, s, span, n, true);
}


}  // namespace blaze::mill
