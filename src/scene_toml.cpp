// Scene files in TOML (scene_file.hpp): parsing, command-line overrides and validation.
// Host only, compiled by g++ in both builds (nvcc cannot parse toml++). Every rejection is a
// SceneError of the form
//   <file>:<line>: <table>: key '<key>' = <value given>: <what is allowed>
// and every key not listed here is an error (a typo must not silently fall back to a default).
// toml++ 3.3 asserts on some malformed input (for example "[[[material]]") just before it would
// report the parse error; with assertions off (as in its release builds) it reports the error.
// The fuzz test in verification/test_scene_file.cpp found this.
#define TOML_ASSERT(expr) static_cast<void>(0)
#include <toml++/toml.h>

#include <algorithm>
#include <cctype>
#include <charconv>
#include <cmath>
#include <fstream>
#include <limits>
#include <map>
#include <set>
#include <sstream>
#include <utility>
#include "blaze/scene/critical_step.hpp"
#include "blaze/scene/run_size.hpp"
#include "blaze/scene/scene_file.hpp"
#include "blaze/io/mesh_io.hpp"
#include "blaze/shapes/shape_io.hpp"
#include "blaze/world/planar_polygon.hpp"
#include "blaze/grid/grid_spec.hpp"

namespace blaze {
namespace {

constexpr double kInf = std::numeric_limits<double>::infinity();
constexpr long kMaxParticles = (1L << 31) - 1;  // Index is a signed 32-bit integer

// "file:line", or the command line for values that came from --set (copied nodes keep no source).
std::string where(const toml::source_region& s, const std::string& file) {
  if (s.begin.line == 0) return "command line (--set)";
  return (s.path ? *s.path : file) + ":" + std::to_string(s.begin.line);
}

// A value as the user wrote it: shortest round-trip numbers, strings in double quotes.
std::string shown(const toml::node& n) {
  std::string s;
  if (const auto* f = n.as_floating_point()) {
    char buf[32];
    const auto r = std::to_chars(buf, buf + sizeof buf, f->get());
    s.assign(buf, r.ptr);
  } else if (const auto* i = n.as_integer()) {
    s = std::to_string(i->get());
  } else if (const auto* str = n.as_string()) {
    s = "\"" + str->get() + "\"";
  } else if (const auto* b = n.as_boolean()) {
    s = b->get() ? "true" : "false";
  } else if (const auto* a = n.as_array()) {
    s = "[";
    for (std::size_t k = 0; k < a->size(); ++k) s += (k ? ", " : "") + shown(*a->get(k));
    s += "]";
  } else if (n.is_table()) {
    s = "{...}";
  } else {
    std::ostringstream os;
    n.visit([&](const auto& v) { os << v; });
    s = os.str();
  }
  if (s.size() > 60) s = s.substr(0, 57) + "...";
  return s;
}

// An allowed interval of a number, with its unit, for checks and messages.
struct Range {
  double lo, hi;
  bool lo_open, hi_open;
  const char* unit;
  bool contains(double v) const {
    return std::isfinite(v) && (lo_open ? v > lo : v >= lo) && (hi_open ? v < hi : v <= hi);
  }
  std::string text() const {
    std::ostringstream os;
    os.precision(6);
    if (lo == -kInf && hi == kInf) os << "a finite number";
    else if (hi == kInf) os << (lo_open ? "> " : ">= ") << lo;
    else os << "in " << (lo_open ? "(" : "[") << lo << ", " << hi << (hi_open ? ")" : "]");
    if (*unit) os << " " << unit;
    return os.str();
  }
};
Range non_negative(const char* unit) { return {0, kInf, false, false, unit}; }
// Physical inputs are bounded far beyond any granular scene, so that no derived quantity (a mass
// r^3 rho, an energy m v^2, a stiffness estimate) can overflow a double and reach the run as inf
// or NaN (issue 17: a gravity of 1e300 gave |g| = inf and an impact speed of NaN that no check saw).
constexpr double kMaxCoordinate = 1e9;   // m
constexpr double kMaxSpeed = 1e5;        // m/s
constexpr double kMaxGravity = 1e7;      // m/s^2 (a centrifuge reaches 1e6)
constexpr double kMaxSize = 1e3;         // m, a particle's radius
constexpr double kMaxDensity = 1e9;      // kg/m^3 (density scaling reaches 1e3 x that of steel)
constexpr double kMaxModulus = 1e15;     // Pa and N/m
Range position(const char* unit) { return {-kMaxCoordinate, kMaxCoordinate, false, false, unit}; }
Range speed() { return {-kMaxSpeed, kMaxSpeed, false, false, "m/s"}; }
Range up_to(double hi, const char* unit) { return {0, hi, true, false, unit}; }

// One TOML table being read. Keys not in `keys` are errors, found before any value is read (a
// misspelt key must not leave a default in place, nor surface as "missing" under its real name).
class Fields {
 public:
  Fields(const toml::table& t, std::string label, std::string file, const std::vector<std::string>& keys = {})
      : t_(t), label_(std::move(label)), file_(std::move(file)) {
    if (keys.empty()) return;
    for (const auto& [k, v] : t_) {
      if (std::find(keys.begin(), keys.end(), std::string(k.str())) != keys.end()) continue;
      std::string allowed;
      for (const auto& u : keys) allowed += (allowed.empty() ? "" : ", ") + u;
      throw SceneError(where(v.source(), file_) + ": " + label_ + ": unknown key '" + std::string(k.str()) +
                       "'; allowed: " + allowed);
    }
  }

  [[noreturn]] void fail(const toml::node& n, const std::string& key, const std::string& allowed) const {
    throw SceneError(where(n.source(), file_) + ": " + label_ + ": key '" + key + "' = " + shown(n) + ": " + allowed);
  }
  [[noreturn]] void missing(const std::string& key, const std::string& allowed) const {
    throw SceneError(where(t_.source(), file_) + ": " + label_ + ": missing key '" + key + "' (" + allowed + ")");
  }
  const toml::node* get(const std::string& key) const { return t_.get(key); }
  bool has(const std::string& key) const { return t_.contains(key); }

  double number(const std::string& key, const Range& r) {
    const toml::node* n = get(key);
    if (!n) missing(key, "a number " + r.text());
    return checked(*n, key, r);
  }
  double number_or(const std::string& key, double fallback, const Range& r) {
    const toml::node* n = get(key);
    return n ? checked(*n, key, r) : fallback;
  }
  long integer(const std::string& key, long lo, long hi) {
    const toml::node* n = get(key);
    const std::string allowed = "an integer in [" + std::to_string(lo) + ", " + std::to_string(hi) + "]";
    if (!n) missing(key, allowed);
    return integer_of(*n, key, lo, hi, allowed);
  }
  long integer_or(const std::string& key, long fallback, long lo, long hi) {
    const toml::node* n = get(key);
    return n ? integer_of(*n, key, lo, hi, "an integer in [" + std::to_string(lo) + ", " + std::to_string(hi) + "]")
             : fallback;
  }
  bool boolean_or(const std::string& key, bool fallback) {
    const toml::node* n = get(key);
    if (!n) return fallback;
    if (!n->is_boolean()) fail(*n, key, "true or false");
    return n->as_boolean()->get();
  }
  std::string string(const std::string& key, const std::string& allowed) {
    const toml::node* n = get(key);
    if (!n) missing(key, allowed);
    if (!n->is_string() || n->as_string()->get().empty()) fail(*n, key, allowed);
    return n->as_string()->get();
  }
  std::string string_or(const std::string& key, const std::string& fallback, const std::string& allowed) {
    return has(key) ? string(key, allowed) : fallback;
  }
  // One of `choices` (strings), as its index.
  int choice(const std::string& key, const std::vector<std::string>& choices, int fallback) {
    const toml::node* n = get(key);
    if (!n) return fallback;
    std::string allowed = "one of";
    for (const auto& c : choices) allowed += " \"" + c + "\"";
    if (!n->is_string()) fail(*n, key, allowed);
    const auto it = std::find(choices.begin(), choices.end(), n->as_string()->get());
    if (it == choices.end()) fail(*n, key, allowed);
    return static_cast<int>(it - choices.begin());
  }
  Vec3<double> vec3(const std::string& key, const Range& r) {
    const toml::node* n = get(key);
    if (!n) missing(key, "[x, y, z], each " + r.text());
    return vec3_of(*n, key, r);
  }
  Vec3<double> vec3_or(const std::string& key, Vec3<double> fallback, const Range& r) {
    const toml::node* n = get(key);
    return n ? vec3_of(*n, key, r) : fallback;
  }
  std::vector<Vec3<double>> vec3_list(const std::string& key, const Range& r, std::size_t min_size, std::size_t max_size) {
    const toml::node* n = get(key);
    const std::string allowed = "a list of " + std::to_string(min_size) + " to " + std::to_string(max_size) +
                                " points [[x, y, z], ...], each " + r.text();
    if (!n) missing(key, allowed);
    const toml::array* a = n->as_array();
    if (!a || a->size() < min_size || a->size() > max_size) fail(*n, key, allowed);
    std::vector<Vec3<double>> out;
    for (const auto& e : *a) out.push_back(vec3_of(e, key, r));
    return out;
  }

  // A list of min_size to max_size numbers, each in r.
  std::vector<double> numbers(const std::string& key, const Range& r, std::size_t min_size, std::size_t max_size) {
    const toml::node* n = get(key);
    const std::string allowed = "a list of " + std::to_string(min_size) + " to " + std::to_string(max_size) + " numbers, each " + r.text();
    if (!n) missing(key, allowed);
    const toml::array* a = n->as_array();
    if (!a || a->size() < min_size || a->size() > max_size) fail(*n, key, allowed);
    std::vector<double> out;
    for (const auto& e : *a) {
      if (!e.is_number()) fail(*n, key, allowed);
      const double v = e.is_floating_point() ? e.as_floating_point()->get() : static_cast<double>(e.as_integer()->get());
      if (!r.contains(v)) fail(*n, key, allowed);
      out.push_back(v);
    }
    return out;
  }
  const toml::table& table() const { return t_; }
  const std::string& label() const { return label_; }
  const std::string& file() const { return file_; }
  // "file:line" of a key (of the table when the key is absent: its default was taken).
  std::string where_of(const std::string& key) const {
    const toml::node* n = get(key);
    return where(n ? n->source() : t_.source(), file_);
  }
  // Records where each key is for the derived-size and run checks (Scene::where).
  void note(Scene& s, const std::string& prefix, std::initializer_list<const char*> keys) const {
    for (const char* k : keys) s.where[prefix + k] = where_of(k);
  }

 private:
  double checked(const toml::node& n, const std::string& key, const Range& r) const {
    double v;
    if (n.is_floating_point()) v = n.as_floating_point()->get();
    else if (n.is_integer()) v = static_cast<double>(n.as_integer()->get());
    else fail(n, key, "a number " + r.text());
    if (!r.contains(v)) fail(n, key, "must be " + r.text());
    return v;
  }
  long integer_of(const toml::node& n, const std::string& key, long lo, long hi, const std::string& allowed) const {
    if (!n.is_integer()) fail(n, key, allowed);
    const std::int64_t v = n.as_integer()->get();
    if (v < lo || v > hi) fail(n, key, allowed);
    return static_cast<long>(v);
  }
  Vec3<double> vec3_of(const toml::node& n, const std::string& key, const Range& r) const {
    const std::string allowed = "[x, y, z], each " + r.text();
    const toml::array* a = n.as_array();
    if (!a || a->size() != 3) fail(n, key, allowed);
    double c[3];
    for (int k = 0; k < 3; ++k) {
      const toml::node& e = *a->get(static_cast<std::size_t>(k));
      if (e.is_floating_point()) c[k] = e.as_floating_point()->get();
      else if (e.is_integer()) c[k] = static_cast<double>(e.as_integer()->get());
      else fail(n, key, allowed);
      if (!r.contains(c[k])) fail(n, key, allowed);
    }
    return {c[0], c[1], c[2]};
  }

