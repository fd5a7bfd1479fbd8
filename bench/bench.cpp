// make bench: particle-steps per second of densely packed spheres under gravity at N = 1e4 ... 1e7
// (GPU) or ... 1e6 (CPU), with per-phase times, for float and double and both normal laws. The bed
// is an fcc lattice compressed by 1% of a radius inside a closed box (12 neighbours, all touching);
// each case runs warm-up steps first, then a timed stretch without
// synchronisation (throughput), then a stretch with every phase fenced (the phase split).
// Also (issue 6): the feature-skip pair (the same bed with friction, rotation and walls, and as a
// frictionless, non-rotating scene without walls) and the thesis's lab ball mill (242 balls, where
// per-step overhead dominates; steps per second).
// Prints a table and writes bench/results/<device>-<date>.csv. Options: --out DIR, --skin S (skin in
// radii, default 0.2), --max-n N, --cases spheres,polyhedra,skip,mill (default all).
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
  double rate = 0, bytes_per_particle = 0;  // particle-steps/s
  double steps_per_s() const { return rate / static_cast<double>(n); }
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
ContactLaw<float, LinearSpringDashpot, NoFriction> make_law() {
  return {LinearSpringDashpot<float>::from_restitution(kStiffness, 0.5), {}};
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
  if constexpr (Sim::features::statistics) {
    const auto [vertex_face, edge_edge] = sim.contact_counts();
    row.contacts = 2.0 * static_cast<double>(vertex_face + edge_edge) / static_cast<double>(sim.size());
    row.edge_fraction = vertex_face + edge_edge > 0 ? static_cast<double>(edge_edge) / static_cast<double>(vertex_face + edge_edge) : 0;
  }
  return row;
}

using Stats = FeatureSet<true, true>;

template <class Law, class Features = Stats>
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
  Simulation<DefaultSpace, SphereShape, Law, VelocityVerlet, ContactPointVelocity, Features> sim(scene.params, laws, scene.world,
                                                                                                  scene.particles);
  return measure(sim, "sphere", law_name, sizeof(Real) == 4 ? "float" : "double", warmup, steps);
}

// Feature skipping: a frictionless bed that needs no walls and no gravity (fcc at 0.999 of the
// contact spacing, radii +-0.05%: every neighbour pair overlaps by ~0.1% of a radius and the bed
// barely moves over the timed steps), run by the full-feature build (rotation, the friction law
// with mu = 0) and by the build that compiles rotation and friction out. Same scene, same forces.
template <class Law, class Features>
Row skip_case(const char* label, long n, long warmup, long steps) {
  const double m = kDensity * 4.0 / 3.0 * kPi * kRadius * kRadius * kRadius;
  const double dt = kPi * std::sqrt(0.5 * m / kStiffness) / 25;
  auto scene = gravity_packing<float>(static_cast<int>(n), kRadius, 42, dt, {Lattice::fcc, 1.998, 0.0005, 0.01, true});
  scene.world = {};
  scene.params.gravity = {0, 0, 0};
  scene.params.skin = static_cast<float>(g_skin_fraction * kRadius);
  Law law = make_law<Law>();
  if constexpr (std::is_same_v<decltype(law.tangential), HistoryFreeFriction<float>>) law.tangential.mu = 0;
  PairTable<Law> laws;
  laws.set(0, 0, law);
  Simulation<DefaultSpace, SphereShape, Law, VelocityVerlet, ContactPointVelocity, Features> sim(scene.params, laws, scene.world,
                                                                                                  scene.particles);
  return measure(sim, label, "linear", "float", warmup, steps);
}

// The thesis's lab mill (section 4.2.1): a 90 cm x 15 cm steel drum (the inner cylinder plus two
// octagonal end plates covering its faces), 242 steel balls of r = 2.5 cm (30% filling), e =
// 0.825, mu = 0.15 (its calibrated combination 3), dt = 4.14e-5 s (its eq. 4.4 limit); k = 2e6 N/m
// puts dt at 0.06 of the critical step. The drum does not rotate yet (mills come later): the
// balls drop from a lattice, settle over the warm-up, then the bed is timed.
Row mill_case(long warmup, long steps) {
  using Law = ContactLaw<float, LinearSpringDashpot, HistoryFreeFriction>;
  using V = Vec3<double>;
  const double r = 0.025, rho = 7800, drum_r = 0.45, length = 0.15, dt = 4.14e-5;
  ParticleState<float> balls;
  for (int layer = 0; layer < 2; ++layer)
    for (int iy = 0; iy < 11; ++iy)
      for (int ix = 0; ix < 11; ++ix)
        balls.add_sphere(Vec3<float>{float(-0.275 + 0.055 * ix), float(-0.275 + 0.055 * iy), float(0.045 + 0.06 * layer)},
                         float(r), float(rho), 0, Vec3<float>{0, 0, 0});
  World<float> world;
  world.cylinders.push_back(Cylinder<float>::make(V{0, 0, 0}, V{0, 0, 1}, drum_r, length, 1));
  const double rc = drum_r / std::cos(kPi / 8);  // the octagon's circumradius: it covers the disc
  std::vector<V> front, back;
  for (int k = 0; k < 8; ++k) {
    const double a = kPi / 8 + k * kPi / 4;
    front.push_back({rc * std::cos(a), rc * std::sin(a), 0});  // counter-clockwise seen from +z: normal +z
    back.push_back({rc * std::cos(-a), rc * std::sin(-a), length});
  }
  world.polygons.push_back(PlanarPolygon<float>::make(front, 1, 0u));
  world.polygons.push_back(PlanarPolygon<float>::make(back, 1, 0u));
  const SimulationParams<float> params{float(dt), {0, -9.81f, 0}, {-0.5f, -0.5f, -0.05f}, {0.5f, 0.5f, 0.2f},
                                       float(g_skin_fraction * r)};
  const Law law{LinearSpringDashpot<float>::from_restitution(2e6, 0.825), HistoryFreeFriction<float>::make(0.15, 100)};
  PairTable<Law> laws;
  laws.set(0, 0, law);
  laws.set(0, 1, law);
  Simulation<DefaultSpace, SphereShape, Law, VelocityVerlet, ContactPointVelocity, Stats> sim(params, laws, world, balls);
  Row row = measure(sim, "mill-242", "linear", "float", warmup, steps);
  if (sim.removed_count() != 0) std::printf("WARNING: %d balls left the mill\n", static_cast<int>(sim.removed_count()));
  return row;
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

void print_rows(const std::vector<Row>& rows, std::size_t first) {
  for (std::size_t r = first; r < rows.size(); ++r)
    std::printf("  N=%-9ld %-12s %-6s %-6s %10.3e particle-steps/s %9.3e steps/s (%ld steps, %llu rebuilds, %.1f "
                "neighbours, %.2f contacts, %.0f B/particle)\n",
                rows[r].n, rows[r].shape.c_str(), rows[r].law.c_str(), rows[r].precision.c_str(), rows[r].rate,
                rows[r].steps_per_s(), rows[r].steps, static_cast<unsigned long long>(rows[r].builds), rows[r].neighbours,
                rows[r].contacts, rows[r].bytes_per_particle);
  std::fflush(stdout);
}

}  // namespace

