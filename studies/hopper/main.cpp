// Hopper discharge study (default `make run`; make fig-2.15 / fig-2.16), driven by a scene file:
//   study_hopper [SCENE.toml] [--set key=value]...      (default studies/hopper/hopper.toml)
// Spheres or polyhedra, placed at the start or poured by the scene's [[feed]]s, settle behind the
// wall named "gate"; at [study] gate_open_time the gate is removed (a timed event of the one run:
// the contacts keep their history across it) and the bed drains through the orifice. Particles
// that fall below the hopper leave the domain: they are removed and counted, and that count is the
// discharge. Times are reported from the opening (negative while settling). With [study]
// arch_time > 0, a run whose flow stops (no exit for that long) with particles over the orifice has
// arched (discharge_record.hpp): it ends there and says so. Writes <output
// directory>/{timeseries.csv, discharge.csv (each particle's place at the opening and exit time),
// manifest.txt (with the flow rate, residual and flow pattern: discharge_record.hpp),
// vtu/*.vtu, particles.pvd, walls.vtu} and plots/hopper.png. The scene chooses the law (linear or
// Hertz, history-free or with a tangential spring, rolling resistance for spheres); the study runs in
// double.
#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <map>
#if __has_include(<gnuplot-iostream.h>)
#include <gnuplot-iostream.h>
#define BLAZE_HAVE_GNUPLOT 1
#endif
#include "blaze/shapes/polyhedron_shape.hpp"
#include "blaze/shapes/sphere_shape.hpp"
#include "blaze/exec/device_info.hpp"
#include "blaze/io/manifest.hpp"
#include "blaze/io/vtu_writer.hpp"
#include "blaze/scene/scene_build.hpp"
#include "blaze/scene/run_size.hpp"
#include "blaze/scene/scene_file.hpp"
#include "blaze/sim/schedule.hpp"
#include "blaze/sim/energy.hpp"
#include "pipeline/feeder.hpp"
#include "pipeline/scene_law.hpp"
#include "pipeline/scene_params.hpp"
#include "pipeline/simulation.hpp"
#include "blaze/io/console.hpp"
#include "studies/hopper/discharge_record.hpp"

using namespace blaze;
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

// The scene's world without the wall named "gate" (which must exist).
World<Real> without_gate(Scene s) {
  const auto n = s.walls.size();
  s.walls.erase(std::remove_if(s.walls.begin(), s.walls.end(), [](const WallSpec& w) { return w.name == "gate"; }),
                s.walls.end());
  if (s.walls.size() + 1 != n) throw SceneError(s.path + ": the hopper study needs exactly one [[wall]] with name = \"gate\"");
  return build_world<Real>(s);
}

