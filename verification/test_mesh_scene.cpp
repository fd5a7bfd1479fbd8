// [[mesh]] in scene files (issue 20; src/scene_toml.cpp, scene_build.hpp, world_overlap.hpp):
// - a binary STL in millimetres, scaled, rotated and translated, becomes one mesh object whose
//   vertices lie where the transform puts them; balls poured on it come to rest at the height of
//   the same floor given as a [[wall]] (the run through the whole pipeline, motion included);
// - what the repair changed (a flipped triangle, a repeated one) is a note naming the file;
// - bad meshes and bad keys are refused naming the scene file, the [[mesh]] and the key: a missing
//   file, a truncated STL, a file that is no mesh, scale <= 0, an unknown material, a bad rotate,
//   an unknown key, a still mesh or wall that no particle can reach (wholly beyond a particle
//   diameter from the domain); a particle placed across or into a mesh is refused naming the mesh and its
//   triangle; a [[fill]] avoids the mesh; a wall or mesh facing away from the beads that fall
//   onto it, or that a feed throws at it, is refused;
// - the world's VTU lists the mesh's triangles.
#include <boost/test/unit_test.hpp>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <sstream>
#include "blaze/io/mesh_io.hpp"
#include "blaze/io/vtu_writer.hpp"
#include "blaze/scene/scene_build.hpp"
#include "blaze/scene/scene_file.hpp"
#include "blaze/shapes/sphere_shape.hpp"
#include "pipeline/scene_params.hpp"
#include "verification/tolerances.hpp"

using namespace blaze;

namespace {

std::string temp(const std::string& name) { return (std::filesystem::temp_directory_path() / name).string(); }

// A square floor of side 2a (file units) in the plane z = 0, normal +z, as n x n cells of two
// triangles.
TriangleMesh floor_mesh(double a, int n) {
  TriangleMesh m;
  const double h = 2 * a / n;
  for (int j = 0; j <= n; ++j)
    for (int i = 0; i <= n; ++i) m.vertices.push_back({-a + i * h, -a + j * h, 0});
  for (int j = 0; j < n; ++j)
    for (int i = 0; i < n; ++i) {
      const int p = j * (n + 1) + i;
      m.triangles.push_back({p, p + 1, p + n + 2});
      m.triangles.push_back({p, p + n + 2, p + n + 1});
    }
  return m;
}

// Balls over a floor at y = 0 (normal +y), given as a [[mesh]] (the STL lies in z = 0 and is
// turned by -90 degrees about x) or as a [[wall]].
std::string floor_scene(const std::string& floor_block, const std::string& extra = "") {
  return R"(
[simulation]
law = "hertz"
precision = "double"
dt = 2e-6
end_time = 0.2
gravity = [0, -9.81, 0]
domain_lo = [-0.1, -0.05, -0.1]
domain_hi = [0.1, 0.15, 0.1]
[[material]]
name = "glass"
density = 2500
youngs_modulus = 1e8
poisson_ratio = 0.25
[[material]]
name = "steel"
density = 7800
youngs_modulus = 2e9
poisson_ratio = 0.3
[[pair]]
materials = ["glass", "glass"]
restitution = 0.3
friction = 0.3
[[pair]]
materials = ["glass", "steel"]
restitution = 0.3
friction = 0.3
[[particle_type]]
name = "bead"
material = "glass"
radius = 4e-3
[[lattice]]
type = "bead"
origin = [-0.03, 0.006, -0.03]
count = [4, 1, 4]
spacing = 0.02
)" + floor_block + extra;
}

const char* const kMeshFloor = R"(
[[mesh]]
name = "floor"
file = "FILE"
material = "steel"
scale = 0.001
rotate = { axis = [1, 0, 0], degrees = -90 }
translate = [0.0, 0.0, 0.0]
)";
const char* const kWallFloor = R"(
[[wall]]
material = "steel"
vertices = [[-0.08, 0, -0.08], [-0.08, 0, 0.08], [0.08, 0, 0.08], [0.08, 0, -0.08]]
)";

