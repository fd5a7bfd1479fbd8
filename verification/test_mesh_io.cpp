// Triangle-mesh files (issue 20; blaze/io/mesh_io.hpp, blaze/world/triangle_mesh.hpp):
// - a cube written as ASCII STL, binary STL and OBJ (quads) reads back as the same closed mesh:
//   8 vertices after welding, 12 triangles, one piece, volume 1 (outward normals);
// - icospheres (80 to 1280 triangles) with a random 0-45% of their triangles reversed are
//   repaired: exactly those are flipped back, the volume is the sphere's to the tessellation; with
//   more than half reversed the majority's (inward) orientation is kept, and the volume is negative;
// - degenerate (repeated vertex, collinear) and repeated triangles are dropped and named;
// - open edges (a square of two triangles) and non-manifold edges (a fin) are counted, not refused;
//   a Moebius strip (one-sided) is refused naming the file and a triangle;
// - malformed files are refused naming the file and the line (ASCII, OBJ) or the size (binary);
// - welding joins vertices within the tolerance and no others.
#include <boost/test/unit_test.hpp>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <map>
#include <random>
#include "blaze/io/mesh_io.hpp"
#include "verification/report.hpp"
#include "verification/tolerances.hpp"

using namespace blaze;

namespace {

std::string temp(const std::string& name) { return (std::filesystem::temp_directory_path() / name).string(); }

TriangleMesh cube(double side) {
  TriangleMesh m;
  for (int k = 0; k < 8; ++k) m.vertices.push_back({side * (k & 1), side * ((k >> 1) & 1), side * ((k >> 2) & 1)});
  // outward, counter-clockwise seen from outside
  const int quads[6][4] = {{0, 2, 3, 1}, {4, 5, 7, 6}, {0, 1, 5, 4}, {2, 6, 7, 3}, {0, 4, 6, 2}, {1, 3, 7, 5}};
  for (const auto& q : quads) {
    m.triangles.push_back({q[0], q[1], q[2]});
    m.triangles.push_back({q[0], q[2], q[3]});
  }
  return m;
}

// An icosahedron subdivided `levels` times onto the unit sphere (20 * 4^levels triangles, outward).
TriangleMesh icosphere(int levels) {
  const double t = (1 + std::sqrt(5.0)) / 2;
  TriangleMesh m;
  for (const auto& v : std::vector<Vec3<double>>{{-1, t, 0}, {1, t, 0}, {-1, -t, 0}, {1, -t, 0}, {0, -1, t}, {0, 1, t},
                                                 {0, -1, -t}, {0, 1, -t}, {t, 0, -1}, {t, 0, 1}, {-t, 0, -1}, {-t, 0, 1}})
    m.vertices.push_back(v * (1 / norm(v)));
  m.triangles = {{0, 11, 5}, {0, 5, 1},  {0, 1, 7},   {0, 7, 10}, {0, 10, 11}, {1, 5, 9}, {5, 11, 4}, {11, 10, 2}, {10, 7, 6}, {7, 1, 8},
                 {3, 9, 4},  {3, 4, 2},  {3, 2, 6},   {3, 6, 8},  {3, 8, 9},   {4, 9, 5}, {2, 4, 11}, {6, 2, 10},  {8, 6, 7},  {9, 8, 1}};
  for (int l = 0; l < levels; ++l) {
    std::map<std::pair<int, int>, int> mid;
    const auto middle = [&](int a, int b) {
      const auto key = std::make_pair(std::min(a, b), std::max(a, b));
      const auto it = mid.find(key);
      if (it != mid.end()) return it->second;
      const Vec3<double> v = m.vertices[static_cast<std::size_t>(a)] + m.vertices[static_cast<std::size_t>(b)];
      m.vertices.push_back(v * (1 / norm(v)));
      return mid[key] = static_cast<int>(m.vertices.size()) - 1;
    };
    std::vector<std::array<int, 3>> next;
    for (const auto& tr : m.triangles) {
      const int a = middle(tr[0], tr[1]), b = middle(tr[1], tr[2]), c = middle(tr[2], tr[0]);
      next.push_back({tr[0], a, c}), next.push_back({tr[1], b, a}), next.push_back({tr[2], c, b}), next.push_back({a, b, c});
    }
    m.triangles = next;
  }
  return m;
}

void write_ascii_stl(const TriangleMesh& m, const std::string& path) {
  std::ofstream out(path);
  out.precision(17);
  out << "solid test\n";
  for (std::size_t t = 0; t < m.size(); ++t) {
    out << "  facet normal 0 0 0\n    outer loop\n";
    for (int k = 0; k < 3; ++k) out << "      vertex " << m.corner(t, k).x << ' ' << m.corner(t, k).y << ' ' << m.corner(t, k).z << '\n';
    out << "    endloop\n  endfacet\n";
  }
  out << "endsolid test\n";
}

void write_text(const std::string& path, const std::string& text) { std::ofstream(path) << text; }

std::string error_of(const std::string& path) {
  try {
    MeshReport r;
    load_mesh(path, r);
  } catch (const MeshError& e) {
    return e.what();
  }
  return "";
}

// Every edge of two triangles is run in opposite directions by them.
bool consistent(const TriangleMesh& m) {
  std::map<std::pair<int, int>, int> directed;
  for (const auto& t : m.triangles)
    for (int k = 0; k < 3; ++k) ++directed[{t[static_cast<std::size_t>(k)], t[static_cast<std::size_t>((k + 1) % 3)]}];
  for (const auto& d : directed)
    if (d.second > 1) return false;
  return true;
}

}  // namespace

