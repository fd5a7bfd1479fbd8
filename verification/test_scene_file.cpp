// Scene files (issue 5): every rejection names the file, the line, the key, the value given and
// what is allowed; command-line overrides are validated the same way; the critical time step
// matches its closed forms; placements give the particles they promise; a seeded mutation fuzz
// of the parser never crashes and every rejection is a SceneError.
#include <boost/test/unit_test.hpp>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <random>
#include <sstream>
#include "blaze/shapes/sphere_shape.hpp"
#include "blaze/scene/scene_build.hpp"
#include "blaze/scene/scene_file.hpp"
#include "blaze/scene/critical_step.hpp"
#include "blaze/scene/scene_identity.hpp"
#include "pipeline/scene_law.hpp"
#include "pipeline/simulation.hpp"
#include "studies/hopper/hopper_run.hpp"
#include "studies/mill/mill_run.hpp"
#include "verification/tolerances.hpp"

using namespace blaze;

namespace {

constexpr double kPi = 3.14159265358979323846;

// A small valid scene; the cases below change one line of it.
const std::string kBase = R"(# test scene
[simulation]
law = "linear"
precision = "double"
dt = 1e-5
end_time = 0.01
gravity = [0, -9.81, 0]
domain_lo = [-0.1, -0.1, -0.1]
domain_hi = [0.1, 0.1, 0.1]

[output]
directory = "/tmp/blaze_scene_test"
csv_interval = 0.001

[[material]]
name = "glass"
density = 2500
[[material]]
name = "steel"
density = 7800

[[pair]]
materials = ["glass", "glass"]
stiffness = 2e4
restitution = 0.5
friction = 0.3
[[pair]]
materials = ["glass", "steel"]
stiffness = 4e4
restitution = 0.6

[[particle_type]]
name = "bead"
material = "glass"
radius = 2e-3

[[lattice]]
type = "bead"
origin = [-0.05, -0.05, -0.05]
count = [3, 2, 2]
spacing = 0.005

[[fill]]
type = "bead"
lo = [-0.05, 0.0, -0.05]
hi = [0.05, 0.05, 0.05]
count = 40

[[particles]]
type = "bead"
positions = [[0.0, 0.08, 0.0]]
velocities = [[0.0, -1.0, 0.0]]

[[wall]]
material = "steel"
vertices = [[-0.09, -0.09, -0.09], [-0.09, -0.09, 0.09], [0.09, -0.09, 0.09], [0.09, -0.09, -0.09]]
)";

// kBase with the first line that starts with `needle` replaced by `with` (empty: removed).
std::string edit(const std::string& needle, const std::string& with, std::string base = kBase) {
  const auto at = base.find("\n" + needle);
  BOOST_TEST_REQUIRE(at != std::string::npos, "needle not in the base scene: " << needle);
  const auto end = base.find('\n', at + 1);
  base.replace(at + 1, end - at - 1, with);
  return base;
}
int line_of(const std::string& text, const std::string& needle) {
  const auto at = text.find("\n" + needle);
  return 2 + static_cast<int>(std::count(text.begin(), text.begin() + static_cast<long>(at), '\n'));
}

template <class F>
std::string rejection(F f) {
  try {
    f();
  } catch (const SceneError& e) {
    return e.what();
  }
  return "(accepted)";
}
bool has(const std::string& s, const std::string& part) { return s.find(part) != std::string::npos; }

// One bad value: the line it is on, and what the message must name.
struct BadValue {
  const char* needle;      // the line of kBase to replace
  const char* with;        // the replacement
  const char* key_value;   // "key 'k' = v" as the message shows it
  const char* allowed;     // what is allowed, as the message says it
};

const BadValue kBadValues[] = {
    {"radius =", "radius = -2e-3", "key 'radius' = -0.002", "must be in (0, 1000] m"},
    {"radius =", "radius = \"big\"", "key 'radius' = \"big\"", "a number in (0, 1000] m"},
    {"restitution = 0.5", "restitution = 0", "key 'restitution' = 0", "(0, 1]"},
    {"restitution = 0.5", "restitution = 1.2", "key 'restitution' = 1.2", "(0, 1]"},
    {"dt =", "dt = 0", "key 'dt' = 0", "must be in (0, 1000] s"},
    {"dt =", "dt = -1e-5", "key 'dt' = -1e-05", "must be in (0, 1000] s"},
    {"dt =", "dt = nan", "key 'dt' = nan", "must be in (0, 1000] s"},
    {"density = 2500", "density = -2500", "key 'density' = -2500", "must be in (0, 1e+09] kg/m^3"},
    {"density = 2500", "densty = 2500", "unknown key 'densty'", "allowed: name, density, youngs_modulus"},
    {"law =", "law = \"hooke\"", "key 'law' = \"hooke\"", "one of \"linear\" \"hertz\""},
    {"law =", "pair_evaluation = \"half\"\nlaw = \"linear\"", "key 'pair_evaluation' = \"half\"",
     "one of \"auto\" \"both_sides\" \"once\""},
    {"law =", "world_lists = \"always\"\nlaw = \"linear\"", "key 'world_lists' = \"always\"", "one of \"auto\" \"on\" \"off\""},
    {"friction =", "friction = -0.1", "key 'friction' = -0.1", "in [0, 100]"},
    {"material = \"glass\"", "material = \"glas\"", "key 'material' = \"glas\"", "the name of a [[material]]: \"glass\" \"steel\""},
    {"count = [3, 2, 2]", "count = [3, 2.5, 2]", "key 'count' = [3, 2.5, 2]", "[nx, ny, nz], integers >= 1"},
    {"spacing =", "spacing = 0.003", "key 'spacing' = 0.003", "at least 2 bounding radii"},
    {"origin =", "origin = [-0.2, 0, 0]", "key 'origin' = [-0.2, 0, 0]", "must lie inside the domain"},
    {"count = 40", "count = 6000", "key 'count' = 6000", "random placement jams"},
    {"gravity =", "gravity = [0, -9.81]", "key 'gravity' = [0, -9.81]", "[x, y, z]"},
    {"end_time =", "end_time = 1e400", "", "TOML syntax error"},
    {"vertices =", "vertices = [[-0.09, -0.09, -0.09], [-0.09, -0.09, 0.09], [0.09, -0.05, 0.09], [0.09, -0.09, -0.09]]",
     "key 'vertices'", "off the plane"},
    {"dt =", "dt = 1e-3", "key 'dt' = 0.001", "of the critical step"},
};

// A Hertz scene: materials need an elastic modulus and a Poisson ratio.
std::string hertz_scene() {
  std::string s = edit("law =", "law = \"hertz\"");
  s = edit("density = 2500", "density = 2500\nyoungs_modulus = 6.3e10\npoisson_ratio = 0.23", s);
  s = edit("density = 7800", "density = 7800\nyoungs_modulus = 2.1e11\npoisson_ratio = 0.3", s);
  s = edit("stiffness = 2e4", "", s);
  s = edit("stiffness = 4e4", "", s);
  return edit("dt =", "dt = 1e-7", s);
}

}  // namespace

BOOST_AUTO_TEST_SUITE(scene_file)

BOOST_AUTO_TEST_CASE(base_scene_is_accepted_as_written) {
  const Scene s = parse_scene(kBase, "scene.toml");
  BOOST_TEST(s.dt == 1e-5);
  BOOST_TEST(s.materials.size() == 2u);
  BOOST_TEST(s.pairs.size() == 2u);
  BOOST_TEST(s.pair(1, 0)->stiffness == 4e4);
  BOOST_TEST(s.types[0].radius == 2e-3);
  BOOST_TEST(s.lattices[0].count[0] == 3);
  BOOST_TEST(s.fills[0].count == 40);
  BOOST_TEST(s.walls[0].vertices.size() == 4u);
  BOOST_TEST(s.gravity.y == -9.81);
}