std::string with_file(std::string block, const std::string& file) {
  block.replace(block.find("FILE"), 4, file);
  return block;
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

using Sim = Simulation<DefaultSpace, SphereShape, HertzLaw<double>, VelocityVerlet>;

// The balls' mean height after the run; with `load`, the load on world object 0 against the
// weight: max(|F_y - M g_y| / |M g|, |T - sum x_i m_i g| / (|M g| L)), L = 0.1 m (the balls,
// history-free, still creep: the floor's tangential load is left out).
double mean_height(const Scene& s, double* load = nullptr) {
  Sim sim(simulation_params<double>(s, false), build_laws<HertzLaw<double>>(s), build_world<double>(s), build_particles<double>(s, nullptr));
  sim.run(static_cast<std::uint64_t>(std::llround(s.end_time / s.dt)));
  const auto st = sim.state();
  double y = 0, mass = 0;
  Vec3<double> moment{0, 0, 0};
  for (std::size_t k = 0; k < st.size(); ++k) {
    y += st.position[k].y, mass += st.mass[k];
    moment += cross(st.position[k], s.gravity * st.mass[k]);
  }
  if (load) {
    const auto l = sim.world_loads({0});
    const Vec3<double> weight = s.gravity * mass;
    *load = std::fmax(std::fabs(l[0].force.y - weight.y) / norm(weight), norm(l[0].torque - moment) / (norm(weight) * 0.1));
    BOOST_TEST_MESSAGE("load on the floor (" << l[0].force.x << ", " << l[0].force.y << ", " << l[0].force.z << ") N (weight " << weight.y << " N), torque (" << l[0].torque.x << ", "
                                            << l[0].torque.y << ", " << l[0].torque.z << ") N m vs (" << moment.x << ", " << moment.y << ", "
                                            << moment.z << ")");
  }
  return y / static_cast<double>(st.size());
}

}  // namespace

BOOST_AUTO_TEST_SUITE(mesh_scene)

BOOST_AUTO_TEST_CASE(mesh_is_placed_and_holds_balls_as_a_wall_does) {
  const std::string stl = temp("blaze_floor_mm.stl");
  write_binary_stl(floor_mesh(80, 16), stl);  // 160 mm square, 512 triangles
  const Scene s = parse_scene(floor_scene(with_file(kMeshFloor, stl)), "mesh.toml");
  BOOST_TEST_REQUIRE(s.meshes.size() == 1u);
  const World<double> w = build_world<double>(s);
  BOOST_TEST_REQUIRE(w.meshes.size() == 1u);
  BOOST_TEST(w.meshes[0].mesh.size() == 512u);
  // (x, y, 0) mm turned -90 degrees about x: (x, 0, -y) m... then +z normal becomes +y
  double worst = 0;
  for (const auto& v : w.meshes[0].mesh.vertices) worst = std::fmax(worst, std::fabs(v.y));
  BOOST_TEST(worst < 1e-15);
  const Vec3<double> n = w.meshes[0].mesh.area_vector(0);
  BOOST_TEST(n.y > 0);
  BOOST_TEST(std::fabs(w.meshes[0].mesh.vertices[0].x + 0.08) < 1e-15);
  BOOST_TEST(std::fabs(w.meshes[0].mesh.vertices[0].z - 0.08) < 1e-15);
  double load = 0;
  const double on_mesh = mean_height(s, &load);
  BOOST_TEST_MESSAGE("the mesh's load against the balls' weight and moment: " << load);
  BOOST_TEST(load < tol::mesh_walls_resting_load, "the mesh's load against the balls' weight and moment: " << load);
  const double on_wall = mean_height(parse_scene(floor_scene(kWallFloor), "wall.toml"));
  BOOST_TEST_MESSAGE("mean height on the mesh " << on_mesh << " m, on the wall " << on_wall << " m");
  BOOST_TEST(on_mesh > 0.0039);  // resting on the floor, not through it
  BOOST_TEST(std::fabs(on_mesh - on_wall) < tol::mesh_walls_flat_trajectory * 0.004);
}

