// Hopper discharge study (default `make run`): spheres settle behind a gate in a flat-bottomed
// rectangular hopper, the gate opens at t = 0 and the bed drains through a square orifice.
// Particles that fall below the hopper leave the grid domain: they are removed and counted, and
// that count is the discharge. Writes data/hopper/{timeseries.csv, manifest.txt, *.vtu, .pvd}
// and plots/hopper.png.
#include <chrono>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <random>
#if __has_include(<gnuplot-iostream.h>)
#include <gnuplot-iostream.h>
#define BLAZE_HAVE_GNUPLOT 1
#endif
#include "blaze/contact/sphere.hpp"
#include "blaze/exec/device_info.hpp"
#include "blaze/io/manifest.hpp"
#include "blaze/io/params_file.hpp"
#include "blaze/io/vtu_writer.hpp"
#include "blaze/laws/history_free_friction.hpp"
#include "blaze/laws/linear_spring_dashpot.hpp"
#include "blaze/sim/energy.hpp"
#include "blaze/sim/simulation.hpp"

using namespace blaze;
using Real = double;
using Law = ContactLaw<Real, LinearSpringDashpot, HistoryFreeFriction>;
using Sim = Simulation<DefaultSpace, SphereShape, Law, VelocityVerlet>;
using V = Vec3<double>;