int main(int argc, char** argv) {
  std::string out_dir = "bench/results";
  long max_n = 0;
  std::string cases = "spheres,polyhedra,skip,mill";
  for (int a = 1; a + 1 < argc; ++a) {
    const std::string opt = argv[a];
    if (opt == "--out") out_dir = argv[a + 1];
    if (opt == "--skin") g_skin_fraction = std::stod(argv[a + 1]);
    if (opt == "--max-n") max_n = std::stol(argv[a + 1]);
    if (opt == "--cases") cases = argv[a + 1];
  }
  const auto wanted = [&](const char* name) { return ("," + cases + ",").find("," + std::string(name) + ",") != std::string::npos; };
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
    using LeanF = ContactLaw<float, LinearSpringDashpot, NoFriction>;
    const std::size_t first = rows.size();
    if (wanted("spheres")) {
      rows.push_back(sphere_case<LinF>("linear", n, warmup, steps));
      rows.push_back(sphere_case<LinD>("linear", n, warmup, steps));
      rows.push_back(sphere_case<HzF>("hertz", n, warmup, steps));
    }
    if (wanted("polyhedra") && n <= (gpu ? 1000000L : 100000L))
      for (const char* poly : {"cube", "octahedron", "dodecahedron"}) rows.push_back(polyhedron_case(poly, n, warmup, steps));
    if (wanted("polyhedra") && n == (gpu ? 1000000L : 10000L))  // shape table: kernel arguments vs device memory
      for (const char* poly : {"cube", "dodecahedron"}) rows.push_back(polyhedron_case(poly, n, warmup, steps, true));
    if (wanted("skip") && n == (gpu ? 10000000L : 100000L)) {  // what a scene does not need costs nothing
      rows.push_back(skip_case<LinF, FullFeatures>("sphere-full", n, warmup, steps));
      rows.push_back(skip_case<LeanF, TranslationOnly>("sphere-lean", n, warmup, steps));
      std::printf("  feature skip: frictionless, non-rotating, no walls runs %.2fx the full-feature rate\n",
                  rows.back().rate / rows[rows.size() - 2].rate);
    }
    print_rows(rows, first);
  }
  if (wanted("mill")) {
    rows.push_back(mill_case(gpu ? 10000 : 10000, gpu ? 20000 : 2000));
    print_rows(rows, rows.size() - 1);
  }
  std::filesystem::create_directories(out_dir);
  std::string tag = gpu ? device.substr(0, device.find(" (")) : std::string("cpu");
  for (char& c : tag) c = c == ' ' ? '-' : static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  const std::string file = out_dir + "/" + tag + "-" + date.substr(0, 10) + skin_tag() + ".csv";
  std::ofstream csv(file);
  csv << "device,commit,date,backend,skin_over_radius,N,shape,law,precision,steps,particle_steps_per_s,steps_per_s,"
         "neighbour_builds,neighbour_capacity,neighbours_per_particle,contacts_per_particle,edge_edge_fraction,bytes_per_particle";
  for (const char* ph : kPhases) csv << ",ms_per_step_" << ph;
  csv << '\n';
  std::printf("\n%-9s %-12s %-6s %-6s %11s", "N", "shape", "law", "prec", "p-steps/s");
  for (const char* ph : kPhases) std::printf(" %10.10s", ph);
  std::printf("   (ms/step, phases fenced)\n");
  for (const auto& r : rows) {
    csv << '"' << device << "\"," << commit << ',' << date << ',' << DefaultSpace::name << ',' << g_skin_fraction << ',' << r.n << ',' << r.shape << ',' << r.law
        << ',' << r.precision << ',' << r.steps << ',' << r.rate << ',' << r.steps_per_s() << ',' << r.builds << ',' << r.capacity << ','
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