BOOST_AUTO_TEST_CASE(repairs_are_noted_and_bad_meshes_refused) {
  TriangleMesh m = floor_mesh(80, 4);
  std::swap(m.triangles[5][1], m.triangles[5][2]);  // one triangle against its neighbours
  m.triangles.push_back(m.triangles[2]);             // and one repeated
  const std::string stl = temp("blaze_floor_flawed.stl");
  write_binary_stl(m, stl);
  const Scene s = parse_scene(floor_scene(with_file(kMeshFloor, stl)), "mesh.toml");
  std::string notes;
  for (const auto& n : s.notes) notes += n + "\n";
  BOOST_TEST(has(notes, "1 triangles flipped to agree with their neighbours (triangle 6)"), notes);
  BOOST_TEST(has(notes, "1 repeated triangles dropped (triangle 33)"), notes);
  BOOST_TEST(has(notes, "[[mesh]] #1"), notes);

  const std::string block = with_file(kMeshFloor, stl);
  const auto refused = [&](const std::string& scene_text, std::initializer_list<const char*> parts) {
    const std::string msg = rejection([&] { parse_scene(scene_text, "bad.toml"); });
    for (const char* p : parts) BOOST_TEST(has(msg, p), "message '" << msg << "' lacks '" << p << "'");
  };
  refused(floor_scene(with_file(kMeshFloor, temp("blaze_no_such_mesh.stl"))), {"bad.toml:", "[[mesh]] #1", "key 'file'", "cannot open"});
  {
    std::ifstream in(stl, std::ios::binary);
    std::string bytes((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    std::ofstream(temp("blaze_truncated.stl"), std::ios::binary) << bytes.substr(0, bytes.size() - 20);
    std::ofstream(temp("blaze_not_a_mesh.stl")) << "this is not a mesh\n";
  }
  refused(floor_scene(with_file(kMeshFloor, temp("blaze_truncated.stl"))), {"[[mesh]] #1", "key 'file'", "binary STL", "header announces 33 triangles", "truncated"});
  refused(floor_scene(with_file(kMeshFloor, temp("blaze_not_a_mesh.stl"))), {"[[mesh]] #1", "key 'file'", "ASCII"});
  const auto edited = [&](const std::string& from, const std::string& to) {
    std::string b = block;
    b.replace(b.find(from), from.size(), to);
    return floor_scene(b);
  };
  refused(edited("scale = 0.001", "scale = 0"), {"[[mesh]] #1", "key 'scale'", "m per file unit"});
  refused(edited("scale = 0.001", "scale = -1"), {"key 'scale'"});
  refused(edited("material = \"steel\"", "material = \"gold\""), {"[[mesh]] #1", "key 'material'"});
  refused(edited("degrees = -90", "angle = -90"), {"rotate", "unknown key 'angle'"});
  refused(edited("rotate = { axis = [1, 0, 0], degrees = -90 }", "rotate = { axis = [0, 0, 0], degrees = 5 }"), {"key 'axis'", "non-zero"});
  refused(edited("name = \"floor\"", "colour = \"red\""), {"[[mesh]] #1", "unknown key 'colour'"});
  refused(edited("file = ", "nofile = "), {"[[mesh]] #1"});
  // a still mesh or wall that no particle can reach (wholly beyond a bead's diameter, 8 mm, from
  // the domain: y in [-0.05, 0.15]) is a placement mistake; one with a motion may come in later
  refused(edited("translate = [0.0, 0.0, 0.0]", "translate = [0.0, 5.0, 0.0]"),
          {"bad.toml:", "[[mesh]] #1", "key 'file'", "a mesh that particles can reach", "spans [", ", 5, "});
  refused(edited("translate = [0.0, 0.0, 0.0]", "translate = [0.0, -0.059, 0.0]"), {"no triangle comes within a particle diameter (0.008 m)"});
  BOOST_TEST(rejection([&] { parse_scene(edited("translate = [0.0, 0.0, 0.0]", "translate = [0.0, -0.057, 0.0]"), "ok.toml"); }) == "(accepted)");
  BOOST_TEST(rejection([&] {
    parse_scene(edited("translate = [0.0, 0.0, 0.0]", "translate = [0.0, 5.0, 0.0]\nmotion = { kind = \"translation\", velocity = [0, -1, 0] }"), "ok.toml");
  }) == "(accepted)");
  {
    std::string far = kWallFloor;  // the floor as a [[wall]], 20 cm beside the domain (x in [-0.1, 0.1])
    const std::string up = "[[-0.08, 0, -0.08], [-0.08, 0, 0.08], [0.08, 0, 0.08], [0.08, 0, -0.08]]";
    far.replace(far.find(up), up.size(), "[[0.3, 0, -0.08], [0.3, 0, 0.08], [0.4, 0, 0.08], [0.4, 0, -0.08]]");
    refused(floor_scene(far), {"[[wall]] #1", "key 'vertices'", "a polygon that particles can reach"});
  }
  // a particle across the mesh, and one into it
  const std::string across = floor_scene(block, "[[particles]]\ntype = \"bead\"\npositions = [[0.002, -0.001, 0.003]]\n");
  const std::string into = floor_scene(block, "[[particles]]\ntype = \"bead\"\npositions = [[0.002, 0.003, 0.003]]\n");
  const auto build = [](const std::string& text) { build_particles<double>(parse_scene(text, "bad.toml"), nullptr); };
  std::string msg = rejection([&] { build(across); });
  BOOST_TEST((has(msg, "[[mesh]] #1 'floor'") && has(msg, "lies across") && has(msg, "triangle")), msg);
  msg = rejection([&] { build(into); });
  BOOST_TEST((has(msg, "[[mesh]] #1 'floor'") && has(msg, "overlaps by 0.001 m")), msg);
  // a floor that faces away from the balls over it (flipped, or turned the other way), as a
  // [[wall]] that does is refused (stop 49: the balls fell through its back), with the way out
  const std::string flipped = edited("translate = ", "flip = true\ntranslate = ");
  msg = rejection([&] { build(flipped); });
  BOOST_TEST((has(msg, "bad.toml:") && has(msg, "[[mesh]] #1: key 'file'") && has(msg, "faces away from the particles over it") &&
              has(msg, "of 16 looked at") && has(msg, "set flip = false")), msg);
  msg = rejection([&] { build(edited("degrees = -90", "degrees = 90")); });
  BOOST_TEST((has(msg, "faces away") && has(msg, "set flip = true")), msg);
  BOOST_TEST(rejection([&] { build(floor_scene(block)); }) == "(accepted)");
  // the same with no particle at the start, only a feed over the floor (stop 50: a scene of feeds
  // alone was never looked at): its region's centres are
  const auto fed = [](std::string text) {
    const std::string lattice = text.substr(text.find("[[lattice]]"), text.find("spacing = 0.02\n") + 15 - text.find("[[lattice]]"));
    text.replace(text.find(lattice), lattice.size(), "");
    return text + "[[feed]]\ntype = \"bead\"\nregion = { kind = \"box\", lo = [-0.05, 0.05, -0.05], hi = [0.05, 0.1, 0.05] }\nrate = 1000\n";
  };
  BOOST_TEST_REQUIRE(fed(flipped).find("[[lattice]]") == std::string::npos);
  msg = rejection([&] { build(fed(flipped)); });
  BOOST_TEST((has(msg, "faces away from the particles over it") && has(msg, "of 64 looked at") && has(msg, "set flip = false")), msg);
  BOOST_TEST(rejection([&] { build(fed(floor_scene(block))); }) == "(accepted)");
  // and a [[wall]] floor facing away from a feed
  const std::string wall_fed = fed(floor_scene(kWallFloor));
  BOOST_TEST(rejection([&] { build(wall_fed); }) == "(accepted)");
  std::string turned = wall_fed;
  const std::string up = "[[-0.08, 0, -0.08], [-0.08, 0, 0.08], [0.08, 0, 0.08], [0.08, 0, -0.08]]";
  turned.replace(turned.find(up), up.size(), "[[0.08, 0, -0.08], [0.08, 0, 0.08], [-0.08, 0, 0.08], [-0.08, 0, -0.08]]");
  msg = rejection([&] { build(turned); });
  BOOST_TEST((has(msg, "[[wall]] #1: key 'vertices'") && has(msg, "faces away from the 64 particles over it")), msg);
}

// A feed that throws its beads sideways (+x) at a side wall, given as a [[wall]] or as a [[mesh]]
// (stop 52: only the fall along gravity was looked at, so a wall whose back met the throw was let
// through and the beads flew through it): refused when the wall faces away from the throw, naming
// the wall and the feed, accepted when it faces the beads; a throw along the wall or away from it
// does not look at it.
BOOST_AUTO_TEST_CASE(walls_facing_away_from_a_feeds_throw_are_refused) {
  const std::string stl = temp("blaze_side_wall.stl");
  write_binary_stl(floor_mesh(80, 8), stl);
  const auto fed = [](const std::string& side, const std::string& velocity) {
    std::string text = floor_scene(kWallFloor, side);
    const std::size_t from = text.find("[[lattice]]"), to = text.find("spacing = 0.02\n") + 15;
    text.replace(from, to - from, "");
    return text + "[[feed]]\ntype = \"bead\"\nregion = { kind = \"box\", lo = [-0.05, 0.05, -0.05], hi = [0.05, 0.1, 0.05] }\n"
                  "rate = 1000\nvelocity = " + velocity + "\n";
  };
  const auto build = [](const std::string& text) { build_particles<double>(parse_scene(text, "side.toml"), nullptr); };
  // the plane x = 0.08: normal +x (its back to the beads) or -x (facing them)
  const std::string away = "[[wall]]\nmaterial = \"steel\"\nvertices = [[0.08, 0, -0.08], [0.08, 0.15, -0.08], [0.08, 0.15, 0.08], [0.08, 0, 0.08]]\n";
  const std::string facing = "[[wall]]\nmaterial = \"steel\"\nvertices = [[0.08, 0, 0.08], [0.08, 0.15, 0.08], [0.08, 0.15, -0.08], [0.08, 0, -0.08]]\n";
  std::string msg = rejection([&] { build(fed(away, "[1, 0, 0]")); });
  BOOST_TEST((has(msg, "side.toml:") && has(msg, "[[wall]] #2: key 'vertices'") && has(msg, "faces away from the feed at") &&
              has(msg, "[[feed]] #1: key 'velocity'") && has(msg, "of 64 rays along its velocity, 64 meet this wall first") &&
              has(msg, "opposite order")),
             msg);
  BOOST_TEST(rejection([&] { build(fed(facing, "[1, 0, 0]")); }) == "(accepted)");
  BOOST_TEST(rejection([&] { build(fed(away, "[0, 0, 1]")); }) == "(accepted)");    // thrown along the wall
  BOOST_TEST(rejection([&] { build(fed(away, "[-1, 0, 0]")); }) == "(accepted)");   // thrown away from it
  msg = rejection([&] { build(fed(away, "[2, -1, 0]")); });  // thrown down towards it: some rays meet the floor first
  BOOST_TEST((has(msg, "[[wall]] #2: key 'vertices'") && has(msg, "throws its particles at its back")), msg);
  // the same wall as a mesh: the floor STL turned about y by +90 degrees (normal +z -> +x)
  const auto mesh = [&](const std::string& extra) {
    return "[[mesh]]\nname = \"side\"\nfile = \"" + stl + "\"\nmaterial = \"steel\"\nscale = 0.001\n" + extra +
           "rotate = { axis = [0, 1, 0], degrees = 90 }\ntranslate = [0.08, 0.07, 0.0]\n";
  };
  msg = rejection([&] { build(fed(mesh(""), "[1, 0, 0]")); });
  BOOST_TEST((has(msg, "[[mesh]] #1: key 'file'") && has(msg, "the mesh 'side' faces away from the feed at") &&
              has(msg, "meet this mesh first, from behind") && has(msg, "set flip = true")),
             msg);
  BOOST_TEST(rejection([&] { build(fed(mesh("flip = true\n"), "[1, 0, 0]")); }) == "(accepted)");
}

BOOST_AUTO_TEST_CASE(fills_avoid_meshes_and_the_vtu_shows_them) {
  const std::string stl = temp("blaze_floor_fill.stl");
  write_binary_stl(floor_mesh(80, 8), stl);
  // a fill whose box reaches through the floor: no bead overlaps it or lies across it (those
  // deeper behind it than their size are let through, as behind a [[wall]])
  const Scene s = parse_scene(floor_scene(with_file(kMeshFloor, stl), "[[fill]]\ntype = \"bead\"\ncount = 60\nlo = [-0.07, -0.04, -0.07]\nhi = [0.07, 0.06, 0.07]\n"),
                              "fill.toml");
  const auto p = build_particles<double>(s, nullptr);
  BOOST_TEST_REQUIRE(p.size() == 76u);
  long touching = 0, above = 0;  // beads within r of the floor inside its outline; beads over it
  for (std::size_t k = 0; k < p.size(); ++k) {
    const Vec3<double> x = p.position[k];
    const bool inside = std::fabs(x.x) < 0.08 && std::fabs(x.z) < 0.08;
    touching += inside && std::fabs(x.y) < p.radius[k];
    above += inside && x.y >= p.radius[k];
  }
  BOOST_TEST(touching == 0);
  BOOST_TEST(above > 40);
  const std::string vtu = temp("blaze_mesh_walls.vtu");
  write_world_vtu(vtu, build_world<double>(s));
  std::ifstream in(vtu);
  const std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  BOOST_TEST(has(text, "NumberOfCells=\"128\""), text.substr(0, 400));
}

BOOST_AUTO_TEST_SUITE_END()