template <class Law, class Shape>
int run(const Scene& s, const std::vector<std::string>& overrides) {
  constexpr bool polyhedra = !std::is_same_v<Shape, SphereShape>;
  using Sim = Simulation<DefaultSpace, Shape, Law, VelocityVerlet, ContactPointVelocity, MonitoredFeatures>;
  const double gate_open = s.study_value("gate_open_time", 0, s.end_time, "s (at most end_time)");
  const double orifice = s.study_value_or("orifice_half_width", 0, 10, "m (the flow pattern's centre column)", 0.025);
  const double axis_x = s.study_value_or("orifice_x", -1e3, 1e3, "m (the orifice's centre line)", 0.0);
  // an arch: no exit for this long with particles over the orifice ends the run (0: run to the end)
  const double arch_span = s.study_value_or("arch_time", 0, 1e3, "s without a particle leaving, with some over the orifice (0: off)", 0.0);
  s.check_study_used();
  const SimulationParams<Real> sp = simulation_params<Real>(s, polyhedra);
  Shape shape;
  std::vector<ConvexShape> shapes;
  const PolyhedronTable<Real>* table = nullptr;
  if constexpr (polyhedra) shapes = build_shapes(s), shape.table = build_shape_table<Real>(s, shapes), table = &shape.table;
  const ParticleState<Real> initial = build_particles<Real>(s, table);
  std::printf("hopper: %zu particles (%s) placed, %zu feeds, dt = %.3g s (%.3f of the critical step %.3g s), impact overlap %.3g%% of the "
              "radius\n", initial.size(), Shape::name, s.feeds.size(), s.dt, s.dt / s.dt_critical, s.dt_critical, 100 * s.impact_overlap);
  std::printf("backend: %s, %s\n", DefaultSpace::name, device_name(DefaultSpace{}).c_str());
  std::printf("law: %s\n", scene_law_name(s).c_str());
  // One run: the gate is removed at gate_open_time (a timed event), the contacts keep their state.
  Sim sim(sp, build_laws<Law>(s), build_world<Real>(with_wall_removed_at(s, "gate", gate_open)), initial, shape);
  std::vector<Feeder<Real>> feeders;
  for (std::size_t k = 0; k < s.feeds.size(); ++k) feeders.emplace_back(s, k, table);

  const std::string dir = s.output.directory;
  std::filesystem::create_directories(dir + "/vtu");
  std::filesystem::create_directories("plots");
  std::ofstream csv(dir + "/timeseries.csv");
  csv << "t_s,discharged_mass_kg,discharged_count,particles_in_hopper,kinetic_translational_J,kinetic_rotational_J,"
         "potential_J,max_penetration_ratio,elastic_J,contacts_wall\n";
  PvdCollection pvd(dir + "/particles.pvd");
  write_world_vtu(dir + "/walls.vtu", without_gate(s));
  int frame = 0;
  long over_limit = 0;
  double worst_penetration = 0;
  std::uint64_t particle_steps = 0;
  const auto every = [&](double interval) {
    return std::max<std::uint64_t>(1, static_cast<std::uint64_t>(std::llround(interval / s.dt)));
  };
  const std::uint64_t csv_every = every(s.output.csv_interval > 0 ? s.output.csv_interval : s.end_time / 100);
  const std::uint64_t vtu_every = every(s.output.vtu_interval > 0 ? s.output.vtu_interval : s.end_time / 10);
  const auto k_open = static_cast<std::uint64_t>(std::llround(gate_open / s.dt));
  const auto k_end = static_cast<std::uint64_t>(std::llround(s.end_time / s.dt));
  const auto wall_start = std::chrono::steady_clock::now();
  hopper::DischargeRecord record;
  double arched_at = -1;  // s from the opening, when an arch was seen (-1: none)
  Index count0 = 0;  // what had left the domain when the gate opened (the discharge counts from there)
  double mass0 = 0;
  for (std::uint64_t k = 0;; ) {
    const double t = static_cast<double>(k) * s.dt - gate_open;
    if (k == k_open) {
      count0 = sim.removed_count(), mass0 = sim.removed_mass();
      if (count0 > 0) std::printf("WARNING: %d particles left the domain while the gate was closed\n", static_cast<int>(count0));
      for (const auto& f : feeders)
        if (f.next_insertion(k) != ~std::uint64_t{0}) std::printf("WARNING: feed %s still feeds after the gate opens\n", f.spec().name.c_str());
      record.open(sim.state(), axis_x, orifice);
    }
    const bool end = k == k_end, csv_due = k % csv_every == 0 || end, vtu_due = k % vtu_every == 0 || end;
    if (csv_due || vtu_due) {
      const auto st = sim.state();
      if (csv_due) {
        const auto en = energies(st, sp.gravity);
        const PenetrationReport pen = sim.take_penetration(s.output.penetration_warning);
        const ContactEnergy stored = sim.contact_energy();
        over_limit += pen.over;
        worst_penetration = std::max(worst_penetration, static_cast<double>(pen.worst));
        csv << t << ',' << sim.removed_mass() - mass0 << ',' << sim.removed_count() - count0 << ',' << st.size() << ','
            << en.translational << ',' << en.rotational << ',' << en.potential << ',' << pen.worst << ',' << stored.total() << ','
            << stored.wall_contacts << '\n';
        if (k >= k_open) record.sample(t, st);
        if (k >= k_open && record.arch(t, arch_span)) {
          std::printf("  t = %6.3f s  an arch holds: none has left since t = %.3f s, %zu particles over the orifice; the run ends\n", t,
                      record.last_exit(), record.over_orifice());
          arched_at = t;
        }
      }
      if (vtu_due) {
        char name[64];
        std::snprintf(name, sizeof name, "vtu/particles_%04d.vtu", frame++);
        if constexpr (polyhedra) write_polyhedra_vtu(dir + "/" + name, st, shapes);
        else write_particles_vtu(dir + "/" + name, st);
        pvd.add(t, name);
        std::printf("  t = %6.3f s  in hopper %6zu  discharged %6d (%.3f kg)\n", t, st.size(),
                    static_cast<int>(sim.removed_count() - count0), sim.removed_mass() - mass0);
      }
    }
    if (end || arched_at >= 0) break;
    for (auto& f : feeders)
      if (f.inserts_at(k)) f.feed(sim);
    // Up to the next row, frame, insertion or the opening in one stretch (the GPU batches it).
    std::uint64_t next = next_event(k, k_end, {csv_every, vtu_every});
    if (k < k_open) next = std::min(next, k_open);
    for (const auto& f : feeders) next = std::min(next, f.next_insertion(k + 1));
    sim.run(next - k);
    particle_steps += static_cast<std::uint64_t>(sim.size()) * (next - k);
    k = next;
  }
  csv.close();

  const double wall = std::chrono::duration<double>(std::chrono::steady_clock::now() - wall_start).count();
  const hopper::DischargeSummary d = record.summary(orifice, arch_span);
  const double t_run = arched_at >= 0 ? arched_at : s.end_time - gate_open;  // s of discharge run
  record.write_csv(dir + "/discharge.csv");
  std::printf("discharged %zu of %zu particles (%s; %.3f kg) in %.2f s; %.1f%% remain in the hopper\n", d.discharged, d.particles, Shape::name,
              sim.removed_mass() - mass0, t_run, 100 * d.residual);
  if (arch_span > 0)
    std::printf("%s\n", d.arched ? ("arched: the flow stopped at t = " + std::to_string(d.last_exit) + " s with " +
                                    std::to_string(record.over_orifice()) + " particles over the orifice").c_str()
                                 : "no arch: the flow did not stop with particles over the orifice");
  std::printf("steady mass flow rate %.4g kg/s (R^2 %.4f); median exit: top centre %.3g s, bottom sides %.3g s (%s)\n", d.flow_rate,
              d.flow_r2, d.t_top_centre, d.t_bottom_side, d.funnel() ? "funnel flow" : "not funnel flow");
  for (const auto& f : feeders)
    std::printf("feed %s: %ld inserted, %ld due not placed\n", f.spec().name.c_str(), f.inserted(), f.undelivered());
  std::printf("deepest penetration %.3g%% of the radius; %ld particle-samples over %.3g%%\n", 100 * worst_penetration,
              over_limit, 100 * s.output.penetration_warning);
  std::printf("wall time %.1f s, %.3g particle-steps/s\n", wall, static_cast<double>(particle_steps) / wall);
  std::map<std::string, std::string> manifest;
  manifest["scene"] = s.path;
  std::string set;
  for (const auto& o : overrides) set += (set.empty() ? "" : " ") + o;
  manifest["overrides"] = set.empty() ? "(none)" : set;
  manifest["commit"] = git_commit();
  manifest["date"] = utc_date();
  manifest["backend"] = DefaultSpace::name;
  manifest["device"] = device_name(DefaultSpace{});
  manifest["shape"] = Shape::name;
  manifest["law"] = scene_law_name(s);
  auto put = [&](const char* key, double v) {
    char buf[64];
    std::snprintf(buf, sizeof buf, "%.17g", v);
    manifest[key] = buf;
  };
  put("dt_s", s.dt);
  put("wall_time_s", wall);
  manifest["particles_at_opening"] = std::to_string(d.particles);
  manifest["discharged_count"] = std::to_string(d.discharged);
  put("residual_fraction", d.residual);
  put("flow_rate_kg_s", d.flow_rate);
  put("flow_fit_r2", d.flow_r2);
  put("exit_top_centre_s", d.t_top_centre);
  put("exit_bottom_sides_s", d.t_bottom_side);
  manifest["funnel_flow"] = d.funnel() ? "yes" : "no";
  if (arch_span > 0) {
    manifest["arched"] = d.arched ? "yes" : "no";
    put("last_exit_s", d.last_exit);
    put("arch_time_s", arch_span);
    manifest["over_orifice_at_end"] = std::to_string(record.over_orifice());
  }
  write_manifest(dir + "/manifest.txt", manifest);
  const bool plotted = plot(dir + "/timeseries.csv", "plots/hopper.png");
  std::printf("wrote %s/timeseries.csv, %s/discharge.csv, %s/particles.pvd (%d frames)%s\n", dir.c_str(), dir.c_str(), dir.c_str(),
              frame, plotted ? ", plots/hopper.png" : "");
  return 0;
}

}  // namespace

