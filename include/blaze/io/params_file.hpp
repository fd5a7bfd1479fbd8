// A study's parameter file: one "key = value" per line, '#' starts a comment (units go there).
// Every key the study reads must be present and every key present must be read: errors name the
// file, the line and the key, and say what is allowed.
#pragma once
#include <fstream>
#include <map>
#include <set>
#include <sstream>
#include <stdexcept>
#include <string>

namespace blaze {

class ParamsFile {
 public:
  explicit ParamsFile(const std::string& path) : path_(path) {
    std::ifstream in(path);
    if (!in) throw std::runtime_error(path + ": cannot open parameter file");
    std::string line;
    for (int number = 1; std::getline(in, line); ++number) {
      const auto hash = line.find('#');
      if (hash != std::string::npos) line.erase(hash);
      if (line.find_first_not_of(" \t\r") == std::string::npos) continue;
      const auto eq = line.find('=');
      if (eq == std::string::npos) fail(number, "", "expected 'key = value'");
      const std::string key = trim(line.substr(0, eq)), value = trim(line.substr(eq + 1));
      if (key.empty() || value.empty()) fail(number, key, "expected 'key = value'");
      if (entries_.count(key)) fail(number, key, "given twice (first on line " + std::to_string(entries_[key].line) + ")");
      entries_[key] = {value, number};
    }
  }

  // A number in [lo, hi]; 'what' says what it is and its unit, for the error message.
  double number(const std::string& key, double lo, double hi, const std::string& what) {
    const Entry& e = find(key, what);
    std::istringstream s(e.value);
    double v;
    std::string rest;
    if (!(s >> v) || (s >> rest)) fail(e.line, key, "'" + e.value + "' is not a number; expected " + what);
    if (!(v >= lo && v <= hi))
      fail(e.line, key, e.value + " is out of range; allowed " + range(lo, hi) + " (" + what + ")");
    return v;
  }
  long integer(const std::string& key, long lo, long hi, const std::string& what) {
    const double v = number(key, static_cast<double>(lo), static_cast<double>(hi), what);
    if (v != static_cast<double>(static_cast<long>(v))) fail(entries_.at(key).line, key, "must be a whole number");
    return static_cast<long>(v);
  }

  // Call after reading everything: keys nobody asked for are typos.
  void check_all_used() const {
    for (const auto& [key, e] : entries_)
      if (!used_.count(key)) fail(e.line, key, "unknown key");
  }
  const std::string& path() const { return path_; }
  const std::map<std::string, std::string> values() const {
    std::map<std::string, std::string> out;
    for (const auto& [k, e] : entries_) out[k] = e.value;
    return out;
  }

 private:
  struct Entry {
    std::string value;
    int line = 0;
  };
  static std::string trim(const std::string& s) {
    const auto a = s.find_first_not_of(" \t\r"), b = s.find_last_not_of(" \t\r");
    return a == std::string::npos ? "" : s.substr(a, b - a + 1);
  }
  static std::string range(double lo, double hi) {
    std::ostringstream s;
    s << "[" << lo << ", " << hi << "]";
    return s.str();
  }
  const Entry& find(const std::string& key, const std::string& what) {
    const auto it = entries_.find(key);
    if (it == entries_.end()) throw std::runtime_error(path_ + ": missing key '" + key + "' (" + what + ")");
    used_.insert(key);
    return it->second;
  }
  [[noreturn]] void fail(int line, const std::string& key, const std::string& msg) const {
    throw std::runtime_error(path_ + ":" + std::to_string(line) + (key.empty() ? "" : ": key '" + key + "'") + ": " + msg);
  }

  std::string path_;
  std::map<std::string, Entry> entries_;
  std::set<std::string> used_;
};

}  // namespace blaze
