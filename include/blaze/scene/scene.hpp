// A scene: everything a run needs, in SI units, as read from a scene file (scene_file.hpp, TOML).
// Plain host data in double; scene_build.hpp turns it into particles, world and contact laws for a
// Simulation of any precision and backend. Every value here has passed validation: positive
// radii and densities, restitution in (0, 1], Poisson ratio in (-1, 0.5), dt > 0, known names.
#pragma once
#include <array>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <map>
#include <stdexcept>
#include <string>
#include <vector>
#include "blaze/core/vec3.hpp"
#include "blaze/scene/insertion_region.hpp"
#include "blaze/scene/mill_geometry.hpp"
#include "blaze/scene/size_distribution.hpp"
#include "blaze/world/motion.hpp"
#include "blaze/world/triangle_mesh.hpp"

namespace blaze {

// A rejected scene: the message names the file, line, key, the value given and what is allowed.
struct SceneError : std::runtime_error {
  using std::runtime_error::runtime_error;
};

enum class LawKind { linear, hertz };
// The tangential law: history-free friction (thesis eq. 2.3), or a tangential spring, the
// contact's history (Mindlin with Hertz, Cundall-Strack with the linear law).
enum class TangentialKind { history_free, mindlin, linear_spring };
// Rolling resistance of spheres (rolling_resistance.hpp): none, constant torque (Ai et al. model A),
// elastic-plastic spring-dashpot (model C). Needs a tangential spring.
enum class RollingKind { none, cdt, epsd };
enum class PrecisionKind { float32, float64 };
enum class BackendKind { automatic, cpu, gpu };
// Particle-particle pairs evaluated from both sides or once (SimulationParams::pairs).
enum class PairsKind { automatic, both_sides, once };
// World lists (pipeline/world_candidates.hpp): automatic (from 8 world objects), on, off.
enum class WorldListsKind { automatic, on, off };

inline const char* to_string(LawKind k) { return k == LawKind::linear ? "linear" : "hertz"; }
inline const char* to_string(RollingKind k) { return k == RollingKind::none ? "none" : k == RollingKind::cdt ? "cdt" : "epsd"; }
inline const char* to_string(TangentialKind k) {
  return k == TangentialKind::history_free ? "history_free" : k == TangentialKind::mindlin ? "mindlin" : "linear_spring";
}
inline const char* to_string(PrecisionKind p) { return p == PrecisionKind::float32 ? "float" : "double"; }
inline const char* to_string(BackendKind b) {
  return b == BackendKind::automatic ? "auto" : b == BackendKind::cpu ? "cpu" : "gpu";
}

struct MaterialSpec {
  std::string name;
  double density = 0;         // kg/m^3
  double youngs_modulus = 0;  // Pa (Hertz law; 0 when not given)
  double poisson_ratio = 0;   // - (Hertz law)
};

// Contact parameters of one material pair (order does not matter).
struct PairSpec {
  int a = 0, b = 0;               // indices into Scene::materials
  double stiffness = 0;           // linear: k (N/m); 0 when contact_time is given
  double contact_time = 0;        // linear: s, undamped, for the lightest pair of these materials
  double restitution = 1;         // -, (0, 1]
  double friction = 0;            // -, Coulomb mu >= 0
  double tangential_damping = 0;  // kg/s, K_T of eq. 2.3 (history-free law)
  // -, K_T grows by rate m*/dt (history_free_friction.hpp; the thesis's eq. 4.3): min(mu, 0.5) when
  // a history-free pair has friction but no tangential_damping, 0 otherwise
  double tangential_rate = 0;
  double tangential_stiffness = 0;  // N/m, linear_spring k_t (0: 2/7 of the normal stiffness)
  double rolling_friction = 0;      // -, mu_r (rolling resistance)
  double rolling_damping = 0.3;     // -, eta_r (epsd)
  bool no_tension = false;        // clamp the normal force at 0 (no attraction near separation)
};

// A particle type: a sphere of `radius` or a convex polyhedron from `shape` scaled to
// `bounding_radius`.
struct ParticleTypeSpec {
  std::string name;
  int material = 0;
  double radius = 0;           // m, spheres
  std::string shape;           // path of a .shape/.obj file, polyhedra
  double bounding_radius = 0;  // m, polyhedra
  double volume = 0;           // m^3, filled in by the parser (polyhedra: of the scaled shape)
  // A feed's smallest or largest particle (a size distribution's extreme), added by the parser after
  // the scene's own types so that the critical step, the impact overlap, the grid and the overlap
  // checks see it; no particle is of this type (a fed particle is its feed's type, scaled).
  bool derived = false;
  bool is_sphere() const { return shape.empty(); }
  double size() const { return is_sphere() ? radius : bounding_radius; }
};

// Placements (thesis section 2.5: lattice blocks; plus explicit lists and random fills).
struct LatticeSpec {
  int type = 0;
  Vec3<double> origin{0, 0, 0};            // m, centre of the first site
  std::array<long, 3> count{};    // sites along x, y, z
  double spacing = 0;             // m, >= 2 bounding radii
  Vec3<double> velocity{0, 0, 0};          // m/s
  double jitter = 0;              // fraction of the free gap, random offset per site
  bool random_orientation = true;  // polyhedra
};
struct ListSpec {
  int type = 0;
  std::vector<Vec3<double>> position;  // m
  std::vector<Vec3<double>> velocity;  // m/s, empty or one per position
};
struct FillSpec {
  int type = 0;
  Vec3<double> lo{0, 0, 0}, hi{0, 0, 0};  // m, box the particles (whole) lie in
  long count = 0;
  Vec3<double> velocity{0, 0, 0};  // m/s
};

// A feeder ([[feed]], pipeline/feeder.hpp): particles of one type placed at random in `region`
// where they overlap nothing, from start to end at `rate` particles/s or `mass_rate` kg/s (the
// due count or mass, rate x (t - start), is met at every insertion `interval`, what could not be
// placed staying due and reported), with `velocity` plus a uniform random spread of +- `spread`
// per component, random orientations for polyhedra, sizes from `size` (radii of spheres, bounding
// radii of polyhedra: the type's shape scaled to each; PolyhedronShape::Body). Without `size`, the
// type's own.
struct FeedSpec {
  std::string name;               // "[[feed]] #k" unless named
  int type = 0;
  InsertionRegion region;
  double start = 0, end = 0;      // s; end: the feed's end_time, or the run's without one
  double end_given = 0;           // s, the end_time the scene gave (infinity: none, the feed lasts the run)
  double rate = 0;                // particles/s (0: mass_rate)
  double mass_rate = 0;           // kg/s (0: rate)
  long count = 0;                 // the most particles it inserts (0: no limit)
  Vec3<double> velocity{0, 0, 0};          // m/s
  double spread = 0;              // m/s
  bool random_orientation = true;
  double interval = 0;            // s between insertions
  SizeDistribution size;          // m
  std::uint64_t seed = 0;         // its own random stream (the scene's seed + its index unless given)
};

struct WallSpec {  // convex planar polygon; the normal follows the right-hand rule of the vertex order
  std::string name;  // optional; a study may address a wall by it (the hopper's "gate")
  int material = 0;
  std::vector<Vec3<double>> vertices;  // m
  std::uint32_t rim_edges = 0xffffffffu;  // bit k: edge k -> k+1 has rim contact
  Motion motion;  // [wall.motion] and remove_time (blaze/world/motion.hpp); none by default
  ContactClass contact_class = ContactClass::wall;  // its dissipation's account (energy_ledger.hpp)
};
struct CylinderSpec {  // drum: particles inside, contact on the inner surface
  std::string name;  // "mill shell" for a [mill]'s; empty otherwise
  int material = 0;
  Vec3<double> origin{0, 0, 0}, axis{0, 0, 0};  // m, centre of the first end; direction (any length)
  double radius = 0, length = 0;
  Motion motion;
  ContactClass contact_class = ContactClass::wall;
  // Points on the rims of its two ends (the farthest from any axis through it), for peak_speed.
  std::vector<Vec3<double>> rim() const {
    const Vec3<double> u = axis * (1 / norm(axis));
    Vec3<double> side = std::fabs(u.x) < 0.9 ? cross(u, Vec3<double>{1, 0, 0}) : cross(u, Vec3<double>{0, 1, 0});
    side = side * (radius / norm(side));
    const Vec3<double> side2 = cross(u, side);
    std::vector<Vec3<double>> out;
    for (const Vec3<double> end : {origin, origin + u * length})
      for (const Vec3<double> d : {side, side * -1.0, side2, side2 * -1.0}) out.push_back(end + d);
    return out;
  }
};

// A triangle-mesh wall from an STL or OBJ file (blaze/io/mesh_io.hpp): read, welded, repaired
// (blaze/world/triangle_mesh.hpp), then placed: x = R (scale x_file) + translate, R the rotation
// by `degrees` about `axis`. Its triangles act on the side their normals point to (flip = true
// turns them all), edges and vertices from any side (blaze/world/mesh_surface.hpp).
struct MeshSpec {
  std::string name;             // optional; defaults to the file's name
  std::string file;             // as written in the scene
  std::string path;             // where it was read from
  int material = 0;
  double scale = 1;             // m per file unit
  Vec3<double> axis{0, 0, 1};   // unit (rotate)
  double degrees = 0;           // rotate
  Vec3<double> translate{0, 0, 0};       // m
  bool flip = false;
  Motion motion;
  ContactClass contact_class = ContactClass::wall;
  TriangleMesh mesh;            // m, placed
  std::string report;           // what the repair found (empty: nothing)
};

struct OutputSpec {
  std::string directory;          // created if missing
  double csv_interval = 0;        // s between CSV rows (0: none)
  double vtu_interval = 0;        // s between VTU frames (0: none)
  double checkpoint_interval = 0; // s between checkpoints (0: none)
  double penetration_warning = 0.05;  // overlap / radius reported above this (thesis: 5%)
  // A sampled energy above the initial one by this share of the energy scale stops the run
  // (run_log.hpp). The default, 5%, sits above velocity Verlet's energy wobble during contacts at
  // the largest accepted step (omega dt <= 0.4: (omega dt)^2 / 4 = 4% of the colliding particles'
  // energy); an unstable step grows geometrically and crosses any such limit within a few steps.
  double energy_gain_limit = 0.05;
  // Keep the energy dissipated by contact class (pairs, each class of wall) in timeseries.csv even
  // when nothing moves (blaze/particles/energy_ledger.hpp); a world that moves keeps it anyway.
  bool energy_by_class = false;
};

// A value of the scene's [study] table: numbers a study driver reads by name (study_value).
struct StudyValue {
  std::string key, where;  // where: "file:line" or "command line (--set)"
  double value = 0;
  mutable bool used = false;
};

struct Scene {
  std::string path;  // the scene file
  LawKind law = LawKind::linear;
  TangentialKind tangential = TangentialKind::history_free;
  RollingKind rolling = RollingKind::none;
  PrecisionKind precision = PrecisionKind::float64;
  BackendKind backend = BackendKind::automatic;
  double dt = 0;                 // s (given, or t_c / steps_per_contact)
  double steps_per_contact = 0;  // when dt is derived from the contact time
  double end_time = 0;           // s
  Vec3<double> gravity{0, 0, 0};          // m/s^2
  double drag = 0;               // kg/m
  Vec3<double> domain_lo{0, 0, 0}, domain_hi{0, 0, 0};  // m
  double skin = 0.2;             // neighbour-list skin / largest bounding radius
  unsigned periodic = 0;         // periodic axes, bit 0: x, 1: y, 2: z (grid/periodic_images.hpp)
  PairsKind pair_evaluation = PairsKind::automatic;  // auto: once for polyhedra, both sides for spheres
  WorldListsKind world_lists = WorldListsKind::automatic;
  bool force_dt = false;         // run even when dt exceeds the safe fraction of the critical step
  bool force_long_run = false;   // run even when the estimated wall time exceeds kMaxWallTime (run_check.hpp)
  double max_impact_speed = 0;   // m/s, Hertz stiffness estimate (0: from the scene)
  std::uint64_t seed = 1;
  double dt_critical = 0;        // s, filled in by the parser (critical_step.hpp)
  std::string dt_governing;      // which contact or estimate sets dt_critical
  double impact_overlap = 0;     // deepest elastic impact overlap / radius at impact_speed (parser)
  double impact_speed = 0;       // m/s, max_impact_speed or its default (parser)
  std::string overlap_governing; // which pairing sets impact_overlap
  OutputSpec output;
  std::vector<MaterialSpec> materials;
  std::vector<PairSpec> pairs;
  std::vector<ParticleTypeSpec> types;
  std::vector<LatticeSpec> lattices;
  std::vector<ListSpec> lists;
  std::vector<FillSpec> fills;
  std::vector<WallSpec> walls;
  std::vector<CylinderSpec> cylinders;
  std::vector<MeshSpec> meshes;
  std::vector<FeedSpec> feeds;
  MillSpec mill;  // [mill]: its shell, end plates and lifters are in cylinders and walls (named "mill ...")
  std::vector<StudyValue> study;
  // "file:line" of the keys that derived sizes and run checks blame, by their --set name
  // ("simulation.dt", "lattice[0].count", "output.csv_interval"); the command line for --set values.
  std::map<std::string, std::string> where;
  std::vector<std::string> notes;  // what validation found worth saying but not refusing; programs print them