// Every bad value is named with file:line, key, value and what is allowed.
BOOST_AUTO_TEST_CASE(bad_values_name_file_line_key_value_and_allowed) {
  for (const BadValue& c : kBadValues) {
    const std::string text = edit(c.needle, c.with);
    const std::string msg = rejection([&] { parse_scene(text, "scene.toml"); });
    BOOST_TEST_CONTEXT("replacing '" << c.needle << "' by '" << c.with << "': " << msg) {
      BOOST_TEST(has(msg, "scene.toml:" + std::to_string(line_of(text, c.with))));
      BOOST_TEST(has(msg, c.key_value));
      BOOST_TEST(has(msg, c.allowed));
    }
  }
}

// A study's [study] numbers: read by name within a range, rejected by file:line when out of it
// or when the study does not read them; a wall's name and its rim edges as a list.
BOOST_AUTO_TEST_CASE(study_values_wall_names_and_rim_edges) {
  const std::string text = kBase + "[study]\ngate_open_time = 0.5\nsettle = 2\n";
  const Scene s = parse_scene(text, "scene.toml");
  BOOST_TEST(s.study_value("gate_open_time", 0, 1, "s") == 0.5);
  const std::string unread = rejection([&] { s.check_study_used(); });
  BOOST_TEST(has(unread, "scene.toml:" + std::to_string(line_of(text, "settle = 2")) + ": [study]: unknown key 'settle'"), unread);
  const std::string range = rejection([&] { s.study_value("settle", 0, 1, "s"); });
  BOOST_TEST(has(range, "[study]: key 'settle' = 2: must be in [0, 1] s"), range);
  BOOST_TEST(has(rejection([&] { s.study_value("missing", 0, 1, "s"); }), "[study]: missing key 'missing'"));
  // an optional key: its fallback when absent, the same range check when present
  BOOST_TEST(s.study_value_or("missing", 0, 1, "s", 0.75) == 0.75);
  const std::string optional = rejection([&] { s.study_value_or("settle", 0, 1, "(0 or 1)", 0); });
  BOOST_TEST(has(optional, "scene.toml:" + std::to_string(line_of(text, "settle = 2")) + ": [study]: key 'settle' = 2: must be in [0, 1]"),
             optional);
  const Scene o = parse_scene(text, "scene.toml", {"gate_open_time=0.25"});  // a bare key found in [study]
  BOOST_TEST(o.study_value("gate_open_time", 0, 1, "s") == 0.25);
  BOOST_TEST(has(rejection([&] { parse_scene(kBase + "[study]\nx = \"a\"\n", "scene.toml"); }), "[study]: key 'x' = \"a\": a number"));

  const Scene w = parse_scene(edit("material = \"steel\"", "material = \"steel\"\nrim = [0, 2]\nname = \"gate\""), "scene.toml");
  BOOST_TEST(w.walls[0].rim_edges == 5u);
  BOOST_TEST(w.walls[0].name == "gate");
  const std::string bad = rejection([&] { parse_scene(edit("material = \"steel\"", "material = \"steel\"\nrim = [4]"), "scene.toml"); });
  BOOST_TEST(has(bad, "key 'rim' = [4]: true (contact on every edge), false (faces only) or a list of edge indices 0..3"), bad);
  BOOST_TEST(has(rejection([&] { parse_scene(edit("csv_interval = 0.001", "energy_gain_limit = 0"), "scene.toml"); }),
                 "key 'energy_gain_limit' = 0: must be in (0, 1]"));
}

// A wall's motion table and removal time (issue 19): accepted as written, built into the world's
// motions; every bad value named with file:line, key, value and what that kind of motion takes.
BOOST_AUTO_TEST_CASE(wall_motions_are_read_and_bad_ones_named) {
  const auto with_motion = [](const std::string& line) { return kBase + line + "\n"; };
  const Scene r = parse_scene(with_motion("motion = { kind = \"rotation\", axis = [0, 0, 2], point = [0.1, 0, 0], rpm = 30, "
                                          "start_time = 0.5, ramp_time = 1 }\nremove_time = 3"),
                              "scene.toml");
  const Motion& m = r.walls[0].motion;
  BOOST_TEST((m.kind == MotionKind::rotation));
  BOOST_TEST(m.axis.z == 1.0);
  BOOST_TEST(m.point.x == 0.1);
  BOOST_TEST(std::fabs(m.omega - kPi) < 1e-15);  // 30 rpm = pi rad/s
  BOOST_TEST(m.start == 0.5);
  BOOST_TEST(m.ramp == 1.0);
  BOOST_TEST(m.remove == 3.0);
  const World<double> w = build_world<double>(r);
  BOOST_TEST_REQUIRE(w.motions.size() == 1u);
  BOOST_TEST(w.dynamic());
  BOOST_TEST(build_world<double>(parse_scene(kBase, "scene.toml")).motions.empty());  // static: no motions carried
  // a wall faster than max_impact_speed is noted (its impacts overlap more than dt was chosen for)
  const Scene fast = parse_scene(edit("end_time =", "end_time = 0.01\nmax_impact_speed = 1.5",
                                      with_motion("motion = { kind = \"translation\", velocity = [0, 3, 0] }")),
                                 "scene.toml");
  bool noted = false;
  for (const auto& n : fast.notes) noted = noted || has(n, "moves at up to 3");
  BOOST_TEST(noted);
  // a motion that starts, or a removal that comes, at or after the run's end is kept (a restart
  // with a later end_time uses it) but noted at its line: in this run the wall stands still / stays
  for (const double end : {0.01, 0.2, 3.0})
    for (const double at : {0.5 * end, end, 2 * end}) {
      const std::string t = std::to_string(at), e = std::to_string(end);
      const std::string text = edit("end_time = 0.01", "end_time = " + e,
                                    with_motion("motion = { kind = \"translation\", velocity = [0, 0.1, 0], start_time = " + t +
                                                " }\nremove_time = " + t));
      const Scene late = parse_scene(text, "scene.toml");
      bool starts = false, removed = false;
      for (const auto& n : late.notes) {
        starts = starts || (has(n, "scene.toml:" + std::to_string(line_of(text, "motion = "))) && has(n, "stands still in this run"));
        removed = removed || (has(n, "scene.toml:" + std::to_string(line_of(text, "remove_time = " + t))) && has(n, "stays for the whole run"));
      }
      BOOST_TEST(starts == (at >= end), "end " << end << ", start " << at);
      BOOST_TEST(removed == (at >= end), "end " << end << ", removal " << at);
    }
  // without max_impact_speed, the default impact speed takes the wall's speed on top
  const Scene moving = parse_scene(with_motion("motion = { kind = \"translation\", velocity = [0, 3, 0] }"), "scene.toml");
  BOOST_TEST(std::fabs(moving.impact_speed - parse_scene(kBase, "scene.toml").impact_speed - 3) < 1e-12);

  struct Bad {
    const char* line;
    const char* key_value;
    const char* allowed;
  };
  const Bad bad[] = {
      {"motion = { kind = \"spin\" }", "key 'kind' = \"spin\"", "one of \"none\" \"rotation\" \"translation\" \"vibration\""},
      {"motion = { kind = \"rotation\", axis = [0, 1, 0], point = [0, 0, 0] }", "missing key 'rpm'", "or omega: give one of rpm"},
      {"motion = { kind = \"rotation\", axis = [0, 0, 0], point = [0, 0, 0], rpm = 3 }", "key 'axis' = [0, 0, 0]",
       "a non-zero direction"},
      {"motion = { kind = \"vibration\", amplitude = 1e-3, frequency = 20, direction = [0, 1, 0], rpm = 3 }", "key 'rpm' = 3",
       "not a key of kind = \"vibration\" (it takes amplitude, frequency, direction)"},
      {"motion = { kind = \"vibration\", amplitude = -1e-3, frequency = 20, direction = [0, 1, 0] }", "key 'amplitude' = -0.001",
       "must be in (0, 1e+09] m"},
      {"motion = { kind = \"translation\", velocity = [0, 1e6, 0] }", "key 'velocity' = [0, 1e+06, 0]", "m/s"},
      {"motion = { kind = \"translation\", velocity = [0, 1, 0], start_time = -1 }", "key 'start_time' = -1", "must be >= 0 s"},
      {"motion = { kind = \"none\", spin_rate = 3 }", "unknown key 'spin_rate'", "allowed: kind, axis, point, rpm"},
      {"motion = 3", "key 'motion' = 3", "a table"},
      {"remove_time = -1", "key 'remove_time' = -1", "must be >= 0 s"},
  };
  for (const Bad& c : bad) {
    const std::string text = with_motion(c.line);
    const std::string msg = rejection([&] { parse_scene(text, "scene.toml"); });
    BOOST_TEST_CONTEXT("'" << c.line << "': " << msg) {
      BOOST_TEST(has(msg, "scene.toml:" + std::to_string(line_of(text, c.line))));
      BOOST_TEST(has(msg, c.key_value));
      BOOST_TEST(has(msg, c.allowed));
    }
  }
}

