// Runs the blaze program (build/<backend>/blaze, beside the test binary: make test builds both),
// or another program built there (study_hopper), as a user would, capturing its exit status and
// output; reads its CSV time series.
#pragma once
#include <boost/test/unit_test.hpp>
#include <sys/wait.h>

#include <cstdio>
#include <filesystem>
#include <fstream>
#include <map>
#include <sstream>
#include <string>
#include <vector>

namespace blaze::test {

// A program built beside the test binary (build/<backend>/NAME).
inline std::string program_binary(const std::string& name) {
  const auto& argv = boost::unit_test::framework::master_test_suite().argv;
  return (std::filesystem::absolute(argv[0]).parent_path() / name).string();
}
inline std::string blaze_binary() { return program_binary("blaze"); }

struct ProgramResult {
  int status = -1;  // exit status, -1 when killed by a signal
  std::string output;  // stdout and stderr
};

// Runs a command line (a program's path and its arguments) through the shell.
inline ProgramResult run_command(const std::string& command) {
  ProgramResult r;
  FILE* p = popen((command + " 2>&1").c_str(), "r");
  if (!p) return r;
  char buf[512];
  while (fgets(buf, sizeof buf, p)) r.output += buf;
  const int st = pclose(p);
  r.status = WIFEXITED(st) ? WEXITSTATUS(st) : -1;
  return r;
}
inline ProgramResult run_blaze(const std::string& args) { return run_command(blaze_binary() + " " + args); }

inline std::string slurp(const std::filesystem::path& p) {
  std::ifstream in(p, std::ios::binary);
  std::ostringstream s;
  s << in.rdbuf();
  return s.str();
}

// A CSV with a header line: columns by name, every cell as a double ("nan", "inf" included).
inline std::map<std::string, std::vector<double>> read_csv(const std::filesystem::path& p) {
  std::ifstream in(p);
  std::string line, cell;
  std::vector<std::string> names;
  std::map<std::string, std::vector<double>> cols;
  if (std::getline(in, line)) {
    std::istringstream h(line);
    while (std::getline(h, cell, ',')) names.push_back(cell);
  }
  while (std::getline(in, line)) {
    std::istringstream r(line);
    for (std::size_t k = 0; k < names.size() && std::getline(r, cell, ','); ++k) cols[names[k]].push_back(std::strtod(cell.c_str(), nullptr));
  }
  return cols;
}

}  // namespace blaze::test