  // "file:line: [table]: key 'name'" for a key of `where` (the file alone when it was not recorded).
  std::string place(const std::string& key) const {
    const auto it = where.find(key);
    const std::string at = it != where.end() ? it->second : path;
    const auto dot = key.find('.'), bracket = key.find('[');
    if (dot == std::string::npos) return at + ": key '" + key + "'";
    const std::string table = key.substr(0, std::min(dot, bracket));
    const std::string label = bracket < dot ? "[[" + table + "]] #" + std::to_string(std::stoi(key.substr(bracket + 1)) + 1)
                                            : "[" + table + "]";
    return at + ": " + label + ": key '" + key.substr(dot + 1) + "'";
  }

  // A [study] value in [lo, hi] (unit for messages); missing or out of range: a SceneError
  // naming the file, line, key, value and the allowed range.
  double study_value(const std::string& key, double lo, double hi, const std::string& unit) const {
    const std::string allowed = "in [" + shortest(lo) + ", " + shortest(hi) + "] " + unit;
    for (const auto& v : study)
      if (v.key == key) {
        if (!(v.value >= lo && v.value <= hi))
          throw SceneError(v.where + ": [study]: key '" + key + "' = " + shortest(v.value) + ": must be " + allowed);
        v.used = true;
        return v.value;
      }
    throw SceneError(path + ": [study]: missing key '" + key + "' (a number " + allowed + ")");
  }
  // The same for an optional key: `fallback` when the table does not have it.
  double study_value_or(const std::string& key, double lo, double hi, const std::string& unit, double fallback) const {
    for (const auto& v : study)
      if (v.key == key) return study_value(key, lo, hi, unit);
    return fallback;
  }
  // After a study has read its values: any other [study] key is a typo, an error.
  void check_study_used() const {
    for (const auto& v : study)
      if (!v.used) throw SceneError(v.where + ": [study]: unknown key '" + v.key + "' (this study does not read it)");
  }

  // The fastest any moving wall, cylinder or mesh moves (m/s; motion.hpp's peak_speed).
  double fastest_wall() const {
    double v = 0;
    for (const auto& w : walls) v = std::fmax(v, peak_speed(w.motion, w.vertices));
    for (const auto& c : cylinders) v = std::fmax(v, peak_speed(c.motion, c.rim()));
    for (const auto& m : meshes) v = std::fmax(v, peak_speed(m.motion, m.mesh.vertices));
    return v;
  }

  bool all_spheres() const {
    for (const auto& t : types)
      if (!t.is_sphere()) return false;
    return true;
  }
  static std::string shortest(double v) {
    char buf[32];
    std::snprintf(buf, sizeof buf, "%.9g", v);
    return buf;
  }
  const PairSpec* pair(int a, int b) const {
    for (const auto& p : pairs)
      if ((p.a == a && p.b == b) || (p.a == b && p.b == a)) return &p;
    return nullptr;
  }
};

}  // namespace blaze