BOOST_AUTO_TEST_SUITE(mesh_io)

BOOST_AUTO_TEST_CASE(a_cube_reads_the_same_from_every_format) {
  const TriangleMesh c = cube(0.5);
  write_ascii_stl(c, temp("blaze_cube_ascii.stl"));
  write_binary_stl(c, temp("blaze_cube_binary.stl"));
  {
    std::ofstream obj(temp("blaze_cube.obj"));
    for (const auto& v : c.vertices) obj << "v " << v.x << ' ' << v.y << ' ' << v.z << '\n';
    const int quads[6][4] = {{0, 2, 3, 1}, {4, 5, 7, 6}, {0, 1, 5, 4}, {2, 6, 7, 3}, {0, 4, 6, 2}, {1, 3, 7, 5}};
    for (const auto& q : quads) obj << "f " << q[0] + 1 << "/1/1 " << q[1] + 1 << ' ' << q[2] + 1 << ' ' << q[3] - 8 << '\n';  // relative last
  }
  for (const char* f : {"blaze_cube_ascii.stl", "blaze_cube_binary.stl", "blaze_cube.obj"}) {
    MeshReport r;
    const TriangleMesh m = load_mesh(temp(f), r);
    BOOST_TEST(m.vertices.size() == 8u, f);
    BOOST_TEST(m.size() == 12u, f);
    BOOST_TEST(r.closed(), f);
    BOOST_TEST(r.pieces == 1, f);
    BOOST_TEST(r.flipped == 0, f);
    BOOST_TEST(std::fabs(m.signed_volume() - 0.125) < tol::mesh_volume_exact, f << ": volume " << m.signed_volume());
    BOOST_TEST(consistent(m), f);
    std::filesystem::remove(temp(f));
  }
}

BOOST_AUTO_TEST_CASE(reversed_triangles_are_turned_back_to_the_majority) {
  std::mt19937_64 rng(20);
  for (int level : {1, 2, 3})
    for (double fraction : {0.0, 0.05, 0.3, 0.45, 0.7}) {
      TriangleMesh m = icosphere(level);
      const double v0 = m.signed_volume();
      long reversed = 0;
      for (auto& t : m.triangles)
        if (std::uniform_real_distribution<double>(0, 1)(rng) < fraction) std::swap(t[1], t[2]), ++reversed;
      const std::string path = temp("blaze_sphere.stl");
      write_binary_stl(m, path);
      MeshReport r;
      const TriangleMesh back = load_mesh(path, r);
      const long n = static_cast<long>(m.size());
      const bool majority_out = 2 * reversed < n;
      BOOST_TEST(r.closed());
      BOOST_TEST(consistent(back), level << ", " << fraction);
      BOOST_TEST(r.flipped == (majority_out ? reversed : n - reversed), level << ", " << fraction << ": flipped " << r.flipped);
      const double v = back.signed_volume();
      BOOST_TEST(std::fabs(std::fabs(v) - v0) < tol::mesh_volume_float * v0, level << ", " << fraction << ": volume " << v << " vs " << v0);
      BOOST_TEST((v > 0) == majority_out);
      BOOST_TEST((v0 < 4.0 / 3.0 * 3.14159265358979 && v0 > (level >= 2 ? 0.95 : 0.8) * 4.0 / 3.0 * 3.14159265358979));
      std::filesystem::remove(path);
    }
}

