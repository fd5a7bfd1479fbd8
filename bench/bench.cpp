// make bench: particle-steps per second of densely packed spheres under gravity at N = 1e4 ... 1e7
// (GPU) or ... 1e6 (CPU), with per-phase times, for float and double and both normal laws. The bed
// is an fcc lattice compressed by 1% of a radius inside a closed box (12 neighbours, all touching);
// each case runs warm-up steps first, then a timed stretch without
// synchronisation (throughput), then a stretch with every phase fenced (the phase split).
// Also (issue 6): the feature-skip pair (the same bed with friction, rotation and walls, and as a
// frictionless, non-rotating scene without walls) and the thesis's lab ball mill (242 balls, where
// per-step overhead dominates; steps per second).
// Polyhedra: falling from a loose lattice (free-fall) and packed and in contact (packed), and the
// world-surface sweep (surfaces: the floor split into tiles). On request (--cases largest): the
// largest runs, a dense sphere bed of --largest-spheres (default 5e8) and packed cubes of
// 3.4e7 (the thesis's largest) and --largest-cubes (default 1e8).
// Prints a table and writes bench/results/<device>-<date>[-TAG].csv (rows already in that file
// are kept, this run's added after them). Options: --out DIR, --skin S
// (skin in radii, default 0.2), --pairs auto|both_sides|once (SimulationParams::pairs; auto:
// polyhedra once, spheres from both sides), --min-n N, --max-n N, --mesh-n N (the mesh cases'
// particles: default 1e6 on the GPU, 2e4 on the CPU), --mesh-triangles T1,T2,... (the sphere bed's
// box as meshes of about these many triangles, 0: its six polygons; default 0,1e3,1e4,1e5 and 1e6
// on the GPU), --mesh-cubes T1,... (packed cubes on a floor of 1 polygon (0) or these triangles;
// default 0,1e3,1e4,1e5; "none": no cube rows), --tag TAG, --cases
// spheres,polyhedra,packed,surfaces,skip,mill,lifters,mesh,largest (default all but largest, lifters and mesh;
// mill-turning: the turning lab mill alone).
#include <algorithm>
#include <cctype>
#include <cstdio>
#include <exception>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <stdexcept>
#include <string>
#include <vector>
#include "bench/cases.hpp"
#include "blaze/exec/device_info.hpp"
#include "blaze/io/manifest.hpp"
#include "blaze/io/console.hpp"

using namespace blaze;
using namespace blaze::bench;

