// The verification table. Every acceptance check is one row: case, quantity, measured value,
// limit, the thesis's number and the source. check_*() asserts the row (Boost.Test) and, when the
// environment names a file in BLAZE_REPORT, appends it there (tab-separated) with the backend;
// tools/verification_table.py renders those rows into verification/README.md, so the README's
// numbers are the suite's, never typed.
// FigureData writes the series behind a thesis figure to $BLAZE_FIGURE_DIR/<figure>.dat (when
// set) for plots/<figure>.gp; blocks separated by two blank lines are gnuplot's `index`.
#pragma once
#include <boost/test/unit_test.hpp>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <sstream>
#include <string>
#include "blaze/exec/space.hpp"

namespace blaze::test {

// One row's text: what is checked and against what.
struct Row {
  std::string case_name;  // e.g. "Drag fall (2.5.1, Fig 2.11)"
  std::string quantity;   // e.g. "max |x - x_exact| / x, Verlet, dt = 1e-3 s"
  std::string thesis;     // the thesis's number, or "-"
  std::string source;     // closed form or paper the expectation comes from
};

inline void record(const Row& row, double measured, const std::string& relation, double limit, bool pass) {
  const char* path = std::getenv("BLAZE_REPORT");
  if (path == nullptr || *path == 0) return;
  std::ofstream out(path, std::ios::app);
  char m[32], l[32];
  std::snprintf(m, sizeof m, "%.3g", measured);
  std::snprintf(l, sizeof l, "%.3g", limit);
  out << row.case_name << '\t' << row.quantity << '\t' << row.thesis << '\t' << relation << ' ' << l << '\t' << m
      << '\t' << (pass ? "pass" : "FAIL") << '\t' << DefaultSpace::name << '\t' << row.source << '\n';
  if (!out) BOOST_TEST_MESSAGE("could not append to BLAZE_REPORT file " << path);
}

// measured <= limit (errors, drifts).
inline void check_at_most(const Row& row, double measured, double limit) {
  const bool pass = measured <= limit;  // NaN fails
  BOOST_TEST(pass, row.case_name << ": " << row.quantity << " = " << measured << ", limit " << limit);
  record(row, measured, "<=", limit, pass);
}
// measured >= limit (e.g. a count that must be reached).
inline void check_at_least(const Row& row, double measured, double limit) {
  const bool pass = measured >= limit;
  BOOST_TEST(pass, row.case_name << ": " << row.quantity << " = " << measured << ", must be >= " << limit);
  record(row, measured, ">=", limit, pass);
}
// |measured - expected| <= tolerance (absolute; for orders of convergence and the like).
inline void check_near(const Row& row, double measured, double expected, double tolerance) {
  const bool pass = std::fabs(measured - expected) <= tolerance;
  BOOST_TEST(pass, row.case_name << ": " << row.quantity << " = " << measured << ", expected " << expected << " +- "
                                 << tolerance);
  std::ostringstream rel;
  rel << expected << " +-";
  record(row, measured, rel.str(), tolerance, pass);
}
// Relative error |measured / expected - 1| <= tolerance; records the relative error.
inline double check_relative(const Row& row, double measured, double expected, double tolerance) {
  const double err = std::fabs(measured / expected - 1);
  const bool pass = err <= tolerance;
  BOOST_TEST(pass, row.case_name << ": " << row.quantity << " = " << measured << " vs " << expected
                                 << " (relative error " << err << ", limit " << tolerance << ")");
  record(row, err, "<=", tolerance, pass);
  return err;
}

class FigureData {
 public:
  FigureData() = default;  // writes nothing
  // columns: the header line, e.g. "t_s v_m_per_s v_exact_m_per_s".
  FigureData(const std::string& figure, const std::string& columns) {
    const char* dir = std::getenv("BLAZE_FIGURE_DIR");
    if (dir == nullptr || *dir == 0) return;
    out_.open(std::string(dir) + "/" + figure + ".dat");
    if (!out_) BOOST_FAIL("cannot write figure data " << dir << "/" << figure << ".dat");
    out_ << "# " << figure << " (blaze verification, " << DefaultSpace::name << ")\n# " << columns << '\n';
    out_.precision(10);
  }
  bool enabled() const { return out_.is_open(); }
  // Starts a new gnuplot index block (the first block needs no call).
  void block(const std::string& title) {
    if (!enabled()) return;
    if (rows_ > 0) out_ << "\n\n";
    out_ << "# " << title << '\n';
    rows_ = 0;
  }
  template <class... T>
  void row(const T&... values) {
    if (!enabled()) return;
    const char* sep = "";
    ((out_ << sep << values, sep = " "), ...);
    out_ << '\n';
    ++rows_;
  }

 private:
  std::ofstream out_;
  long rows_ = 0;
};

}  // namespace blaze::test