// [mill]: a shell, two end plates and the lifter rows, all turning at the mill's speed; bad mill
// input (a lifter taller than the radius, an axis of zero length, rows that do not fit around the
// shell, a lean that closes the bar, both rpm and omega, a drum reaching past the domain: its
// balls would leave it) named with file, line and key.
BOOST_AUTO_TEST_CASE(a_mill_is_built_and_bad_mills_are_named) {
  const std::string mill = "[mill]\nmaterial = \"steel\"\ncentre = [0, 0, 0]\naxis = [0, 0, 1]\ndiameter = 0.9\nlength = 0.15\n"
                           "rpm = 32\nramp_time = 0.5\nlifters = [{ count = 8, height = 0.04, width = 0.04 }]\n";
  std::string base = kBase;  // a domain that holds the drum: 1 m across its axis, 0.2 m along it
  const std::string domain = "domain_lo = [-0.1, -0.1, -0.1]\ndomain_hi = [0.1, 0.1, 0.1]";
  BOOST_TEST_REQUIRE(base.find(domain) != std::string::npos);
  base.replace(base.find(domain), domain.size(), "domain_lo = [-0.5, -0.5, -0.1]\ndomain_hi = [0.5, 0.5, 0.1]");
  const Scene s = parse_scene(base + mill, "scene.toml");
  BOOST_TEST_REQUIRE(s.cylinders.size() == 1u);
  BOOST_TEST(s.cylinders[0].radius == 0.45);
  BOOST_TEST(s.walls.size() == 1u + 2u + 3u * 8u);  // the base scene's floor, the end plates, 8 bars of 3 faces
  for (std::size_t k = 1; k < s.walls.size(); ++k) {
    BOOST_TEST((s.walls[k].motion.kind == MotionKind::rotation));
    BOOST_TEST(std::fabs(s.walls[k].motion.omega - 32 * 2 * kPi / 60) < 1e-12);
    BOOST_TEST(s.walls[k].name.rfind("mill ", 0) == 0u);
  }
  BOOST_TEST(s.walls[0].motion.is_static());  // the scene's own wall does not turn
  // a drum that starts turning at or after the run's end (end_time = 0.01) is noted at its line
  for (const double start : {0.005, 0.01, 0.02}) {
    const std::string text = base + mill + "start_time = " + std::to_string(start) + "\n";
    bool noted = false;
    for (const auto& n : parse_scene(text, "scene.toml").notes)
      noted = noted || (has(n, "scene.toml:" + std::to_string(line_of(text, "start_time = "))) && has(n, "[mill] starts turning"));
    BOOST_TEST(noted == (start >= 0.01), "start " << start);
  }
  struct Bad {
    const char* from;
    const char* to;
    const char* key_value;
    const char* allowed;
  };
  const Bad bad[] = {
      {"height = 0.04", "height = 0.5", "key 'height' = 0.5", "below the drum's radius"},
      {"axis = [0, 0, 1]", "axis = [0, 0, 0]", "key 'axis' = [0, 0, 0]", "an axis of zero length has none"},
      {"count = 8", "count = 80", "key 'count' = 80", "fit around the shell"},
      {"width = 0.04 }", "width = 0.04, face_angle = 40 }", "key 'face_angle' = 40", "height tan(face_angle) < width / 2"},
      {"rpm = 32", "rpm = 32\nomega = 3", "key 'omega' = 3", "not both (rpm is given too)"},
      {"diameter = 0.9", "diameter = -0.9", "key 'diameter' = -0.9", "must be in (0, 1e+09] m"},
      {"rpm = 32", "rpms = 32", "unknown key 'rpms'", "allowed: material, centre"},
      {"diameter = 0.9", "diameter = 1.2", "key 'diameter' = 1.2", "a drum inside the domain (particles that leave it are removed): along x it spans -0.6 to 0.6 m, the domain -0.5 to 0.5 m"},
      {"length = 0.15", "length = 0.3", "key 'length' = 0.3", "along z it spans -0.15 to 0.15 m, the domain -0.1 to 0.1 m"},
      {"centre = [0, 0, 0]", "centre = [0.1, 0, 0]", "key 'centre' = [0.1, 0, 0]", "along x it spans -0.35 to 0.55 m"},
  };
  for (const Bad& c : bad) {
    std::string m2 = mill;
    m2.replace(m2.find(c.from), std::string(c.from).size(), c.to);
    const std::string text = base + m2;
    const std::string msg = rejection([&] { parse_scene(text, "scene.toml"); });
    // the key's line: that of the replacement's last line (the lifters' table for its keys)
    const std::string to = c.to;
    const std::string last = to.substr(to.rfind('\n') == std::string::npos ? 0 : to.rfind('\n') + 1);
    const auto at = text.find(last);
    const int line = 1 + static_cast<int>(std::count(text.begin(), text.begin() + static_cast<long>(at), '\n'));
    BOOST_TEST_CONTEXT("'" << c.to << "': " << msg) {
      BOOST_TEST(has(msg, "scene.toml:" + std::to_string(line) + ":"));
      BOOST_TEST(has(msg, c.key_value));
      BOOST_TEST(has(msg, c.allowed));
    }
  }
}

