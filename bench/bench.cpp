// make bench: particle-steps per second of densely packed spheres under gravity at N = 1e4 ... 1e7
// (GPU) or ... 1e6 (CPU), with per-phase times, for float and double and both normal laws. The bed
// is an fcc lattice compressed by 1% of a radius inside a closed box (12 neighbours, all touching);
// each case runs warm-up steps first, then a timed stretch without
// synchronisation (throughput), then a stretch with every phase fenced (the phase split).
// Prints a table and writes bench/results/<device>-<date>.csv. Options: --out DIR, --skin S (skin in
// radii, default 0.2), --max-n N.
#include <cctype>
#include <chrono>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>
#include "blaze/contact/sphere.hpp"
#include "blaze/exec/device_info.hpp"
#include "blaze/io/manifest.hpp"
#include "blaze/laws/hertz.hpp"
#include "blaze/laws/history_free_friction.hpp"
#include "blaze/laws/linear_spring_dashpot.hpp"
#include "blaze/scenes/gravity_packing.hpp"
#include "blaze/scenes/polyhedron_packing.hpp"
#include "blaze/shapes/shape_io.hpp"

using namespace blaze;

namespace {

constexpr double kPi = 3.14159265358979323846, kRadius = 1e-3, kDensity = 2500, kStiffness = 1e4;
const char* kPhases[] = {"rebuild-check", "hash", "sort", "reorder", "neighbours", "contacts", "walls", "integrate"};

struct Row {
  std::string shape, law, precision;
  long n = 0, steps = 0;
  double rate = 0, bytes_per_particle = 0;
  std::uint64_t builds = 0;
  Index capacity = 0;
  double neighbours = 0, contacts = 0;  // per particle, at the end of the timed stretch
  double edge_fraction = 0;             // edge-edge share of the contacts (thesis Fig 3.27)
  std::vector<double> phase_ms;         // per step
};

template <class Law>
Law make_law();
template <>
ContactLaw<float, LinearSpringDashpot, HistoryFreeFriction> make_law() {
  return {LinearSpringDashpot<float>::from_restitution(kStiffness, 0.5), HistoryFreeFriction<float>::make(0.4, 0.05)};
}
template <>
ContactLaw<double, LinearSpringDashpot, HistoryFreeFriction> make_law() {
  return {LinearSpringDashpot<double>::from_restitution(kStiffness, 0.5), HistoryFreeFriction<double>::make(0.4, 0.05)};
}
template <>
ContactLaw<float, Hertz, HistoryFreeFriction> make_law() {
  // K_n such that a contact at 1 m/s lasts as long as the linear one (t_c = 2.94 delta_max / v).
  return {Hertz<float>::from_stiffness(2.3e6, 0.5 * kRadius, 20), HistoryFreeFriction<float>::make(0.4, 0.05)};
}

double g_skin_fraction = 0.2;  // neighbour-list skin / radius (--skin)

std::string skin_tag() {
  if (g_skin_fraction == 0.2) return "";
  char buf[32];
  std::snprintf(buf, sizeof buf, "-skin%g", g_skin_fraction);
  return buf;
}

// Warm-up, then the timed stretch, then the fenced stretch for the phase split.
template <class Sim>
Row measure(Sim& sim, const char* shape, const char* law_name, const char* precision, long warmup, long steps) {
  sim.run(static_cast<std::uint64_t>(warmup));
  fence(DefaultSpace{});
  const auto builds0 = sim.neighbour_builds();
  const auto t0 = std::chrono::steady_clock::now();
  sim.run(static_cast<std::uint64_t>(steps));
  fence(DefaultSpace{});
  const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  Row row{shape, law_name, precision, sim.size(), steps,
          static_cast<double>(sim.size()) * static_cast<double>(steps) / seconds,
          static_cast<double>(sim.memory_bytes()) / static_cast<double>(sim.size()), sim.neighbour_builds() - builds0,
          sim.neighbour_capacity(), 0, 0, 0, {}};
  const auto nl = sim.neighbour_lists();
  long listed = 0;
  for (Index c : nl.count) listed += c;
  row.neighbours = static_cast<double>(listed) / static_cast<double>(sim.size());
  sim.timer().enabled = true;
  const long phase_steps = std::max(10L, steps / 4);
  sim.run(static_cast<std::uint64_t>(phase_steps));
  for (const char* ph : kPhases) {
    const auto it = sim.timer().seconds().find(ph);
    row.phase_ms.push_back(it == sim.timer().seconds().end() ? 0.0 : 1e3 * it->second / phase_steps);
  }
  const auto [vertex_face, edge_edge] = sim.contact_counts();
  row.contacts = 2.0 * static_cast<double>(vertex_face + edge_edge) / static_cast<double>(sim.size());
  row.edge_fraction = vertex_face + edge_edge > 0 ? static_cast<double>(edge_edge) / static_cast<double>(vertex_face + edge_edge) : 0;
  return row;
}

using Stats = FeatureSet<true, true>;

template <class Law>
Row sphere_case(const char* law_name, long n, long warmup, long steps) {
  using Real = typename Law::real_type;
  const double m = kDensity * 4.0 / 3.0 * kPi * kRadius * kRadius * kRadius;
  const double dt = kPi * std::sqrt(0.5 * m / kStiffness) / 25;
  // Dense bed: fcc at 0.99 of contact spacing, radii +-0.5%: every neighbour pair overlaps by
  // 0-2% of a radius, held by six walls.
  auto scene = gravity_packing<Real>(static_cast<int>(n), kRadius, 42, dt, {Lattice::fcc, 1.98, 0.005, 0.01, true});
  scene.params.skin = static_cast<Real>(g_skin_fraction * kRadius);
  PairTable<Law> laws;
  laws.set(0, 0, make_law<Law>());
  laws.set(0, 1, make_law<Law>());
  Simulation<DefaultSpace, SphereShape, Law, VelocityVerlet, ContactPointVelocity, Stats> sim(scene.params, laws, scene.world,
                                                                                               scene.particles);
  return measure(sim, "sphere", law_name, sizeof(Real) == 4 ? "float" : "double", warmup, steps);
}

// Polyhedra of one shape (about 1 cm) falling from a loose lattice in a box, linear law, float.
// table_in_memory: read the shape table from device memory instead of the kernel arguments.
Row polyhedron_case(const char* shape_name, long n, long warmup, long steps, bool table_in_memory = false) {
  using Law = ContactLaw<float, LinearSpringDashpot, HistoryFreeFriction>;
  PolyhedronShape<float> shape;
  shape.table.add(load_shape(std::string("data/shapes/") + shape_name + ".shape"), kDensity);
  const double k = 1e5, dt = kPi * std::sqrt(0.5 * shape.table.type[0].mass / k) / 25;
  auto scene = polyhedron_packing(shape.table, 0, static_cast<int>(n), 42, dt);
  scene.params.skin = static_cast<float>(g_skin_fraction * shape.table.type[0].bounding_radius);
  const Law law{LinearSpringDashpot<float>::from_restitution(k, 0.5), HistoryFreeFriction<float>::make(0.4, 0.05)};
  PairTable<Law> laws;
  laws.set(0, 0, law);
  laws.set(0, 1, law);
  Buffer<PolyhedronTable<float>, DefaultSpace> table_copy(1);
  if (table_in_memory) {
    copy_n(&shape.table, 1, table_copy.data(), Host{}, DefaultSpace{});
    shape.table_in_memory = table_copy.data();
  }
  Simulation<DefaultSpace, PolyhedronShape<float>, Law, VelocityVerlet, ContactPointVelocity, Stats> sim(
      scene.params, laws, scene.world, scene.particles, shape);
  const std::string label = std::string(shape_name) + (table_in_memory ? "@mem" : "");
  return measure(sim, label.c_str(), "linear", "float", warmup, steps);
}

}  // namespace