  const toml::table& t_;
  std::string label_, file_;
};

// Exactly one of keys a and b (`what` names both): both given is an error at b's line, neither one
// at the table's.
void one_of(Fields& f, const std::string& a, const std::string& b, const std::string& what) {
  if (f.has(a) && f.has(b)) f.fail(*f.get(b), b, "give one of " + what + ", not both (" + a + " is given too)");
  if (!f.has(a) && !f.has(b)) f.missing(a, "or " + b + ": give one of " + what);
}

// ---- command-line overrides -----------------------------------------------------------------

// The key grammar of --set, parsed strictly (a loose split accepted "material[0.density" and
// "material[0]density" as material[0].density):
//   key   := name ( '.' name | '[' digits ']' )*      name := [A-Za-z_][A-Za-z0-9_]*
// An index follows a name (or another index) directly; a name after an index needs its dot.
// Returns the parts ("material", "1", "density"), or throws naming the offending character.
std::vector<std::string> split_path(const std::string& key, const std::string& arg) {
  std::vector<std::string> parts;
  const auto bad = [&](std::size_t at, const std::string& why) {
    throw SceneError("command line --set " + arg + ": bad key '" + key + "' at character " + std::to_string(at + 1) + ": " +
                     why + " (keys are name, table.name or table[index].name; names of letters, digits and '_')");
  };
  const auto is_name_char = [](char c) { return std::isalnum(static_cast<unsigned char>(c)) || c == '_'; };
  std::size_t k = 0;
  bool expect_name = true;  // at the start and after a '.'
  while (k < key.size()) {
    if (expect_name) {
      if (!std::isalpha(static_cast<unsigned char>(key[k])) && key[k] != '_') bad(k, "a name must start here");
      const std::size_t begin = k;
      while (k < key.size() && is_name_char(key[k])) ++k;
      parts.push_back(key.substr(begin, k - begin));
      expect_name = false;
    } else if (key[k] == '.') {
      ++k;
      expect_name = true;
      if (k == key.size()) bad(k - 1, "a name must follow '.'");
    } else if (key[k] == '[') {
      const std::size_t begin = ++k;
      while (k < key.size() && std::isdigit(static_cast<unsigned char>(key[k]))) ++k;
      if (k == begin) bad(k, "an index (digits) must follow '['");
      if (k == key.size() || key[k] != ']') bad(k, "the index must be closed by ']'");
      if (k - begin > 9) bad(begin, "the index is too large");
      parts.push_back(key.substr(begin, k - begin));
      ++k;
      if (k < key.size() && key[k] != '.' && key[k] != '[') bad(k, "'.' or '[' must follow ']'");
    } else {
      bad(k, std::string("unexpected '") + key[k] + "'");
    }
  }
  if (parts.empty()) bad(0, "empty key");
  return parts;
}

// True when parts[k] came from an index in brackets (digits only; names start with a letter or '_').
bool is_index(const std::string& part) { return !part.empty() && std::isdigit(static_cast<unsigned char>(part[0])); }

const std::vector<std::string> kSimulationKeys = {
    "law", "precision", "backend", "dt", "steps_per_contact", "end_time", "gravity", "drag", "domain_lo", "domain_hi", "skin",
    "pair_evaluation", "world_lists", "force_dt", "max_impact_speed", "seed", "force_long_run", "tangential", "rolling", "periodic"};
const std::vector<std::string> kOutputKeys = {"directory", "csv_interval", "vtu_interval", "checkpoint_interval",
                                              "penetration_warning", "energy_gain_limit", "energy_by_class"};

void apply_override(toml::table& root, const std::string& arg) {
  const auto eq = arg.find('=');
  const std::string usage = "command line --set " + arg + ": expected key=value, for example --set simulation.dt=1e-5";
  if (eq == std::string::npos || eq == 0 || eq + 1 == arg.size()) throw SceneError(usage);
  const std::string key = arg.substr(0, eq), text = arg.substr(eq + 1);
  // One value on one line: a newline would end the value and start another TOML key (silently
  // dropped or, worse, applied), and other control characters have no place in a value.
  for (char c : text)
    if (static_cast<unsigned char>(c) < 0x20 && c != '\t')
      throw SceneError("command line --set " + key + "=...: the value contains a control character (a newline?); "
                       "give one value on one line");
  std::vector<std::string> parts = split_path(key, arg);
  if (is_index(parts[0])) throw SceneError("command line --set " + arg + ": a key starts with a name");
  if (parts.size() == 1) {  // bare key: a key of [output] goes there, one of [study] where the file has it, others to [simulation]
    const auto is = [&](const std::vector<std::string>& keys) { return std::find(keys.begin(), keys.end(), parts[0]) != keys.end(); };
    const char* table = is(kOutputKeys) && !is(kSimulationKeys) ? "output" : !is(kSimulationKeys) && root["study"][parts[0]] ? "study" : "simulation";
    parts.insert(parts.begin(), table);
  }
  if (is_index(parts.back())) throw SceneError("command line --set " + arg + ": the key must end with a name, as material[0].density");
  // The value as TOML; a bare word (precision=float) is taken as a string. Exactly one value:
  // "v = 1 x = 2" does not parse, and nothing but v may come out of it.
  toml::table parsed;
  try {
    parsed = toml::parse("v = " + text, "--set " + arg);
  } catch (const toml::parse_error&) {
    if (text.find('"') != std::string::npos || text.find('\\') != std::string::npos)
      throw SceneError("command line --set " + arg + ": the value is not TOML");
    try {
      parsed = toml::parse("v = \"" + text + "\"", "--set " + arg);
    } catch (const toml::parse_error& e) {
      throw SceneError("command line --set " + arg + ": the value is not TOML: " + std::string(e.description()));
    }
  }
  if (parsed.size() != 1 || !parsed.contains("v")) throw SceneError("command line --set " + arg + ": the value is not one TOML value");
  toml::table* t = &root;
  // Keys that stand for one another: setting one on the command line drops the other.
  static const std::map<std::string, std::string> alternative = {
      {"dt", "steps_per_contact"}, {"steps_per_contact", "dt"}, {"stiffness", "contact_time"},
      {"contact_time", "stiffness"}, {"radius", "shape"}, {"shape", "radius"}};
  for (std::size_t k = 0; k + 1 < parts.size(); ++k) {
    toml::node* next = t->get(parts[k]);
    if (is_index(parts[k])) throw SceneError("command line --set " + arg + ": index [" + parts[k] + "] of something that is not a list of tables");
    if (next && next->is_array()) {  // array of tables: the next part is an index
      toml::array* a = next->as_array();
      if (k + 2 >= parts.size() || !is_index(parts[k + 1]))
        throw SceneError("command line --set " + arg + ": '" + parts[k] + "' needs an index, as " + parts[k] + "[0].key");
      char* end = nullptr;
      const long i = std::strtol(parts[k + 1].c_str(), &end, 10);
      if (*end || i < 0 || static_cast<std::size_t>(i) >= a->size() || !a->get(static_cast<std::size_t>(i))->is_table())
        throw SceneError("command line --set " + arg + ": index '" + parts[k + 1] + "' of '" + parts[k] + "' must be 0.." +
                         std::to_string(static_cast<long>(a->size()) - 1));
      t = a->get(static_cast<std::size_t>(i))->as_table();
      ++k;
      continue;
    }
    if (!next) next = &t->insert_or_assign(parts[k], toml::table{}).first->second;
    if (!next->is_table()) throw SceneError("command line --set " + arg + ": '" + parts[k] + "' is not a table");
    t = next->as_table();
  }
  parsed.get("v")->visit([&](const auto& v) { t->insert_or_assign(parts.back(), v); });
  const auto alt = alternative.find(parts.back());
  if (alt != alternative.end()) {
    t->erase(alt->second);
    if (alt->first == "radius") t->erase("bounding_radius");
  }
}

// ---- the scene's tables -----------------------------------------------------------------------

// Array of tables [[name]] (absent: empty); a plain table given instead is an error.
std::vector<const toml::table*> tables(const toml::table& root, const std::string& name, const std::string& file) {
  std::vector<const toml::table*> out;
  const toml::node* n = root.get(name);
  if (!n) return out;
  const toml::array* a = n->as_array();
  if (!a || !a->is_array_of_tables())
    throw SceneError(where(n->source(), file) + ": '" + name + "' must be an array of tables, written [[" + name + "]]");
  for (const auto& e : *a) out.push_back(e.as_table());
  return out;
}

const toml::table& table(const toml::table& root, const std::string& name, const std::string& file) {
  static const toml::table empty;
  const toml::node* n = root.get(name);
  if (!n) return empty;
  if (!n->is_table()) throw SceneError(where(n->source(), file) + ": '" + name + "' must be a table, written [" + name + "]");
  return *n->as_table();
}

std::string item_label(const std::string& name, std::size_t k) { return "[[" + name + "]] #" + std::to_string(k + 1); }

// Index of the named item in `names`, or an error naming the choices.
int lookup(Fields& f, const std::string& key, const std::vector<std::string>& names, const char* kind) {
  const std::string allowed_head = std::string("the name of a [[") + kind + "]]";
  const toml::node* n = f.get(key);
  std::string allowed = allowed_head + ":";
  for (const auto& s : names) allowed += " \"" + s + "\"";
  if (names.empty()) allowed = allowed_head + " (none is defined)";
  if (!n) f.missing(key, allowed);
  if (!n->is_string()) f.fail(*n, key, allowed);
  const auto it = std::find(names.begin(), names.end(), n->as_string()->get());
  if (it == names.end()) f.fail(*n, key, allowed);
  return static_cast<int>(it - names.begin());
}

void read_simulation(const toml::table& t, const std::string& file, Scene& s) {
  Fields f(t, "[simulation]", file, kSimulationKeys);
  s.law = static_cast<LawKind>(f.choice("law", {"linear", "hertz"}, 0));
  s.tangential = static_cast<TangentialKind>(f.choice("tangential", {"history_free", "mindlin", "linear_spring"}, 0));
  if (s.tangential == TangentialKind::mindlin && s.law != LawKind::hertz)
    f.fail(*f.get("tangential"), "tangential", "\"mindlin\" needs law = \"hertz\" (its stiffness 8 G* sqrt(R* delta)); "
                                               "with law = \"linear\": \"history_free\" or \"linear_spring\"");
  s.rolling = static_cast<RollingKind>(f.choice("rolling", {"none", "cdt", "epsd"}, 0));
  if (s.rolling != RollingKind::none && s.tangential == TangentialKind::history_free)
    f.fail(*f.get("rolling"), "rolling", "rolling resistance needs a tangential spring: tangential = \"mindlin\" (Hertz) or "
                                         "\"linear_spring\" (linear)");
  if (s.tangential == TangentialKind::linear_spring && s.law != LawKind::linear)
    f.fail(*f.get("tangential"), "tangential", "\"linear_spring\" needs law = \"linear\"; with law = \"hertz\": "
                                               "\"history_free\" or \"mindlin\"");
  s.precision = static_cast<PrecisionKind>(f.choice("precision", {"float", "double"}, 1));
  s.backend = static_cast<BackendKind>(f.choice("backend", {"auto", "cpu", "gpu"}, 0));
  if (f.has("dt") == f.has("steps_per_contact")) {
    const char* both = "give exactly one of 'dt' (s, > 0) and 'steps_per_contact' (dt = t_c / steps_per_contact, >= 5)";
    if (f.has("dt")) f.fail(*f.get("dt"), "dt", both);
    f.missing("dt", both);
  }
  s.dt = f.number_or("dt", 0, up_to(1e3, "s"));
  s.steps_per_contact = f.number_or("steps_per_contact", 0, {5, 1e6, false, false, "steps per contact time"});
  s.end_time = f.number("end_time", up_to(1e15, "s"));
  s.gravity = f.vec3_or("gravity", {0, -9.81, 0}, {-kMaxGravity, kMaxGravity, false, false, "m/s^2"});
  s.drag = f.number_or("drag", 0, {0, 1e9, false, false, "kg/m"});
  s.domain_lo = f.vec3("domain_lo", position("m"));
  s.domain_hi = f.vec3("domain_hi", position("m"));
  if (!(s.domain_hi.x > s.domain_lo.x && s.domain_hi.y > s.domain_lo.y && s.domain_hi.z > s.domain_lo.z))
    f.fail(*f.get("domain_hi"), "domain_hi", "must exceed domain_lo in x, y and z");
  s.skin = f.number_or("skin", 0.2, {0, 10, false, false, "x largest bounding radius"});
  if (const toml::node* n = f.get("periodic")) {  // periodic = ["x", "z"] (grid/periodic_images.hpp)
    const std::string allowed = "an array of distinct axes among \"x\", \"y\", \"z\" (e.g. periodic = [\"x\"])";
    if (!n->is_array()) f.fail(*n, "periodic", allowed);
    for (const auto& e : *n->as_array()) {
      const auto* a = e.as_string();
      const std::string axis = a ? a->get() : "";
      const unsigned bit = axis == "x" ? 1u : axis == "y" ? 2u : axis == "z" ? 4u : 0u;
      if (!bit || (s.periodic & bit)) f.fail(e, "periodic", allowed);
      s.periodic |= bit;
    }
  }
  s.pair_evaluation = static_cast<PairsKind>(f.choice("pair_evaluation", {"auto", "both_sides", "once"}, 0));
  s.world_lists = static_cast<WorldListsKind>(f.choice("world_lists", {"auto", "on", "off"}, 0));
  s.force_dt = f.boolean_or("force_dt", false);
  s.max_impact_speed = f.number_or("max_impact_speed", 0, non_negative("m/s"));
  s.seed = static_cast<std::uint64_t>(f.integer_or("seed", 1, 0, std::numeric_limits<long>::max()));
  s.force_long_run = f.boolean_or("force_long_run", false);
  f.note(s, "simulation.", {"dt", "steps_per_contact", "end_time", "domain_lo", "domain_hi", "skin", "max_impact_speed",
                            "precision", "force_long_run"});
}

void read_output(const toml::table& t, const std::string& file, Scene& s) {
  Fields f(t, "[output]", file, kOutputKeys);
  s.output.directory = f.string_or("directory", "data/run", "a directory path (created if missing)");
  s.output.csv_interval = f.number_or("csv_interval", 0, non_negative("s (0: no CSV)"));
  s.output.vtu_interval = f.number_or("vtu_interval", 0, non_negative("s (0: no VTU frames)"));
  s.output.checkpoint_interval = f.number_or("checkpoint_interval", 0, non_negative("s (0: no checkpoints)"));
  s.output.penetration_warning = f.number_or("penetration_warning", 0.05, {0, 1, true, false, "overlap / radius"});
  s.output.energy_gain_limit = f.number_or("energy_gain_limit", 0.05, {0, 1, true, false, "x the energy scale"});
  s.output.energy_by_class = f.boolean_or("energy_by_class", false);
  f.note(s, "output.", {"csv_interval", "vtu_interval", "checkpoint_interval"});
}

// [study]: numbers only, read by name by a study driver (Scene::study_value), which also rejects
// keys it does not read.
void read_study(const toml::table& t, const std::string& file, Scene& s) {
  Fields f(t, "[study]", file);
  for (const auto& [k, v] : t) {
    if (!v.is_number()) f.fail(v, std::string(k.str()), "a number (a study reads [study] values as numbers)");
    s.study.push_back({std::string(k.str()), where(v.source(), file), v.value_or(0.0)});
  }
}

void read_materials(const toml::table& root, const std::string& file, Scene& s) {
  const auto items = tables(root, "material", file);
  for (std::size_t k = 0; k < items.size(); ++k) {
    Fields f(*items[k], item_label("material", k), file, {"name", "density", "youngs_modulus", "poisson_ratio"});
    MaterialSpec m;
    m.name = f.string("name", "a non-empty name");
    for (const auto& o : s.materials)
      if (o.name == m.name) f.fail(*f.get("name"), "name", "must be unique among [[material]]");
    m.density = f.number("density", up_to(kMaxDensity, "kg/m^3"));
    if (s.law == LawKind::hertz) {
      m.youngs_modulus = f.number("youngs_modulus", up_to(kMaxModulus, "Pa"));
      m.poisson_ratio = f.number("poisson_ratio", {-1, 0.5, true, true, "(Poisson ratio)"});
    } else {
      m.youngs_modulus = f.number_or("youngs_modulus", 0, up_to(kMaxModulus, "Pa"));
      m.poisson_ratio = f.number_or("poisson_ratio", 0, {-1, 0.5, true, true, "(Poisson ratio)"});
    }
    s.materials.push_back(m);
  }
  if (s.materials.size() > 8)
    throw SceneError(s.place("material[8].name") + ": a 9th [[material]]; at most 8 (the contact-law table's size)");
  if (s.materials.empty()) throw SceneError(file + ": no [[material]]: at least one is needed");
}

std::vector<std::string> material_names(const Scene& s) {
  std::vector<std::string> n;
  for (const auto& m : s.materials) n.push_back(m.name);
  return n;
}

void read_pairs(const toml::table& root, const std::string& file, Scene& s) {
  const auto items = tables(root, "pair", file);
  const auto names = material_names(s);
  for (std::size_t k = 0; k < items.size(); ++k) {
    // Hertz takes its stiffness from the materials' youngs_modulus and poisson_ratio.
    // The history-free law's K_T (tangential_damping) or the linear spring's k_t (tangential_stiffness).
    std::vector<std::string> keys = s.law == LawKind::linear ? std::vector<std::string>{"materials", "stiffness", "contact_time", "restitution", "friction", "no_tension"}
                                                             : std::vector<std::string>{"materials", "restitution", "friction", "no_tension"};
    if (s.tangential == TangentialKind::history_free) keys.push_back("tangential_damping");
    if (s.tangential == TangentialKind::linear_spring) keys.push_back("tangential_stiffness");
    if (s.rolling != RollingKind::none) keys.push_back("rolling_friction");
    if (s.rolling == RollingKind::epsd) keys.push_back("rolling_damping");
    Fields f(*items[k], item_label("pair", k), file, keys);
    PairSpec p;
    const toml::node* mats = f.get("materials");
    const std::string allowed = "two material names, [\"a\", \"b\"]";
    if (!mats) f.missing("materials", allowed);
    const toml::array* a = mats->as_array();
    if (!a || a->size() != 2 || !a->get(0)->is_string() || !a->get(1)->is_string()) f.fail(*mats, "materials", allowed);
    int idx[2];
    for (int j = 0; j < 2; ++j) {
      const auto it = std::find(names.begin(), names.end(), a->get(static_cast<std::size_t>(j))->as_string()->get());
      if (it == names.end()) f.fail(*mats, "materials", "names of [[material]] items");
      idx[j] = static_cast<int>(it - names.begin());
    }
    p.a = idx[0], p.b = idx[1];
    if (s.pair(p.a, p.b)) f.fail(*mats, "materials", "each pair once");
    if (s.law == LawKind::linear) {
      if (f.has("stiffness") == f.has("contact_time")) {
        const char* one = "give exactly one of 'stiffness' (N/m) and 'contact_time' (s)";
        if (f.has("stiffness")) f.fail(*f.get("stiffness"), "stiffness", one);
        f.missing("stiffness", one);
      }
      p.stiffness = f.number_or("stiffness", 0, up_to(kMaxModulus, "N/m"));
      p.contact_time = f.number_or("contact_time", 0, up_to(1e3, "s"));
    }
    p.restitution = f.number("restitution", {0, 1, true, false, "(coefficient of restitution)"});
    p.friction = f.number_or("friction", 0, {0, 100, false, false, "(Coulomb coefficient)"});
    p.tangential_damping = f.number_or("tangential_damping", 0, non_negative("kg/s (K_T of eq. 2.3)"));
    // Friction without K_T would never act (the viscous branch is K_T |v_t|): the history-free law
    // then takes the thesis's mill friction, eq. 4.3 (history_free_friction.hpp).
    if (s.tangential == TangentialKind::history_free && p.friction > 0 && !f.has("tangential_damping")) {
      p.tangential_rate = std::min(p.friction, 0.5);
      s.notes.push_back("note: " + f.where_of("friction") + ": " + item_label("pair", k) +
                        " has friction but no tangential_damping (K_T, kg/s): the history-free friction takes the "
                        "thesis's eq. 4.3, K_T = " + (p.friction > 0.5 ? std::string("0.5") : std::string("mu")) +
                        " m*/dt (give tangential_damping for a fixed K_T, 0 for none)");
    }
    p.tangential_stiffness = f.number_or("tangential_stiffness", 0, up_to(kMaxModulus, "N/m (k_t; default 2/7 of the normal stiffness)"));
    p.rolling_friction = f.number_or("rolling_friction", 0, {0, 1, false, false, "(rolling friction coefficient mu_r)"});
    p.rolling_damping = f.number_or("rolling_damping", 0.3, {0, 10, false, false, "(damping ratio eta_r of the rolling spring)"});
    p.no_tension = f.boolean_or("no_tension", s.law == LawKind::hertz);
    s.pairs.push_back(p);
  }
}

void read_types(const toml::table& root, const std::string& file, Scene& s) {
  const auto items = tables(root, "particle_type", file);
  const auto materials = material_names(s);
  for (std::size_t k = 0; k < items.size(); ++k) {
    Fields f(*items[k], item_label("particle_type", k), file, {"name", "material", "radius", "shape", "bounding_radius"});
    ParticleTypeSpec t;
    t.name = f.string("name", "a non-empty name");
    for (const auto& o : s.types)
      if (o.name == t.name) f.fail(*f.get("name"), "name", "must be unique among [[particle_type]]");
    t.material = lookup(f, "material", materials, "material");
    if (f.has("radius") == f.has("shape")) {
      const char* one = "give 'radius' (m, a sphere) or 'shape' (a .shape/.obj file) with 'bounding_radius' (m)";
      if (f.has("radius")) f.fail(*f.get("radius"), "radius", one);
      f.missing("radius", one);
    }
    if (f.has("radius")) {
      t.radius = f.number("radius", up_to(kMaxSize, "m"));
      t.volume = 4.0 / 3.0 * 3.14159265358979323846 * t.radius * t.radius * t.radius;
    } else {
      t.shape = f.string("shape", "a path to a .shape or .obj file");
      t.bounding_radius = f.number("bounding_radius", up_to(kMaxSize, "m"));
      try {
        t.volume = load_scaled_shape(t.shape, t.bounding_radius).volume;
      } catch (const std::exception& e) {
        f.fail(*f.get("shape"), "shape", std::string("cannot be loaded: ") + e.what());
      }
    }
    s.types.push_back(t);
  }
  if (s.types.empty()) throw SceneError(file + ": no [[particle_type]]: at least one is needed");
  if (!s.all_spheres() && s.types.size() > 4)
    throw SceneError(file + ": at most 4 [[particle_type]] when any is a polyhedron (the shape table's size)");
  if (!s.all_spheres() && s.rolling != RollingKind::none)
    throw SceneError(s.place("simulation.rolling") + ": rolling resistance is for spheres (a polyhedron resists rolling by its "
                     "shape); with polyhedra: rolling = \"none\"");
}

std::vector<std::string> type_names(const Scene& s) {
  std::vector<std::string> n;
  for (const auto& t : s.types) n.push_back(t.name);
  return n;
}

bool inside_domain(const Scene& s, const Vec3<double>& x, double r) {
  return x.x - r >= s.domain_lo.x && x.x + r <= s.domain_hi.x && x.y - r >= s.domain_lo.y && x.y + r <= s.domain_hi.y &&
         x.z - r >= s.domain_lo.z && x.z + r <= s.domain_hi.z;
}

std::string shown_vec(const Vec3<double>& v);

// Can a particle touch the convex planar polygon `v` (a wall, a mesh triangle) inside the domain?
// False when the polygon's box misses the domain grown by `margin`, or its plane passes the grown
// domain by (the box's separating axes and the plane's; without the edges' cross axes the test
// may answer true for a polygon that misses, never false for one that reaches).
// The box of points v[0, n) (n >= 1): {lowest, highest} corner.
std::pair<Vec3<double>, Vec3<double>> bounds(const Vec3<double>* v, std::size_t n) {
  Vec3<double> a = v[0], b = v[0];
  for (std::size_t i = 1; i < n; ++i)
    a = {std::fmin(a.x, v[i].x), std::fmin(a.y, v[i].y), std::fmin(a.z, v[i].z)},
    b = {std::fmax(b.x, v[i].x), std::fmax(b.y, v[i].y), std::fmax(b.z, v[i].z)};
  return {a, b};
}

bool reaches_domain(const Scene& s, const Vec3<double>* v, std::size_t n, double margin) {
  const Vec3<double> lo = s.domain_lo - Vec3<double>{margin, margin, margin}, hi = s.domain_hi + Vec3<double>{margin, margin, margin};
  const auto [a, b] = bounds(v, n);
  if (a.x > hi.x || a.y > hi.y || a.z > hi.z || b.x < lo.x || b.y < lo.y || b.z < lo.z) return false;
  Vec3<double> normal{0, 0, 0};
  for (std::size_t i = 1; i + 1 < n; ++i) normal = normal + cross(v[i] - v[0], v[i + 1] - v[0]);
  const Vec3<double> c = (lo + hi) * 0.5, e = (hi - lo) * 0.5;
  const double reach = e.x * std::fabs(normal.x) + e.y * std::fabs(normal.y) + e.z * std::fabs(normal.z);
  return std::fabs(dot(normal, c - v[0])) <= reach;
}

// A still object no particle can reach (every part of it beyond a particle diameter from the
// domain, where particles are removed) is a placement mistake: a sign in translate, often a mesh
// in mm read as m.
// A moving one may come in later and is let be.
double reach_margin(const Scene& s) {
  double largest = 0;
  for (const auto& t : s.types) largest = std::fmax(largest, t.is_sphere() ? t.radius : t.bounding_radius);
  return 2 * largest;
}
std::string domain_text(const Scene& s) { return shown_vec(s.domain_lo) + " to " + shown_vec(s.domain_hi) + " m"; }

long read_placements(const toml::table& root, const std::string& file, Scene& s) {
  const auto types = type_names(s);
  long total = 0;
  const auto items = tables(root, "lattice", file);
  for (std::size_t k = 0; k < items.size(); ++k) {
    Fields f(*items[k], item_label("lattice", k), file,
             {"type", "origin", "count", "spacing", "velocity", "jitter", "random_orientation"});
    LatticeSpec l;
    l.type = lookup(f, "type", types, "particle_type");
    const double r = s.types[static_cast<std::size_t>(l.type)].size();
    l.origin = f.vec3("origin", position("m"));
    const toml::node* c = f.get("count");
    const std::string allowed = "[nx, ny, nz], integers >= 1";
    if (!c) f.missing("count", allowed);
    const toml::array* a = c->as_array();
    if (!a || a->size() != 3) f.fail(*c, "count", allowed);
    double sites = 1;
    for (int j = 0; j < 3; ++j) {
      const toml::node* e = a->get(static_cast<std::size_t>(j));
      if (!e->is_integer() || e->as_integer()->get() < 1 || e->as_integer()->get() > kMaxParticles) f.fail(*c, "count", allowed);
      l.count[static_cast<std::size_t>(j)] = static_cast<long>(e->as_integer()->get());
      sites *= static_cast<double>(l.count[static_cast<std::size_t>(j)]);
    }
    if (sites > static_cast<double>(kMaxParticles)) f.fail(*c, "count", "at most 2^31 - 1 sites");
    l.spacing = f.number("spacing", {2 * r, kInf, false, false, "m (at least 2 bounding radii: no overlap)"});
    l.velocity = f.vec3_or("velocity", {0, 0, 0}, speed());
    l.jitter = f.number_or("jitter", 0, {0, 1, false, false, "x the free gap between neighbours"});
    l.random_orientation = f.boolean_or("random_orientation", true);
    const Vec3<double> last = l.origin + Vec3<double>{double(l.count[0] - 1), double(l.count[1] - 1), double(l.count[2] - 1)} * l.spacing;
    if (!inside_domain(s, l.origin, r) || !inside_domain(s, last, r))
      f.fail(*f.get("origin"), "origin", "the lattice (origin + (count - 1) spacing, plus the radius) must lie inside the domain");
    total += static_cast<long>(sites);
    f.note(s, "lattice[" + std::to_string(k) + "].", {"count", "origin", "velocity"});
    s.lattices.push_back(l);
  }
  const auto lists = tables(root, "particles", file);
  for (std::size_t k = 0; k < lists.size(); ++k) {
    Fields f(*lists[k], item_label("particles", k), file, {"type", "positions", "velocities"});
    ListSpec l;
    l.type = lookup(f, "type", types, "particle_type");
    const double r = s.types[static_cast<std::size_t>(l.type)].size();
    l.position = f.vec3_list("positions", position("m"), 1, 1000000);
    if (f.has("velocities")) {
      l.velocity = f.vec3_list("velocities", speed(), l.position.size(), l.position.size());
    }
    for (std::size_t i = 0; i < l.position.size(); ++i)
      if (!inside_domain(s, l.position[i], r))
        f.fail(*f.get("positions"), "positions", "point " + std::to_string(i) + " (and its radius) must lie inside the domain");
    total += static_cast<long>(l.position.size());
    f.note(s, "particles[" + std::to_string(k) + "].", {"positions", "velocities"});
    s.lists.push_back(l);
  }
  const auto fills = tables(root, "fill", file);
  for (std::size_t k = 0; k < fills.size(); ++k) {
    Fields f(*fills[k], item_label("fill", k), file, {"type", "lo", "hi", "count", "velocity"});
    FillSpec l;
    l.type = lookup(f, "type", types, "particle_type");
    const double r = s.types[static_cast<std::size_t>(l.type)].size();
    l.lo = f.vec3("lo", position("m"));
    l.hi = f.vec3("hi", position("m"));
    const Vec3<double> span = l.hi - l.lo;
    if (!(span.x > 2 * r && span.y > 2 * r && span.z > 2 * r)) f.fail(*f.get("hi"), "hi", "the box must exceed lo by more than a diameter in x, y and z");
    if (!inside_domain(s, l.lo, 0) || !inside_domain(s, l.hi, 0)) f.fail(*f.get("hi"), "hi", "the box must lie inside the domain");
    l.count = f.integer("count", 1, kMaxParticles);
    // Random sequential placement jams near a solid fraction of 0.38 (spheres); stay well below.
    const double fraction = static_cast<double>(l.count) * 4.0 / 3.0 * 3.14159265358979 * r * r * r / (span.x * span.y * span.z);
    if (fraction > 0.3)
      f.fail(*f.get("count"), "count", "fills " + std::to_string(fraction) + " of the box by bounding volume; random placement jams "
             "near 0.38, so at most 0.3 is allowed (use a larger box or a [[lattice]])");
    l.velocity = f.vec3_or("velocity", {0, 0, 0}, speed());
    total += l.count;
    f.note(s, "fill[" + std::to_string(k) + "].", {"count", "lo", "hi", "velocity"});
    s.fills.push_back(l);
  }
  return total;
}

// A [[feed]]'s `region` and `size` tables, and the feed (scene.hpp's FeedSpec). A feed with a size
// distribution adds two derived particle types, its smallest and largest particle (for a polyhedral
// type: its shape scaled to those bounding radii), so that the critical step, the impact overlap,
// the grid and the overlap checks see them.
InsertionRegion read_region(Fields& feed, const std::string& file, const Scene& s, double r) {
  const toml::node* n = feed.get("region");
  const std::string allowed = "a table: region = { kind = \"box\", lo = [..], hi = [..] }, { kind = \"cylinder\", centre, axis, radius, "
                              "length } or { kind = \"disc\", centre, normal, radius }";
  if (!n) feed.missing("region", allowed);
  if (!n->is_table()) feed.fail(*n, "region", allowed);
  InsertionRegion g;
  Fields f(*n->as_table(), feed.label() + " region", file, {"kind", "lo", "hi", "centre", "axis", "normal", "radius", "length"});
  if (!f.has("kind")) f.missing("kind", "one of \"box\", \"cylinder\", \"disc\"");
  g.kind = static_cast<RegionKind>(f.choice("kind", {"box", "cylinder", "disc"}, 0));
  const std::vector<std::vector<std::string>> used = {{"lo", "hi"}, {"centre", "axis", "radius", "length"}, {"centre", "normal", "radius"}};
  for (const std::string key : {"lo", "hi", "centre", "axis", "normal", "radius", "length"}) {
    const auto& mine = used[static_cast<std::size_t>(g.kind)];
    if (f.has(key) && std::find(mine.begin(), mine.end(), key) == mine.end())
      f.fail(*f.get(key), key, std::string("not a key of kind = \"") + to_string(g.kind) + "\"");
  }
  if (g.kind == RegionKind::box) {
    g.lo = f.vec3("lo", position("m"));
    g.hi = f.vec3("hi", position("m"));
    const Vec3<double> span = g.hi - g.lo;
    if (!(span.x >= 2 * r && span.y >= 2 * r && span.z >= 2 * r))
      f.fail(*f.get("hi"), "hi", "the box must exceed lo by at least the largest particle's diameter (" + Scene::shortest(2 * r) + " m) in x, y and z");
  } else {
    g.centre = f.vec3("centre", position("m"));
    const char* key = g.kind == RegionKind::disc ? "normal" : "axis";
    const Vec3<double> a = f.vec3(key, {-1e9, 1e9, false, false, "(a direction)"});
    if (!(norm(a) > 0)) f.fail(*f.get(key), key, "a non-zero direction");
    g.axis = a * (1 / norm(a));
    g.radius = f.number("radius", {r, kMaxCoordinate, false, false, "m (at least the largest particle's radius)"});
    if (g.kind == RegionKind::cylinder) g.length = f.number("length", {2 * r, kMaxCoordinate, false, false, "m (at least the largest particle's diameter)"});
  }
  Vec3<double> lo, hi;
  g.bounds(lo, hi);
  if (!inside_domain(s, lo, 0) || !inside_domain(s, hi, 0)) feed.fail(*n, "region", "the region must lie inside the domain");
  return g;
}

SizeDistribution read_size(Fields& feed, const std::string& file, double type_radius) {
  SizeDistribution d;
  d.radius = type_radius;
  const toml::node* n = feed.get("size");
  if (!n) return d;
  const std::string allowed = "a table: size = { kind = \"classes\" | \"uniform\" | \"normal\" | \"lognormal\" | \"rosin_rammler\", ... }";
  if (!n->is_table()) feed.fail(*n, "size", allowed);
  Fields f(*n->as_table(), feed.label() + " size", file, {"kind", "by", "radii", "fractions", "min", "max", "mean", "deviation", "median", "sigma", "r63", "k"});
  if (!f.has("kind")) f.missing("kind", "one of \"classes\", \"uniform\", \"normal\", \"lognormal\", \"rosin_rammler\"");
  d.kind = static_cast<SizeKind>(1 + f.choice("kind", {"classes", "uniform", "normal", "lognormal", "rosin_rammler"}, 0));
  d.by_mass = f.choice("by", {"number", "mass"}, 0) == 1;
  const std::vector<std::vector<std::string>> used = {{}, {"radii", "fractions"}, {"min", "max"}, {"mean", "deviation", "min", "max"},
                                                      {"median", "sigma", "min", "max"}, {"r63", "k", "min", "max"}};
  for (const std::string key : {"radii", "fractions", "min", "max", "mean", "deviation", "median", "sigma", "r63", "k"}) {
    const auto& mine = used[static_cast<std::size_t>(d.kind)];
    if (f.has(key) && std::find(mine.begin(), mine.end(), key) == mine.end())
      f.fail(*f.get(key), key, std::string("not a key of kind = \"") + to_string(d.kind) + "\"");
  }
  const Range size{0, kMaxSize, true, false, "m"};
  if (d.kind == SizeKind::classes) {
    d.sizes = f.numbers("radii", size, 1, 64);
    d.fractions = f.numbers("fractions", {0, 1, false, false, ""}, d.sizes.size(), d.sizes.size());
  } else {
    d.min = f.number("min", size);
    d.max = f.number("max", size);
    if (d.kind == SizeKind::normal) d.mean = f.number("mean", size), d.deviation = f.number("deviation", size);
    if (d.kind == SizeKind::lognormal) d.mean = f.number("median", size), d.deviation = f.number("sigma", {0, 10, true, false, "(of ln r)"});
    if (d.kind == SizeKind::rosin_rammler) d.scale = f.number("r63", size), d.shape = f.number("k", {0, 100, true, false, ""});
  }
  try {
    d.validate();
  } catch (const std::exception& e) {
    feed.fail(*n, "size", e.what());
  }
  return d;
}

void read_feeds(const toml::table& root, const std::string& file, Scene& s) {
  const auto types = type_names(s);
  const auto items = tables(root, "feed", file);
  for (std::size_t k = 0; k < items.size(); ++k) {
    Fields f(*items[k], item_label("feed", k), file,
             {"name", "type", "region", "start_time", "end_time", "rate", "mass_rate", "count", "velocity", "velocity_spread",
              "random_orientation", "interval", "size", "seed"});
    FeedSpec d;
    d.name = f.string_or("name", item_label("feed", k), "a non-empty name");
    for (const FeedSpec& other : s.feeds)  // its reports and checkpoint state go by the name
      if (other.name == d.name && f.has("name")) f.fail(*f.get("name"), "name", "a name no other [[feed]] has (\"" + d.name + "\" is taken)");
    d.type = lookup(f, "type", types, "particle_type");
    const ParticleTypeSpec t = s.types[static_cast<std::size_t>(d.type)];
    d.size = read_size(f, file, t.size());  // polyhedra: bounding radii, the shape scaled to each
    const double r = d.size.largest();
    d.region = read_region(f, file, s, r);
    // A feed starts before the run ends (one that would start later inserts nothing) and lasts to
    // its end_time; without one it lasts the run, so a restart that runs longer (--set end_time)
    // feeds on. (An end_time past the run's is kept as given: a run stopped there and continued
    // with a later end_time is bitwise the run that was that long from the start.)
    const std::string run_end = "s (before the run's end_time, " + Scene::shortest(s.end_time) + " s)";
    d.start = f.number_or("start_time", 0, {0, s.end_time, false, true, run_end.c_str()});
    d.end_given = f.number_or("end_time", kInf, {d.start, kInf, true, false, "s (after start_time)"});
    d.end = d.end_given < kInf ? d.end_given : s.end_time;
    one_of(f, "rate", "mass_rate", "rate (particles/s) and mass_rate (kg/s)");
    d.rate = f.number_or("rate", 0, {0, 1e12, true, false, "particles/s"});
    d.mass_rate = f.number_or("mass_rate", 0, {0, 1e12, true, false, "kg/s"});
    d.count = f.integer_or("count", 0, 1, kMaxParticles);  // (0 inside: no limit; a scene leaves the key out for that)
    d.velocity = f.vec3_or("velocity", {0, 0, 0}, speed());
    d.spread = f.number_or("velocity_spread", 0, {0, kMaxSpeed, false, false, "m/s"});
    d.random_orientation = f.boolean_or("random_orientation", true);
    // Default interval: the time the largest particle takes to move two diameters from rest at the
    // feed's speed under gravity (|v| t + |g| t^2 / 2 = 4 r): the batch before has left its place.
    const double v = norm(d.velocity) + d.spread, g = norm(s.gravity);
    const double clear = g > 0 ? (-v + std::sqrt(v * v + 8 * g * r)) / g : v > 0 ? 4 * r / v : 0;
    if (!f.has("interval") && !(clear > 0))
      f.missing("interval", "without gravity or a velocity the particles do not leave the region: give the time between insertions");
    d.interval = f.number_or("interval", clear, {0, kInf, true, false, "s (rounded up to whole steps)"});
    d.seed = static_cast<std::uint64_t>(f.integer_or("seed", static_cast<long>((s.seed + 7919 * (k + 1)) & 0x7fffffff), 0, 2147483647));
    f.note(s, "feed[" + std::to_string(k) + "].", {"rate", "mass_rate", "count", "interval", "size", "region"});
    if (d.size.kind != SizeKind::constant)  // the extremes as derived types (see above)
      for (const double radius : {d.size.smallest(), d.size.largest()}) {
        ParticleTypeSpec e = t;
        e.name = t.name + " (" + d.name + (radius == d.size.smallest() ? " smallest)" : " largest)");
        e.derived = true;
        if (t.is_sphere()) {
          e.radius = radius;
          e.volume = 4.0 / 3.0 * 3.14159265358979323846 * radius * radius * radius;
        } else {
          const double scale = radius / t.bounding_radius;
          e.bounding_radius = radius;
          e.volume = t.volume * scale * scale * scale;
        }
        s.types.push_back(e);
      }
    s.feeds.push_back(d);
  }
}

// An object's `motion` table (blaze/world/motion.hpp) and its `remove_time`.
// `label`: the object's, for messages ("[[wall]] #2"); `prefix`: its place, for where() ("wall[1]").
Motion read_motion(Fields& object, const std::string& file, const std::string& label, const std::string& prefix, Scene& s) {
  Motion m;
  m.remove = object.number_or("remove_time", kInf, non_negative("s"));
  if (m.remove < kInf && m.remove >= s.end_time)  // kept for a restart that runs longer, but said
    s.notes.push_back("note: " + object.where_of("remove_time") + ": " + label + " is removed at t = " + Scene::shortest(m.remove) +
                      " s, not before [simulation] end_time = " + Scene::shortest(s.end_time) + " s: it stays for the whole run");
  const toml::node* n = object.get("motion");
  if (!n) return m;
  if (!n->is_table()) object.fail(*n, "motion", "a table: motion = { kind = \"rotation\", ... }");
  const std::vector<std::string> kinds = {"none", "rotation", "translation", "vibration"};
  Fields f(*n->as_table(), label + " motion", file,
           {"kind", "axis", "point", "rpm", "omega", "velocity", "amplitude", "frequency", "direction", "start_time", "ramp_time"});
  if (!f.has("kind")) f.missing("kind", "one of \"rotation\", \"translation\", \"vibration\", \"none\"");
  m.kind = static_cast<MotionKind>(f.choice("kind", kinds, 0));
  m.start = f.number_or("start_time", 0, non_negative("s"));
  m.ramp = f.number_or("ramp_time", 0, non_negative("s"));
  // the keys each kind takes; any other is an error naming the kind
  const std::vector<std::vector<std::string>> used = {{},
                                                      {"axis", "point", "rpm", "omega"},
                                                      {"velocity"},
                                                      {"amplitude", "frequency", "direction"}};
  for (const std::string key : {"axis", "point", "rpm", "omega", "velocity", "amplitude", "frequency", "direction"}) {
    const auto& mine = used[static_cast<std::size_t>(m.kind)];
    if (f.has(key) && std::find(mine.begin(), mine.end(), key) == mine.end())
      f.fail(*f.get(key), key, "not a key of kind = \"" + kinds[static_cast<std::size_t>(m.kind)] + "\" (it takes " +
                                   (mine.empty() ? std::string("none: only start_time and ramp_time") : [&] {
                                     std::string t;
                                     for (const auto& k : mine) t += (t.empty() ? "" : ", ") + k;
                                     return t;
                                   }()) + ")");
  }
  const Range direction{-1e9, 1e9, false, false, "(direction)"};
  const auto unit = [&](const std::string& key) {
    const Vec3<double> v = f.vec3(key, direction);
    if (!(norm(v) > 0)) f.fail(*f.get(key), key, "a non-zero direction");
    return v * (1 / norm(v));
  };
  switch (m.kind) {
    case MotionKind::rotation: {
      m.axis = unit("axis");
      m.point = f.vec3("point", position("m"));
      one_of(f, "rpm", "omega", "rpm (revolutions per minute) and omega (rad/s), signed by the right-hand rule about axis");
      const Range spin{-1e7, 1e7, false, false, f.has("rpm") ? "rpm" : "rad/s"};
      m.omega = f.has("rpm") ? f.number("rpm", spin) * 2 * 3.14159265358979323846 / 60 : f.number("omega", spin);
      break;
    }
    case MotionKind::translation:
      m.velocity = f.vec3("velocity", speed());
      break;
    case MotionKind::vibration:
      m.amplitude = f.number("amplitude", up_to(kMaxCoordinate, "m"));
      m.frequency = f.number("frequency", up_to(1e7, "Hz"));
      m.direction = unit("direction");
      if (!(2 * 3.14159265358979323846 * m.frequency * m.amplitude <= kMaxSpeed))
        f.fail(*f.get("frequency"), "frequency", "a peak speed 2 pi f A of at most " + std::to_string(kMaxSpeed) + " m/s");
      break;
    case MotionKind::none:
      break;
  }
  f.note(s, prefix + ".motion.", {"kind", "start_time", "ramp_time"});
  // A motion that begins at or after the run's end is kept (a restart with a later end_time moves
  // the object then), but said: in this run the object stands still.
  if (m.kind != MotionKind::none && m.start >= s.end_time)
    s.notes.push_back("note: " + f.where_of("start_time") + ": " + label + " starts moving at t = " + Scene::shortest(m.start) +
                      " s, not before [simulation] end_time = " + Scene::shortest(s.end_time) + " s: it stands still in this run");
  return m;
}

void note_wall_speed(Scene& s, const std::string& label, const std::string& where, double v) {
  if (v > 0 && s.max_impact_speed > 0 && v > s.max_impact_speed)
    s.notes.push_back("note: " + where + ": " + label + " moves at up to " + std::to_string(v) +
                      " m/s, above [simulation] max_impact_speed = " + std::to_string(s.max_impact_speed) +
                      " m/s: its impacts may overlap more than the time step was chosen for");
}

// An object's `contact_class`: the account its contacts' dissipation is booked under
// (blaze/particles/energy_ledger.hpp; the mill's objects have theirs).
ContactClass read_contact_class(Fields& f) {
  if (!f.has("contact_class")) return ContactClass::wall;
  const std::string allowed = "one of \"wall\", \"shell\", \"lifter\", \"end_plate\"";
  const std::string v = f.string("contact_class", allowed);
  for (int c = 0; c < kContactClasses; ++c)
    if (v == contact_class_name(c)) return static_cast<ContactClass>(c);
  f.fail(*f.get("contact_class"), "contact_class", allowed);
  return ContactClass::wall;
}

void read_world(const toml::table& root, const std::string& file, Scene& s) {
  const auto materials = material_names(s);
  const auto walls = tables(root, "wall", file);
  for (std::size_t k = 0; k < walls.size(); ++k) {
    Fields f(*walls[k], item_label("wall", k), file,
             {"name", "material", "vertices", "rim", "motion", "remove_time", "contact_class"});
    WallSpec w;
    w.name = f.string_or("name", "", "a non-empty name");
    w.material = lookup(f, "material", materials, "material");
    w.vertices = f.vec3_list("vertices", position("m"), 3, PlanarPolygon<double>::kMaxVertices);
    try {
      (void)PlanarPolygon<double>::make(w.vertices, 0);
    } catch (const std::exception& e) {
      f.fail(*f.get("vertices"), "vertices", std::string("a convex planar polygon: ") + e.what());
    }
    if (const toml::node* rim = f.get("rim")) {
      const std::string allowed = "true (contact on every edge), false (faces only) or a list of edge indices 0.." +
                                  std::to_string(w.vertices.size() - 1) + " (edge k runs from vertex k to k + 1)";
      if (rim->is_boolean()) {
        w.rim_edges = rim->as_boolean()->get() ? 0xffffffffu : 0u;
      } else if (const toml::array* edges = rim->as_array()) {
        w.rim_edges = 0;
        for (const auto& e : *edges) {
          if (!e.is_integer() || e.as_integer()->get() < 0 ||
              e.as_integer()->get() >= static_cast<std::int64_t>(w.vertices.size()))
            f.fail(*rim, "rim", allowed);
          w.rim_edges |= 1u << e.as_integer()->get();
        }
      } else {
        f.fail(*rim, "rim", allowed);
      }
    }
    w.motion = read_motion(f, file, item_label("wall", k), "wall[" + std::to_string(k) + "]", s);
    if (!w.motion.moves() && !reaches_domain(s, w.vertices.data(), w.vertices.size(), reach_margin(s)))
      f.fail(*f.get("vertices"), "vertices", "a polygon that particles can reach: this one lies wholly beyond a particle diameter (" +
                                                 Scene::shortest(reach_margin(s)) + " m) from the domain, " + domain_text(s) +
                                                 " (a still wall; one with a motion may lie outside)");
    w.contact_class = read_contact_class(f);
    note_wall_speed(s, item_label("wall", k), f.where_of("motion"), peak_speed(w.motion, w.vertices));
    s.walls.push_back(w);
  }
  const auto cylinders = tables(root, "cylinder", file);
  for (std::size_t k = 0; k < cylinders.size(); ++k) {
    Fields f(*cylinders[k], item_label("cylinder", k), file,
             {"material", "origin", "axis", "radius", "length", "motion", "remove_time", "contact_class"});
    CylinderSpec c;
    c.material = lookup(f, "material", materials, "material");
    c.origin = f.vec3("origin", position("m"));
    c.axis = f.vec3("axis", {-1e9, 1e9, false, false, "(direction)"});
    if (!(norm(c.axis) > 0)) f.fail(*f.get("axis"), "axis", "a non-zero direction");
    c.radius = f.number("radius", up_to(kMaxCoordinate, "m"));
    c.length = f.number("length", up_to(kMaxCoordinate, "m"));
    c.motion = read_motion(f, file, item_label("cylinder", k), "cylinder[" + std::to_string(k) + "]", s);
    c.contact_class = read_contact_class(f);
    note_wall_speed(s, item_label("cylinder", k), f.where_of("motion"), peak_speed(c.motion, c.rim()));
    s.cylinders.push_back(c);
  }
}

// A [[mesh]]'s file: as written (from the working directory, as shape files are), else beside
// the scene file.
std::string mesh_path(const std::string& file, const std::string& scene) {
  if (std::ifstream(file).good() || file.empty() || file[0] == '/') return file;
  const auto slash = scene.find_last_of('/');
  const std::string beside = slash == std::string::npos ? file : scene.substr(0, slash + 1) + file;
  return std::ifstream(beside).good() ? beside : file;
}

// [[mesh]] (MeshSpec): read, welded, repaired, placed.
void read_meshes(const toml::table& root, const std::string& file, Scene& s) {
  const auto materials = material_names(s);
  const auto items = tables(root, "mesh", file);
  for (std::size_t k = 0; k < items.size(); ++k) {
    const std::string label = item_label("mesh", k), prefix = "mesh[" + std::to_string(k) + "]";
    Fields f(*items[k], label, file,
             {"name", "file", "material", "scale", "rotate", "translate", "flip", "motion", "remove_time", "contact_class"});
    MeshSpec m;
    m.file = f.string("file", "a path to an .stl (ASCII or binary) or .obj file");
    m.name = f.string_or("name", m.file, "a non-empty name");
    m.material = lookup(f, "material", materials, "material");
    m.scale = f.number_or("scale", 1, {0, 1e9, true, false, "m per file unit (0.001 for a file in mm)"});
    m.translate = f.vec3_or("translate", {0, 0, 0}, position("m"));
    m.flip = f.boolean_or("flip", false);
    if (const toml::node* r = f.get("rotate")) {
      if (!r->is_table()) f.fail(*r, "rotate", "a table: rotate = { axis = [x, y, z], degrees = a }");
      Fields rf(*r->as_table(), label + " rotate", file, {"axis", "degrees"});
      m.axis = rf.vec3("axis", {-1e9, 1e9, false, false, "(direction)"});
      if (!(norm(m.axis) > 0)) rf.fail(*rf.get("axis"), "axis", "a non-zero direction");
      m.axis = m.axis * (1 / norm(m.axis));
      m.degrees = rf.number("degrees", {-1e6, 1e6, false, false, "degrees, right-handed about axis"});
    }
    m.path = mesh_path(m.file, file);
    MeshReport report;
    try {
      m.mesh = load_mesh(m.path, report);
    } catch (const std::exception& e) {
      f.fail(*f.get("file"), "file", std::string("a readable, valid mesh: ") + e.what());
    }
    const double half = 0.5 * m.degrees * 3.14159265358979323846 / 180;
    const Mat3<double> rot = Mat3<double>::rotation(
        Quat<double>{std::cos(half), std::sin(half) * m.axis.x, std::sin(half) * m.axis.y, std::sin(half) * m.axis.z});
    for (auto& v : m.mesh.vertices) {
      v = rot * (v * m.scale) + m.translate;
      if (!(std::fabs(v.x) <= kMaxCoordinate && std::fabs(v.y) <= kMaxCoordinate && std::fabs(v.z) <= kMaxCoordinate))
        f.fail(*f.get(f.has("scale") ? "scale" : "file"), f.has("scale") ? "scale" : "file",
               "vertices within " + Scene::shortest(kMaxCoordinate) + " m of the origin once placed");
    }
    if (m.flip)
      for (auto& t : m.mesh.triangles) std::swap(t[1], t[2]);
    m.report = report.summary();
    if (!m.report.empty()) s.notes.push_back("note: " + f.where_of("file") + ": " + label + " '" + m.path + "': " + m.report);
    m.motion = read_motion(f, file, label, prefix, s);
    if (!m.motion.moves()) {
      bool reaches = false;
      const auto [a, b] = bounds(m.mesh.vertices.data(), m.mesh.vertices.size());  // load_mesh: at least one triangle
      for (const auto& t : m.mesh.triangles) {
        const Vec3<double> tri[3] = {m.mesh.vertices[t[0]], m.mesh.vertices[t[1]], m.mesh.vertices[t[2]]};
        if ((reaches = reaches_domain(s, tri, 3, reach_margin(s)))) break;
      }
      if (!reaches)
        f.fail(*f.get("file"), "file", "a mesh that particles can reach: placed (scale " + Scene::shortest(m.scale) + ", rotate, translate) it spans " +
                                           shown_vec(a) + " to " + shown_vec(b) + " m and no triangle comes within a particle diameter (" +
                                           Scene::shortest(reach_margin(s)) + " m) of the domain, " + domain_text(s) +
                                           " (scale = 0.001 reads a file in mm; a mesh with a motion may lie outside)");
    }
    m.contact_class = read_contact_class(f);
    note_wall_speed(s, label, f.where_of("motion"), peak_speed(m.motion, m.mesh.vertices));
    f.note(s, prefix + ".", {"file", "scale", "translate"});
    s.meshes.push_back(std::move(m));
  }
}

// A [mill] and a periodic domain: a drum whose axis runs along a periodic axis is a slice of a long
// mill (thesis section 4.3.1), so it has no end plates, and its shell and lifters reach past the
// domain's faces by a particle diameter (a particle near a face meets them as its images do);
// a drum across a periodic axis would be cut by the period. Without periodic ends, end plates.
void check_mill_period(Fields& f, const Scene& s, const MillSpec& m) {
  int along = -1;
  for (int d = 0; d < 3; ++d)
    if (std::fabs(std::fabs(d == 0 ? m.axis.x : d == 1 ? m.axis.y : m.axis.z) - 1) < 1e-12) along = d;
  double largest = 0;
  for (const auto& t : s.types) largest = std::fmax(largest, t.is_sphere() ? t.radius : t.bounding_radius);
  for (int d = 0; d < 3; ++d) {
    if (!((s.periodic >> d) & 1u)) continue;
    if (d != along)
      f.fail(*f.get("axis"), "axis", std::string("the periodic axis \"") + "xyz"[d] + "\" (simulation.periodic): a drum's axis may run along a " +
                                         "periodic axis (a slice of a long mill), not across one (the period would cut the drum)");
    const double lo = d == 0 ? s.domain_lo.x : d == 1 ? s.domain_lo.y : s.domain_lo.z, hi = d == 0 ? s.domain_hi.x : d == 1 ? s.domain_hi.y : s.domain_hi.z;
    const double c = d == 0 ? m.centre.x : d == 1 ? m.centre.y : m.centre.z;
    if (m.end_plates) {
      const std::string allowed = std::string("false: the domain is periodic along the drum's axis \"") + "xyz"[d] +
                                  "\" (simulation.periodic), a slice of a long mill, which has no end plates; or drop \"" + "xyz"[d] +
                                  "\" from periodic for a whole drum";
      if (f.has("end_plates")) f.fail(*f.get("end_plates"), "end_plates", allowed);
      f.missing("end_plates", allowed);
    }
    if (c - 0.5 * m.length > lo - 2 * largest || c + 0.5 * m.length < hi + 2 * largest)
      f.fail(*f.get("length"), "length", "a drum reaching a particle diameter past the periodic domain's faces (from " + Scene::shortest(lo - 2 * largest) +
                                             " to " + Scene::shortest(hi + 2 * largest) + " m along the axis; the domain spans " + Scene::shortest(lo) +
                                             " to " + Scene::shortest(hi) + " m)");
  }
  if (!m.end_plates && along >= 0 && !((s.periodic >> along) & 1u))
    f.fail(*f.get("end_plates"), "end_plates", std::string("true, or the domain periodic along the drum's axis (periodic = [\"") + "xyz"[along] +
                                                   "\"]): a drum without end plates spills its charge out of its ends");
  if (!m.end_plates && along < 0)
    f.fail(*f.get("end_plates"), "end_plates", "true: a drum without end plates needs its axis along a periodic axis of the domain (x, y or z)");
}

// The drum inside the domain along every axis that is not periodic: its charge lies within the
// shell and the end plates, and a particle that leaves the domain is removed, so a drum reaching
// past a face would lose the balls that go there (a drum of 5 m in a domain of 1 m ran, its
// charge falling through the domain's floor). Its box: centre +- (L/2 |a_d| + R sqrt(1 - a_d^2)).
void check_mill_inside(Fields& f, const Scene& s, const MillSpec& m) {
  const double a[3] = {m.axis.x, m.axis.y, m.axis.z}, c[3] = {m.centre.x, m.centre.y, m.centre.z};
  const double lo[3] = {s.domain_lo.x, s.domain_lo.y, s.domain_lo.z}, hi[3] = {s.domain_hi.x, s.domain_hi.y, s.domain_hi.z};
  for (int d = 0; d < 3; ++d) {
    if ((s.periodic >> d) & 1u) continue;  // a slice's ends: check_mill_period
    const double h = 0.5 * m.length * std::fabs(a[d]) + 0.5 * m.diameter * std::sqrt(std::fmax(0.0, 1 - a[d] * a[d]));
    const double slack = 1e-9 * (hi[d] - lo[d]);
    if (c[d] - h < lo[d] - slack || c[d] + h > hi[d] + slack) {
      // too big for the domain: its size; else where it stands
      const char* key = 2 * h > hi[d] - lo[d] + 2 * slack ? (std::fabs(a[d]) > 0.5 ? "length" : "diameter") : "centre";
      f.fail(*f.get(key), key, std::string("a drum inside the domain (particles that leave it are removed): along ") + "xyz"[d] + " it spans " +
                                   Scene::shortest(c[d] - h) + " to " + Scene::shortest(c[d] + h) + " m, the domain " + Scene::shortest(lo[d]) +
                                   " to " + Scene::shortest(hi[d]) + " m");
    }
  }
}

// [mill] (include/blaze/scene/mill_geometry.hpp): a drum shell, end plates and lifter rows, all
// turning together, added to the scene's cylinders and walls.
void read_mill(const toml::table& root, const std::string& file, Scene& s) {
  const toml::node* node = root.get("mill");
  if (!node) return;
  if (!node->is_table()) throw SceneError(where(node->source(), file) + ": 'mill' must be a table, written [mill]");
  Fields f(*node->as_table(), "[mill]", file,
           {"material", "centre", "axis", "diameter", "length", "rpm", "omega", "start_time", "ramp_time", "lifters", "end_plates"});
  MillSpec m;
  m.present = true;
  m.material = lookup(f, "material", material_names(s), "material");
  m.centre = f.vec3("centre", position("m"));
  m.axis = f.vec3("axis", {-1e9, 1e9, false, false, "(direction)"});
  if (!(norm(m.axis) > 0)) f.fail(*f.get("axis"), "axis", "a non-zero direction (the drum's axis; an axis of zero length has none)");
  m.axis = m.axis * (1 / norm(m.axis));
  m.diameter = f.number("diameter", up_to(kMaxCoordinate, "m"));
  m.length = f.number("length", up_to(kMaxCoordinate, "m"));
  one_of(f, "rpm", "omega", "rpm (revolutions per minute) and omega (rad/s), signed by the right-hand rule about axis");
  m.omega = f.has("rpm") ? f.number("rpm", {-1e6, 1e6, false, false, "rpm"}) * 2 * 3.14159265358979323846 / 60
                         : f.number("omega", {-1e5, 1e5, false, false, "rad/s"});
  m.start = f.number_or("start_time", 0, non_negative("s"));
  if (m.start >= s.end_time)  // kept for a restart that runs longer, but said (as a wall's motion)
    s.notes.push_back("note: " + f.where_of("start_time") + ": [mill] starts turning at t = " + Scene::shortest(m.start) +
                      " s, not before [simulation] end_time = " + Scene::shortest(s.end_time) + " s: it stands still in this run");
  m.ramp = f.number_or("ramp_time", 0, non_negative("s"));
  m.end_plates = f.boolean_or("end_plates", true);
  check_mill_period(f, s, m);
  check_mill_inside(f, s, m);
  const double r = 0.5 * m.diameter;
  if (const toml::node* rows = f.get("lifters")) {
    const toml::array* list = rows->as_array();
    const std::string allowed = "a list of tables { count, height, width, face_angle, offset }";
    if (!list) f.fail(*rows, "lifters", allowed);
    double occupied = 0;  // of the circumference, m
    for (std::size_t k = 0; k < list->size(); ++k) {
      const toml::table* t = list->get(k)->as_table();
      if (!t) f.fail(*list->get(k), "lifters", allowed);
      Fields g(*t, "[mill] lifters #" + std::to_string(k + 1), file, {"count", "height", "width", "face_angle", "offset"});
      LifterRowSpec l;
      l.count = static_cast<int>(g.integer("count", 1, 1000));
      l.height = g.number("height", {0, r, true, true, "m (below the drum's radius)"});
      l.width = g.number("width", {0, r, true, true, "m (below the drum's radius)"});
      l.face_angle = g.number_or("face_angle", 0, {-60, 60, true, true, "deg"});
      l.offset = g.number_or("offset", 0, {-360, 360, false, false, "deg"});
      const double top = l.width - 2 * l.height * std::tan(l.face_angle * 3.14159265358979323846 / 180);
      if (!(top > 1e-6 * l.width))
        g.fail(*g.get("face_angle"), "face_angle", "a lean whose faces stay apart up to the top: height tan(face_angle) < width / 2");
      occupied += l.count * l.width;
      if (occupied >= 2 * 3.14159265358979323846 * r)
        g.fail(*g.get("count"), "count", "rows whose widths together fit around the shell (pi diameter = " +
                                             std::to_string(3.14159265358979323846 * m.diameter) + " m)");
      m.lifters.push_back(l);
    }
  }
  f.note(s, "mill.", {"material", "centre", "axis", "diameter", "length"});
  const Motion motion = mill_motion(m);
  CylinderSpec shell;
  shell.material = m.material;
  shell.origin = m.centre - m.axis * (0.5 * m.length);
  shell.axis = m.axis;
  shell.radius = r;
  shell.length = m.length;
  shell.motion = motion;
  shell.contact_class = ContactClass::shell;
  shell.name = "mill shell";
  s.cylinders.push_back(shell);
  for (const MillWall& w : mill_walls(m)) {
    WallSpec spec;
    spec.name = "mill " + w.name;
    spec.material = m.material;
    spec.vertices = w.vertices;
    spec.rim_edges = w.rim_edges;
    spec.motion = motion;
    spec.contact_class = w.contact_class;
    s.walls.push_back(spec);
  }
  note_wall_speed(s, "[mill]", f.where_of("diameter"), std::fabs(m.omega) * r);
  s.mill = m;
}

// Every material that meets another (particle-particle, particle-wall) needs its [[pair]].
void check_pairs_complete(const toml::table& root, const std::string& file, const Scene& s) {
  std::set<int> particle_materials, world_materials;
  for (const auto& t : s.types) particle_materials.insert(t.material);
  for (const auto& w : s.walls) world_materials.insert(w.material);
  for (const auto& c : s.cylinders) world_materials.insert(c.material);
  for (const auto& m : s.meshes) world_materials.insert(m.material);
  auto need = [&](int a, int b) {
    if (!s.pair(a, b))
      throw SceneError(where(root.source(), file) + ": no [[pair]] for materials \"" + s.materials[static_cast<std::size_t>(a)].name +
                       "\" and \"" + s.materials[static_cast<std::size_t>(b)].name + "\": add one with materials = [\"" +
                       s.materials[static_cast<std::size_t>(a)].name + "\", \"" + s.materials[static_cast<std::size_t>(b)].name + "\"]");
  };
  for (int a : particle_materials) {
    for (int b : particle_materials) need(a, b);
    for (int b : world_materials) need(a, b);
  }
}

// dt from steps_per_contact, and dt against the critical step (critical_step.hpp).
void check_time_step(const toml::table& sim, const std::string& file, Scene& s) {
  const CriticalStep c = critical_step(s);
  s.dt_critical = c.dt_critical;
  s.dt_governing = c.governing;
  s.impact_overlap = c.impact_overlap;
  s.impact_speed = c.impact_speed;
  s.overlap_governing = c.overlap_governing;
  if (s.steps_per_contact > 0) s.dt = c.contact_time / s.steps_per_contact;
  if (!(s.impact_overlap <= kMaxImpactOverlap) && !s.force_dt) {
    std::ostringstream msg;
    msg.precision(3);
    msg << ": an impact at " << c.impact_speed << " m/s (" << (s.max_impact_speed > 0 ? "max_impact_speed" : "the default: "
        "initial speeds plus a fall through the domain") << ") of " << c.overlap_governing << " overlaps " << 100 * s.impact_overlap
        << "% of the radius; above " << 100 * kMaxImpactOverlap << "% particles near tunnelling through walls and each other. "
        << "Raise the stiffness, lower max_impact_speed if no impact is that fast, or set force_dt = true";
    if (const toml::node* v = sim.get("max_impact_speed"))
      throw SceneError(where(v->source(), file) + ": [simulation]: key 'max_impact_speed' = " + shown(*v) + msg.str());
    // The stiffness of the pairing is what to raise: its [[pair]] (linear) or its materials' modulus (Hertz).
    std::size_t k = 0;
    while (k < s.pairs.size() && !(s.pairs[k].a == c.overlap_a && s.pairs[k].b == c.overlap_b)) ++k;
    const std::string key = k == s.pairs.size() ? "simulation.max_impact_speed"
                            : s.law == LawKind::hertz ? "material[" + std::to_string(c.overlap_a) + "].youngs_modulus"
                            : "pair[" + std::to_string(k) + "]." + (s.pairs[k].stiffness > 0 ? "stiffness" : "contact_time");
    throw SceneError(s.place(key) + msg.str());
  }
  if (s.dt <= kSafeStepFraction * s.dt_critical || s.force_dt) return;
  Fields f(sim, "[simulation]", file);
  std::ostringstream allowed;
  allowed.precision(4);
  allowed << "dt = " << s.dt << " s is " << s.dt / s.dt_critical << " of the critical step " << s.dt_critical << " s ("
          << c.governing << (s.law == LawKind::hertz ? ", impact speed " + std::to_string(c.impact_speed) + " m/s" : "")
          << "); at most " << kSafeStepFraction << " is safe. Lower it, or set force_dt = true to run anyway";
  const char* key = s.steps_per_contact > 0 ? "steps_per_contact" : "dt";
  f.fail(*f.get(key), key, allowed.str());
}

// Where every key of the file (and of --set) is, by its --set name (Scene::where).
void record_places(const toml::table& root, const std::string& file, Scene& s) {
  for (const auto& [k, v] : root) {
    const std::string name(k.str());
    if (const toml::table* t = v.as_table()) {
      for (const auto& [key, value] : *t) s.where[name + "." + std::string(key.str())] = where(value.source(), file);
    } else if (const toml::array* a = v.as_array()) {
      for (std::size_t i = 0; i < a->size(); ++i)
        if (const toml::table* item = a->get(i)->as_table())
          for (const auto& [key, value] : *item)
            s.where[name + "[" + std::to_string(i) + "]." + std::string(key.str())] = where(value.source(), file);
    }
  }
}

std::string shown_vec(const Vec3<double>& v) {
  return "[" + Scene::shortest(v.x) + ", " + Scene::shortest(v.y) + ", " + Scene::shortest(v.z) + "]";
}


// Derived sizes (run_size.hpp), computed in double and refused before anything is allocated,
// naming the key that makes them too large: the grid's cells, the step count.
void check_sizes(Scene& s) {
  const RunSize z = run_size(s, false);
  if (!(z.cells[0] < 2147483647.0 && z.cells[1] < 2147483647.0 && z.cells[2] < 2147483647.0 && z.cells_total < GridSpec<double>::kMaxCells)) {
    char msg[320];
    std::snprintf(msg, sizeof msg, ": the domain spans %.3g x %.3g x %.3g = %.3g cells of 2 r_max + skin = %.3g m; at most "
                  "4.29e9 in all (32-bit cell hashes): shrink the domain (particles that leave it are removed) or raise skin",
                  z.cells[0], z.cells[1], z.cells[2], z.cells_total, z.cell);
    throw SceneError(s.place("simulation.domain_hi") + " = " + shown_vec(s.domain_hi) + msg);
  }
  for (int d = 0; d < 3; ++d)
    if (((s.periodic >> d) & 1u) && z.cells[d] < 3) {
      const double length = d == 0 ? s.domain_hi.x - s.domain_lo.x : d == 1 ? s.domain_hi.y - s.domain_lo.y : s.domain_hi.z - s.domain_lo.z;
      char msg[320];
      std::snprintf(msg, sizeof msg, ": the domain along %c is %.4g m, less than 3 cells of 2 r_max + skin = %.4g m: a particle "
                    "would meet two images of another. Give a period of at least %.4g m along %c, or lower skin",
                    "xyz"[d], length, z.cell, 3 * z.cell, "xyz"[d]);
      throw SceneError(s.place("simulation.periodic") + msg);
    }
  const char* dt_key = s.steps_per_contact > 0 ? "simulation.steps_per_contact" : "simulation.dt";
  if (s.end_time < s.dt)
    throw SceneError(s.place("simulation.end_time") + " = " + Scene::shortest(s.end_time) + ": shorter than one time step (dt = " +
                     Scene::shortest(s.dt) + " s); give end_time >= dt");
  const std::pair<const char*, double> intervals[] = {{"output.csv_interval", s.output.csv_interval},
                                                      {"output.vtu_interval", s.output.vtu_interval},
                                                      {"output.checkpoint_interval", s.output.checkpoint_interval}};
  for (const auto& [key, interval] : intervals)
    if (interval > 0 && interval < s.dt * (1 - 1e-9))
      throw SceneError(s.place(key) + " = " + Scene::shortest(interval) + ": shorter than one time step (dt = " +
                       Scene::shortest(s.dt) + " s); give at least dt (output every step) or 0 (none)");
  if (!(z.steps <= kMaxSteps))
    throw SceneError(s.place(dt_key) + ": end_time / dt = " + Scene::shortest(s.end_time) + " s / " + Scene::shortest(s.dt) +
                     " s = " + Scene::shortest(z.steps) + " steps; at most " + Scene::shortest(kMaxSteps) +
                     " (a step takes at least a microsecond: such a run cannot finish). Raise dt or lower end_time");
}

// max_impact_speed sets the stiffness and overlap estimates: a particle that starts faster than it
// overlaps more than estimated and can tunnel through a wall.
void check_impact_speed(const toml::table& sim, const std::string& file, const Scene& s) {
  if (!(s.max_impact_speed > 0)) return;
  std::string key;
  const double v0 = largest_initial_speed(s, &key);
  if (v0 <= s.max_impact_speed) return;
  Fields f(sim, "[simulation]", file);
  f.fail(*f.get("max_impact_speed"), "max_impact_speed",
         "below the initial speed " + Scene::shortest(v0) + " m/s of " + s.place(key) +
             "; a particle faster than max_impact_speed overlaps more than estimated and can tunnel through a wall: "
             "give at least " + Scene::shortest(v0) + " m/s (or leave it out: the default covers every initial speed)");
}

// Quadratic drag F = -drag |v| v slows a particle at the rate drag |v| / m; the explicit step
// overshoots (reverses the velocity) once that rate times dt nears 1. Refused above 0.5 at the
// impact speed for the lightest particle type.
void check_drag(const toml::table& sim, const std::string& file, const Scene& s) {
  if (!(s.drag > 0)) return;
  double m_min = INFINITY;
  for (const auto& t : s.types) m_min = std::min(m_min, s.materials[static_cast<std::size_t>(t.material)].density * t.volume);
  const double rate_dt = s.drag * s.impact_speed * s.dt / m_min;
  if (rate_dt <= 0.5) return;
  Fields f(sim, "[simulation]", file);
  f.fail(*f.get("drag"), "drag",
         "slows the lightest particle at " + Scene::shortest(rate_dt) + " of its speed per step at " +
             Scene::shortest(s.impact_speed) + " m/s (dt = " + Scene::shortest(s.dt) +
             " s); above 0.5 the explicit step overshoots. Lower drag or dt");
}

// Float resolution far from the origin: positions are held to ulp(|x|) (2^-23 |x| in float), and a
// contact's overlap is a difference of positions. Where ulp at the domain's largest coordinate is
// not small against the overlap of an impact (impact_overlap x the smallest radius, the least
// overlap the contacts must resolve), forces come out in steps of ulp k, and such a run's energy
// guard blames the time step. Refused above a tenth of the overlap, noted above a hundredth.
void check_resolution(Scene& s) {
  const double far = std::max({std::fabs(s.domain_lo.x), std::fabs(s.domain_lo.y), std::fabs(s.domain_lo.z),
                               std::fabs(s.domain_hi.x), std::fabs(s.domain_hi.y), std::fabs(s.domain_hi.z)});
  const bool single = s.precision == PrecisionKind::float32;
  const double ulp = single ? static_cast<double>(std::nextafter(static_cast<float>(far), INFINITY) - static_cast<float>(far))
                            : std::nextafter(far, INFINITY) - far;
  double r_min = INFINITY;
  for (const auto& t : s.types) r_min = std::min(r_min, t.size());
  const double overlap = s.impact_overlap * r_min;
  if (!(overlap > 0)) return;
  const double ratio = ulp / overlap;
  char numbers[320];
  std::snprintf(numbers, sizeof numbers, "positions %.3g m from the origin are resolved to %.3g m in %s, %.3g of the overlap of "
                "an impact at %.3g m/s (%.3g m = %.3g of the smallest radius)", far, ulp, single ? "float" : "double", ratio,
                s.impact_speed, overlap, s.impact_overlap);
  if (ratio > kMaxResolutionShare)
    throw SceneError(s.place("simulation.domain_hi") + ": " + numbers + "; above " + Scene::shortest(kMaxResolutionShare) +
                     " contacts cannot be resolved. Move the scene's origin near the particles" +
                     (single ? std::string(" or set precision = \"double\"") : std::string()));
  if (ratio > kNoteResolutionShare)
    s.notes.push_back(std::string("note: ") + numbers + "; contact forces are coarse above " +
                      Scene::shortest(kNoteResolutionShare) + (single ? " (precision = \"double\" resolves them)" : ""));
}

Scene read(toml::table& root, const std::string& file, const std::vector<std::string>& overrides) {
  for (const auto& o : overrides) apply_override(root, o);
  static const std::set<std::string> known = {"simulation", "output", "material", "pair", "particle_type",
                                              "lattice", "particles", "fill", "feed", "wall", "cylinder", "mesh", "mill", "study"};
  for (const auto& [k, v] : root)
    if (!known.count(std::string(k.str()))) {
      std::string allowed;
      for (const auto& n : known) allowed += (allowed.empty() ? "" : ", ") + n;
      throw SceneError(where(v.source(), file) + ": unknown table or key '" + std::string(k.str()) + "'; allowed: " + allowed);
    }
  Scene s;
  s.path = file;
  record_places(root, file, s);
  if (!root.contains("simulation")) throw SceneError(file + ": no [simulation] table (dt or steps_per_contact, end_time, domain_lo, domain_hi)");
  read_simulation(table(root, "simulation", file), file, s);
  read_output(table(root, "output", file), file, s);
  read_study(table(root, "study", file), file, s);
  read_materials(root, file, s);
  read_pairs(root, file, s);
  read_types(root, file, s);
  const long total = read_placements(root, file, s);
  read_feeds(root, file, s);
  if (total == 0 && s.feeds.empty()) throw SceneError(file + ": no particles: add a [[lattice]], [[particles]], [[fill]] or [[feed]]");
  if (total > kMaxParticles) throw SceneError(file + ": " + std::to_string(total) + " particles; at most 2^31 - 1");
  read_world(root, file, s);
  read_meshes(root, file, s);
  read_mill(root, file, s);
  check_pairs_complete(root, file, s);
  check_time_step(table(root, "simulation", file), file, s);
  check_impact_speed(table(root, "simulation", file), file, s);
  check_drag(table(root, "simulation", file), file, s);
  check_sizes(s);
  check_resolution(s);
  return s;
}

}  // namespace

Scene parse_scene(const std::string& text, const std::string& name, const std::vector<std::string>& overrides) {
  toml::table root;
  try {
    root = toml::parse(text, name);
  } catch (const toml::parse_error& e) {
    throw SceneError(name + ":" + std::to_string(e.source().begin.line) + ":" + std::to_string(e.source().begin.column) +
                     ": TOML syntax error: " + std::string(e.description()));
  }
  return read(root, name, overrides);
}

Scene load_scene(const std::string& path, const std::vector<std::string>& overrides) {
  std::ifstream in(path, std::ios::binary);
  if (!in) throw SceneError(path + ": cannot open scene file");
  std::ostringstream text;
  text << in.rdbuf();
  return parse_scene(text.str(), path, overrides);
}

}  // namespace blaze
