// The adversarial scene list (issue 17): scenes a careless or hostile user could write, generated
// from three small valid scenes by edits of their text or --set overrides. Each case says what
// must happen: the run ends correctly, or the scene is refused with a message naming the file (or
// the command line) and the key; some cases also name words the message must hold. `either`:
// sweeps of odd values where refusing and running are both right, so long as neither crashes,
// hangs, lies (a non-finite time series) or takes more memory than the program's own estimate.
#pragma once
#include <string>
#include <utility>
#include <vector>

namespace blaze::test::adversarial {

enum class Expect { runs, rejected, either };

struct Case {
  std::string name;
  std::string base;                                         // "spheres", "drum" or "cubes"
  std::vector<std::pair<std::string, std::string>> edits;  // text replacements in the scene file
  std::vector<std::string> sets;                            // --set overrides
  Expect expect = Expect::rejected;
  std::vector<std::string> must;  // substrings of the message (rejected) or the output (runs)
  bool check_only = false;        // --check: validate and estimate, take no step
  bool guard_may_stop = false;    // a guard stopping the run (exit 3) is right: the case asks for it
};

// 19 glass beads over a steel floor, linear law, 100 steps.
inline const char* kSpheres = R"(# adversarial base: spheres
[simulation]
law = "linear"
precision = "double"
dt = 1e-5
end_time = 1e-3
gravity = [0, -9.81, 0]
domain_lo = [-0.05, -0.01, -0.05]
domain_hi = [0.05, 0.1, 0.05]

[output]
directory = "@DIR@"
csv_interval = 2e-4

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
tangential_damping = 0.1
[[pair]]
materials = ["glass", "steel"]
stiffness = 2e4
restitution = 0.5
friction = 0.3

[[particle_type]]
name = "bead"
material = "glass"
radius = 2e-3

[[lattice]]
type = "bead"
origin = [-0.01, 0.01, -0.01]
count = [3, 2, 3]
spacing = 0.005
velocity = [0, 0, 0]
jitter = 0.1

[[fill]]
type = "bead"
lo = [-0.04, 0.05, -0.04]
hi = [0.04, 0.09, 0.04]
count = 5

[[particles]]
type = "bead"
positions = [[0.0, 0.04, 0.0]]
velocities = [[0.0, -1.0, 0.0]]

[[wall]]
material = "steel"
vertices = [[-0.04, 0, -0.04], [-0.04, 0, 0.04], [0.04, 0, 0.04], [0.04, 0, -0.04]]
)";

// Beads in a steel drum (axis z), Hertz law, float.
inline const char* kDrum = R"(# adversarial base: drum
[simulation]
law = "hertz"
precision = "float"
dt = 2e-6
end_time = 2e-4
gravity = [0, -9.81, 0]
domain_lo = [-0.06, -0.06, -0.01]
domain_hi = [0.06, 0.06, 0.05]
max_impact_speed = 2.0

[output]
directory = "@DIR@"
csv_interval = 5e-5

[[material]]
name = "plastic"
density = 1200
youngs_modulus = 1e8
poisson_ratio = 0.35
[[material]]
name = "steel"
density = 7800
youngs_modulus = 2e11
poisson_ratio = 0.3

[[pair]]
materials = ["plastic", "plastic"]
restitution = 0.6
friction = 0.4
[[pair]]
materials = ["plastic", "steel"]
restitution = 0.7
friction = 0.3

[[particle_type]]
name = "bead"
material = "plastic"
radius = 3e-3

[[lattice]]
type = "bead"
origin = [-0.02, -0.02, 0.01]
count = [4, 4, 2]
spacing = 0.01

[[cylinder]]
material = "steel"
origin = [0, 0, 0]
axis = [0, 0, 1]
radius = 0.05
length = 0.04

[[wall]]
material = "steel"
vertices = [[-0.05, -0.05, 0], [-0.05, 0.05, 0], [0.05, 0.05, 0], [0.05, -0.05, 0]]
[[wall]]
material = "steel"
vertices = [[-0.05, -0.05, 0.04], [0.05, -0.05, 0.04], [0.05, 0.05, 0.04], [-0.05, 0.05, 0.04]]
)";

