// Angle of repose of monodisperse glass beads (acceptance item 5), driven by a scene file:
//   study_repose [SCENE.toml] [--set key=value]...        run the pile (default studies/repose/repose.toml)
//   study_repose ... --export-liggghts DIR                 write the same pile for LIGGGHTS (walls as STL,
//                                                          beads as a data file, numbers as NAME=value)
//   study_repose ... --measure DUMP [--wall-time S]        measure a LIGGGHTS dump of the settled pile
//
// Method: the fixed-base cone (Train 1958's "fixed base" method; ISO 4324 pours the same way): beads
// pour from a funnel onto a circular base of radius R_b (an octagon, inscribed radius
// R_in = R_b cos 22.5 deg) until the pile covers it; the excess rolls over the rim, falls out of the
// domain and is removed. The angle is then that of a pile bounded by the material alone, neither by
// a container (a lifted cylinder's angle depends on the lifting speed, which static walls cannot
// give) nor by a slot's walls: Zhou et al. 2001-2002 poured into a slot of thickness W and found the
// angle falling with W, so a 3D conical pile is compared with 3D (conical) measurements. Blaze has no
// inserter: the beads start as a loose bcc block above the funnel, settle behind a gate in the outlet
// (a wall removed at [study] gate_open_time: a timed event, the contacts keep their history, as in
// studies/hopper), then pour at the funnel's rate
// from a few d above the apex of the steepest pile, so they land slowly (< 1 m/s).
// The angle (include/blaze/sim/repose_angle.hpp): the highest bead top per radial bin of width d,
// a line h = h_0 - tan(theta) r fitted between 0.2 and 0.8 R_in; its rms residual is reported.
// Contact law: Hertz + Mindlin spring (history) + rolling resistance model C (Ai, Chen, Rotter & Ooi,
// Powder Technol. 206 (2011) 269): M_r limited to mu_r R* F_n, spring k_r = 2.25 k_n mu_r^2 R*^2.
// Model C, not A: a pile at rest needs a resisting moment at zero rolling speed (Ai et al. found
// model A's piles creep and chatter), and it is LIGGGHTS's `rolling_friction epsd`. E is reduced to
// 5e7 Pa (1e7 for the small CPU runs): Zhou et al. (Phys. Rev. E 64 (2001) 021301) found the angle
// insensitive to Young's modulus, density, Poisson's ratio and damping, sensitive to mu_s, mu_r.
// The study stops once the funnel is empty and the beads' rms speed is below [study] rest_speed.
//
// References (what each says, and how far it was checked here):
//   Zhou, Xu, Yu & Zulli, Phys. Rev. E 64 (2001) 021301: DEM sandpiles of monosized spheres in a
//     slot; the angle rises with mu_s and mu_r, falls with particle size and slot thickness, and is
//     insensitive to E, density, Poisson's ratio and damping (abstract, read).
//   Zhou, Xu, Yu & Zulli, Powder Technol. 125 (2002) 45: experiments and DEM of coarse glass beads
//     poured from a hopper into a slot, and a correlation in mu_s, mu_r (their mu_r is a length),
//     d and the slot (not retrieved here: slot piles are steeper than conical ones, so it is not
//     used for the 2-degree check).
//   Zhou et al., Physica A 269 (1999) 536: without rolling friction spheres form no stable pile.
//   Ai, Chen, Rotter & Ooi, Powder Technol. 206 (2011) 269: rolling models A-D, model C for piles.
//   Train (1958), glass spheres by four methods incl. the fixed-base cone (method as cited by the
//     powder-metallurgy handbook; its numbers not retrieved here).
//   Measured heaps of dry glass beads: 22-26 deg, the range commonly quoted (no one measurement
//     of 3 mm beads was retrieved here; the figure shows it as a band, and the 2-degree check is
//     made against LIGGGHTS's pile of the same beads). Which (mu_s, mu_r) stands for glass beads
//     is itself a calibration: mu_s ~ 0.3-0.4 glass on glass, mu_r ~ 0.01-0.1 for near-spheres
//     (Wensrich & Katterfeld, Powder Technol. 217 (2012) 409, read mu_r as a shape parameter).
// Writes <output directory>/{profile.csv, manifest.txt, pile.vtu, walls.vtu} and a row of
// angles.csv beside it (data/repose/angles.csv for the sweep's directories; both codes' angles side
// by side, --measure fills the LIGGGHTS columns).
#include <fcntl.h>
#include <sys/file.h>
#include <unistd.h>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <map>
#include <sstream>
#include "blaze/exec/device_info.hpp"
#include "blaze/io/console.hpp"
#include "blaze/io/manifest.hpp"
#include "blaze/io/vtu_writer.hpp"
#include "blaze/scene/scene_build.hpp"
#include "blaze/scene/run_size.hpp"
#include "blaze/scene/scene_file.hpp"
#include "blaze/shapes/sphere_shape.hpp"
#include "blaze/sim/repose_angle.hpp"
#include "pipeline/scene_params.hpp"
#include "pipeline/simulation.hpp"
#include "studies/repose/repose_geometry.hpp"