namespace {

void print_rows(const std::vector<Row>& rows, std::size_t first) {
  for (std::size_t r = first; r < rows.size(); ++r)
    std::printf("  N=%-9ld %-12s %-6s %-6s %10.3e particle-steps/s %9.3e steps/s (%ld steps, %llu rebuilds, %.1f "
                "neighbours, %.2f contacts, %.0f B/particle)\n",
                rows[r].n, rows[r].shape.c_str(), rows[r].law.c_str(), rows[r].precision.c_str(), rows[r].rate,
                rows[r].steps_per_s(), rows[r].steps, static_cast<unsigned long long>(rows[r].builds), rows[r].neighbours,
                rows[r].contacts, rows[r].bytes_per_particle);
  std::fflush(stdout);
}

struct Provenance {
  std::string device, commit, date;
};

std::string csv_header() {
  std::string h = "device,commit,date,backend,skin_over_radius,N,shape,law,precision,steps,particle_steps_per_s,steps_per_s,"
                  "neighbour_builds,neighbour_capacity,neighbours_per_particle,contacts_per_particle,edge_edge_fraction,"
                  "bytes_per_particle";
  for (const char* ph : kPhases) h += std::string(",ms_per_step_") + ph;
  return h + ",scene,world_surfaces,ms_per_rebuild,pairs";
}

// The rows an earlier run wrote to FILE (same day, device and tag), kept ahead of this run's: a
// second invocation adds to the file instead of replacing it. A file with another header is
// not ours to extend: the run stops before measuring anything.
std::vector<std::string> earlier_rows(const std::string& file) {
  std::vector<std::string> lines;
  std::ifstream in(file);
  if (!in) return lines;
  std::string line;
  std::getline(in, line);
  if (line != csv_header())
    throw std::runtime_error(file + ", line 1: the header is not this bench's (" + std::to_string(std::size(kPhases)) +
                             " phase columns expected); move the file or choose another --tag");
  while (std::getline(in, line))
    if (!line.empty()) lines.push_back(line);
  return lines;
}

// The whole table (the earlier rows, then this run's), rewritten after every block of cases: a
// run that fails or is stopped keeps what it measured. Written to FILE.tmp, then renamed.
void write_csv(const std::string& file, const std::vector<std::string>& earlier, const std::vector<Row>& rows,
               const Provenance& at) {
  std::ofstream csv(file + ".tmp");
  csv << csv_header() << '\n';
  for (const std::string& line : earlier) csv << line << '\n';
  for (const auto& r : rows) {
    csv << '"' << at.device << "\"," << at.commit << ',' << at.date << ',' << DefaultSpace::name << ',' << g_skin_fraction << ','
        << r.n << ',' << r.shape << ',' << r.law << ',' << r.precision << ',' << r.steps << ',' << r.rate << ','
        << r.steps_per_s() << ',' << r.builds << ',' << r.capacity << ',' << r.neighbours << ',' << r.contacts << ','
        << r.edge_fraction << ',' << r.bytes_per_particle;
    for (double ms : r.phase_ms) csv << ',' << ms;
    csv << ',' << r.scene << ',' << r.surfaces << ',' << r.rebuild_ms << ',' << r.pairs << '\n';
  }
  csv.close();
  if (!csv) throw std::runtime_error("cannot write " + file + ".tmp");
  std::filesystem::rename(file + ".tmp", file);
}

}  // namespace