// Cubes on a floor, linear law, double (polyhedra: pairs once).
inline const char* kCubes = R"(# adversarial base: cubes
[simulation]
law = "linear"
precision = "double"
dt = 1e-5
end_time = 5e-4
gravity = [0, -9.81, 0]
domain_lo = [-0.05, -0.01, -0.05]
domain_hi = [0.05, 0.1, 0.05]

[output]
directory = "@DIR@"
csv_interval = 1e-4

[[material]]
name = "rock"
density = 2600
[[material]]
name = "steel"
density = 7800

[[pair]]
materials = ["rock", "rock"]
stiffness = 2e4
restitution = 0.5
friction = 0.5
[[pair]]
materials = ["rock", "steel"]
stiffness = 2e4
restitution = 0.5
friction = 0.5

[[particle_type]]
name = "cube"
material = "rock"
shape = "data/shapes/cube.shape"
bounding_radius = 3e-3

[[lattice]]
type = "cube"
origin = [-0.01, 0.01, -0.01]
count = [3, 2, 3]
spacing = 0.007

[[wall]]
material = "steel"
vertices = [[-0.04, 0, -0.04], [-0.04, 0, 0.04], [0.04, 0, 0.04], [0.04, 0, -0.04]]
)";

// gpu_build: the blaze program under test is the CUDA build (its backend case is the other one).
inline std::vector<Case> cases(bool gpu_build) {
  std::vector<Case> c;
  const auto rejected = [&](std::string name, std::string base, std::vector<std::string> sets, std::vector<std::string> must,
                            bool check_only = true) {
    c.push_back({std::move(name), std::move(base), {}, std::move(sets), Expect::rejected, std::move(must), check_only});
  };
  const auto edited = [&](std::string name, std::string base, std::vector<std::pair<std::string, std::string>> edits,
                          Expect e, std::vector<std::string> must) {
    c.push_back({std::move(name), std::move(base), std::move(edits), {}, e, std::move(must), e != Expect::runs});
  };
  const auto runs = [&](std::string name, std::string base, std::vector<std::string> sets, std::vector<std::string> must = {}) {
    c.push_back({std::move(name), std::move(base), {}, std::move(sets), Expect::runs, std::move(must), false});
  };

  // --- the three bases run as they are
  runs("base spheres", "spheres", {});
  runs("base drum", "drum", {});
  runs("base cubes", "cubes", {});

  // --- 1. derived sizes: every one computed in double and refused before allocation, by key
  rejected("cells overflow int per axis", "spheres", {"gravity=[0,0,0]", "domain_lo=[-1e7,-1e7,-1e7]", "domain_hi=[1e7,1e7,1e7]"},
           {"key 'domain_hi'", "cells"});
  rejected("cells beyond 2^32 in total", "spheres", {"gravity=[0,0,0]", "domain_hi=[20,20,20]"}, {"key 'domain_hi'", "4.29e9"});
  rejected("one long axis of 3e9 cells", "spheres", {"gravity=[0,0,0]", "domain_hi=[1.5e7,0.1,0.05]"}, {"key 'domain_hi'"});
  rejected("lattice of 1200^3 needs terabytes", "spheres",
           {"gravity=[0,0,0]", "domain_hi=[5,5,5]", "lattice[0].count=[1200,1200,1200]", "lattice[0].spacing=0.004",
            "lattice[0].jitter=0"},
           {"key 'count'", "of host memory", "available"});
  rejected("fill of 1e9 particles", "spheres",
           {"gravity=[0,0,0]", "particle_type[0].radius=0.02", "lattice[0].count=[1,1,1]", "lattice[0].origin=[1,1,1]",
            "lattice[0].spacing=0.05", "particles[0].positions=[[2,2,2]]", "fill[0].lo=[3,3,3]", "fill[0].hi=[59,59,59]", "domain_hi=[60,60,60]",
            "fill[0].count=1000000000"},
           {"key 'count'", "of host memory"});
  rejected("2^31 particles (Index overflow)", "spheres",
           {"gravity=[0,0,0]", "domain_hi=[200,200,200]", "fill[0].hi=[199,199,199]", "fill[0].count=2147483648"}, {"key 'count'"});
  rejected("lattice sites beyond 2^31 - 1", "spheres", {"lattice[0].count=[2000,2000,1000]"}, {"key 'count'"});
  rejected("dt of 1e-13 s: a run that cannot finish", "spheres", {"dt=1e-13", "end_time=1"}, {"key 'dt'", "days", "force_long_run"});
  rejected("end_time of 1e12 s: beyond 1e15 steps", "spheres", {"end_time=1e12"}, {"key 'dt'", "steps"});
  rejected("end_time of 1e8 s: months", "spheres", {"end_time=1e8"}, {"key 'dt'", "days"});
  rejected("dt larger than end_time", "spheres", {"end_time=5e-6"}, {"key 'end_time'", "shorter than one time step"});
  rejected("steps_per_contact with end_time below one step", "spheres", {"steps_per_contact=50", "end_time=1e-7"},
           {"key 'end_time'"});
  c.push_back({"force_long_run lets --check pass", "spheres", {}, {"dt=1e-13", "force_long_run=true", "force_dt=true"},
               Expect::runs, {"size:"}, true});
  runs("csv_interval of 1e300 s (no overflow)", "spheres", {"output.csv_interval=1e300"});
  rejected("vtu_interval below dt", "spheres", {"output.vtu_interval=1e-9"}, {"key 'vtu_interval'", "shorter than one time step"});
  runs("vtu_interval of one step", "spheres", {"output.vtu_interval=1e-5", "end_time=5e-5"});
  rejected("checkpoint_interval below dt", "spheres", {"output.checkpoint_interval=1e-300"}, {"key 'checkpoint_interval'"});
  runs("checkpoint_interval of 1e300 s", "spheres", {"output.checkpoint_interval=1e300"});
  runs("large skin: long neighbour lists", "spheres", {"skin=10"});
  runs("skin 0: rebuild whenever anything moves", "spheres", {"skin=0"});
  runs("end_time not a multiple of dt", "spheres", {"end_time=1.00049e-3"});
  runs("a wall far away in a large domain", "spheres", {"domain_hi=[5, 0.1, 5]"});

  // --- 3. (restarts: test case restart_refuses_a_changed_scene below)
  // --- 4. initial particle-world overlaps, walls facing away, narrow drums
  rejected("particle deep in the floor", "spheres", {"particles[0].positions=[[0.0, 0.001, 0.0]]"},
           {"[[particles]] #1", "overlaps", "[[wall]] #1"});
  rejected("particle centre behind the floor", "spheres", {"particles[0].positions=[[0.0, -0.001, 0.0]]"},
           {"lies across", "[[wall]] #1"});
  rejected("particle on the floor's rim", "spheres", {"particles[0].positions=[[0.041, 0.001, 0.0]]"}, {"overlaps the rim"});
  runs("particle on the rim of a wall with rim = false", "spheres",
       {"particles[0].positions=[[0.041, 0.001, 0.0]]", "wall[0].rim=false"});
  runs("particle resting exactly on the floor (touching)", "spheres", {"particles[0].positions=[[0.0, 0.002, 0.0]]"});
  edited("floor facing down under the particles", "spheres",
         {{"vertices = [[-0.04, 0, -0.04], [-0.04, 0, 0.04], [0.04, 0, 0.04], [0.04, 0, -0.04]]",
           "vertices = [[-0.04, 0, -0.04], [0.04, 0, -0.04], [0.04, 0, 0.04], [-0.04, 0, 0.04]]"}},
         Expect::rejected, {"faces away", "opposite order"});
  rejected("lattice overlapping the floor", "spheres", {"lattice[0].origin=[-0.01, 0.0015, -0.01]"}, {"[[lattice]] #1", "[[wall]] #1"});
  rejected("bead outside the drum", "drum", {"lattice[0].origin=[-0.005, -0.02, 0.01]", "lattice[0].count=[2,1,1]", "lattice[0].spacing=0.06"},
           {"outside", "[[cylinder]] #1"});
  rejected("bead overlapping the drum", "drum", {"lattice[0].origin=[-0.045, -0.02, 0.01]"}, {"overlaps", "[[cylinder]] #1"});
  rejected("drum narrower than its beads", "drum",
           {"cylinder[0].radius=0.002", "lattice[0].count=[1,1,1]", "lattice[0].origin=[0,0,0.02]"}, {"wider", "[[cylinder]] #1"});
  rejected("bead deep in an end plate", "drum", {"lattice[0].origin=[-0.02, -0.02, 0.001]"}, {"[[wall]] #1"});
  rejected("cube vertex in the floor", "cubes", {"lattice[0].origin=[-0.01, 0.0022, -0.01]"}, {"vertex", "deep in", "[[wall]] #1"});
  runs("cube bounding sphere over the floor but no vertex in it", "cubes",
       {"lattice[0].origin=[-0.01, 0.0026, -0.01]", "lattice[0].random_orientation=false"});

  // --- 5. max_impact_speed below an initial speed
  rejected("max_impact_speed below a particle's speed", "spheres", {"max_impact_speed=0.5"}, {"key 'max_impact_speed'", "1 m/s"});
  rejected("max_impact_speed below a lattice velocity", "drum", {"lattice[0].velocity=[0,0,3]"}, {"key 'max_impact_speed'"});
  runs("max_impact_speed above every initial speed", "spheres", {"max_impact_speed=3"});

  // --- 6. --set grammar
  for (const char* key : {"material[0.density=1000", "material[0]density=1000", "material.0.density=1000",
                          "material[].density=1000", "material[x].density=1000", "material[0]=1000", "material.density=1000",
                          "simulation[0].dt=1e-5", "simulation..dt=1e-5", "simulation.dt.=1e-5", ".dt=1e-5", "[0].dt=1",
                          "material[0].density[1]=1", "material[99].density=1", "material[0].density==1", "=1", "dt=",
                          "dt", "d t=1e-5", "dt=1e-5 end_time=1", "precision=\"float", "dt=[1e-5", "simulation.dt=\"1e-5\""})
    rejected(std::string("--set ") + key, "spheres", {key}, {"--set"});
  rejected("--set value with a newline", "spheres", {"dt=1e-5\nend_time=100"}, {"control character"});
  rejected("--set value with a carriage return", "spheres", {"precision=float\r"}, {"control character"});

  // --- 7. float far from the origin
  const std::vector<std::string> far_away = {
      "gravity=[0,0,0]", "domain_lo=[9999.9, 9999.9, 9999.9]", "domain_hi=[10000.1, 10000.1, 10000.1]",
      "lattice[0].origin=[10000, 10000, 10000]", "particles[0].positions=[[10000, 10000.05, 10000]]",
      "fill[0].lo=[9999.95, 9999.95, 9999.95]", "fill[0].hi=[10000.05, 10000.0, 10000.05]",
      "wall[0].vertices=[[9999.95, 9999.91, 9999.95], [9999.95, 9999.91, 10000.05], [10000.05, 9999.91, 10000.05], [10000.05, 9999.91, 9999.95]]"};
  std::vector<std::string> far_float = far_away;
  far_float.push_back("precision=float");
  rejected("float 1e4 m from the origin", "spheres", far_float, {"key 'domain_hi'", "resolved to", "precision = \"double\""});
  runs("double 1e4 m from the origin", "spheres", far_away);

  // --- neighbouring classes: TOML, structure, names, files
  edited("TOML syntax: unclosed array", "spheres", {{"gravity = [0, -9.81, 0]", "gravity = [0, -9.81, 0"}}, Expect::rejected,
         {"TOML syntax error"});
  edited("TOML syntax: triple bracket", "spheres", {{"[[material]]\nname = \"glass\"", "[[[material]]]\nname = \"glass\""}},
         Expect::rejected, {"TOML syntax error"});
  edited("TOML syntax: duplicate key", "spheres", {{"dt = 1e-5", "dt = 1e-5\ndt = 2e-5"}}, Expect::rejected, {"TOML syntax error"});
  edited("TOML syntax: missing value", "spheres", {{"dt = 1e-5", "dt ="}}, Expect::rejected, {"TOML syntax error"});
  edited("TOML syntax: binary garbage", "spheres", {{"[simulation]", "[simulation]\n\x01\x02\x03"}}, Expect::rejected,
         {"TOML syntax error"});
  edited("unknown table", "spheres", {{"[output]", "[outptu]"}}, Expect::rejected, {"unknown table or key 'outptu'"});
  edited("unknown key in [simulation]", "spheres", {{"dt = 1e-5", "dt = 1e-5\ntimestep = 1"}}, Expect::rejected,
         {"unknown key 'timestep'"});
  edited("unknown key in [[pair]]", "spheres", {{"friction = 0.3\ntangential_damping", "frictoin = 0.3\ntangential_damping"}},
         Expect::rejected, {"unknown key 'frictoin'"});
  edited("[simulation] written as array of tables", "spheres", {{"[simulation]", "[[simulation]]"}}, Expect::rejected,
         {"must be a table"});
  edited("[[material]] written as a table", "spheres",
         {{"[[material]]\nname = \"glass\"\ndensity = 2500\n[[material]]\nname = \"steel\"\ndensity = 7800",
           "[material]\nname = \"glass\"\ndensity = 2500"}},
         Expect::rejected, {"array of tables"});
  edited("no [simulation]", "spheres", {{"[simulation]", "[study]"}}, Expect::rejected, {"[simulation]"});
  edited("duplicate material name", "spheres", {{"name = \"steel\"", "name = \"glass\""}}, Expect::rejected, {"unique"});
  edited("pair of unknown material", "spheres", {{"materials = [\"glass\", \"steel\"]", "materials = [\"glass\", \"iron\"]"}},
         Expect::rejected, {"key 'materials'"});
  edited("missing pair for the wall", "spheres",
         {{"[[pair]]\nmaterials = [\"glass\", \"steel\"]\nstiffness = 2e4\nrestitution = 0.5\nfriction = 0.3", ""}}, Expect::rejected,
         {"no [[pair]]"});
  edited("same pair twice", "spheres", {{"materials = [\"glass\", \"steel\"]", "materials = [\"glass\", \"glass\"]"}},
         Expect::rejected, {"each pair once"});
  edited("particle type of unknown material", "spheres", {{"material = \"glass\"\nradius", "material = \"sand\"\nradius"}},
         Expect::rejected, {"key 'material'"});
  edited("radius and shape both", "spheres", {{"radius = 2e-3", "radius = 2e-3\nshape = \"data/shapes/cube.shape\""}},
         Expect::rejected, {"key 'radius'"});
  edited("missing shape file", "cubes", {{"data/shapes/cube.shape", "data/shapes/no_such.shape"}}, Expect::rejected,
         {"key 'shape'", "cannot be loaded"});
  edited("shape file is a directory", "cubes", {{"data/shapes/cube.shape", "data/shapes"}}, Expect::rejected, {"key 'shape'"});
  edited("shape file is a scene", "cubes", {{"data/shapes/cube.shape", "data/scenes/box_fill.toml"}}, Expect::rejected,
         {"key 'shape'"});
  edited("no particles", "cubes", {{"[[lattice]]\ntype = \"cube\"\norigin = [-0.01, 0.01, -0.01]\ncount = [3, 2, 3]\nspacing = 0.007", ""}},
         Expect::rejected, {"no particles"});
  edited("wall not planar", "spheres", {{"[0.04, 0, -0.04]]", "[0.04, 0.01, -0.04]]"}}, Expect::rejected, {"off the plane"});
  edited("wall not convex", "spheres", {{"[0.04, 0, 0.04], [0.04, 0, -0.04]]", "[0.0, 0, -0.03], [0.04, 0, -0.04]]"}},
         Expect::rejected, {"key 'vertices'"});
  edited("wall of two vertices", "spheres",
         {{"vertices = [[-0.04, 0, -0.04], [-0.04, 0, 0.04], [0.04, 0, 0.04], [0.04, 0, -0.04]]",
           "vertices = [[-0.04, 0, -0.04], [0.04, 0, 0.04]]"}},
         Expect::rejected,
         {"key 'vertices'"});
  edited("overlapping placements", "spheres", {{"positions = [[0.0, 0.04, 0.0]]", "positions = [[-0.01, 0.01, -0.01]]"}},
         Expect::rejected, {"overlaps particle"});
  edited("fill too dense", "spheres", {{"count = 5", "count = 5000"}}, Expect::rejected, {"key 'count'", "0.3"});
  edited("velocities shorter than positions", "spheres",
         {{"positions = [[0.0, 0.04, 0.0]]", "positions = [[0.0, 0.04, 0.0], [0.01, 0.04, 0.0]]"}}, Expect::rejected,
         {"key 'velocities'"});
  edited("lattice outside the domain", "spheres", {{"count = [3, 2, 3]", "count = [30, 2, 3]"}}, Expect::rejected,
         {"inside the domain"});
  rejected("backend of the other build", "spheres", {gpu_build ? "backend=cpu" : "backend=gpu"}, {"key 'backend'"});
  rejected("dt above the safe fraction", "spheres", {"dt=1e-4"}, {"key 'dt'", "force_dt"});
  rejected("impact overlap beyond half the radius", "spheres", {"pair[1].stiffness=5"}, {"max_impact_speed"});
  rejected("more than 8 materials", "spheres", {}, {}, true);  // replaced below by a generated text
  c.back().sets.clear();
  {
    std::string extra;
    for (int k = 0; k < 8; ++k) extra += "[[material]]\nname = \"m" + std::to_string(k) + "\"\ndensity = 1000\n";
    c.back().edits = {{"[[pair]]\nmaterials = [\"glass\", \"glass\"]", extra + "[[pair]]\nmaterials = [\"glass\", \"glass\"]"}};
    c.back().must = {"at most 8"};
  }

  // --- contact history (issue 18): the tangential law's keys
  const std::pair<std::string, std::string> no_kt{"tangential_damping = 0.1\n", ""};
  edited("spheres with the linear tangential spring", "spheres", {{"law = \"linear\"", "law = \"linear\"\ntangential = \"linear_spring\""}, no_kt},
         Expect::runs, {"linear tangential spring"});
  edited("linear spring with its stiffness", "spheres",
         {{"law = \"linear\"", "law = \"linear\"\ntangential = \"linear_spring\""}, {"tangential_damping = 0.1", "tangential_stiffness = 5e3"}},
         Expect::runs, {"tangential spring"});
  runs("drum with the Mindlin spring", "drum", {"tangential=\"mindlin\""}, {"Mindlin tangential spring"});
  rejected("Mindlin with the linear law", "spheres", {"tangential=\"mindlin\""}, {"key 'tangential'", "hertz"});
  rejected("linear spring with Hertz", "drum", {"tangential=\"linear_spring\""}, {"key 'tangential'", "linear"});
  rejected("unknown tangential law", "spheres", {"tangential=\"sticky\""}, {"key 'tangential'", "history_free"});
  edited("K_T given to the linear spring", "spheres", {{"law = \"linear\"", "law = \"linear\"\ntangential = \"linear_spring\""}},
         Expect::rejected, {"tangential_damping"});
  edited("tangential_stiffness with the history-free law", "spheres", {{"tangential_damping = 0.1", "tangential_stiffness = 5e3"}},
         Expect::rejected, {"tangential_stiffness"});
  const std::pair<std::string, std::string> spring{"law = \"linear\"", "law = \"linear\"\ntangential = \"linear_spring\""};
  for (const char* model : {"cdt", "epsd"})
    c.push_back({std::string("spheres with rolling ") + model, "spheres",
                 {{"law = \"linear\"", std::string("law = \"linear\"\ntangential = \"linear_spring\"\nrolling = \"") + model + "\""}, no_kt},
                 {"pair[0].rolling_friction=0.1"}, Expect::runs, {"rolling resistance"}, false});
  edited("rolling without a spring", "spheres", {{"law = \"linear\"", "law = \"linear\"\nrolling = \"cdt\""}}, Expect::rejected,
         {"key 'rolling'", "tangential spring"});
  edited("rolling with polyhedra", "cubes", {{"law = \"linear\"", "law = \"linear\"\ntangential = \"linear_spring\"\nrolling = \"epsd\""}},
         Expect::rejected, {"rolling", "spheres"});
  edited("rolling_friction without rolling", "spheres", {spring, no_kt, {"friction = 0.3\n", "friction = 0.3\nrolling_friction = 0.1\n"}},
         Expect::rejected, {"rolling_friction"});
  for (const auto& v : {"-1", "0", "nan", "2", "1e300"})
    c.push_back({std::string("odd rolling_friction = ") + v, "spheres",
                 {{"law = \"linear\"", "law = \"linear\"\ntangential = \"linear_spring\"\nrolling = \"epsd\""}, no_kt},
                 {std::string("pair[0].rolling_friction=") + v}, Expect::either, {}, false});
  for (const auto& v : {"-1", "0", "nan", "\"text\""})
    c.push_back({std::string("odd rolling_damping = ") + v, "spheres",
                 {{"law = \"linear\"", "law = \"linear\"\ntangential = \"linear_spring\"\nrolling = \"epsd\""}, no_kt},
                 {std::string("pair[0].rolling_damping=") + v}, Expect::either, {}, false});
  for (const auto& v : {"-1", "0", "nan", "1e300", "\"text\""})
    c.push_back({std::string("odd tangential_stiffness = ") + v, "spheres",
                 {{"law = \"linear\"", "law = \"linear\"\ntangential = \"linear_spring\""}, no_kt},
                 {std::string("pair[0].tangential_stiffness=") + v}, Expect::either, {}, false});

  // --- sweeps: odd values of every number, vector and choice key (either refused by key, or run)
  const std::vector<std::string> odd_numbers = {"-1", "0", "nan", "inf", "-inf", "1e300", "1e-300", "\"text\"", "[1, 2]", "true"};
  for (const char* key : {"dt", "end_time", "drag", "skin", "max_impact_speed", "seed", "output.csv_interval",
                          "output.vtu_interval", "output.checkpoint_interval", "output.penetration_warning",
                          "output.energy_gain_limit", "material[0].density", "pair[0].stiffness", "pair[0].restitution",
                          "pair[0].friction", "pair[0].tangential_damping", "particle_type[0].radius", "lattice[0].spacing",
                          "lattice[0].jitter", "fill[0].count"})
    for (const auto& v : odd_numbers)
      c.push_back({std::string("odd ") + key + " = " + v, "spheres", {}, {std::string(key) + "=" + v}, Expect::either, {}, false,
                   std::string(key) == "output.energy_gain_limit"});  // a limit of 1e-300 is below the integrator's wobble
  for (const char* key : {"material[0].youngs_modulus", "material[0].poisson_ratio", "cylinder[0].radius", "cylinder[0].length"})
    for (const auto& v : {"-1", "0", "nan", "0.5", "1e300"})
      c.push_back({std::string("odd drum ") + key + " = " + v, "drum", {}, {std::string(key) + "=" + v}, Expect::either, {}, false});
  const std::vector<std::string> odd_vectors = {"[nan, 0, 0]", "[1e300, 0, 0]", "[0, 0]", "\"x\"", "[[0, 0, 0]]", "[inf, 0, 0]"};
  for (const char* key : {"gravity", "domain_lo", "domain_hi", "lattice[0].origin", "lattice[0].velocity", "fill[0].lo",
                          "cylinder[0].axis"})
    for (const auto& v : odd_vectors)
      c.push_back({std::string("odd ") + key + " = " + v, std::string(key).rfind("cylinder", 0) == 0 ? "drum" : "spheres", {},
                   {std::string(key) + "=" + v}, Expect::either, {}, false});
  for (const char* key : {"law", "precision", "backend", "pair_evaluation", "tangential"})
    for (const auto& v : {"bogus", "1", "\"\""})
      c.push_back({std::string("odd ") + key + " = " + v, "spheres", {}, {std::string(key) + "=" + v}, Expect::either, {}, false});
  for (const auto& v : {"[[0, 0, 0]]", "[]", "[[nan, 0, 0]]", "[[0.2, 0.05, 0]]"})
    c.push_back({std::string("odd positions = ") + v, "spheres", {}, {std::string("particles[0].positions=") + v}, Expect::either,
                 {}, false});
  for (const auto& v : {"[0, 1, 1]", "[1, 1, -1]", "[1.5, 1, 1]", "[3000000000, 1, 1]"})
    c.push_back({std::string("odd lattice count = ") + v, "cubes", {}, {std::string("lattice[0].count=") + v}, Expect::either, {},
                 false});
  return c;
}

}  // namespace blaze::test::adversarial