using namespace blaze;
using Real = double;
using Law = HertzMindlinRollingLaw<Real>;
using Sim = Simulation<DefaultSpace, SphereShape, Law, VelocityVerlet, ContactPointVelocity, MonitoredFeatures>;

namespace {

std::string num(double v) {
  char b[40];
  std::snprintf(b, sizeof b, "%.17g", v);
  return b;
}

// One row per (mu_s, mu_r) in angles.csv beside the case's output directory (data/repose/ for
// data/repose/mus0.4_mur0.05); a run replaces its own code's columns only.
void record(const Scene& s, const std::map<std::string, std::string>& cols) {
  const std::filesystem::path parent = std::filesystem::path(s.output.directory).lexically_normal().parent_path();
  const std::string path = (parent.empty() ? std::filesystem::path(".") : parent).string() + "/angles.csv";
  if (!parent.empty()) std::filesystem::create_directories(parent);
  // cases run side by side (tools/repose_sweep.sh): one writer at a time reads, merges and writes
  const int lock = ::open((path + ".lock").c_str(), O_CREAT | O_RDWR, 0644);
  if (lock >= 0) ::flock(lock, LOCK_EX);
  struct Unlock {
    int fd;
    ~Unlock() {
      if (fd >= 0) ::close(fd);  // closing releases the lock
    }
  } unlock{lock};
  const std::vector<std::string> header = {"case", "mu_s", "mu_r", "blaze_deg", "blaze_rms_mm", "blaze_particles",
                                           "blaze_wall_s", "blaze_backend", "liggghts_deg", "liggghts_rms_mm",
                                           "liggghts_particles", "liggghts_wall_s"};
  std::map<std::string, std::map<std::string, std::string>> rows;
  std::ifstream in(path);
  for (std::string line; std::getline(in, line);) {
    std::stringstream ss(line);
    std::map<std::string, std::string> row;
    std::string cell;
    for (std::size_t k = 0; k < header.size() && std::getline(ss, cell, ','); ++k) row[header[k]] = cell;
    if (row["case"] != "case" && !row["case"].empty()) rows[row["case"]] = row;
  }
  char key[64];
  std::snprintf(key, sizeof key, "mus%.2f_mur%.3f", s.pairs[0].friction, s.pairs[0].rolling_friction);
  auto& row = rows[key];
  row["case"] = key, row["mu_s"] = num(s.pairs[0].friction), row["mu_r"] = num(s.pairs[0].rolling_friction);
  for (const auto& [k, v] : cols) row[k] = v;
  std::ofstream out(path);
  for (std::size_t k = 0; k < header.size(); ++k) out << header[k] << (k + 1 < header.size() ? ',' : '\n');
  for (auto& [name, r] : rows)
    for (std::size_t k = 0; k < header.size(); ++k) out << (r.count(header[k]) ? r[header[k]] : "") << (k + 1 < header.size() ? ',' : '\n');
}

// The profile, the fit and its summary; returns the columns for angles.csv (prefix "blaze"/"liggghts").
std::map<std::string, std::string> report(const ReposeProfile& p, const ReposeSetup& g, const std::string& dir,
                                          const std::string& code, std::size_t on_base) {
  std::ofstream csv(dir + "/" + code + "_profile.csv");
  csv << "r_m,h_top_m,fitted,h_fit_m\n";
  const double slope = -std::tan(p.angle_deg * 3.14159265358979323846 / 180);
  for (std::size_t k = 0; k < p.r.size(); ++k)
    csv << p.r[k] << ',' << p.h[k] << ',' << (p.fitted[k] ? 1 : 0) << ',' << p.intercept + slope * p.r[k] << '\n';
  std::printf("%s: angle of repose %.2f deg (fit over %d bins of %.3g m, rms %.3g mm = %.2f d), %zu beads on the base\n",
              code.c_str(), p.angle_deg, p.bins_used, g.d, 1e3 * p.rms, p.rms / g.d, on_base);
  char a[32], r[32];
  std::snprintf(a, sizeof a, "%.2f", p.angle_deg);
  std::snprintf(r, sizeof r, "%.3f", 1e3 * p.rms);
  return {{code + "_deg", a}, {code + "_rms_mm", r}};
}

std::size_t on_base(const std::vector<double>& y) {
  std::size_t n = 0;
  for (double v : y) n += v > 0;
  return n;
}

int run(const Scene& s, const ReposeSetup& g, const std::vector<std::string>& overrides) {
  const double gate_open = s.study_value("gate_open_time", 0, s.end_time, "s (at most end_time)");
  const double check = s.study_value("check_interval", s.dt, s.end_time, "s");
  const double rest_speed = s.study_value("rest_speed", 0, 1, "m/s");
  s.check_study_used();
  const SimulationParams<Real> sp = simulation_params<Real>(s);
  const PairTable<Law> laws = build_laws<Law>(s);
  const ParticleState<Real> initial = build_particles<Real>(s, nullptr);
  std::printf("repose: %zu beads of d = %.3g m, base R_in = %.3g m (%.1f d), mu_s = %g, mu_r = %g; dt = %.3g s (%.3f of "
              "the critical %.3g s)\nbackend: %s, %s\n",
              initial.size(), g.d, g.r_in, g.r_in / g.d, s.pairs[0].friction, s.pairs[0].rolling_friction, s.dt,
              s.dt / s.dt_critical, s.dt_critical, DefaultSpace::name, device_name(DefaultSpace{}).c_str());
  const std::string dir = make_output_directory(s);
  const auto t0 = std::chrono::steady_clock::now();
  std::uint64_t particle_steps = 0;
  const auto steps = [&](double t) { return static_cast<std::uint64_t>(std::llround(t / s.dt)); };

  // One run: the gate is removed at gate_open_time (a timed event), so the beads' contacts keep
  // their springs across the opening, as LIGGGHTS's do.
  Sim pour(sp, laws, build_world<Real>(with_wall_removed_at(s, "gate", gate_open)), initial);
  pour.run(steps(gate_open));
  particle_steps += pour.size() * steps(gate_open);
  write_world_vtu(dir + "/walls.vtu", build_world<Real>(without_gate(s)));
  double t = gate_open, v_rms = 0;
  std::size_t in_funnel = 0;
  std::string stop = "end_time";
  while (t < s.end_time) {
    const std::uint64_t k = std::min(steps(check), steps(s.end_time - t));
    pour.run(k);
    particle_steps += static_cast<std::uint64_t>(pour.size()) * k;
    t += static_cast<double>(k) * s.dt;
    const ParticleState<Real> st = pour.state();
    double v2 = 0;
    in_funnel = 0;
    for (std::size_t i = 0; i < st.size(); ++i) {
      v2 += norm2(st.velocity[i]);
      in_funnel += st.position[i].y > g.outlet_y - g.d / 2;
    }
    v_rms = st.size() ? std::sqrt(v2 / st.size()) : 0;
    std::printf("  t = %5.2f s  in funnel %6zu  fell off %6d  rms speed %.3g m/s\n", t, in_funnel,
                static_cast<int>(pour.removed_count()), v_rms);
    if (v_rms < rest_speed) {
      stop = in_funnel ? "jammed: the funnel stopped with beads in it" : "at rest";
      break;
    }
  }
  const double wall = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  const ParticleState<Real> final_state = pour.state();
  write_particles_vtu(dir + "/pile.vtu", final_state);
  std::vector<double> x, y, z, r;
  for (std::size_t i = 0; i < final_state.size(); ++i)
    x.push_back(final_state.position[i].x), y.push_back(final_state.position[i].y), z.push_back(final_state.position[i].z),
        r.push_back(final_state.radius[i]);
  const ReposeProfile p = measure_repose(x, y, z, r, g.measure());
  auto cols = report(p, g, dir, "blaze", on_base(y));
  std::printf("stopped at t = %.2f s (%s); wall time %.1f s, %.3g particle-steps/s\n", t, stop.c_str(), wall,
              static_cast<double>(particle_steps) / wall);
  cols["blaze_particles"] = std::to_string(initial.size());
  cols["blaze_wall_s"] = std::to_string(static_cast<long>(std::lround(wall)));
  cols["blaze_backend"] = DefaultSpace::name;
  if (stop != "at rest") cols["blaze_deg"] += "?";
  record(s, cols);

  std::map<std::string, std::string> m = g.manifest();
  std::string set;
  for (const auto& o : overrides) set += (set.empty() ? "" : " ") + o;
  m["scene"] = s.path, m["overrides"] = set.empty() ? "(none)" : set, m["commit"] = git_commit(), m["date"] = utc_date();
  m["backend"] = DefaultSpace::name, m["device"] = device_name(DefaultSpace{}), m["dt_s"] = num(s.dt);
  m["mu_s"] = num(s.pairs[0].friction), m["mu_r"] = num(s.pairs[0].rolling_friction);
  m["youngs_modulus_Pa"] = num(s.materials[0].youngs_modulus), m["particles"] = std::to_string(initial.size());
  m["stopped"] = stop + " at t = " + num(t) + " s", m["wall_time_s"] = num(wall);
  m["particle_steps_per_s"] = num(static_cast<double>(particle_steps) / wall);
  m["angle_deg"] = num(p.angle_deg), m["fit_rms_m"] = num(p.rms), m["fit_bins"] = std::to_string(p.bins_used);
  m["removed"] = std::to_string(pour.removed_count());
  write_manifest(dir + "/manifest.txt", m);
  return stop == "at rest" ? 0 : 2;
}

// A LAMMPS/LIGGGHTS text dump ("ITEM: ATOMS id x y z radius"), measured as Blaze's pile is.
int measure_dump(const Scene& s, const ReposeSetup& g, const std::string& dump, double wall) {
  std::ifstream in(dump);
  if (!in) throw SceneError("cannot read " + dump);
  std::vector<double> x, y, z, r;
  bool atoms = false;
  for (std::string line; std::getline(in, line);) {
    if (line.rfind("ITEM:", 0) == 0) {
      atoms = line.rfind("ITEM: ATOMS id x y z radius", 0) == 0;
      continue;
    }
    if (!atoms) continue;
    std::stringstream ss(line);
    double id, a, b, c, rad;
    if (ss >> id >> a >> b >> c >> rad) x.push_back(a), y.push_back(b), z.push_back(c), r.push_back(rad);
  }
  if (x.empty()) throw SceneError(dump + ": no 'ITEM: ATOMS id x y z radius' section");
  make_output_directory(s);
  auto cols = report(measure_repose(x, y, z, r, g.measure()), g, s.output.directory, "liggghts", on_base(y));
  cols["liggghts_particles"] = std::to_string(g.particles);
  if (wall > 0) cols["liggghts_wall_s"] = std::to_string(static_cast<long>(std::lround(wall)));
  record(s, cols);
  return 0;
}

}  // namespace

