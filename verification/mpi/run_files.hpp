// What the MPI suite's program runs share (test_blaze_run.cpp, test_mill_run.cpp,
// test_hopper_run.cpp): a folder for a case's runs, the rows of a CSV file they wrote, and two
// runs' series compared column by column.
#pragma once
#include <stdlib.h>

#include <algorithm>
#include <cmath>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>
#include "pipeline/parallel/communicator.hpp"

namespace blaze::test {

// A folder for a case's runs, named by rank 0, with the scene in it.
inline std::string scene_folder(const Communicator& comm, const std::string& text) {
  std::string base;
  if (comm.rank() == 0) {
    char tmpl[] = "/tmp/blaze_mpi_run_XXXXXX";
    base = mkdtemp(tmpl) ? tmpl : "";
    if (!base.empty()) std::ofstream(base + "/scene.toml") << text;
  }
  base = comm.all_gather_bytes(base)[0];
  comm.barrier();
  return base;
}

inline std::vector<std::vector<double>> csv_rows(const std::string& path, std::vector<std::string>& header) {
  std::ifstream in(path);
  std::string line;
  std::vector<std::vector<double>> rows;
  for (bool first = true; std::getline(in, line); first = false) {
    std::stringstream ss(line);
    std::string cell;
    std::vector<double> row;
    while (std::getline(ss, cell, ',')) {
      if (first) header.push_back(cell);
      else row.push_back(std::stod(cell));
    }
    if (!first) rows.push_back(row);
  }
  return rows;
}

// A run's CSV series (a) against another's (b): the same header and rows; the `exact` columns
// (counts, times, ids) equal cell by cell; every other cell's difference relative to its column's
// largest magnitude in b, the worst of them named. A wall-clock column (wall_s) is not compared.
struct SeriesComparison {
  bool same_shape = false;
  long exact_wrong = 0;
  double worst = 0;
  std::string worst_name;
};
inline SeriesComparison compare_series(const std::vector<std::string>& ha, const std::vector<std::vector<double>>& ra,
                                       const std::vector<std::string>& hb, const std::vector<std::vector<double>>& rb,
                                       const std::vector<std::string>& exact) {
  SeriesComparison c;
  c.same_shape = ha == hb && ra.size() == rb.size();
  for (std::size_t r = 0; r < std::min(ra.size(), rb.size()); ++r) {
    c.same_shape = c.same_shape && ra[r].size() == rb[r].size();
    for (std::size_t k = 0; k < std::min(ra[r].size(), rb[r].size()); ++k) {
      const std::string& name = k < hb.size() ? hb[k] : std::string("?");
      if (name == "wall_s") continue;
      if (std::find(exact.begin(), exact.end(), name) != exact.end()) {
        c.exact_wrong += ra[r][k] != rb[r][k];
        continue;
      }
      double scale = 0;
      for (const auto& row : rb)
        if (k < row.size()) scale = std::fmax(scale, std::fabs(row[k]));
      const double d = scale > 0 ? std::fabs(ra[r][k] - rb[r][k]) / scale : std::fabs(ra[r][k] - rb[r][k]);
      if (d > c.worst) c.worst = d, c.worst_name = name;
    }
  }
  return c;
}

}  // namespace blaze::test