int main(int argc, char** argv) {
  std::string out_dir = "bench/results";
  long max_n = 0;
  for (int a = 1; a + 1 < argc; ++a) {
    const std::string opt = argv[a];
    if (opt == "--out") out_dir = argv[a + 1];
    if (opt == "--skin") g_skin_fraction = std::stod(argv[a + 1]);
    if (opt == "--max-n") max_n = std::stol(argv[a + 1]);
  }
  const bool gpu = std::string(DefaultSpace::name) == "gpu";
  const std::vector<long> sizes = gpu ? std::vector<long>{10000, 100000, 1000000, 10000000}
                                      : std::vector<long>{10000, 100000, 1000000};
  const std::string device = device_name(DefaultSpace{}), commit = git_commit(), date = utc_date();
  std::printf("blaze bench: %s backend on %s, commit %s, %s\n", DefaultSpace::name, device.c_str(), commit.c_str(), date.c_str());
  std::vector<Row> rows;
  for (long n : sizes) {
    if (max_n > 0 && n > max_n) break;
    // Fewer steps for large N on the CPU keeps make bench to minutes.
    const long steps = gpu ? 400 : std::max(20L, 2000000L / n * 10 > 400 ? 400 : 2000000L / n * 10);
    const long warmup = steps;
    using LinF = ContactLaw<float, LinearSpringDashpot, HistoryFreeFriction>;
    using LinD = ContactLaw<double, LinearSpringDashpot, HistoryFreeFriction>;
    using HzF = ContactLaw<float, Hertz, HistoryFreeFriction>;
    const std::size_t first = rows.size();
    rows.push_back(sphere_case<LinF>("linear", n, warmup, steps));
    rows.push_back(sphere_case<LinD>("linear", n, warmup, steps));
    rows.push_back(sphere_case<HzF>("hertz", n, warmup, steps));
    if (n <= (gpu ? 1000000L : 100000L))
      for (const char* poly : {"cube", "octahedron", "dodecahedron"}) rows.push_back(polyhedron_case(poly, n, warmup, steps));
    if (n == (gpu ? 1000000L : 10000L))  // where the shape table lives: kernel arguments vs device memory
      for (const char* poly : {"cube", "dodecahedron"}) rows.push_back(polyhedron_case(poly, n, warmup, steps, true));
    for (std::size_t r = first; r < rows.size(); ++r)
      std::printf("  N=%-9ld %-12s %-6s %-6s %10.3e particle-steps/s  (%ld steps, %llu rebuilds, %.1f neighbours, %.2f contacts, %.0f B/particle)\n",
                  rows[r].n, rows[r].shape.c_str(), rows[r].law.c_str(), rows[r].precision.c_str(), rows[r].rate, rows[r].steps,
                  static_cast<unsigned long long>(rows[r].builds), rows[r].neighbours, rows[r].contacts,
                  rows[r].bytes_per_particle);
    std::fflush(stdout);
  }
  std::filesystem::create_directories(out_dir);
  std::string tag = gpu ? device.substr(0, device.find(" (")) : std::string("cpu");
  for (char& c : tag) c = c == ' ' ? '-' : static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  const std::string file = out_dir + "/" + tag + "-" + date.substr(0, 10) + skin_tag() + ".csv";
  std::ofstream csv(file);
  csv << "device,commit,date,backend,skin_over_radius,N,shape,law,precision,steps,particle_steps_per_s,neighbour_builds,"
         "neighbour_capacity,neighbours_per_particle,contacts_per_particle,edge_edge_fraction,bytes_per_particle";
  for (const char* ph : kPhases) csv << ",ms_per_step_" << ph;
  csv << '\n';
  std::printf("\n%-9s %-12s %-6s %-6s %11s", "N", "shape", "law", "prec", "p-steps/s");
  for (const char* ph : kPhases) std::printf(" %10.10s", ph);
  std::printf("   (ms/step, phases fenced)\n");
  for (const auto& r : rows) {
    csv << '"' << device << "\"," << commit << ',' << date << ',' << DefaultSpace::name << ',' << g_skin_fraction << ',' << r.n << ',' << r.shape << ',' << r.law
        << ',' << r.precision << ',' << r.steps << ',' << r.rate << ',' << r.builds << ',' << r.capacity << ','
        << r.neighbours << ',' << r.contacts << ',' << r.edge_fraction << ',' << r.bytes_per_particle;
    std::printf("%-9ld %-12s %-6s %-6s %11.3e", r.n, r.shape.c_str(), r.law.c_str(), r.precision.c_str(), r.rate);
    for (double ms : r.phase_ms) {
      csv << ',' << ms;
      std::printf(" %10.4f", ms);
    }
    csv << '\n';
    std::printf("\n");
  }
  std::printf("wrote %s\n", file.c_str());
  return 0;
}
