// Derived sizes of a run, computed in double from the validated scene before anything is
// allocated (issue 17: a domain far larger than its particles overflowed the int cell count and
// the run silently did nothing; a 1200^3 lattice allocated 5 GB before std::bad_alloc).
//
//   particles   N = sum of lattice sites, list points and fill counts
//   steps       n = round(end_time / dt)
//   cells       n_d = floor(extent_d / (2 r_max + skin)) per axis (grid_spec.hpp), and their product
//   neighbours  C = the list's capacity per particle: at most the particles whose centres lie within
//               D = 2 r_max + skin of a centre, bounded by packing them at the fcc density 0.74 into
//               the ball of radius D + r_min: 0.74 ((D + r_min) / r_min)^3 - 1 (an upper estimate
//               of a dense bed; equal spheres at skin 0.2 r give 23 against fcc's 12), grown by
//               the broad phase's headroom 1.25 (broad_phase.hpp), and at least its initial 16.
//   memory      bytes per particle of each array the run holds, R = bytes per real:
//     device store     30 R + 11     (particle_store.hpp: 21 vector components, 4 quaternion, radius,
//                                     inverse mass and inertia, scratch, penetration; 3 bytes, 2 Index)
//     broad phase      16 + 3 R + 4 C, pairs once + C (7 R + 5) (keys, order, sort scratch,
//                                     reference positions, list; reverse index and pair slots,
//                                     polyhedra + 3 R for the contact patch's moment)
//     statistics       8             (contact counts by kind)
//     energy sample    20            (stored contact energy per particle, Simulation::contact_energy)
//     grid             8 (cells + 1) (cell start and end)
//     host             3 (18 R + 6) + 4 R  (the scene's particles, the last good state, one sample)
//     set-up           250           (the overlap hash of the placements and their names, freed
//                                     before the run; it peaks with one host copy of the state)
//   On the CPU backend the device arrays are host memory too.
// Units: bytes, counts; the numbers are estimates meant to be upper bounds of what a run holds,
// checked against the machine before the run (memory_fit) and printed by --check.
#pragma once
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <string>
#include "blaze/exec/device_info.hpp"
#include "blaze/scene/scene.hpp"