BOOST_AUTO_TEST_CASE(degenerate_and_repeated_triangles_are_dropped_and_named) {
  TriangleMesh m = cube(1);
  m.triangles.push_back({0, 0, 5});   // 13: a repeated vertex
  m.vertices.push_back({0.5, 0, 0});  // on the edge 0-1
  m.triangles.push_back({0, 8, 1});   // 14: collinear, no area
  m.triangles.push_back({3, 2, 0});   // 15: triangle 1 reversed: the same three vertices
  const std::string path = temp("blaze_dirty.stl");
  write_ascii_stl(m, path);
  MeshReport r;
  const TriangleMesh back = load_mesh(path, r);
  BOOST_TEST(back.size() == 12u);
  BOOST_TEST(r.degenerate == 2);
  BOOST_TEST(r.duplicate == 1);
  BOOST_TEST(r.closed());
  BOOST_TEST(std::fabs(back.signed_volume() - 1) < tol::mesh_volume_exact);
  const std::string s = r.summary();
  BOOST_TEST(s.find("2 degenerate triangles dropped (triangles 13, 14)") != std::string::npos, s);
  BOOST_TEST(s.find("1 repeated triangles dropped (triangle 15)") != std::string::npos, s);
  std::filesystem::remove(path);
}

BOOST_AUTO_TEST_CASE(open_and_non_manifold_edges_are_counted_and_a_one_sided_strip_refused) {
  {
    TriangleMesh sq;
    sq.vertices = {{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}, {0.5, 0.5, 1}};
    sq.triangles = {{0, 1, 2}, {0, 2, 3}};
    MeshReport r = repair(sq, "square");
    BOOST_TEST(r.open_edges == 4);
    BOOST_TEST(r.non_manifold_edges == 0);
    BOOST_TEST(r.pieces == 1);
    sq.triangles.push_back({0, 2, 4});  // a fin on the diagonal
    r = repair(sq, "fin");
    BOOST_TEST(r.non_manifold_edges == 1);
  }
  // A Moebius strip: a band of 8 quads whose ends are joined with a half twist.
  TriangleMesh band;
  const int segments = 8;
  for (int k = 0; k < segments; ++k) {
    const double a = 2 * 3.14159265358979 * k / segments, half = a / 2;
    const Vec3<double> centre{std::cos(a), std::sin(a), 0}, across{std::cos(half) * std::cos(a), std::cos(half) * std::sin(a), std::sin(half)};
    band.vertices.push_back(centre + across * 0.3);
    band.vertices.push_back(centre - across * 0.3);
  }
  for (int k = 0; k < segments; ++k) {
    const int a0 = 2 * k, a1 = 2 * k + 1;
    const bool last = k == segments - 1;
    const int b0 = last ? 1 : 2 * k + 2, b1 = last ? 0 : 2 * k + 3;  // the twist swaps the sides
    band.triangles.push_back({a0, a1, b1});
    band.triangles.push_back({a0, b1, b0});
  }
  std::string msg;
  try {
    repair(band, "strip.stl");
  } catch (const MeshError& e) {
    msg = e.what();
  }
  BOOST_TEST((msg.rfind("strip.stl: triangle ", 0) == 0 && msg.find("cannot be oriented") != std::string::npos), msg);
}

