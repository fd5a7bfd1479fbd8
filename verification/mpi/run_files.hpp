// What the MPI suite's program runs share (test_blaze_run.cpp, test_mill_run.cpp): a folder for a
// case's runs and the rows of a CSV file they wrote.
#pragma once
#include <stdlib.h>

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

}  // namespace blaze::test
