// Study parameter files: every defect is reported with the file, the line, the key and what is
// allowed; unknown and missing keys are errors.
#include <boost/test/unit_test.hpp>
#include <filesystem>
#include <fstream>
#include "blaze/io/params_file.hpp"

using namespace blaze;

namespace {

std::string write(const std::string& text) {
  const auto path = (std::filesystem::temp_directory_path() / "blaze_params_test.params").string();
  std::ofstream(path) << text;
  return path;
}

// The message of the error raised by f, or "" if none.
template <class F>
std::string error_of(F f) {
  try {
    f();
  } catch (const std::runtime_error& e) {
    return e.what();
  }
  return "";
}

bool contains(const std::string& s, const std::string& part) { return s.find(part) != std::string::npos; }

}  // namespace

BOOST_AUTO_TEST_SUITE(params_file)

BOOST_AUTO_TEST_CASE(reads_numbers_and_ignores_comments) {
  ParamsFile p(write("# a study\nradius = 2.5e-3   # m\n\ncount = 12\n"));
  BOOST_TEST(p.number("radius", 0, 1, "m") == 2.5e-3);
  BOOST_TEST(p.integer("count", 1, 100, "-") == 12);
  BOOST_CHECK_NO_THROW(p.check_all_used());
}

BOOST_AUTO_TEST_CASE(errors_name_file_line_key_and_what_is_allowed) {
  const std::string path = write("radius = -1\nrestitution = high\ncount = 2.5\ntypo = 3\n");
  ParamsFile p(path);
  const auto range = error_of([&] { p.number("radius", 0, 1, "sphere radius, m"); });
  BOOST_TEST(contains(range, path + ":1: key 'radius'"));
  BOOST_TEST(contains(range, "allowed [0, 1]"));
  const auto nan = error_of([&] { p.number("restitution", 0, 1, "(0, 1]"); });
  BOOST_TEST(contains(nan, ":2: key 'restitution': 'high' is not a number"));
  BOOST_TEST(contains(error_of([&] { p.integer("count", 0, 9, "-"); }), ":3: key 'count': must be a whole number"));
  BOOST_TEST(contains(error_of([&] { p.number("density", 1, 1e5, "kg/m^3"); }), "missing key 'density'"));
  BOOST_TEST(contains(error_of([&] { p.check_all_used(); }), ":4: key 'typo': unknown key"));
}

BOOST_AUTO_TEST_CASE(malformed_lines_and_duplicates_are_rejected) {
  BOOST_TEST(contains(error_of([] { ParamsFile p(write("radius 2\n")); }), ":1: expected 'key = value'"));
  BOOST_TEST(contains(error_of([] { ParamsFile p(write("a = 1\na = 2\n")); }), ":2: key 'a': given twice (first on line 1)"));
  BOOST_TEST(contains(error_of([] { ParamsFile p("/nonexistent/blaze.params"); }), "cannot open"));
}

BOOST_AUTO_TEST_SUITE_END()