int main(int argc, char** argv) try {
  blaze::line_buffered_output();
  std::string path = "studies/repose/repose.toml", export_dir, dump;
  double dump_wall = 0;
  std::vector<std::string> overrides;
  for (int k = 1; k < argc; ++k) {
    const std::string a = argv[k];
    if (a == "--set" && k + 1 < argc) overrides.push_back(argv[++k]);
    else if (a == "--export-liggghts" && k + 1 < argc) export_dir = argv[++k];
    else if (a == "--measure" && k + 1 < argc) dump = argv[++k];
    else if (a == "--wall-time" && k + 1 < argc) dump_wall = std::stod(argv[++k]);
    else if (a.rfind("--", 0) == 0)
      throw SceneError("unknown option '" + a + "'; usage: study_repose [SCENE.toml] [--set key=value]... "
                       "[--export-liggghts DIR | --measure DUMP [--wall-time S]]");
    else path = a;
  }
  const ReposeSetup g = derive_repose(path, overrides);
  const Scene& s = g.scene;
  // The study runs one law, Hertz-Mindlin with rolling resistance (mu_r = 0 allowed): a scene that
  // names another is refused, not run with this one.
  if (s.law != LawKind::hertz) throw SceneError(s.place("simulation.law") + ": the repose study runs \"hertz\" (with tangential = \"mindlin\")");
  if (s.tangential != TangentialKind::mindlin)
    throw SceneError(s.place("simulation.tangential") + ": the repose study runs \"mindlin\" (a pile needs the tangential spring)");
  for (const auto& note : s.notes) std::printf("%s\n", note.c_str());
  if (!export_dir.empty()) return export_liggghts(g, export_dir);
  if (!dump.empty()) return measure_dump(s, g, dump, dump_wall);
  check_run_fits_here(s);
  return run(s, g, overrides);
} catch (const std::exception& ex) {
  std::fprintf(stderr, "error: %s\n", ex.what());
  return 1;
}