namespace {

constexpr double kPi = 3.14159265358979323846;
enum Material : std::uint8_t { kGlass = 0, kWall = 1 };

struct Hopper {
  double width, depth, height, orifice;
};

PlanarPolygon<Real> floor_plate(double x0, double x1, double z0, double z1, std::uint32_t rim_edges) {
  return PlanarPolygon<Real>::make({{x0, 0, z1}, {x1, 0, z1}, {x1, 0, z0}, {x0, 0, z0}}, kWall, rim_edges);
}

// Four walls and a floor of eight plates around the orifice. Only plate edges that face the
// orifice have rim contact; seams between plates do not (planar_polygon.hpp).
World<Real> hopper_world(const Hopper& h, bool gate) {
  const double xs[4] = {-h.width / 2, -h.orifice / 2, h.orifice / 2, h.width / 2};
  const double zs[4] = {-h.depth / 2, -h.orifice / 2, h.orifice / 2, h.depth / 2};
  World<Real> w;
  for (int ix = 0; ix < 3; ++ix)
    for (int iz = 0; iz < 3; ++iz) {
      if (ix == 1 && iz == 1) continue;
      // Edges 0..3 of floor_plate: z = z1, x = x1, z = z0, x = x0.
      const std::uint32_t rim = (ix == 1 && iz == 0 ? 1u : 0u) | (ix == 0 && iz == 1 ? 2u : 0u) |
                                (ix == 1 && iz == 2 ? 4u : 0u) | (ix == 2 && iz == 1 ? 8u : 0u);
      w.polygons.push_back(floor_plate(xs[ix], xs[ix + 1], zs[iz], zs[iz + 1], rim));
    }
  if (gate) w.polygons.push_back(floor_plate(xs[1], xs[2], zs[1], zs[2], 0u));
  const double a = h.width / 2, b = h.depth / 2, t = h.height;
  w.polygons.push_back(PlanarPolygon<Real>::make({V{-a, 0, -b}, {-a, t, -b}, {-a, t, b}, {-a, 0, b}}, kWall, 0u));
  w.polygons.push_back(PlanarPolygon<Real>::make({V{a, 0, b}, {a, t, b}, {a, t, -b}, {a, 0, -b}}, kWall, 0u));
  w.polygons.push_back(PlanarPolygon<Real>::make({V{a, 0, -b}, {a, t, -b}, {-a, t, -b}, {-a, 0, -b}}, kWall, 0u));
  w.polygons.push_back(PlanarPolygon<Real>::make({V{-a, 0, b}, {-a, t, b}, {a, t, b}, {a, 0, b}}, kWall, 0u));
  return w;
}

// A jittered lattice filling the hopper from the floor up.
ParticleState<Real> lattice_fill(const Hopper& h, long n, double r_min, double r_max, double density, unsigned seed) {
  std::mt19937_64 rng(seed);
  std::uniform_real_distribution<double> u(-1, 1);
  const double pitch = 2.2 * r_max;
  const int nx = static_cast<int>((h.width - 2 * r_max) / pitch) + 1;
  const int nz = static_cast<int>((h.depth - 2 * r_max) / pitch) + 1;
  const double x0 = -0.5 * (nx - 1) * pitch, z0 = -0.5 * (nz - 1) * pitch;
  ParticleState<Real> s;
  for (long k = 0; k < n; ++k) {
    const long layer = k / (nx * nz), in_layer = k % (nx * nz);
    const V x{x0 + (in_layer % nx) * pitch + 0.05 * r_max * u(rng), 1.1 * r_max + layer * pitch,
              z0 + (in_layer / nx) * pitch + 0.05 * r_max * u(rng)};
    if (x.y + r_max > h.height) throw std::runtime_error("hopper: particles do not fit below hopper_height");
    const double r = r_min + (r_max - r_min) * 0.5 * (1 + u(rng));
    s.add_sphere(x, r, density, kGlass, V{0.1 * u(rng), 0.1 * u(rng), 0.1 * u(rng)});
  }
  return s;
}

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
  const std::string params_path = argc > 1 ? argv[1] : "studies/hopper/hopper.params";
  ParamsFile prm(params_path);
  const long n = prm.integer("particles", 1, 10000000, "number of spheres");
  const double r_min = prm.number("radius_min", 1e-6, 1, "smallest radius, m");
  const double r_max = prm.number("radius_max", r_min, 4 * r_min, "largest radius, m, at most 4 x radius_min");
  const double density = prm.number("density", 1, 1e5, "kg/m^3");
  const Hopper h{prm.number("hopper_width", 1e-3, 100, "m"), prm.number("hopper_depth", 1e-3, 100, "m"),
                 prm.number("hopper_height", 1e-3, 100, "m"), prm.number("orifice_width", 1e-4, 100, "m")};
  const double k = prm.number("stiffness", 1e-3, 1e12, "N/m");
  const double e = prm.number("restitution", 1e-6, 1, "coefficient of restitution, (0, 1]");
  const double mu_p = prm.number("friction_particle", 0, 10, "-"), mu_w = prm.number("friction_wall", 0, 10, "-");
  const double kt = prm.number("tangential_damping", 0, 1e6, "kg/s");
  const double steps_per_contact = prm.number("steps_per_contact", 5, 1e4, "-");
  const double settle_time = prm.number("settle_time", 0, 100, "s"), discharge_time = prm.number("discharge_time", 0, 1e3, "s");
  const double out_dt = prm.number("output_interval", 1e-9, 1e3, "s"), snap_dt = prm.number("snapshot_interval", 1e-9, 1e3, "s");
  const double skin = prm.number("skin_fraction", 0, 2, "-") * r_max;
  const unsigned seed = static_cast<unsigned>(prm.integer("seed", 0, 1L << 31, "-"));
  prm.check_all_used();
  if (!(h.orifice < h.depth && h.orifice < h.width)) throw std::runtime_error(params_path + ": orifice_width must be smaller than the hopper");

  // Derived: the time step from the contact time of the lightest pair (undamped, the shortest).
  const double m_min = density * 4.0 / 3.0 * kPi * r_min * r_min * r_min;
  const double t_c = kPi * std::sqrt(0.5 * m_min / k), dt = t_c / steps_per_contact;
  const double dt_critical = 2 / std::sqrt(k / (0.5 * m_min));  // thesis section 2.3.2
  std::printf("hopper: %ld spheres, t_c = %.3g s, dt = %.3g s (%.2f of the stability limit 2/sqrt(k/m))\n", n, t_c, dt,
              dt / dt_critical);
  std::printf("backend: %s, %s\n", DefaultSpace::name, device_name(DefaultSpace{}).c_str());

  PairTable<Law> laws;
  const auto normal = LinearSpringDashpot<Real>::from_restitution(k, e);
  laws.set(kGlass, kGlass, {normal, HistoryFreeFriction<Real>::make(mu_p, kt)});
  laws.set(kGlass, kWall, {normal, HistoryFreeFriction<Real>::make(mu_w, kt)});
  const double margin = 4 * r_max;
  const SimulationParams<Real> sp{dt, {0, -9.81, 0}, {-h.width / 2 - margin, -0.05, -h.depth / 2 - margin},
                                  {h.width / 2 + margin, h.height + margin, h.depth / 2 + margin}, skin};