// History-free friction without tangential_damping takes the thesis's eq. 4.3 (K_T = mu m*/dt, the
// rate capped at 0.5) and says so; an explicit tangential_damping, 0 included, keeps its K_T; a
// pair without friction gets no rate. The built law's K_T follows m*/dt.
using State0 = LinearLaw<double>::State;
BOOST_AUTO_TEST_CASE(friction_without_tangential_damping_takes_eq_4_3) {
  const auto note_of = [](const Scene& sc) {
    for (const auto& n : sc.notes)
      if (has(n, "eq. 4.3")) return n;
    return std::string();
  };
  for (double mu : {0.1, 0.3, 0.5, 0.9}) {
    const std::string text = edit("friction = 0.3", "friction = " + std::to_string(mu));
    const Scene sc = parse_scene(text, "scene.toml");
    BOOST_TEST(sc.pairs[0].tangential_rate == std::min(mu, 0.5));
    BOOST_TEST(sc.pairs[1].tangential_rate == 0.0);  // no friction
    const int line = 1 + static_cast<int>(std::count(text.begin(), text.begin() + static_cast<long>(text.find("friction = ")), '\n'));
    BOOST_TEST(has(note_of(sc), "scene.toml:" + std::to_string(line) + ":"), note_of(sc));
    const auto law = build_laws<LinearLaw<double>>(sc)(0, 0);
    State0 none{};
    const double m_eff = 0.01, dt = 1e-5, v = 1e-4;  // slow slip: the viscous branch
    const auto t = law.tangential.force({{0, 1, 0}, 1e-4, 1e-3, {v, 0, 0}, 0, 1.0, m_eff, dt}, none, 0);
    BOOST_TEST(std::fabs(t.force.x + std::min(mu, 0.5) * m_eff / dt * v) < 1e-12);
  }
  for (const char* kt : {"0", "2.5"}) {
    const Scene sc = parse_scene(edit("friction = 0.3", std::string("friction = 0.3\ntangential_damping = ") + kt), "scene.toml");
    BOOST_TEST(sc.pairs[0].tangential_rate == 0.0);
    BOOST_TEST(note_of(sc).empty());
  }
}

// The output folder (make_output_directory, used by blaze run and the study programs): a folder
// path through a file, or a file in the folder's place, was a bare filesystem error naming no key
// (an adversarial pass, 2026-12-07); it is a SceneError naming output.directory with its line.
// A folder that can be made is made, with `sub` inside it.
BOOST_AUTO_TEST_CASE(an_output_folder_that_cannot_be_made_is_named) {
  namespace fs = std::filesystem;
  const fs::path root = fs::temp_directory_path() / "blaze_output_folder_test";
  fs::remove_all(root);
  fs::create_directories(root);
  std::ofstream(root / "a_file") << "x";
  const auto scene_at = [&](const fs::path& dir) {
    std::string text = kBase;
    const std::string line = "directory = \"/tmp/blaze_scene_test\"";
    BOOST_TEST_REQUIRE(text.find(line) != std::string::npos);
    text.replace(text.find(line), line.size(), "directory = \"" + dir.string() + "\"");
    return parse_scene(text, "scene.toml");
  };
  for (const fs::path& bad : {root / "a_file", root / "a_file" / "sub"})
    for (const std::string sub : {"", "vtu"}) {
      try {
        make_output_directory(scene_at(bad), sub);
        BOOST_ERROR("an output folder through a file was made: " << bad);
      } catch (const SceneError& e) {
        const std::string m = e.what();
        BOOST_TEST(m.find("scene.toml:12: [output]: key 'directory'") != std::string::npos, m);  // kBase's line 12
        BOOST_TEST(m.find("cannot create the folder") != std::string::npos, m);
      }
    }
  const fs::path good = root / "made" / "here";
  BOOST_TEST(make_output_directory(scene_at(good), "vtu") == (good / "vtu").string());
  BOOST_TEST(fs::is_directory(good / "vtu"));
  BOOST_TEST(make_output_directory(scene_at(good)) == good.string());  // an existing folder is fine
  fs::remove_all(root);
}

// study_hopper's keys (studies/hopper/hopper_run.hpp): a gate opening at the run's end (no
// discharge at all) and an orifice column of zero width (no particle ever over it: no arch found,
// no flow pattern) ran silently (an adversarial pass, 2026-12-07); both are refused with the key.
BOOST_AUTO_TEST_CASE(a_hopper_study_with_no_discharge_or_no_orifice_is_refused) {
  const auto keys = [](const std::vector<std::string>& set) { return hopper::HopperKeys(load_scene("studies/hopper/hopper.toml", set)); };
  const auto refused = [&](const std::vector<std::string>& set, const std::string& key) {
    try {
      keys(set);
      BOOST_ERROR("accepted: " << set.front());
    } catch (const SceneError& e) {
      BOOST_TEST(std::string(e.what()).find("[study]: key '" + key + "'") != std::string::npos, e.what());
    }
  };
  for (const double end : {1.0, 3.0}) {  // the gate at the end, or past it, is refused; just before it runs
    const std::string e = "simulation.end_time=" + std::to_string(end);
    refused({"study.gate_open_time=" + std::to_string(end), e}, "gate_open_time");
    refused({"study.gate_open_time=" + std::to_string(end + 1), e}, "gate_open_time");
    BOOST_TEST(keys({"study.gate_open_time=" + std::to_string(0.9 * end), e}).gate_open == 0.9 * end);
  }
  refused({"study.orifice_half_width=0"}, "orifice_half_width");
  refused({"study.orifice_half_width=-0.01"}, "orifice_half_width");
  BOOST_TEST(keys({"study.orifice_half_width=0.001"}).orifice == 0.001);
}

// study_mill's span (studies/mill/mill_run.hpp): a run ending before its first averaged
// revolution wrote a power of 0 W from no revolution at all (found by an adversarial pass,
// 2026-12-07). Over speeds, ramps and skipped revolutions: an end_time just short of the ramp plus
// skip + 1 revolutions is refused naming end_time and the least that holds one; that least is
// accepted; a fractional skip_revolutions is refused.
BOOST_AUTO_TEST_CASE(a_mill_study_too_short_to_average_a_revolution_is_refused) {
  const auto load = [](double rpm, double ramp, double skip, double end) {
    return load_scene("studies/mill/lab_mill.toml", {"mill.rpm=" + std::to_string(rpm), "mill.ramp_time=" + std::to_string(ramp),
                                                     "study.skip_revolutions=" + std::to_string(skip),
                                                     "simulation.end_time=" + std::to_string(end)});
  };
  int cases = 0;
  for (const double rpm : {14.0, 32.0, 93.3})
    for (const double ramp : {0.0, 0.5})
      for (const int skip : {0, 1, 3}) {
        const double least = ramp + (skip + 1) * 60 / rpm;
        const mill::MillSpan span = mill::mill_span(load(rpm, ramp, skip, least * (1 + 1e-6)));
        BOOST_TEST(std::fabs(span.first_averaged_end() - least) < 1e-12 * least);
        try {
          mill::mill_span(load(rpm, ramp, skip, least * (1 - 1e-3)));
          BOOST_ERROR("a run ending before its first averaged revolution was accepted: rpm " << rpm << ", skip " << skip);
        } catch (const SceneError& e) {
          const std::string m = e.what();
          BOOST_TEST(m.find("command line (--set): [simulation]: key 'end_time'") != std::string::npos, m);
          BOOST_TEST(m.find("end_time must be at least") != std::string::npos, m);
        }
        ++cases;
      }
  BOOST_TEST(cases == 18);
  try {  // the file's own end_time (10 s) against 14 rpm and two revolutions skipped (13.4 s needed)
    mill::mill_span(load_scene("studies/mill/lab_mill.toml", {"mill.rpm=14", "study.skip_revolutions=2"}));
    BOOST_ERROR("the lab mill's 10 s at 14 rpm with two revolutions skipped was accepted");
  } catch (const SceneError& e) {
    BOOST_TEST(std::string(e.what()).find("lab_mill.toml:13: [simulation]: key 'end_time' = 10 s") != std::string::npos, e.what());
  }
  try {
    mill::mill_span(load(32, 0.5, 1.5, 10));
    BOOST_ERROR("a fractional skip_revolutions was accepted");
  } catch (const SceneError& e) {
    BOOST_TEST(std::string(e.what()).find("skip_revolutions' = 1.5") != std::string::npos, e.what());
  }
}