BOOST_AUTO_TEST_CASE(malformed_files_are_refused_naming_the_place) {
  const std::string stl = temp("blaze_bad.stl"), obj = temp("blaze_bad.obj");
  write_text(stl, "solid x\n facet normal 0 0 1\n  outer loop\n   vertex 0 0 0\n   vertex 1 0\n");
  BOOST_TEST(error_of(stl).rfind(stl + ":5: expected 'vertex x y z'", 0) == 0, error_of(stl));
  write_text(stl, "solid x\n facet normal 0 0 1\n  outer loop\n   vertex 0 0 0\n   vertex 1 0 0\n  endloop\n endfacet\n");
  BOOST_TEST(error_of(stl).rfind(stl + ":7: a facet needs three vertices, got 2", 0) == 0, error_of(stl));
  write_text(stl, "solid x\n facet normal 0 0 1\n  outer loop\n   vertex 0 0 0\n   vertex 1 0 0\n   vertex 0 nan 0\n");
  BOOST_TEST(error_of(stl).rfind(stl + ":6:", 0) == 0, error_of(stl));
  // cut after a whole facet: only the missing endsolid tells
  const std::string facet = " facet normal 0 0 1\n  outer loop\n   vertex 0 0 0\n   vertex 1 0 0\n   vertex 0 1 0\n  endloop\n endfacet\n";
  write_text(stl, "solid x\n" + facet + facet);
  BOOST_TEST(error_of(stl) == stl + ": the file ends without 'endsolid' after 2 facets: it is truncated (an ASCII STL closes its solid with 'endsolid')",
             error_of(stl));
  write_text(stl, "solid x\n" + facet + "endsolid x\n" + facet);
  BOOST_TEST(error_of(stl).rfind(stl + ":10: 'facet' after 'endsolid'", 0) == 0, error_of(stl));
  write_text(stl, std::string(80, 'x') + std::string("\x02\0\0\0", 4) + std::string(60, '\0'));  // 2 triangles promised, 1.2 given
  BOOST_TEST(error_of(stl).find("neither a binary STL (84 + 50 n bytes for n triangles; this file has 144, and its header announces 2 "
                                "triangles, 184 bytes: truncated, or not an STL) nor an ASCII one") != std::string::npos,
             error_of(stl));
  write_text(stl, std::string(80, 'x') + std::string("\x01\0\0\0", 4) + std::string(110, '\0'));  // 1 triangle and 60 bytes more
  BOOST_TEST(error_of(stl).find("announces 1 triangles, 134 bytes: bytes past the last triangle") != std::string::npos, error_of(stl));
  write_text(stl, std::string(50, 'x'));  // shorter than a header
  BOOST_TEST(error_of(stl).find("this file has 50) nor an ASCII one") != std::string::npos, error_of(stl));
  write_text(obj, "v 0 0 0\nv 1 0 0\nf 1 2 3\n");
  BOOST_TEST(error_of(obj).rfind(obj + ":3: vertex reference '3' outside the 2 vertices read so far", 0) == 0, error_of(obj));
  write_text(obj, "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 x\n");
  BOOST_TEST(error_of(obj).rfind(obj + ":4: bad vertex reference 'x'", 0) == 0, error_of(obj));
  write_text(obj, "# nothing\n");
  BOOST_TEST(error_of(obj) == obj + ": no triangles");
  BOOST_TEST(error_of(temp("blaze_mesh.ply")).find("cannot open") != std::string::npos);
  write_text(temp("blaze_mesh.ply"), "ply\n");
  BOOST_TEST(error_of(temp("blaze_mesh.ply")).find("must be .stl (ASCII or binary) or .obj") != std::string::npos);
  for (const auto& p : {stl, obj, temp("blaze_mesh.ply")}) std::filesystem::remove(p);
}

BOOST_AUTO_TEST_CASE(welding_joins_vertices_within_the_tolerance_only) {
  for (double gap : {1e-14, 1e-11, 1e-6, 1e-3}) {
    TriangleMesh m;
    m.vertices = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {1, 0, gap}, {0, 1, -gap}, {1, 1, 0}};  // two triangles sharing an edge (almost)
    m.triangles = {{0, 1, 2}, {3, 5, 4}};
    MeshReport r;
    weld(m, r);  // tolerance 1e-9 of the extent (1 m)
    const bool joined = gap <= 1e-9;
    BOOST_TEST(r.welded == (joined ? 2 : 0), gap);
    BOOST_TEST(m.vertices.size() == (joined ? 4u : 6u), gap);
    const MeshReport q = repair(m, "pair");
    BOOST_TEST(q.open_edges == (joined ? 4 : 6), gap);
  }
}

BOOST_AUTO_TEST_SUITE_END()