int main(int argc, char** argv) {
  blaze::line_buffered_output();
  std::string out_dir = "bench/results";
  long max_n = 0, min_n = 0;
  // polydisperse: by default on the GPU only (settling its bed takes minutes on 2 CPU cores)
  std::string cases = "spheres,history,polyhedra,packed,surfaces,skip,mill", tag_suffix;
  bool cases_given = false;
  long largest_spheres = 500000000, largest_cubes = 100000000, mesh_n = 0;
  std::string mesh_triangles, mesh_cubes = "0,1000,10000,100000";
  // "a,b,c" -> {a, b, c}; "none" -> {}
  const auto longs = [](const std::string& list) {
    std::vector<long> v;
    if (list == "none") return v;
    std::size_t at = 0;
    while (at <= list.size()) {
      const std::size_t comma = std::min(list.find(',', at), list.size());
      v.push_back(std::stol(list.substr(at, comma - at)));
      at = comma + 1;
    }
    return v;
  };
  for (int a = 1; a + 1 < argc; ++a) {
    const std::string opt = argv[a];
    if (opt == "--out") out_dir = argv[a + 1];
    if (opt == "--tag") tag_suffix = std::string("-") + argv[a + 1];
    if (opt == "--pairs") {
      const std::string v = argv[a + 1];
      if (v != "auto" && v != "both_sides" && v != "once") {
        std::fprintf(stderr, "blaze bench: --pairs %s: allowed are auto (the default), both_sides and once\n", v.c_str());
        return 2;
      }
      g_pairs = v == "auto" ? BenchPairs::automatic : v == "once" ? BenchPairs::once : BenchPairs::both_sides;
    }
    if (opt == "--largest-spheres") largest_spheres = std::stol(argv[a + 1]);
    if (opt == "--largest-cubes") largest_cubes = std::stol(argv[a + 1]);
    if (opt == "--skin") g_skin_fraction = std::stod(argv[a + 1]);
    if (opt == "--max-n") max_n = std::stol(argv[a + 1]);
    if (opt == "--min-n") min_n = std::stol(argv[a + 1]);
    if (opt == "--mesh-n") mesh_n = std::stol(argv[a + 1]);
    if (opt == "--mesh-triangles") mesh_triangles = argv[a + 1];
    if (opt == "--mesh-cubes") mesh_cubes = argv[a + 1];
    if (opt == "--cases") cases = argv[a + 1], cases_given = true;
  }
  const auto wanted = [&](const char* name) { return ("," + cases + ",").find("," + std::string(name) + ",") != std::string::npos; };
  const bool gpu = std::string(DefaultSpace::name) == "gpu";
  const std::vector<long> sizes = gpu ? std::vector<long>{10000, 100000, 1000000, 10000000}
                                      : std::vector<long>{10000, 100000, 1000000};
  const std::string device = device_name(DefaultSpace{}), commit = git_commit(), date = utc_date();
  std::printf("blaze bench: %s backend on %s, commit %s, %s\n", DefaultSpace::name, device.c_str(), commit.c_str(), date.c_str());
  std::filesystem::create_directories(out_dir);
  std::string tag = gpu ? device.substr(0, device.find(" (")) : std::string("cpu");
  for (char& c : tag) c = c == ' ' ? '-' : static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  const std::string file = out_dir + "/" + tag + "-" + date.substr(0, 10) + skin_tag() + tag_suffix + ".csv";
  const Provenance at{device, commit, date};
  std::vector<std::string> earlier;
  try {
    earlier = earlier_rows(file);
  } catch (const std::exception& e) {
    std::fprintf(stderr, "blaze bench: %s\n", e.what());
    return 2;
  }
  std::vector<Row> rows;
  for (long n : sizes) {
    if (max_n > 0 && n > max_n) break;
    if (n < min_n) continue;
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
    if (wanted("history")) {  // issue 18: Hertz-Mindlin with the contact store, and with rolling resistance
      rows.push_back(sphere_case<ContactLaw<float, Hertz, TangentialSpring>>("hertz-mindlin", n, warmup, steps));
      rows.push_back(sphere_case<ContactLaw<float, Hertz, TangentialSpring, RollingResistance>>("mindlin-epsd", n, warmup, steps));
    }
    if (wanted("polydisperse") || (gpu && !cases_given)) {  // issue 18: a settled random bed, not only the lattice
      const auto bed = settled_polydisperse_bed<float>(n);
      rows.push_back(settled_polydisperse_case<ContactLaw<float, LinearSpringDashpot, HistoryFreeFriction>>("linear", bed, warmup, steps));
      rows.push_back(settled_polydisperse_case<ContactLaw<float, Hertz, TangentialSpring>>("hertz-mindlin", bed, warmup, steps));
    }
    // Polyhedra: fewer steps from 1e6 (GPU) / 1e4 (CPU) up, so that each case takes seconds.
    const long poly_steps = std::clamp((gpu ? 400000000L : 2000000L) / n, 10L, 400L);
    if (wanted("polyhedra") && n <= (gpu ? 10000000L : 100000L))
      for (const char* poly : {"cube", "octahedron", "dodecahedron"})
        rows.push_back(polyhedron_case(poly, PolyScene::free_fall, n, poly_steps, poly_steps));
    // Packed lattice beds relax by rotation after ~150 steps (packed_polyhedra): 20 warm-up steps,
    // 60 timed, 15 fenced, all while every body still presses on its neighbours.
    if (wanted("packed") && n <= (gpu ? 10000000L : 100000L))
      for (const char* poly : {"cube", "dodecahedron"}) rows.push_back(polyhedron_case(poly, PolyScene::packed, n, 20, 60));
    if (wanted("surfaces") && n == (gpu ? 1000000L : 10000L))  // world contact against the number of surfaces
      for (const char* poly : {"cube", "dodecahedron"})
        for (int tiles : {2, 4, 8, 16}) rows.push_back(polyhedron_case(poly, PolyScene::packed, n, 20, 60, tiles));
    if (wanted("skip") && n == (gpu ? 10000000L : 100000L)) {  // what a scene does not need costs nothing
      rows.push_back(skip_case<LinF, FullFeatures>("sphere-full", n, warmup, steps));
      rows.push_back(skip_case<LeanF, TranslationOnly>("sphere-lean", n, warmup, steps));
      std::printf("  feature skip: frictionless, non-rotating, no walls runs %.2fx the full-feature rate\n",
                  rows.back().rate / rows[rows.size() - 2].rate);
    }
    print_rows(rows, first);
    write_csv(file, earlier, rows, at);
  }
  if (wanted("largest")) {  // few steps: a step of 5e8 spheres takes about 0.1 s
    const std::size_t first = rows.size();
    // The largest that fits: the asked size, else 80% and 60% of it.
    const auto largest = [&](long asked, auto&& run_case) {
      for (double f : {1.0, 0.8, 0.6}) try {
          rows.push_back(run_case(static_cast<long>(f * static_cast<double>(asked))));
          return;
        } catch (const std::exception& e) {
          std::printf("  N=%ld did not run: %s\n", static_cast<long>(f * static_cast<double>(asked)), e.what());
        }
    };
    largest(largest_spheres, [](long n) {
      return sphere_case<ContactLaw<float, LinearSpringDashpot, HistoryFreeFriction>>("linear", n, 10, 20);
    });
    rows.push_back(polyhedron_case("cube", PolyScene::packed, 34000000L, 5, 10, 1, true));
    largest(largest_cubes, [](long n) { return polyhedron_case("cube", PolyScene::packed, n, 5, 10, 1, true); });
    print_rows(rows, first);
    write_csv(file, earlier, rows, at);
  }
  if (wanted("mill") || wanted("mill-turning")) {  // mill-turning: the turning mill alone
    const std::size_t first = rows.size();
    if (wanted("mill")) rows.push_back(mill_case(gpu ? 10000 : 10000, gpu ? 20000 : 2000));
    rows.push_back(mill_case(gpu ? 10000 : 10000, gpu ? 20000 : 2000, true));
    print_rows(rows, first);
  }
  if (wanted("lifters")) {  // world kernel cost against lifter rows, lists on (automatic) and off
    const std::size_t first = rows.size();
    for (int lifter_rows : {0, 8, 16, 32, 64})
      for (WorldLists lists : {WorldLists::automatic, WorldLists::off})
        rows.push_back(mill_case(gpu ? 10000 : 2000, gpu ? 20000 : 1000, true, lifter_rows, lists));
    print_rows(rows, first);
  }
  if (wanted("mesh")) {  // the world phase against the size of a mesh (issue 20)
    const std::size_t first = rows.size();
    const long n = mesh_n > 0 ? mesh_n : gpu ? 1000000L : 20000L;
    std::vector<long> sizes_t = {0L, 1000L, 10000L, 100000L};
    if (gpu) sizes_t.push_back(1000000L);
    if (!mesh_triangles.empty()) sizes_t = longs(mesh_triangles);
    for (long triangles : sizes_t) rows.push_back(mesh_box_case(n, triangles, 20, gpu ? 200 : 40));
    // packed cubes on a floor of 1 polygon or a mesh of 1e3-1e5 triangles (issue 20's polyhedron row)
    for (long triangles : longs(mesh_cubes))
      rows.push_back(polyhedron_case("cube", PolyScene::packed, n, 20, 60, 1, false, triangles));
    print_rows(rows, first);
  }
  write_csv(file, earlier, rows, at);
  std::printf("\n%-9s %-12s %-6s %-6s %11s", "N", "shape", "law", "prec", "p-steps/s");
  for (const char* ph : kPhases) std::printf(" %10.10s", ph);
  std::printf(" %10s   (ms/step, phases timed by events; broad phase per rebuild)\n", "rebuild");
  for (const auto& r : rows) {
    std::printf("%-9ld %-12s %-6s %-6s %11.3e", r.n, r.shape.c_str(), r.law.c_str(), r.precision.c_str(), r.rate);
    for (double ms : r.phase_ms) std::printf(" %10.4f", ms);
    std::printf(" %10.4f %s/%d\n", r.rebuild_ms, r.scene.c_str(), r.surfaces);
  }
  std::printf("wrote %s\n", file.c_str());
  return 0;
}
