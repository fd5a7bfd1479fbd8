// The benchmark scenes of make bench (bench.cpp runs them): each builds a scene, a simulation,
// and measures it (measure: warm-up, an unfenced timed stretch for the throughput, a fenced
// stretch for the phase split, three timed neighbour-list rebuilds).
#pragma once
#include <chrono>
#include <cstdio>
#include <string>
#include <vector>
#include "blaze/shapes/sphere_shape.hpp"
#include "blaze/laws/hertz.hpp"
#include "blaze/laws/history_free_friction.hpp"
#include "blaze/laws/linear_spring_dashpot.hpp"
#include "blaze/scene/mill_geometry.hpp"
#include "pipeline/gravity_packing.hpp"
#include "pipeline/polyhedron_packing.hpp"
#include "blaze/shapes/shape_io.hpp"

namespace blaze::bench {

constexpr double kPi = 3.14159265358979323846, kRadius = 1e-3, kDensity = 2500, kStiffness = 1e4;
// "rebuild-check" reads 0 from ee214ae on: the check is timed inside the drift's "integrate".
inline const char* kPhases[] = {"rebuild-check", "hash", "sort", "reorder", "neighbours", "contacts", "walls", "integrate"};

struct Row {
  std::string shape, law, precision;
  std::string scene;  // dense-bed, free-fall, packed, no-walls, mill
  long n = 0, steps = 0;
  double rate = 0, bytes_per_particle = 0;  // particle-steps/s
  double steps_per_s() const { return rate / static_cast<double>(n); }
  std::uint64_t builds = 0;
  Index capacity = 0;
  double neighbours = 0, contacts = 0;  // per particle, at the end of the timed stretch
  double edge_fraction = 0;             // edge-edge share of the contacts (thesis Fig 3.27)
  std::vector<double> phase_ms;         // per step
  int surfaces = 0;                     // world surfaces (planar polygons + cylinders)
  double rebuild_ms = 0;                // one broad-phase rebuild: hash + sort + reorder + cells and list
  std::string pairs;                    // both_sides or once (SimulationParams::pairs)
};

template <class Law>
Law make_law();
template <>
inline ContactLaw<float, LinearSpringDashpot, HistoryFreeFriction> make_law() {
  return {LinearSpringDashpot<float>::from_restitution(kStiffness, 0.5), HistoryFreeFriction<float>::make(0.4, 0.05)};
}
template <>
inline ContactLaw<double, LinearSpringDashpot, HistoryFreeFriction> make_law() {
  return {LinearSpringDashpot<double>::from_restitution(kStiffness, 0.5), HistoryFreeFriction<double>::make(0.4, 0.05)};
}
template <>
inline ContactLaw<float, LinearSpringDashpot, NoFriction> make_law() {
  return {LinearSpringDashpot<float>::from_restitution(kStiffness, 0.5), {}};
}
template <>
inline ContactLaw<float, Hertz, HistoryFreeFriction> make_law() {
  // K_n such that a contact at 1 m/s lasts as long as the linear one (t_c = 2.94 delta_max / v).
  return {Hertz<float>::from_stiffness(2.3e6, 0.5 * kRadius, 20), HistoryFreeFriction<float>::make(0.4, 0.05)};
}

// Hertz-Mindlin with contact history (issue 18): the same Hertz spring, a Mindlin tangential spring
// for a material of nu = 0.3 (G* = E* (1 - nu) / (2 (2 - nu))), the same restitution and friction.
inline Hertz<float> bench_hertz() { return Hertz<float>::from_restitution(0.75 * 2.3e6 / std::sqrt(0.5 * kRadius), 0.5, true); }
inline TangentialSpring<float> bench_mindlin() {
  return TangentialSpring<float>::mindlin(0.4, 0.75 * 2.3e6 / std::sqrt(0.5 * kRadius) * 0.7 / 3.4, 0.5);
}
template <>
inline ContactLaw<float, Hertz, TangentialSpring> make_law() {
  return {bench_hertz(), bench_mindlin()};
}
// ... and rolling resistance, the elastic-plastic spring (its state kept too).
template <>
inline ContactLaw<float, Hertz, TangentialSpring, RollingResistance> make_law() {
  return {bench_hertz(), bench_mindlin(), RollingResistance<float>::make(RollingModel::epsd, 0.1, 0.3)};
}

inline double g_skin_fraction = 0.2;  // neighbour-list skin / radius (--skin)

// How the cases evaluate their pairs (--pairs auto|both_sides|once; SimulationParams::pairs).
// auto, as `blaze run`: polyhedra once, spheres from both sides.
enum class BenchPairs { automatic, both_sides, once };
inline BenchPairs g_pairs = BenchPairs::automatic;
inline PairEvaluation pairs_for(bool polyhedra) {
  const bool once = g_pairs == BenchPairs::automatic ? polyhedra : g_pairs == BenchPairs::once;
  return once ? PairEvaluation::once : PairEvaluation::both_sides;
}

// The output file's suffix for options off their defaults.
inline std::string skin_tag() {
  std::string tag = g_pairs == BenchPairs::automatic ? "" : g_pairs == BenchPairs::once ? "-pairs-once" : "-pairs-both";
  if (g_skin_fraction == 0.2) return tag;
  char buf[32];
  std::snprintf(buf, sizeof buf, "-skin%g", g_skin_fraction);
  return buf + tag;
}

// Warm-up, then the timed stretch, then the fenced stretch for the phase split, then three
// rebuilds of the neighbour list timed alone (the broad phase per rebuild).
template <class Sim>
Row measure(Sim& sim, const char* shape, const char* law_name, const char* precision, const char* scene, int surfaces,
            long warmup, long steps) {
  sim.run(static_cast<std::uint64_t>(warmup));
  fence(DefaultSpace{});
  const auto builds0 = sim.neighbour_builds();
  const auto t0 = std::chrono::steady_clock::now();
  sim.run(static_cast<std::uint64_t>(steps));
  fence(DefaultSpace{});
  const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  Row row{shape, law_name, precision, scene, sim.size(), steps,
          static_cast<double>(sim.size()) * static_cast<double>(steps) / seconds,
          static_cast<double>(sim.memory_bytes()) / static_cast<double>(sim.size()), sim.neighbour_builds() - builds0,
          sim.neighbour_capacity(), 0, 0, 0, {}, surfaces, 0, ""};
  row.neighbours = sim.mean_neighbours();
  row.pairs = sim.params().pairs == PairEvaluation::once ? "once" : "both_sides";
  sim.timer().enabled = true;
  sim.timer().reset();
  const long phase_steps = std::max(10L, steps / 4);
  sim.run(static_cast<std::uint64_t>(phase_steps));
  const auto phase_seconds = [&](const char* ph) {
    return sim.timer().seconds(ph);
  };
  for (const char* ph : kPhases) row.phase_ms.push_back(1e3 * phase_seconds(ph) / phase_steps);
  if constexpr (Sim::features::statistics) {  // from the last step of the fenced stretch
    const auto [vertex_face, edge_edge] = sim.contact_counts();
    row.contacts = 2.0 * static_cast<double>(vertex_face + edge_edge) / static_cast<double>(sim.size());
    row.edge_fraction = vertex_face + edge_edge > 0 ? static_cast<double>(edge_edge) / static_cast<double>(vertex_face + edge_edge) : 0;
  }
  sim.timer().reset();
  for (int k = 0; k < 3; ++k) sim.rebuild_neighbours();
  for (const char* ph : {"hash", "sort", "reorder", "neighbours"}) row.rebuild_ms += 1e3 * phase_seconds(ph) / 3;
  sim.timer().enabled = false;
  return row;
}

// The features `blaze run` compiles (contact counts and the per-particle penetration monitor), so
// that the bench measures the program users run, not a leaner one.
using Stats = MonitoredFeatures;

template <class Law, class Features = Stats>
Row sphere_case(const char* law_name, long n, long warmup, long steps) {
  using Real = typename Law::real_type;
  const double m = kDensity * 4.0 / 3.0 * kPi * kRadius * kRadius * kRadius;
  const double dt = kPi * std::sqrt(0.5 * m / kStiffness) / 25;
  // Dense bed: fcc at 0.99 of contact spacing, radii +-0.5%: every neighbour pair overlaps by
  // 0-2% of a radius, held by six walls.
  auto scene = gravity_packing<Real>(static_cast<int>(n), kRadius, 42, dt, {Lattice::fcc, 1.98, 0.005, 0.01, true});
  scene.params.skin = static_cast<Real>(g_skin_fraction * kRadius);
  scene.params.pairs = pairs_for(false);
  PairTable<Law> laws;
  laws.set(0, 0, make_law<Law>());
  laws.set(0, 1, make_law<Law>());
  Simulation<DefaultSpace, SphereShape, Law, VelocityVerlet, ContactPointVelocity, Features> sim(scene.params, laws, scene.world,
                                                                                                  scene.particles);
  scene.particles = {};  // the largest runs need the host memory back
  return measure(sim, "sphere", law_name, sizeof(Real) == 4 ? "float" : "double", "dense-bed", 6, warmup, steps);
}

// A gravity-settled random polydisperse bed (issue 18: the lattice's rate must hold off the
// lattice): radii uniform in r (1 +- 0.2) (ratio 1.5), poured from a loose cubic lattice with
// random velocities into a box of five walls and settled with the history-free linear law for
// twice the top layer's fall time plus 0.05 s. Settling is the dear part, so a block of n / t^2
// spheres (t = 10 from 1e6, 2 from 4e3, else 1) is settled once and laid t x t times side by side
// in x and z inside one box (the seams, where two settled wall layers face each other, are looser
// than the bulk); the bed is built once and every law runs on it (settled_polydisperse_case).
template <class Real>
Packing<Real> settled_polydisperse_bed(long n) {
  using LinF = ContactLaw<Real, LinearSpringDashpot, HistoryFreeFriction>;
  using V = Vec3<double>;
  const int t = n >= 1000000 ? 10 : n >= 4000 ? 2 : 1;
  const long block = n / (t * t);
  const double spread = 0.2, r_min = kRadius * (1 - spread), m_min = kDensity * 4.0 / 3.0 * kPi * r_min * r_min * r_min;
  const double dt = kPi * std::sqrt(0.5 * m_min / kStiffness) / 25;
  auto scene = gravity_packing<Real>(static_cast<int>(block), kRadius, 7, dt, {Lattice::cubic, 2.5, spread, 0.1, false});
  scene.params.skin = static_cast<Real>(g_skin_fraction * kRadius * (1 + spread));
  PairTable<LinF> laws;
  laws.set(0, 0, make_law<LinF>());
  laws.set(0, 1, make_law<LinF>());
  double top = 0;
  for (const auto& x : scene.particles.position) top = std::max(top, static_cast<double>(x.y));
  const auto settle_steps = static_cast<std::uint64_t>((2 * std::sqrt(2 * top / 9.81) + 0.05) / dt);
  Simulation<DefaultSpace, SphereShape, LinF, VelocityVerlet> settle(scene.params, laws, scene.world, scene.particles);
  settle.run(settle_steps);
  const ParticleState<Real> settled = settle.state();
  // t x t copies, the block's inner width apart (polygon 2 is the block's +x side); one box around them all.
  const double half = static_cast<double>(scene.world.polygons[2].vertex[0].x), width = 2 * half;
  double height = 0;
  for (const auto& x : settled.position) height = std::max(height, static_cast<double>(x.y));
  Packing<Real> bed;
  bed.particles.reserve(settled.size() * static_cast<std::size_t>(t * t));
  for (int a = 0; a < t; ++a)
    for (int b = 0; b < t; ++b)
      for (std::size_t k = 0; k < settled.size(); ++k)
        bed.particles.add_sphere(settled.position[k] + vec_cast<Real>(V{a * width, 0, b * width}), settled.radius[k],
                                 Real(kDensity), 0, settled.velocity[k]);
  const double lo = -half, hi = -half + t * width, h = height + 4 * kRadius;
  bed.world.polygons = open_box<Real>(lo, hi, lo, hi, h);
  bed.params = scene.params;
  bed.params.domain_lo = vec_cast<Real>(V{lo - 4 * kRadius, -4 * kRadius, lo - 4 * kRadius});
  bed.params.domain_hi = vec_cast<Real>(V{hi + 4 * kRadius, h + 4 * kRadius, hi + 4 * kRadius});
  bed.params.pairs = pairs_for(false);
  std::printf("  settled polydisperse bed: %d x %d blocks of %ld, settled for %llu steps (%d left then)\n", t, t, block,
              static_cast<unsigned long long>(settle_steps), static_cast<int>(settle.removed_count()));
  return bed;
}

template <class Law>
Row settled_polydisperse_case(const char* law_name, const Packing<typename Law::real_type>& bed, long warmup, long steps) {
  using Real = typename Law::real_type;
  PairTable<Law> laws;
  laws.set(0, 0, make_law<Law>());
  laws.set(0, 1, make_law<Law>());
  Simulation<DefaultSpace, SphereShape, Law, VelocityVerlet, ContactPointVelocity, Stats> sim(bed.params, laws, bed.world,
                                                                                               bed.particles);
  Row row = measure(sim, "sphere", law_name, sizeof(Real) == 4 ? "float" : "double", "settled-poly", 5, warmup, steps);
  if (sim.removed_count() != 0) std::printf("WARNING: %d spheres left the settled bed\n", static_cast<int>(sim.removed_count()));
  return row;
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
  scene.params.pairs = pairs_for(false);
  Law law = make_law<Law>();
  if constexpr (std::is_same_v<decltype(law.tangential), HistoryFreeFriction<float>>) law.tangential.mu = 0;
  PairTable<Law> laws;
  laws.set(0, 0, law);
  Simulation<DefaultSpace, SphereShape, Law, VelocityVerlet, ContactPointVelocity, Features> sim(scene.params, laws, scene.world,
                                                                                                  scene.particles);
  return measure(sim, label, "linear", "float", "no-walls", 0, warmup, steps);
}

// The thesis's lab mill (section 4.2.1): a 90 cm x 15 cm steel drum (the inner cylinder plus two
// octagonal end plates covering its faces), 242 steel balls of r = 2.5 cm (30% filling), e =
// 0.825, mu = 0.15 (its calibrated combination 3), dt = 4.14e-5 s (its eq. 4.4 limit); k = 2e6 N/m
// puts dt at 0.06 of the critical step. The balls drop from a lattice, settle (or start tumbling)
// over the warm-up, then the bed is timed. turning: the mill of `make` studies (issue 19), its
// shell, end plates and eight 4 cm square lifters ([mill], mill_geometry.hpp) turning at 32 rpm
// (ramped over 0.2 s); otherwise the static drum of issue 6 (the thesis's 1.06e5 steps/s row).
// lifter_rows (turning only): the lifter-count sweep (--cases lifters, issue 19's world-kernel row):
// 0-64 rows of 4 cm x 2 cm bars (8 rows keep the 4 cm square bars), with the world lists as
// `blaze run` picks them (automatic) or off.
#ifdef BLAZE_FUSED_CLOCKS
// The one-block kernel's cycles per step, by phase index (phases.hpp, BLAZE_FUSED_CLOCKS): the
// phase (slowest warp and barrier), and each warp's work before the barrier.
inline void print_fused_clocks(const char* scene, const FusedClocks& c) {
  std::printf("fused clocks, %s: %llu steps begun in the one-block kernel; cycles per step: phase [warp 0..%d work]\n", scene,
              c.steps, kFusedClockWarps - 1);
  double total = 0;
  for (std::size_t k = 0; k < c.phase.size(); ++k) {
    if (c.phase[k][0] == 0) continue;
    const double d = c.steps ? static_cast<double>(c.steps) : 1.0;
    total += static_cast<double>(c.phase[k][0]) / d;
    std::printf("  phase %zu: %8.0f [", k, static_cast<double>(c.phase[k][0]) / d);
    for (std::size_t w = 1; w < c.phase[k].size(); ++w) std::printf(" %6.0f", static_cast<double>(c.phase[k][w]) / d);
    std::printf(" ]\n");
  }
  std::printf("  all phases: %.0f cycles per step\n", total);
}
#endif

inline Row mill_case(long warmup, long steps, bool turning = false, int lifter_rows = 8, WorldLists lists = WorldLists::automatic) {
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
  if (turning) {
    MillSpec m;
    m.centre = {0, 0, 0.5 * length}, m.axis = {0, 0, 1}, m.diameter = 2 * drum_r, m.length = length;
    m.omega = 32 * 2 * kPi / 60, m.ramp = 0.2;
    if (lifter_rows > 0) m.lifters.push_back({lifter_rows, 0.04, lifter_rows == 8 ? 0.04 : 0.02, 0, 22.5});
    world = World<float>{};
    world.cylinders.push_back(Cylinder<float>::make(V{0, 0, 0}, V{0, 0, 1}, drum_r, length, 1));
    for (const MillWall& w : mill_walls(m)) world.polygons.push_back(PlanarPolygon<float>::make(w.vertices, 1, w.rim_edges));
    for (int k = 0; k < world.object_count(); ++k) world.set_motion(k, mill_motion(m));
  }
  SimulationParams<float> params{float(dt), {0, -9.81f, 0}, {-0.5f, -0.5f, -0.05f}, {0.5f, 0.5f, 0.2f},
                                       float(g_skin_fraction * r), 0, pairs_for(false)};
  params.world_lists = lists;
  const Law law{LinearSpringDashpot<float>::from_restitution(2e6, 0.825), HistoryFreeFriction<float>::make(0.15, 100)};
  PairTable<Law> laws;
  laws.set(0, 0, law);
  laws.set(0, 1, law);
  Simulation<DefaultSpace, SphereShape, Law, VelocityVerlet, ContactPointVelocity, Stats> sim(params, laws, world, balls);
  std::string scene = turning ? "mill-turning" : "mill";
  if (turning && (lifter_rows != 8 || lists != WorldLists::automatic))
    scene = "mill-lifters" + std::to_string(lifter_rows) + (lists == WorldLists::off ? "-nolists" : "");
#ifdef BLAZE_FUSED_CLOCKS
  fused_clock_counts();  // from zero
#endif
  Row row = measure(sim, "mill-242", "linear", "float", scene.c_str(), world.object_count(), warmup, steps);
#ifdef BLAZE_FUSED_CLOCKS
  print_fused_clocks(scene.c_str(), fused_clock_counts());
#endif
  if (sim.removed_count() != 0) std::printf("WARNING: %d balls left the mill\n", static_cast<int>(sim.removed_count()));
  return row;
}

// The floor (the world's first polygon, a quadrilateral) split into tiles x tiles quadrilaterals
// with its orientation: more world surfaces, the same contacts (thesis Fig 3.21).
template <class Real>
void tile_floor(World<Real>& world, int tiles) {
  using V = Vec3<double>;
  const PlanarPolygon<Real> floor = world.polygons.front();
  V c[4];
  for (int k = 0; k < 4; ++k) c[k] = vec_cast<double>(floor.vertex[k]);
  const auto at = [&](double s, double t) { return c[0] + s * (c[1] - c[0]) + t * (c[3] - c[0]); };
  world.polygons.erase(world.polygons.begin());
  for (int i = 0; i < tiles; ++i)
    for (int j = 0; j < tiles; ++j) {
      const double s0 = double(i) / tiles, s1 = double(i + 1) / tiles, t0 = double(j) / tiles, t1 = double(j + 1) / tiles;
      world.polygons.push_back(PlanarPolygon<Real>::make({at(s0, t0), at(s1, t0), at(s1, t1), at(s0, t1)}, floor.material));
    }
}

// The dense bed's box (sphere_case) with its six walls as one triangle mesh of about `triangles`
// triangles (each quadrilateral wall an n x n grid of cell pairs, welded along the box's edges),
// or as the six polygons (triangles = 0): the world phase's cost against the mesh's size
// (issue 20: a 1e5-triangle mesh within 1.5x the polygons' world phase).
inline Row mesh_box_case(long n, long triangles, long warmup, long steps) {
  using Law = ContactLaw<float, LinearSpringDashpot, HistoryFreeFriction>;
  const double m = kDensity * 4.0 / 3.0 * kPi * kRadius * kRadius * kRadius;
  const double dt = kPi * std::sqrt(0.5 * m / kStiffness) / 25;
  auto scene = gravity_packing<float>(static_cast<int>(n), kRadius, 42, dt, {Lattice::fcc, 1.98, 0.005, 0.01, true});
  scene.params.skin = static_cast<float>(g_skin_fraction * kRadius);
  scene.params.pairs = pairs_for(false);
  int surfaces = scene.world.object_count();
  if (triangles > 0) {
    const int walls = static_cast<int>(scene.world.polygons.size());
    const int grid = std::max(1, static_cast<int>(std::lround(std::sqrt(static_cast<double>(triangles) / (2.0 * walls)))));
    TriangleMesh box;
    for (const auto& w : scene.world.polygons) {
      if (w.vertex_count != 4) throw std::logic_error("mesh box: the bed's walls are quadrilaterals");
      Vec3<double> c[4];
      for (int k = 0; k < 4; ++k) c[k] = vec_cast<double>(w.vertex[k]);
      const int base = static_cast<int>(box.vertices.size());
      for (int j = 0; j <= grid; ++j)
        for (int i = 0; i <= grid; ++i) {
          const double s = double(i) / grid, t = double(j) / grid;
          box.vertices.push_back(c[0] + s * (c[1] - c[0]) + t * (c[3] - c[0]) + s * t * (c[2] - c[1] - c[3] + c[0]));
        }
      for (int j = 0; j < grid; ++j)
        for (int i = 0; i < grid; ++i) {
          const int p = base + j * (grid + 1) + i;
          box.triangles.push_back({p, p + 1, p + grid + 2});
          box.triangles.push_back({p, p + grid + 2, p + grid + 1});
        }
    }
    MeshReport report;
    weld(box, report);
    report = repair(box, "bench box", report);
    World<float> world;
    world.meshes.push_back({"box", box, scene.world.polygons.front().material});
    scene.world = world;
    surfaces = static_cast<int>(box.size());
  }
  PairTable<Law> laws;
  laws.set(0, 0, make_law<Law>());
  laws.set(0, 1, make_law<Law>());
  Simulation<DefaultSpace, SphereShape, Law, VelocityVerlet, ContactPointVelocity, Stats> sim(scene.params, laws, scene.world,
                                                                                               scene.particles);
  const std::string name = triangles > 0 ? "dense-bed-mesh" : "dense-bed-walls";
  Row row = measure(sim, "sphere", "linear", "float", name.c_str(), surfaces, warmup, steps);
  if (sim.removed_count() != 0) std::printf("WARNING: %d spheres left the box\n", static_cast<int>(sim.removed_count()));
  return row;
}

// The floor (the world's first polygon, a quadrilateral) replaced by a mesh of about `triangles`
// triangles (an n x n grid of cell pairs) with its orientation (issue 20: polyhedra on a mesh).
template <class Real>
void mesh_floor(World<Real>& world, long triangles) {
  const PlanarPolygon<Real> floor = world.polygons.front();
  Vec3<double> c[4];
  for (int k = 0; k < 4; ++k) c[k] = vec_cast<double>(floor.vertex[k]);
  const int grid = std::max(1, static_cast<int>(std::lround(std::sqrt(0.5 * static_cast<double>(triangles)))));
  TriangleMesh m;
  for (int j = 0; j <= grid; ++j)
    for (int i = 0; i <= grid; ++i) {
      const double s = double(i) / grid, t = double(j) / grid;
      m.vertices.push_back(c[0] + s * (c[1] - c[0]) + t * (c[3] - c[0]) + s * t * (c[2] - c[1] - c[3] + c[0]));
    }
  for (int j = 0; j < grid; ++j)
    for (int i = 0; i < grid; ++i) {
      const int p = j * (grid + 1) + i;
      m.triangles.push_back({p, p + 1, p + grid + 2});
      m.triangles.push_back({p, p + grid + 2, p + grid + 1});
    }
  world.polygons.erase(world.polygons.begin());
  world.meshes.push_back({"floor", m, floor.material});
}

enum class PolyScene { free_fall, packed };

// Polyhedra of one shape (about 1 cm), linear law (k = 1e5 N/m, e = 0.5), float, dt = t_c/25.
// free_fall: random orientations falling from a loose lattice in a box (thesis section 3.4.1's
// benchmark); packed: packed_polyhedra, every body pressed on its six axial neighbours.
// floor_tiles > 1: the floor as floor_tiles^2 polygons (world-surface scaling).
// fit_memory: pairs from both sides whatever --pairs says (the largest runs: pair slots would
// take ~1 KB per cube).
inline Row polyhedron_case(const char* shape_name, PolyScene kind, long n, long warmup, long steps, int floor_tiles = 1,
                           bool fit_memory = false, long floor_triangles = 0) {
  using Law = ContactLaw<float, LinearSpringDashpot, HistoryFreeFriction>;
  PolyhedronShape<float> shape;
  const ConvexShape convex = load_shape(std::string("data/shapes/") + shape_name + ".shape");
  shape.table.add(convex, kDensity);
  const double k = 1e5, dt = kPi * std::sqrt(0.5 * shape.table.type[0].mass / k) / 25;
  auto scene = kind == PolyScene::packed ? packed_polyhedra(shape.table, 0, static_cast<int>(n), 42, dt, drawn_orientation(convex))
                                         : polyhedron_packing(shape.table, 0, static_cast<int>(n), 42, dt);
  if (floor_tiles > 1) tile_floor(scene.world, floor_tiles);
  if (floor_triangles > 0) mesh_floor(scene.world, floor_triangles);
  scene.params.skin = static_cast<float>(g_skin_fraction * shape.table.type[0].bounding_radius);
  scene.params.pairs = fit_memory ? PairEvaluation::both_sides : pairs_for(true);
  const Law law{LinearSpringDashpot<float>::from_restitution(k, 0.5), HistoryFreeFriction<float>::make(0.4, 0.05)};
  PairTable<Law> laws;
  laws.set(0, 0, law);
  laws.set(0, 1, law);
  const int surfaces = static_cast<int>(scene.world.polygons.size() + scene.world.cylinders.size() + scene.world.triangle_count());
  Simulation<DefaultSpace, PolyhedronShape<float>, Law, VelocityVerlet, ContactPointVelocity, Stats> sim(
      scene.params, laws, scene.world, std::move(scene.particles), shape);
  const std::string scene_name = std::string(kind == PolyScene::packed ? "packed" : "free-fall") + (floor_triangles > 0 ? "-mesh-floor" : "");
  Row row = measure(sim, shape_name, "linear", "float", scene_name.c_str(), surfaces, warmup, steps);
  if (sim.removed_count() != 0) std::printf("WARNING: %d bodies left the box\n", static_cast<int>(sim.removed_count()));
  return row;
}

}  // namespace blaze::bench