// A charge that does not fit in the drum: the lattice of the base scene (at -0.05 m) against a mill
// of 6 cm centred at the origin is outside its shell; the message names the [mill] and its diameter
// (not a [[cylinder]] the file does not have).
BOOST_AUTO_TEST_CASE(a_charge_outside_the_mill_is_named_with_the_mill) {
  const std::string mill = "[mill]\nmaterial = \"steel\"\ncentre = [0, 0, 0]\naxis = [0, 0, 1]\ndiameter = 0.06\nlength = 0.15\n"
                           "rpm = 32\n";
  const std::string text = kBase + mill;
  const Scene s = parse_scene(text, "scene.toml");
  const std::string msg = rejection([&] { (void)build_particles<double>(s, nullptr); });
  const int line = 1 + static_cast<int>(std::count(text.begin(), text.begin() + static_cast<long>(text.find("diameter = 0.06")), '\n'));
  BOOST_TEST_CONTEXT(msg) {
    BOOST_TEST(has(msg, "outside"));
    BOOST_TEST(has(msg, "the [mill]'s shell"));
    BOOST_TEST(has(msg, "scene.toml:" + std::to_string(line) + ": [mill]: key 'diameter' = 0.06"));
    BOOST_TEST(!has(msg, "[[cylinder]]"));
  }
}

BOOST_AUTO_TEST_CASE(poisson_ratio_outside_its_range_is_rejected) {
  for (const char* nu : {"0.5", "-1", "0.7"}) {
    const std::string text = edit("poisson_ratio = 0.23", std::string("poisson_ratio = ") + nu, hertz_scene());
    const std::string msg = rejection([&] { parse_scene(text, "scene.toml"); });
    BOOST_TEST_CONTEXT(msg) {
      BOOST_TEST(has(msg, "key 'poisson_ratio' = " + std::string(nu)));
      BOOST_TEST(has(msg, "in (-1, 0.5)"));
    }
  }
  BOOST_CHECK_NO_THROW(parse_scene(hertz_scene(), "scene.toml"));
}

BOOST_AUTO_TEST_CASE(missing_items_and_tables_are_named) {
  struct Case {
    std::string text, expected;
  };
  const Case cases[] = {
      {edit("restitution = 0.5", ""), "missing key 'restitution'"},
      {edit("materials = [\"glass\", \"steel\"]", "materials = [\"steel\", \"steel\"]"), "no [[pair]] for materials \"glass\" and \"steel\""},
      {edit("[output]", "[outptu]"), "unknown table or key 'outptu'"},
      {edit("dt =", "steps_per_contact = 20\ndt = 1e-5"), "give exactly one of 'dt'"},
      {edit("radius =", "shape = \"data/shapes/nothing.shape\"\nbounding_radius = 2e-3"), "cannot be loaded"},
      {"simulation = 3\n", "'simulation' must be a table"},
  };
  for (const auto& c : cases) {
    const std::string msg = rejection([&] { parse_scene(c.text, "scene.toml"); });
    BOOST_TEST(has(msg, c.expected), msg << " should contain " << c.expected);
    BOOST_TEST(has(msg, "scene.toml"), msg);
  }
}

BOOST_AUTO_TEST_CASE(dt_above_the_safe_fraction_runs_only_when_forced) {
  const std::string text = edit("dt =", "dt = 1e-3");
  BOOST_TEST(has(rejection([&] { parse_scene(text, "scene.toml"); }), "set force_dt = true"));
  const Scene s = parse_scene(text, "scene.toml", {"force_dt=true"});
  BOOST_TEST(s.dt == 1e-3);
  BOOST_TEST(s.dt > kSafeStepFraction * s.dt_critical);
}

BOOST_AUTO_TEST_CASE(command_line_overrides_are_applied_and_validated) {
  const Scene s = parse_scene(kBase, "scene.toml",
                              {"dt=1.5e-5", "material[0].density=2600", "output.csv_interval=0.002", "precision=float"});
  BOOST_TEST(s.dt == 1.5e-5);
  BOOST_TEST(s.materials[0].density == 2600);
  BOOST_TEST(s.output.csv_interval == 0.002);
  BOOST_TEST((s.precision == PrecisionKind::float32));
  // dt on the command line replaces steps_per_contact in the file.
  const Scene t = parse_scene(edit("dt =", "steps_per_contact = 30"), "scene.toml", {"simulation.dt=3e-6"});
  BOOST_TEST(t.dt == 3e-6);
  const std::pair<const char*, const char*> bad[] = {
      {"material[0].density=-1", "command line (--set): [[material]] #1: key 'density' = -1: must be in (0, 1e+09]"},
      {"dt", "expected key=value"},
      {"material[7].density=1", "index '7' of 'material' must be 0..1"},
      {"simulation.dtt=1", "unknown key 'dtt'"},
      // The key grammar is strict (issue 17): no unclosed index, no name glued to an index.
      {"material[0.density=1000", "the index must be closed by ']'"},
      {"material[0]density=1000", "'.' or '[' must follow ']'"},
      {"material.0.density=1000", "a name must start here"},
      {"material[].density=1000", "an index (digits) must follow '['"},
      {"material[-1].density=1000", "an index (digits) must follow '['"},
      {"material[0]=1000", "the key must end with a name"},
      {"material.density=1000", "'material' needs an index"},
      {"simulation[0].dt=1e-5", "not a list of tables"},
      {"simulation..dt=1e-5", "a name must start here"},
      {"simulation.dt.=1e-5", "a name must follow '.'"},
      {"sim ulation.dt=1e-5", "unexpected ' '"},
      {"dt=1e-5\nend_time = 5", "control character"},
      {"dt=1e-5\rx", "control character"},
      {"dt=1e-5 end_time = 5", "key 'dt' = \"1e-5 end_time = 5\": a number"},
      {"precision=\"float", "not TOML"},
  };
  for (const auto& c : bad) {
    const std::string msg = rejection([&] { parse_scene(kBase, "scene.toml", {c.first}); });
    BOOST_TEST(has(msg, c.second), c.first << ": " << msg);
  }
}

// The thesis's bound dt < 2/sqrt(k/m*) with m* of the lightest pair, and the Hertz bound at the
// deepest overlap of an impact, against their closed forms.
BOOST_AUTO_TEST_CASE(critical_step_matches_closed_forms) {
  const Scene s = parse_scene(kBase, "scene.toml");
  const double m = 2500 * 4.0 / 3.0 * kPi * 8e-9;
  // glass-glass: k 2e4, m* = m/2; glass-wall: k 4e4, m* = m. The smaller bound governs.
  const double expected = std::min(2 / std::sqrt(2e4 / (m / 2)), 2 / std::sqrt(4e4 / m));
  BOOST_TEST(s.dt_critical == expected, boost::test_tools::tolerance(1e-12));
  BOOST_TEST(has(s.dt_governing, "\"glass\"-\"glass\""));

  const Scene h = parse_scene(hertz_scene(), "scene.toml", {"max_impact_speed=2"});
  const double e_glass = 6.3e10 / (1 - 0.23 * 0.23), e_steel = 2.1e11 / (1 - 0.09);
  auto bound = [&](double e_star, double r_eff, double m_eff) {
    const double kn = 4.0 / 3.0 * e_star * std::sqrt(r_eff), delta = std::pow(5 * m_eff * 4 / (4 * kn), 0.4);
    return 2 / std::sqrt(1.5 * kn * std::sqrt(delta) / m_eff);
  };
  const double pair = bound(e_glass / 2, 1e-3, m / 2), wall = bound(1 / (1 / e_glass + 1 / e_steel), 2e-3, m);
  const double shear = 6.3e10 / (2 * 1.23), rayleigh = kPi * 2e-3 * std::sqrt(2500 / shear) / (0.1631 * 0.23 + 0.8766);
  BOOST_TEST(h.dt_critical == std::min({pair, wall, rayleigh}), boost::test_tools::tolerance(1e-12));
}