namespace blaze {

struct RunSize {
  double particles = 0, steps = 0;
  double cell = 0, cells[3] = {0, 0, 0}, cells_total = 0;
  double neighbours = 0;  // list capacity per particle (estimate)
  double host_bytes = 0;  // peak host memory (the device arrays included on the CPU backend)
  double device_bytes = 0;  // GPU memory (GPU backend; 0 on the CPU)
  std::string biggest;      // the placement with the most particles, "[[lattice]] #1 count (1.7e+09 particles)"
  std::string biggest_key;  // its key in Scene::where, "lattice[0].count"
};

// Most steps a run may take: a step takes at least a microsecond, so 1e15 steps is 30 years.
constexpr double kMaxSteps = 1e15;
// Float resolution (scene_toml.cpp, check_resolution): ulp at the domain's largest coordinate
// against the overlap of an impact; refused above the first share, noted above the second.
constexpr double kMaxResolutionShare = 0.1, kNoteResolutionShare = 0.01;

// Fixed costs of a process beside its arrays (bytes): the program, its libraries and stacks on the
// CPU; the CUDA context on the host and on the GPU.
constexpr double kHostOverhead = 64e6, kGpuHostOverhead = 512e6, kGpuContext = 512e6;

inline double scene_particles(const Scene& s, RunSize* z = nullptr) {
  double total = 0, most = -1;
  auto consider = [&](double n, const char* table, std::size_t k, const char* key) {
    total += n;
    if (n > most && z) {
      most = n;
      char buf[48];
      std::snprintf(buf, sizeof buf, " (%.3g particles)", n);
      z->biggest = std::string("[[") + table + "]] #" + std::to_string(k + 1) + " " + key + buf;
      z->biggest_key = std::string(table) + "[" + std::to_string(k) + "]." + key;
    }
  };
  for (std::size_t k = 0; k < s.lattices.size(); ++k)
    consider(double(s.lattices[k].count[0]) * double(s.lattices[k].count[1]) * double(s.lattices[k].count[2]), "lattice", k,
             "count");
  for (std::size_t k = 0; k < s.lists.size(); ++k) consider(double(s.lists[k].position.size()), "particles", k, "positions");
  for (std::size_t k = 0; k < s.fills.size(); ++k) consider(double(s.fills[k].count), "fill", k, "count");
  // feeds: the most they can insert (by mass: in particles of the smallest size)
  for (std::size_t k = 0; k < s.feeds.size(); ++k) {
    const FeedSpec& f = s.feeds[k];
    const ParticleTypeSpec& t = s.types[static_cast<std::size_t>(f.type)];
    const double r = f.size.smallest(), rho = s.materials[static_cast<std::size_t>(t.material)].density;
    const double lightest = rho * (t.is_sphere() ? 4.0 / 3.0 * 3.14159265358979 * r * r * r : t.volume);
    // (up to the run's end, and the last insertion's due up to the next: one interval past it)
    const double span = std::min(f.end, s.end_time + f.interval) - f.start;
    double n = std::max(0.0, span) * (f.rate > 0 ? f.rate : f.mass_rate / lightest) + 1;
    if (f.count > 0) n = std::min(n, static_cast<double>(f.count));
    consider(n, "feed", k, f.rate > 0 ? "rate" : "mass_rate");
  }
  return total;
}

inline RunSize run_size(const Scene& s, bool gpu) {
  RunSize z;
  z.particles = scene_particles(s, &z);
  z.steps = std::round(s.end_time / s.dt);
  double r_max = 0, r_min = INFINITY;
  for (const auto& t : s.types) r_max = std::max(r_max, t.size()), r_min = std::min(r_min, t.size());
  z.cell = 2 * r_max + s.skin * r_max;
  const Vec3<double> ext = s.domain_hi - s.domain_lo;
  const double e[3] = {ext.x, ext.y, ext.z};
  z.cells_total = 1;
  for (int d = 0; d < 3; ++d) {
    z.cells[d] = std::max(1.0, std::floor(e[d] / z.cell));
    z.cells_total *= z.cells[d];
  }
  const double reach = z.cell + r_min;
  const double dense = 0.74 * std::pow(reach / r_min, 3) - 1;
  z.neighbours = std::max(16.0, std::ceil(1.25 * std::min(dense, std::max(0.0, z.particles - 1))) + 1);
  const double R = s.precision == PrecisionKind::float32 ? 4 : 8;
  const bool once = s.pair_evaluation == PairsKind::once || (s.pair_evaluation == PairsKind::automatic && !s.all_spheres());
  const double slot = s.all_spheres() ? 7 * R + 5 : 10 * R + 5;  // polyhedra: + the contact patch's moment
  const double per_particle = 30 * R + 11 + 16 + 3 * R + 4 * z.neighbours + (once ? z.neighbours * slot : 0) + 8 + 20;
  const double device = z.particles * per_particle + 8 * (z.cells_total + 1);
  const double host_state = 18 * R + 6;
  const double run_host = z.particles * (3 * host_state + 4 * R), setup_host = z.particles * (host_state + 250);
  if (gpu) {
    z.device_bytes = device + kGpuContext;
    z.host_bytes = std::max(run_host, setup_host) + kGpuHostOverhead;
  } else {
    z.host_bytes = std::max(run_host + device, setup_host) + kHostOverhead;
  }
  return z;
}

// Steps between two outputs of `interval` s (0: none), without overflow for any interval: an
// interval beyond the run's end never comes round (steps + 1); one of the run's length comes at
// its end (a checkpoint with interval = end_time is written: make bench-compare restarts from it).
inline std::uint64_t interval_steps(double interval, double dt, std::uint64_t steps) {
  if (!(interval > 0)) return 0;
  const double k = std::round(interval / dt);
  if (!(k <= static_cast<double>(steps))) return steps + 1;
  return std::max<std::uint64_t>(1, static_cast<std::uint64_t>(k));
}

// The longest run accepted without force_long_run (s), and the optimistic speeds the estimate
// takes: above the best measured (bench/README.md: 4.1e9 particle-steps/s for spheres on an H200,
// 5e6 on 2 CPU cores), so that only runs that cannot finish are refused; and the least time a
// step takes however few its particles (a fused GPU batch; one OpenMP loop on the CPU).
constexpr double kMaxWallTime = 30 * 86400.0;
constexpr double kGpuParticleStepsPerSecond = 5e9, kCpuParticleStepsPerSecondPerThread = 5e6;
constexpr double kGpuStepSeconds = 2e-6, kCpuStepSeconds = 2e-7;
inline double estimated_seconds(const RunSize& z, bool gpu, int threads) {
  const double rate = gpu ? kGpuParticleStepsPerSecond : kCpuParticleStepsPerSecondPerThread * std::max(1, threads);
  return std::max(z.particles * z.steps / rate, z.steps * (gpu ? kGpuStepSeconds : kCpuStepSeconds));
}

inline std::string gigabytes(double bytes) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.3g GB", bytes / 1e9);
  return buf;
}