  const std::string dir = "data/hopper";
  std::filesystem::create_directories(dir + "/vtu");
  std::filesystem::create_directories("plots");
  std::ofstream csv(dir + "/timeseries.csv");
  csv << "t_s,discharged_mass_kg,discharged_count,particles_in_hopper,kinetic_translational_J,kinetic_rotational_J,"
         "potential_J\n";
  PvdCollection pvd(dir + "/particles.pvd");
  write_world_vtu(dir + "/walls.vtu", hopper_world(h, false));
  int frame = 0;
  double next_out = -settle_time, next_snap = -settle_time;
  std::uint64_t particle_steps = 0;
  const auto wall_start = std::chrono::steady_clock::now();

  // Runs one phase, writing rows and frames on the way; returns its final state.
  auto run_phase = [&](Sim& sim, double t0, double t1, Index removed_before) {
    const auto steps = static_cast<std::uint64_t>(std::llround((t1 - t0) / dt));
    for (std::uint64_t s = 0; s <= steps; ++s) {
      const double t = t0 + static_cast<double>(s) * dt;
      if (t >= next_out - 0.5 * dt) {
        const auto st = sim.state();
        const auto en = energies(st, sp.gravity);
        csv << t << ',' << sim.removed_mass() << ',' << removed_before + sim.removed_count() << ',' << st.size() << ','
            << en.translational << ',' << en.rotational << ',' << en.potential << '\n';
        next_out += out_dt;
        if (t >= next_snap - 0.5 * dt) {
          char name[64];
          std::snprintf(name, sizeof name, "vtu/particles_%04d.vtu", frame++);
          write_particles_vtu(dir + "/" + name, st);
          pvd.add(t, name);
          next_snap += snap_dt;
          std::printf("  t = %6.3f s  in hopper %6zu  discharged %6d (%.3f kg)\n", t, st.size(),
                      static_cast<int>(removed_before + sim.removed_count()), sim.removed_mass());
          std::fflush(stdout);
        }
      }
      if (s < steps) sim.step();
      particle_steps += static_cast<std::uint64_t>(sim.size());
    }
    return sim.state();
  };

  Sim settle(sp, laws, hopper_world(h, true), lattice_fill(h, n, r_min, r_max, density, seed));
  const auto settled = run_phase(settle, -settle_time, 0, 0);
  if (settle.removed_count() > 0)
    std::printf("WARNING: %d particles left the domain while the gate was closed\n", settle.removed_count());
  Sim discharge(sp, laws, hopper_world(h, false), settled);
  const auto final_state = run_phase(discharge, 0, discharge_time, settle.removed_count());
  csv.close();

  const double wall = std::chrono::duration<double>(std::chrono::steady_clock::now() - wall_start).count();
  std::printf("discharged %d of %ld spheres (%.3f kg) in %.2f s; %zu remain\n", discharge.removed_count(), n,
              discharge.removed_mass(), discharge_time, final_state.size());
  std::printf("wall time %.1f s, %.3g particle-steps/s\n", wall, static_cast<double>(particle_steps) / wall);
  auto manifest = prm.values();
  manifest["commit"] = git_commit();
  manifest["date"] = utc_date();
  manifest["backend"] = DefaultSpace::name;
  manifest["device"] = device_name(DefaultSpace{});
  char buf[64];
  std::snprintf(buf, sizeof buf, "%.17g", dt);
  manifest["dt_s"] = buf;
  std::snprintf(buf, sizeof buf, "%.3f", wall);
  manifest["wall_time_s"] = buf;
  manifest["discharged_count"] = std::to_string(discharge.removed_count());
  write_manifest(dir + "/manifest.txt", manifest);
  const bool plotted = plot(dir + "/timeseries.csv", "plots/hopper.png");
  std::printf("wrote %s/timeseries.csv, %s/particles.pvd (%d frames)%s\n", dir.c_str(), dir.c_str(), frame,
              plotted ? ", plots/hopper.png" : "");
  return 0;
} catch (const std::exception& ex) {
  std::fprintf(stderr, "error: %s\n", ex.what());
  return 1;
}