// contact_time in a [[pair]] gives that contact time: two elastic beads collide head-on.
BOOST_AUTO_TEST_CASE(contact_time_sets_the_stiffness_that_gives_it) {
  const double t_c = 2e-4;
  std::string text = edit("stiffness = 2e4", "contact_time = 2e-4");
  text = edit("restitution = 0.5", "restitution = 1", text);
  text = edit("friction = 0.3", "", text);
  const Scene s = parse_scene(text, "scene.toml");
  using Law = LinearLaw<double>;
  const PairTable<Law> laws = build_laws<Law>(s);
  ParticleState<double> p;
  const double gap = 1e-4, v = 0.5;
  p.add_sphere({-2e-3 - gap, 0, 0}, 2e-3, 2500, 0, {v, 0, 0});
  p.add_sphere({2e-3 + gap, 0, 0}, 2e-3, 2500, 0, {-v, 0, 0});
  const double dt = t_c / 2000;
  Simulation<DefaultSpace, SphereShape, Law, VelocityVerlet> sim({dt, {0, 0, 0}, {-0.1, -0.1, -0.1}, {0.1, 0.1, 0.1}, 0},
                                                                laws, World<double>{}, p);
  double first = -1, last = -1;
  for (int k = 0; k < 6000; ++k) {
    sim.step();
    const auto st = sim.state();
    if (st.position[1].x - st.position[0].x < 4e-3) {
      if (first < 0) first = sim.time();
      last = sim.time();
    }
  }
  BOOST_TEST(last - first == t_c, boost::test_tools::tolerance(tol::scene_contact_time));
}

BOOST_AUTO_TEST_CASE(placements_give_the_particles_they_promise) {
  const Scene s = parse_scene(kBase, "scene.toml");
  const auto p = build_particles<double>(s, nullptr);
  BOOST_TEST_REQUIRE(p.size() == 12u + 40u + 1u);
  // Lattice: x fastest, exact sites (no jitter).
  BOOST_TEST(p.position[1].x - p.position[0].x == 0.005, boost::test_tools::tolerance(1e-12));
  BOOST_TEST(p.position[3].y - p.position[0].y == 0.005, boost::test_tools::tolerance(1e-12));
  // Order: lattice (0-11), list (12), fill (13-52). Fill: inside its box; no overlaps anywhere.
  double worst = 1;
  for (std::size_t i = 0; i < p.size(); ++i) {
    for (std::size_t j = i + 1; j < p.size(); ++j) worst = std::min(worst, norm(p.position[i] - p.position[j]) / 4e-3);
    if (i >= 13) {
      BOOST_TEST((p.position[i].y - 2e-3 >= 0.0 && p.position[i].y + 2e-3 <= 0.05));
      BOOST_TEST((std::fabs(p.position[i].x) + 2e-3 <= 0.05 && std::fabs(p.position[i].z) + 2e-3 <= 0.05));
    }
  }
  BOOST_TEST(worst >= 1.0);
  BOOST_TEST(p.velocity[12].y == -1.0);
  // The seed decides the fill; the same seed gives the same particles.
  const auto again = build_particles<double>(s, nullptr);
  const auto other = build_particles<double>(parse_scene(kBase, "scene.toml", {"seed=2"}), nullptr);
  BOOST_TEST(again.position[30].x == p.position[30].x);
  BOOST_TEST(other.position[30].x != p.position[30].x);
  // Two placements that overlap are an error naming both.
  const std::string overlap = edit("positions =", "positions = [[-0.05, -0.05, -0.05]]");
  const std::string msg = rejection([&] { build_particles<double>(parse_scene(overlap, "scene.toml"), nullptr); });
  BOOST_TEST((has(msg, "[[particles]] #1 point 0 overlaps particle 0 of [[lattice]] #1")), msg);
}

// A 0.9 m x 0.15 m mill at 20 rpm with `rows` lifter rows (0: none) and a [[fill]] of `count`
// balls of radius r whose box is wider than the drum.
std::string mill_fill_scene(double r, long count, int rows) {
  return std::string(R"(
[simulation]
law = "linear"
dt = 1e-5
end_time = 0.1
gravity = [0.0, -9.81, 0.0]
domain_lo = [-0.5, -0.5, -0.1]
domain_hi = [0.5, 0.5, 0.1]
[[material]]
name = "steel"
density = 7800
[[pair]]
materials = ["steel", "steel"]
stiffness = 4e5
restitution = 0.8
[[particle_type]]
name = "ball"
material = "steel"
radius = )") + std::to_string(r) + R"(
[[fill]]
type = "ball"
count = )" + std::to_string(count) + R"(
lo = [-0.46, -0.46, -0.09]
hi = [0.46, 0.46, 0.09]
[mill]
material = "steel"
centre = [0.0, 0.0, 0.0]
axis = [0.0, 0.0, 1.0]
diameter = 0.9
length = 0.15
rpm = 20
)" + (rows > 0 ? "lifters = [{ count = " + std::to_string(rows) + ", height = 0.04, width = 0.03 }]\n" : std::string());
}

// A [[fill]] whose box is wider than a [mill] is clipped to the drum: every particle lies inside
// the shell and between the end plates, touches no lifter, and the count is met; for 0, 8 and 24
// lifter rows and two sizes.
BOOST_AUTO_TEST_CASE(a_fill_wider_than_a_mill_is_clipped_to_its_interior) {
  for (int rows : {0, 8, 24})
    for (double r : {0.01, 0.025}) {
      const long count = r < 0.02 ? 1500 : 120;
      const Scene s = parse_scene(mill_fill_scene(r, count, rows), "mill.toml");
      const auto p = build_particles<double>(s, nullptr);
      BOOST_TEST_REQUIRE(p.size() == static_cast<std::size_t>(count));
      const World<double> w = build_world<double>(s);
      long outside = 0, touching = 0;
      for (std::size_t i = 0; i < p.size(); ++i) {
        const Vec3<double> x = p.position[i];
        outside += std::hypot(x.x, x.y) + r > 0.45 + 1e-12 || std::fabs(x.z) + r > 0.075 + 1e-12;
        for (const auto& g : w.polygons) touching += collide_sphere(x, r, g).touching;
      }
      BOOST_TEST(outside == 0, rows << " lifter rows, r = " << r << ": " << outside << " outside the drum");
      BOOST_TEST(touching == 0, rows << " lifter rows, r = " << r << ": " << touching << " touch a lifter or an end plate");
    }
}

// A fill the drum cannot hold (690 balls of 2.5 cm: 0.3 of the box, 0.47 of the drum; random
// placement jams near 0.38) is refused naming the fill, not run half-filled.
BOOST_AUTO_TEST_CASE(a_fill_the_mill_cannot_hold_is_refused) {
  const std::string msg = rejection([&] { build_particles<double>(parse_scene(mill_fill_scene(0.025, 690, 8), "mill.toml"), nullptr); });
  BOOST_TEST((has(msg, "mill.toml: [[fill]] #1: no free place for particle") && has(msg, "of 690")), msg);
}

