// Convex shapes (issue 3): mass properties of the shipped shapes against closed forms (acceptance
// 1), and malformed shapes rejected or repaired with a message naming the defect (acceptance 2).
#include <boost/test/data/test_case.hpp>
#include <boost/test/unit_test.hpp>
#include <cmath>
#include <sstream>
#include "blaze/shapes/shape_io.hpp"
#include "verification/tolerances.hpp"

using namespace blaze;

namespace {

constexpr double kEdge = 0.01;  // m, every shipped regular solid
const double kPhi = (1 + std::sqrt(5.0)) / 2;

struct MassCase {
  const char* file;
  double volume;                   // m^3
  double moments[3];               // principal moments per unit density, ascending, m^5
};

// Closed forms (solid, uniform): V and I/rho = k V a^2 for the regular solids, box (b^2+c^2)V/12.
std::vector<MassCase> mass_cases() {
  const double a = kEdge, a2 = a * a;
  auto regular = [&](const char* f, double v, double k) { return MassCase{f, v, {k * v * a2, k * v * a2, k * v * a2}}; };
  const double v_box = 3 * a * a * a;
  return {
      regular("cube", a * a * a, 1.0 / 6),
      regular("tetrahedron", a * a * a / (6 * std::sqrt(2.0)), 1.0 / 20),
      regular("octahedron", std::sqrt(2.0) / 3 * a * a * a, 1.0 / 10),
      regular("dodecahedron", (15 + 7 * std::sqrt(5.0)) / 4 * a * a * a, (39 * kPhi + 28) / 150),
      regular("icosahedron", 5 * (3 + std::sqrt(5.0)) / 12 * a * a * a, kPhi * kPhi / 10),
      MassCase{"box", v_box, {v_box * 2 * a2 / 12, v_box * 10 * a2 / 12, v_box * 10 * a2 / 12}},
  };
}

std::ostream& operator<<(std::ostream& o, const MassCase& c) { return o << c.file; }

std::string load_error(const std::string& text, const std::string& name = "bad.shape") {
  std::istringstream in(text);
  try {
    parse_blaze_shape(in, name);
  } catch (const ShapeError& e) {
    return e.what();
  }
  return "";
}

const char* kCube =
    "vertices 8\n0 0 0\n1 0 0\n1 1 0\n0 1 0\n0 0 1\n1 0 1\n1 1 1\n0 1 1\n"
    "faces 6\n4 0 3 2 1\n4 4 5 6 7\n4 0 1 5 4\n4 1 2 6 5\n4 2 3 7 6\n4 3 0 4 7\n";

}  // namespace

BOOST_AUTO_TEST_SUITE(shapes)

BOOST_DATA_TEST_CASE(mass_properties_match_closed_forms, boost::unit_test::data::make(mass_cases()), c) {
  const ConvexShape s = load_shape(std::string("data/shapes/") + c.file + ".shape");
  BOOST_TEST_CONTEXT(c.file) {
    BOOST_TEST(s.volume == c.volume, boost::test_tools::tolerance(tol::mass_properties));
    for (int k = 0; k < 3; ++k)
      BOOST_TEST(s.inertia_per_density[k] == c.moments[k], boost::test_tools::tolerance(tol::mass_properties));
    // Body frame: centre of mass at the origin.
    double first[3] = {0, 0, 0};
    for (const auto& loop : s.faces)
      for (std::size_t k = 1; k + 1 < loop.size(); ++k) {
        const auto &p = s.vertices[loop[0]], &q = s.vertices[loop[k]], &r = s.vertices[loop[k + 1]];
        const double tv = p.dot(q.cross(r)) / 6;
        for (int d = 0; d < 3; ++d) first[d] += tv * (p[d] + q[d] + r[d]) / 4;
      }
    for (double f : first) BOOST_TEST(std::fabs(f) <= tol::mass_properties * s.volume * kEdge);
    BOOST_TEST(s.repairs.empty());
  }
}

BOOST_AUTO_TEST_CASE(every_shipped_shape_loads_within_the_caps) {
  for (const char* f : {"cube", "box", "tetrahedron", "octahedron", "icosahedron", "dodecahedron", "prism", "corn"}) {
    const ConvexShape s = load_shape(std::string("data/shapes/") + f + ".shape");
    BOOST_TEST_CONTEXT(f) {
      BOOST_TEST(s.vertices.size() <= static_cast<std::size_t>(kMaxVertices));
      BOOST_TEST(s.faces.size() <= static_cast<std::size_t>(kMaxFaces));
      BOOST_TEST(s.vertices.size() - s.edges.size() + s.faces.size() == 2u);  // Euler
      BOOST_TEST(s.bounding_radius > 0);
    }
  }
}

BOOST_AUTO_TEST_CASE(obj_and_blaze_formats_agree) {
  const ConvexShape a = load_shape("data/shapes/octahedron.shape"), b = load_shape("data/shapes/octahedron.obj");
  BOOST_TEST(a.volume == b.volume, boost::test_tools::tolerance(tol::mass_properties));
  BOOST_TEST(a.inertia_per_density.x() == b.inertia_per_density.x(), boost::test_tools::tolerance(tol::mass_properties));
}