// The memory estimate against what the machine has (bytes; device_available 0 on the CPU
// backend), and the wall-time estimate against kMaxWallTime: a SceneError naming the key that
// makes the run too large (the largest placement, or the domain when its cells dominate; dt for
// the time).
inline void check_run_fits(const Scene& s, const RunSize& z, bool gpu, double host_available, double device_available,
                           int threads) {
  const double cell_bytes = 8 * (z.cells_total + 1);
  const std::string blame = cell_bytes > 0.5 * (gpu ? z.device_bytes : z.host_bytes) ? "simulation.domain_hi" : z.biggest_key;
  char detail[256];
  std::snprintf(detail, sizeof detail, " (%.3g particles with up to %.3g neighbours each, %.3g grid cells of %.3g m)", z.particles,
                z.neighbours, z.cells_total, z.cell);
  if (z.host_bytes > host_available)
    throw SceneError(s.place(blame) + ": the run needs about " + gigabytes(z.host_bytes) + " of host memory" + detail +
                     "; this machine has " + gigabytes(host_available) + " available. Fewer particles or a smaller domain");
  if (gpu && z.device_bytes > device_available)
    throw SceneError(s.place(blame) + ": the run needs about " + gigabytes(z.device_bytes) + " of GPU memory" + detail +
                     "; the GPU has " + gigabytes(device_available) + " free. Fewer particles or a smaller domain");
  const double seconds = estimated_seconds(z, gpu, threads);
  if (seconds > kMaxWallTime && !s.force_long_run) {
    char msg[320];
    std::snprintf(msg, sizeof msg, ": %.3g steps of %.3g particles take at least %.3g days on this %s at an optimistic "
                  "%.3g particle-steps/s; above %.3g days a run is refused: raise dt, lower end_time, or set "
                  "[simulation] force_long_run = true", z.steps, z.particles, seconds / 86400, gpu ? "GPU" : "CPU",
                  z.particles * z.steps / seconds, kMaxWallTime / 86400);
    throw SceneError(s.place(s.steps_per_contact > 0 ? "simulation.steps_per_contact" : "simulation.dt") + msg);
  }
}

// check_run_fits for this build's backend (DefaultSpace) and the memory and threads free now:
// what a study checks before it builds its run.
inline void check_run_fits_here(const Scene& s) {
  const bool gpu = std::string(DefaultSpace::name) == "gpu";
  const double host_free = available_memory(Host{});
  check_run_fits(s, run_size(s, gpu), gpu, host_free > 0 ? host_free : INFINITY, gpu ? available_memory(DefaultSpace{}) : 0,
                 host_threads());
}

}  // namespace blaze