// Seeded mutations of the base scene: each either parses into a valid scene or is rejected with
// a SceneError that names where; nothing else may escape and nothing may crash.
BOOST_AUTO_TEST_CASE(mutation_fuzz_never_crashes_and_every_rejection_is_clear) {
  std::mt19937_64 rng(20261129);
  const std::string alphabet = "[]{}=\"#.,-+0123456789eEnaifrtux_ \n\t";
  const char* tokens[] = {"1e308", "-0", "nan", "inf", "-inf", "0", "\"\"", "[]", "[[]]", "{}", "true", "1e-300",
                          "9223372036854775807", "[1,2]", "\"glass\"", "[[wall]]", "[simulation]"};
  long accepted = 0, rejected = 0;
  const auto last = (std::filesystem::temp_directory_path() / "blaze_fuzz_last.toml").string();
  for (int k = 0; k < tol::scene_fuzz_mutations; ++k) {
    std::string text = kBase;
    const int edits = 1 + static_cast<int>(rng() % 4);
    for (int e = 0; e < edits; ++e) {
      const std::size_t at = rng() % text.size();
      switch (rng() % 5) {
        case 0: text.erase(at, 1 + rng() % 12); break;
        case 1: text.insert(at, 1, alphabet[rng() % alphabet.size()]); break;
        case 2: text.insert(at, tokens[rng() % (sizeof tokens / sizeof *tokens)]); break;
        case 3: {  // replace the number that starts nearest after `at`
          const auto d = text.find_first_of("0123456789", at);
          if (d != std::string::npos) text.replace(d, 1 + rng() % 3, tokens[rng() % 6]);
          break;
        }
        default: {  // duplicate a line
          const auto b = text.rfind('\n', at), end = text.find('\n', at);
          if (b != std::string::npos && end != std::string::npos) text.insert(end, text.substr(b, end - b));
        }
      }
    }
    std::ofstream(last) << text;  // a crash leaves its input here
    try {
      const Scene s = parse_scene(text, "fuzz.toml");
      ++accepted;
      BOOST_TEST_REQUIRE((s.dt > 0 && std::isfinite(s.dt) && s.end_time > 0), text);
      for (const auto& t : s.types) BOOST_TEST_REQUIRE(t.size() > 0, text);
      for (const auto& p : s.pairs) BOOST_TEST_REQUIRE((p.restitution > 0 && p.restitution <= 1), text);
    } catch (const SceneError& e) {
      ++rejected;
      const std::string msg = e.what();
      BOOST_TEST_REQUIRE((msg.rfind("fuzz.toml", 0) == 0 || msg.rfind("command line", 0) == 0), msg);
    } catch (const std::exception& e) {
      BOOST_FAIL("not a SceneError: " << e.what() << "\nscene:\n" << text);
    }
  }
  BOOST_TEST_MESSAGE("scene fuzz: " << accepted << " accepted, " << rejected << " rejected with a SceneError");
  BOOST_TEST(rejected > tol::scene_fuzz_mutations / 2);  // the mutations do bite
  std::filesystem::remove(last);
}


// The programs that run scenes take the law from pipeline/scene_law.hpp: every combination of the
// law, tangential and rolling keys gets its own law type (a program that dropped one ran the
// history-free law silently: study_hopper did), rolling resistance never reaches a polyhedron run,
// and rolling without a spring is refused.
BOOST_AUTO_TEST_CASE(every_law_the_scene_names_is_the_law_that_runs) {
  struct Case {
    LawKind law;
    TangentialKind tangential;
    RollingKind rolling;
    int expected;  // index into the law list below
  };
  const auto which = [](auto tag) {
    using L = typename decltype(tag)::type;
    return std::is_same_v<L, LinearLaw<double>>   ? 0 : std::is_same_v<L, HertzLaw<double>> ? 1
         : std::is_same_v<L, LinearSpringLaw<double>> ? 2 : std::is_same_v<L, HertzMindlinLaw<double>> ? 3
         : std::is_same_v<L, LinearSpringRollingLaw<double>> ? 4 : std::is_same_v<L, HertzMindlinRollingLaw<double>> ? 5 : -1;
  };
  const Case cases[] = {{LawKind::linear, TangentialKind::history_free, RollingKind::none, 0},
                        {LawKind::hertz, TangentialKind::history_free, RollingKind::none, 1},
                        {LawKind::linear, TangentialKind::linear_spring, RollingKind::none, 2},
                        {LawKind::hertz, TangentialKind::mindlin, RollingKind::none, 3},
                        {LawKind::linear, TangentialKind::linear_spring, RollingKind::cdt, 4},
                        {LawKind::linear, TangentialKind::linear_spring, RollingKind::epsd, 4},
                        {LawKind::hertz, TangentialKind::mindlin, RollingKind::cdt, 5},
                        {LawKind::hertz, TangentialKind::mindlin, RollingKind::epsd, 5}};
  const auto spheres = [&](const Scene& x) { return with_scene_law<double, true>(x, which); };
  const auto polyhedra = [&](const Scene& x) { return with_scene_law<double, false>(x, which); };
  for (const Case& c : cases) {
    Scene s;
    s.path = "scene.toml";
    s.law = c.law, s.tangential = c.tangential, s.rolling = c.rolling;
    BOOST_TEST(spheres(s) == c.expected);
    if (c.rolling == RollingKind::none) {
      BOOST_TEST(polyhedra(s) == c.expected);
    } else {
      BOOST_CHECK_EXCEPTION(polyhedra(s), SceneError, [](const SceneError& e) {
        return std::string(e.what()).find("rolling") != std::string::npos &&
               std::string(e.what()).find("spheres") != std::string::npos;
      });
    }
  }
  Scene s;
  s.path = "scene.toml";
  s.law = LawKind::hertz, s.tangential = TangentialKind::history_free, s.rolling = RollingKind::epsd;
  BOOST_CHECK_EXCEPTION(spheres(s), SceneError,
                        [](const SceneError& e) { return std::string(e.what()).find("tangential") != std::string::npos; });
  s.rolling = RollingKind::none;
  BOOST_TEST(scene_law_name(s) == "hertz + history_free");
}
// The placement grid of the fills (blaze/scene/sphere_grid.hpp: an array over the box, a hash map
// beyond it, or for a box too large for the array) finds an overlap exactly when one exists: against
// a search of every entry, for spheres of three sizes placed inside and outside the box, cells
// 4 r_max wide (the fills': 8 a query) and 2 r_max (27), queries of every size up to the largest,
// with and without a slack.
BOOST_AUTO_TEST_CASE(placement_grid_finds_what_a_search_of_every_sphere_finds) {
  using V = Vec3<double>;
  const double r_max = 0.05;
  for (const double extent : {1.0, 1e6})  // 1e6 m: ~1e20 cells, beyond the array's cap
    for (const double cell : {4 * r_max, 2 * r_max}) {
      SphereGrid grid(V{0, 0, 0}, V{extent, extent, extent}, cell, r_max, 400);
      std::mt19937_64 rng(7);
      std::uniform_real_distribution<double> u(-0.3, 1.3), size(0.2, 1.0);  // a third of a box [0, 1]^3 beyond it
      std::vector<V> centre;
      std::vector<double> radius;
      long found = 0, queries = 0;
      for (int k = 0; k < 4000; ++k) {
        const V x{u(rng), u(rng), u(rng)};
        const double r = r_max * size(rng), slack = k % 3 == 0 ? 0.2 * r : 0.0;
        long expected = -1;
        for (std::size_t j = 0; j < centre.size() && expected < 0; ++j)
          if (norm(x - centre[j]) < r + radius[j] - slack) expected = static_cast<long>(j);
        const long j = grid.overlapping(x, r, slack);
        ++queries;
        BOOST_TEST((j >= 0) == (expected >= 0));
        if (j >= 0) {
          BOOST_TEST(norm(x - centre[static_cast<std::size_t>(j)]) < r + radius[static_cast<std::size_t>(j)] - slack);
          ++found;
        }
        if (j < 0 && centre.size() < 400) grid.add(x, r), centre.push_back(x), radius.push_back(r);
      }
      BOOST_TEST(grid.size() == centre.size());
      BOOST_TEST(found > queries / 40);  // the queries met placed spheres often, inside and out
    }
}
// Every scene the project ships (studies, data/scenes, bench/scenes) loads and validates: a key
// renamed or a range tightened cannot leave a study's scene broken until someone runs it. A scene
// whose mesh is made by its study's script (an STL under data/, not in the repository) is loaded
// with that mesh left out.
BOOST_AUTO_TEST_CASE(every_shipped_scene_loads) {
  namespace fs = std::filesystem;
  int loaded = 0;
  for (const char* folder : {"studies", "data/scenes", "bench/scenes"})
    for (const auto& e : fs::recursive_directory_iterator(folder)) {
      if (e.path().extension() != ".toml") continue;
      const std::string path = e.path().string();
      std::ifstream in(path);
      std::stringstream text;
      text << in.rdbuf();
      std::string body = text.str();
      // a generated mesh (file = "data/...", absent): the scene without its [[mesh]] tables
      const auto generated = body.find("file = \"data/");
      if (generated != std::string::npos) {
        const auto q = body.find('"', generated) + 1;
        if (!fs::exists(body.substr(q, body.find('"', q) - q))) {
          const auto mesh = body.rfind("[[mesh]]", generated);
          BOOST_TEST_REQUIRE(mesh != std::string::npos);
          const auto next = body.find("\n[", generated);
          body.erase(mesh, next == std::string::npos ? std::string::npos : next + 1 - mesh);
        }
      }
      BOOST_TEST_CONTEXT(path) {
        BOOST_CHECK_NO_THROW(parse_scene(body, path));
      }
      ++loaded;
    }
  BOOST_TEST(loaded >= 15);
}