int main(int argc, char** argv) try {
  blaze::line_buffered_output();
  std::string path = "studies/hopper/hopper.toml";
  std::vector<std::string> overrides;
  for (int k = 1; k < argc; ++k) {
    const std::string a = argv[k];
    if (a == "--set" && k + 1 < argc) overrides.push_back(argv[++k]);
    else if (a.rfind("--", 0) == 0) throw SceneError("unknown option '" + a + "'; usage: study_hopper [SCENE.toml] [--set key=value]...");
    else path = a;
  }
  const Scene s = load_scene(path, overrides);
  if (s.precision != PrecisionKind::float64) throw SceneError(path + ": the hopper study runs in double: precision = \"double\"");
  for (const auto& note : s.notes) std::printf("%s\n", note.c_str());
  check_run_fits_here(s);
  // the scene's law, tangential and rolling keys, all of them (pipeline/scene_law.hpp)
  if (s.all_spheres())
    return with_scene_law<Real, true>(s, [&](auto law) { return run<typename decltype(law)::type, SphereShape>(s, overrides); });
  return with_scene_law<Real, false>(s, [&](auto law) { return run<typename decltype(law)::type, PolyhedronShape<Real>>(s, overrides); });
} catch (const std::exception& ex) {
  std::fprintf(stderr, "error: %s\n", ex.what());
  return 1;
}
