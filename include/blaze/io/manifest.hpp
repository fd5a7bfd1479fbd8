// What produced a result: commit, date, backend, device, parameters.
#pragma once
#include <array>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <ctime>
#include <fstream>
#include <map>
#include <string>

namespace blaze {

// BLAZE_COMMIT overrides, for machines that get a copy of the tree without its .git.
inline std::string git_commit() {
  if (const char* c = std::getenv("BLAZE_COMMIT")) return c;
  std::string out;
  if (FILE* p = popen("git rev-parse --short=12 HEAD 2>/dev/null", "r")) {
    std::array<char, 64> buf{};
    if (fgets(buf.data(), buf.size(), p)) out = buf.data();
    pclose(p);
  }
  while (!out.empty() && (out.back() == '\n' || out.back() == '\r')) out.pop_back();
  if (out.empty()) return "unknown";
  if (std::system("git diff --quiet HEAD -- include kernels studies 2>/dev/null") != 0) out += "-dirty";
  return out;
}

inline std::string utc_date() {
  const std::time_t t = std::time(nullptr);
  char buf[32];
  std::strftime(buf, sizeof buf, "%Y-%m-%dT%H:%M:%SZ", std::gmtime(&t));
  return buf;
}

inline void write_manifest(const std::string& path, const std::map<std::string, std::string>& entries) {
  std::ofstream out(path);
  for (const auto& [k, v] : entries) out << k << " = " << v << '\n';
}

}  // namespace blaze