// Found by trying Blaze as an adversarial user would (stop 49): each was a crash, a silent wrong
// run or a message naming the wrong key.
BOOST_AUTO_TEST_CASE(adversarial_feeds_mills_and_overrides_are_named) {
  const std::string feed = "\n[[feed]]\ntype = \"bead\"\nregion = { kind = \"box\", lo = [-0.02, 0.05, -0.02], hi = [0.02, 0.08, 0.02] }\n"
                           "rate = 2000\n";
  // a feed starting at or after the run's end inserted nothing and sized the run negative (a crash)
  for (const double start : {0.01, 0.5}) {
    const std::string text = kBase + feed + "start_time = " + std::to_string(start) + "\n";
    const std::string msg = rejection([&] { parse_scene(text, "scene.toml"); });
    BOOST_TEST(has(msg, "scene.toml:" + std::to_string(line_of(text, "start_time")) + ": [[feed]] #1: key 'start_time'"), msg);
    BOOST_TEST(has(msg, "before the run's end_time, 0.01 s"), msg);
  }
  BOOST_TEST(parse_scene(kBase + feed + "start_time = 0.005\n", "scene.toml").feeds.size() == 1u);
  // a feed's velocity (and spread) enters the impact speed, as every placement's does
  // (the base scene's fastest placement: its [[particles]] at 1 m/s)
  const Scene slow = parse_scene(kBase + feed, "scene.toml");
  BOOST_TEST(largest_initial_speed(slow) == 1.0);
  for (const double v : {2.0, 5.0}) {
    const Scene fast = parse_scene(kBase + feed + "velocity = [0, -" + std::to_string(v) + ", 0]\nvelocity_spread = 0.5\n", "scene.toml",
                                   {"force_dt=true"});
    BOOST_TEST(std::fabs(fast.impact_speed - slow.impact_speed - (v + 0.5 - 1.0)) < 1e-9, v);
  }
  // rate and mass_rate: both, or neither, named as such
  std::string msg = rejection([&] { parse_scene(kBase + feed + "mass_rate = 1\n", "scene.toml"); });
  BOOST_TEST((has(msg, "key 'mass_rate' = 1") && has(msg, "not both (rate is given too)")), msg);
  std::string no_rate = kBase + feed;
  no_rate.replace(no_rate.find("rate = 2000\n"), 12, "");
  msg = rejection([&] { parse_scene(no_rate, "scene.toml"); });
  BOOST_TEST(has(msg, "[[feed]] #1: missing key 'rate' (or mass_rate: give one of rate"), msg);
  // without an end_time a feed lasts the run: its identity does not hold the run's end (a restart
  // may run longer); a given end_time is kept as given
  const auto times = [](const Scene& s) {
    for (const auto& [k, v] : scene_identity(s))
      if (k == "feed[0].times") return v;
    return std::string("none");
  };
  const Scene run = parse_scene(kBase + feed, "scene.toml"), longer = parse_scene(kBase + feed, "scene.toml", {"end_time=0.02"});
  BOOST_TEST(times(run) == times(longer));
  BOOST_TEST(longer.feeds[0].end == 0.02);
  const Scene given = parse_scene(kBase + feed + "end_time = 0.05\n", "scene.toml");
  BOOST_TEST(given.feeds[0].end == 0.05);
  BOOST_TEST(times(given) != times(run));
  // count = 0 was taken for "no limit" (undocumented): leave count out for that; names are unique
  msg = rejection([&] { parse_scene(kBase + feed + "count = 0\n", "scene.toml"); });
  BOOST_TEST((has(msg, "key 'count' = 0") && has(msg, "[1, ")), msg);
  msg = rejection([&] { parse_scene(kBase + feed + "name = \"pour\"\n" + feed + "name = \"pour\"\n", "scene.toml"); });
  BOOST_TEST((has(msg, "[[feed]] #2: key 'name' = \"pour\"") && has(msg, "is taken")), msg);
  // a bare --set key of [output] goes to [output] whether or not the file has it
  const Scene o = parse_scene(kBase, "scene.toml", {"vtu_interval=0.002", "energy_gain_limit=0.1", "checkpoint_interval=0.005"});
  BOOST_TEST(o.output.vtu_interval == 0.002);
  BOOST_TEST(o.output.energy_gain_limit == 0.1);
  BOOST_TEST(o.output.checkpoint_interval == 0.005);
  // a mill with neither rpm nor omega names the [mill], not its diameter
  const std::string mill = "\n[mill]\nmaterial = \"steel\"\ncentre = [0, 0, 0]\naxis = [0, 0, 1]\ndiameter = 0.19\nlength = 0.15\n";
  msg = rejection([&] { parse_scene(kBase + mill, "scene.toml"); });
  BOOST_TEST(has(msg, "scene.toml:" + std::to_string(line_of(kBase + mill, "[mill]")) + ": [mill]: missing key 'rpm' (or omega"), msg);
  // undercut lifters (face_angle < 0: the faces lean over the shell) are the mill's own faces, not
  // a user's wall facing away from the charge behind their planes
  for (const char* angle : {"-30", "-45", "0", "15"}) {
    const std::string drum = std::string(R"([simulation]
law = "linear"
steps_per_contact = 15
end_time = 0.3
gravity = [0.0, -9.81, 0.0]
domain_lo = [-0.2, -0.2, -0.06]
domain_hi = [0.2, 0.2, 0.06]
[[material]]
name = "steel"
density = 7800
[[pair]]
materials = ["steel", "steel"]
stiffness = 4e5
restitution = 0.825
friction = 0.15
tangential_damping = 1.0
[[particle_type]]
name = "ball"
material = "steel"
radius = 0.01
[[lattice]]
type = "ball"
origin = [-0.055, -0.08, -0.03]
count = [6, 3, 3]
spacing = 0.022
[mill]
material = "steel"
centre = [0.0, 0.0, 0.0]
axis = [0.0, 0.0, 1.0]
diameter = 0.3
length = 0.1
rpm = 40
lifters = [{ count = 4, height = 0.03, width = 0.02, face_angle = )") + angle + " }]\n";
    const Scene d = parse_scene(drum, "drum.toml");
    BOOST_TEST(rejection([&] { (void)build_particles<double>(d, nullptr); }) == "(accepted)", angle);
  }
}

BOOST_AUTO_TEST_SUITE_END()