BOOST_AUTO_TEST_CASE(unit_cube_from_text_is_valid) {
  std::istringstream in(kCube);
  const ConvexShape s = parse_blaze_shape(in, "cube.shape");
  BOOST_TEST(s.volume == 1.0, boost::test_tools::tolerance(tol::mass_properties));
  BOOST_TEST(s.bounding_radius == std::sqrt(0.75), boost::test_tools::tolerance(tol::mass_properties));
}

// Each malformed shape and the words its error must contain.
struct BadShape {
  const char* defect;
  std::string text;
  const char* expected;
};

std::ostream& operator<<(std::ostream& o, const BadShape& b) { return o << b.defect; }

std::vector<BadShape> bad_shapes() {
  const std::string v8 = "vertices 8\n0 0 0\n1 0 0\n1 1 0\n0 1 0\n0 0 1\n1 0 1\n1 1 1\n0 1 1\n";
  std::string many = "vertices 33\n";
  for (int i = 0; i < 33; ++i) many += std::to_string(std::cos(i)) + " " + std::to_string(std::sin(i)) + " " + std::to_string(i % 3) + "\n";
  return {
      {"open: a face missing", v8 + "faces 5\n4 0 3 2 1\n4 4 5 6 7\n4 0 1 5 4\n4 1 2 6 5\n4 2 3 7 6\n", "not closed"},
      {"non-convex: a dented top", "vertices 9\n0 0 0\n1 0 0\n1 1 0\n0 1 0\n0 0 1\n1 0 1\n1 1 1\n0 1 1\n0.5 0.5 0.5\n"
                                   "faces 9\n4 0 3 2 1\n4 0 1 5 4\n4 1 2 6 5\n4 2 3 7 6\n4 3 0 4 7\n3 4 5 8\n3 5 6 8\n3 6 7 8\n3 7 4 8\n",
       "not convex"},
      {"degenerate: repeated vertex", v8 + "faces 6\n4 0 3 3 1\n4 4 5 6 7\n4 0 1 5 4\n4 1 2 6 5\n4 2 3 7 6\n4 3 0 4 7\n", "uses vertex 3 twice"},
      {"degenerate: not planar", "vertices 8\n0 0 0\n1 0 0\n1 1 0.2\n0 1 0\n0 0 1\n1 0 1\n1 1 1\n0 1 1\n"
                                 "faces 6\n4 0 3 2 1\n4 4 5 6 7\n4 0 1 5 4\n4 1 2 6 5\n4 2 3 7 6\n4 3 0 4 7\n", "not planar"},
      {"too many vertices", many + "faces 0\n", "more than the cap of 32"},
      {"overlapping faces", v8 + "faces 7\n4 0 3 2 1\n4 4 5 6 7\n4 0 1 5 4\n4 1 2 6 5\n4 2 3 7 6\n4 3 0 4 7\n4 4 5 6 7\n",
       "used twice in the same direction"},
      {"index out of range", v8 + "faces 6\n4 0 3 2 9\n4 4 5 6 7\n4 0 1 5 4\n4 1 2 6 5\n4 2 3 7 6\n4 3 0 4 7\n", "vertex 9, which does not exist"},
      {"unknown keyword", "colour red\n", "unknown keyword 'colour'"},
      {"truncated vertex list", "vertices 8\n0 0 0\n", "file ends after 1 of 8 vertices"},
  };
}

BOOST_DATA_TEST_CASE(malformed_shapes_are_rejected_naming_the_defect, boost::unit_test::data::make(bad_shapes()), bad) {
  const std::string message = load_error(bad.text);
  BOOST_TEST_CONTEXT(bad.defect << ": " << message) {
    BOOST_TEST(message.find("bad.shape") == 0u);  // names the file
    BOOST_TEST(message.find(bad.expected) != std::string::npos);
  }
}

// A clockwise face is reversed and the repair reported; the result equals the correct shape.
BOOST_AUTO_TEST_CASE(clockwise_face_is_repaired_and_reported) {
  std::string text = kCube;
  text.replace(text.find("4 4 5 6 7"), 9, "4 7 6 5 4");
  std::istringstream in(text);
  const ConvexShape s = parse_blaze_shape(in, "flipped.shape");
  BOOST_TEST_REQUIRE(s.repairs.size() == 1u);
  BOOST_TEST(s.repairs[0] == "face 1 was wound clockwise; reversed");
  BOOST_TEST(s.volume == 1.0, boost::test_tools::tolerance(tol::mass_properties));
}

BOOST_AUTO_TEST_CASE(missing_file_is_reported) {
  try {
    load_shape("data/shapes/no_such.shape");
    BOOST_TEST(false);
  } catch (const ShapeError& e) {
    BOOST_TEST(std::string(e.what()) == "data/shapes/no_such.shape: cannot open shape file");
  }
}

BOOST_AUTO_TEST_SUITE_END()
