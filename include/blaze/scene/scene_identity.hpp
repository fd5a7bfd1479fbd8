// The identity of a run: every physical input of its validated scene, one "key = value" line
// each, named as --set names them ("simulation.dt", "material[0].density", "lattice[1].origin").
// A checkpoint carries the identity of the run that wrote it, and a restart continues it only
// when the scene gives the same identity (issue 17: density, radius or positions changed in the
// scene were accepted, and the banner showed them while the checkpoint's old state ran).
//
// In the identity: [simulation] law, precision, dt (as derived from steps_per_contact), gravity,
// drag, domain, skin and seed (it places the fills); every material, pair, particle type (with a
// hash of its shape file's bytes), placement (explicit lists hashed: they may hold 1e6 points),
// wall, cylinder and [study] value. Not in it: end_time (extending a run is what a restart is
// for), [output], backend, pair_evaluation and world_lists (bitwise the same results), force_dt, force_long_run
// and max_impact_speed (validation only: the dt it implies is in the identity).
#pragma once
#include <cstdint>
#include <cstdio>
#include <fstream>
#include <limits>
#include <sstream>
#include <string>
#include <utility>
#include <vector>
#include "blaze/scene/scene.hpp"

namespace blaze {

using SceneIdentity = std::vector<std::pair<std::string, std::string>>;

namespace identity_detail {

inline std::string num(double v) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.17g", v);
  return buf;
}
inline std::string vec(const Vec3<double>& v) { return "[" + num(v.x) + ", " + num(v.y) + ", " + num(v.z) + "]"; }
// FNV-1a 64 of bytes, as 16 hex digits.
inline std::string hash(const std::string& bytes) {
  std::uint64_t h = 1469598103934665603ull;
  for (unsigned char c : bytes) h = (h ^ c) * 1099511628211ull;
  char buf[24];
  std::snprintf(buf, sizeof buf, "%016llx", static_cast<unsigned long long>(h));
  return buf;
}
inline std::string file_hash(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  std::ostringstream s;
  s << in.rdbuf();
  return hash(s.str());
}

}  // namespace identity_detail

inline SceneIdentity scene_identity(const Scene& s) {
  using namespace identity_detail;
  SceneIdentity id;
  auto add = [&](const std::string& k, const std::string& v) { id.emplace_back(k, v); };
  // an object's motion and removal, only where it has one (static scenes keep their identity)
  auto add_motion = [&](const std::string& p, const Motion& m) {
    if (m.is_static()) return;
    static const char* const kinds[] = {"none", "rotation", "translation", "vibration"};
    add(p + "motion", std::string(kinds[static_cast<int>(m.kind)]) + " axis " + vec(m.axis) + " point " + vec(m.point) +
                          " omega " + num(m.omega) + " velocity " + vec(m.velocity) + " amplitude " + num(m.amplitude) +
                          " frequency " + num(m.frequency) + " direction " + vec(m.direction) + " start " + num(m.start) +
                          " ramp " + num(m.ramp) + " remove " + num(m.remove));
  };
  add("simulation.law", to_string(s.law));
  add("simulation.tangential", to_string(s.tangential));
  add("simulation.rolling", to_string(s.rolling));
  add("simulation.precision", to_string(s.precision));
  add("simulation.dt", num(s.dt));
  add("simulation.gravity", vec(s.gravity));
  add("simulation.drag", num(s.drag));
  add("simulation.domain_lo", vec(s.domain_lo));
  add("simulation.domain_hi", vec(s.domain_hi));
  add("simulation.skin", num(s.skin));
  if (s.periodic) add("simulation.periodic", std::to_string(s.periodic));
  add("simulation.seed", std::to_string(s.seed));
  for (std::size_t k = 0; k < s.materials.size(); ++k) {
    const auto& m = s.materials[k];
    const std::string p = "material[" + std::to_string(k) + "].";
    add(p + "name", m.name);
    add(p + "density", num(m.density));
    add(p + "youngs_modulus", num(m.youngs_modulus));
    add(p + "poisson_ratio", num(m.poisson_ratio));
  }
  for (std::size_t k = 0; k < s.pairs.size(); ++k) {
    const auto& q = s.pairs[k];
    const std::string p = "pair[" + std::to_string(k) + "].";
    add(p + "materials", s.materials[static_cast<std::size_t>(q.a)].name + ", " + s.materials[static_cast<std::size_t>(q.b)].name);
    add(p + "stiffness", num(q.stiffness));
    add(p + "contact_time", num(q.contact_time));
    add(p + "restitution", num(q.restitution));
    add(p + "friction", num(q.friction));
    add(p + "tangential_damping", num(q.tangential_damping));
    if (q.tangential_rate > 0) add(p + "tangential_rate", num(q.tangential_rate));
    add(p + "tangential_stiffness", num(q.tangential_stiffness));
    add(p + "rolling_friction", num(q.rolling_friction));
    add(p + "rolling_damping", num(q.rolling_damping));
    add(p + "no_tension", q.no_tension ? "true" : "false");
  }
  for (std::size_t k = 0; k < s.types.size(); ++k) {
    const auto& t = s.types[k];
    const std::string p = "particle_type[" + std::to_string(k) + "].";
    add(p + "name", t.name);
    add(p + "material", s.materials[static_cast<std::size_t>(t.material)].name);
    add(p + "radius", num(t.radius));
    add(p + "shape", t.shape.empty() ? "" : t.shape + " (bytes " + file_hash(t.shape) + ")");
    add(p + "bounding_radius", num(t.bounding_radius));
  }
  for (std::size_t k = 0; k < s.lattices.size(); ++k) {
    const auto& l = s.lattices[k];
    const std::string p = "lattice[" + std::to_string(k) + "].";
    add(p + "type", s.types[static_cast<std::size_t>(l.type)].name);
    add(p + "origin", vec(l.origin));
    add(p + "count", "[" + std::to_string(l.count[0]) + ", " + std::to_string(l.count[1]) + ", " + std::to_string(l.count[2]) + "]");
    add(p + "spacing", num(l.spacing));
    add(p + "velocity", vec(l.velocity));
    add(p + "jitter", num(l.jitter));
    add(p + "random_orientation", l.random_orientation ? "true" : "false");
  }
  for (std::size_t k = 0; k < s.lists.size(); ++k) {
    const auto& l = s.lists[k];
    const std::string p = "particles[" + std::to_string(k) + "].";
    std::string pos, vel;
    for (const auto& x : l.position) pos += vec(x);
    for (const auto& v : l.velocity) vel += vec(v);
    add(p + "type", s.types[static_cast<std::size_t>(l.type)].name);
    add(p + "positions", std::to_string(l.position.size()) + " points (hash " + hash(pos) + ")");
    add(p + "velocities", std::to_string(l.velocity.size()) + " values (hash " + hash(vel) + ")");
  }
  for (std::size_t k = 0; k < s.fills.size(); ++k) {
    const auto& f = s.fills[k];
    const std::string p = "fill[" + std::to_string(k) + "].";
    add(p + "type", s.types[static_cast<std::size_t>(f.type)].name);
    add(p + "lo", vec(f.lo));
    add(p + "hi", vec(f.hi));
    add(p + "count", std::to_string(f.count));
    add(p + "velocity", vec(f.velocity));
  }
  for (std::size_t k = 0; k < s.feeds.size(); ++k) {
    const auto& f = s.feeds[k];
    const std::string p = "feed[" + std::to_string(k) + "].";
    const auto& g = f.region;
    const auto& d = f.size;
    add(p + "type", s.types[static_cast<std::size_t>(f.type)].name);
    add(p + "region", std::string(to_string(g.kind)) + vec(g.lo) + vec(g.hi) + vec(g.centre) + vec(g.axis) + num(g.radius) + num(g.length));
    // the end the scene gave ("run": none, the feed lasts the run, however long a restart makes it)
    add(p + "times", num(f.start) + " " + (f.end_given < std::numeric_limits<double>::infinity() ? num(f.end_given) : std::string("run")) + " " + num(f.interval));
    add(p + "rate", num(f.rate) + " " + num(f.mass_rate) + " " + std::to_string(f.count));
    add(p + "velocity", vec(f.velocity) + num(f.spread) + (f.random_orientation ? " oriented" : ""));
    std::string classes;
    for (std::size_t c = 0; c < d.sizes.size(); ++c) classes += num(d.sizes[c]) + ":" + num(d.fractions[c]) + " ";
    add(p + "size", std::string(to_string(d.kind)) + (d.by_mass ? " by mass " : " by number ") + classes + num(d.radius) + num(d.mean) +
                        num(d.deviation) + num(d.scale) + num(d.shape) + num(d.min) + num(d.max));
    add(p + "seed", std::to_string(f.seed));
  }
  for (std::size_t k = 0; k < s.walls.size(); ++k) {
    const auto& w = s.walls[k];
    const std::string p = "wall[" + std::to_string(k) + "].";
    std::string v;
    for (const auto& x : w.vertices) v += vec(x);
    add(p + "name", w.name);
    add(p + "material", s.materials[static_cast<std::size_t>(w.material)].name);
    add(p + "vertices", v);
    add(p + "rim", std::to_string(w.rim_edges));
    add_motion(p, w.motion);
  }
  for (std::size_t k = 0; k < s.cylinders.size(); ++k) {
    const auto& c = s.cylinders[k];
    const std::string p = "cylinder[" + std::to_string(k) + "].";
    add(p + "material", s.materials[static_cast<std::size_t>(c.material)].name);
    add(p + "origin", vec(c.origin));
    add(p + "axis", vec(c.axis));
    add(p + "radius", num(c.radius));
    add(p + "length", num(c.length));
    add_motion(p, c.motion);
  }
  for (std::size_t k = 0; k < s.meshes.size(); ++k) {
    const auto& m = s.meshes[k];
    const std::string p = "mesh[" + std::to_string(k) + "].";
    // the placed vertices' and the triangles' bytes
    const std::string v(reinterpret_cast<const char*>(m.mesh.vertices.data()), m.mesh.vertices.size() * sizeof(m.mesh.vertices[0]));
    const std::string t(reinterpret_cast<const char*>(m.mesh.triangles.data()), m.mesh.triangles.size() * sizeof(m.mesh.triangles[0]));
    add(p + "name", m.name);
    add(p + "material", s.materials[static_cast<std::size_t>(m.material)].name);
    add(p + "triangles", std::to_string(m.mesh.size()) + " placed (hash " + hash(v) + ", " + hash(t) + ")");
    add_motion(p, m.motion);
  }
  for (const auto& v : s.study) add("study." + v.key, num(v.value));
  return id;
}

// The identity as a checkpoint stores it: a header line, one line per key, an end line.
constexpr const char* kIdentityBegin = "blaze scene identity 1\n";
constexpr const char* kIdentityEnd = "end of scene identity\n";
inline std::string identity_text(const SceneIdentity& id) {
  std::string t = kIdentityBegin;
  for (const auto& [k, v] : id) t += k + " = " + v + "\n";
  return t + kIdentityEnd;
}

// Empty when `stored` (a checkpoint's text, from its start) holds the same identity as `id`;
// otherwise what differs first, for the message of a refused restart. `rest` is set to the text
// after the identity (the driver's own bookkeeping).
inline std::string identity_difference(const std::string& stored, const SceneIdentity& id, const Scene& s, std::string& rest) {
  if (stored.rfind(kIdentityBegin, 0) != 0)
    return "it was written by an older version of blaze, whose checkpoints do not record the scene; rerun from the start";
  const auto end = stored.find(kIdentityEnd);
  if (end == std::string::npos) return "its scene identity is truncated";
  rest = stored.substr(end + std::string(kIdentityEnd).size());
  std::istringstream in(stored.substr(std::string(kIdentityBegin).size(), end - std::string(kIdentityBegin).size()));
  SceneIdentity old;
  for (std::string line; std::getline(in, line);) {
    const auto eq = line.find(" = ");
    old.emplace_back(line.substr(0, eq), eq == std::string::npos ? "" : line.substr(eq + 3));
  }
  const std::string tail = "; a restart continues the same run: only end_time, [output] and the run options may change";
  for (std::size_t k = 0; k < std::max(old.size(), id.size()); ++k) {
    if (k < old.size() && k < id.size() && old[k] == id[k]) continue;
    if (k >= id.size()) return "the checkpoint's run had " + old[k].first + " = " + old[k].second + ", which the scene does not have" + tail;
    if (k >= old.size() || old[k].first != id[k].first)
      return s.place(id[k].first) + " = " + id[k].second + " was not in the checkpoint's run" + tail;
    return s.place(id[k].first) + " = " + id[k].second + " differs from the checkpoint's run, which had " + old[k].second + tail;
  }
  return "";
}

}  // namespace blaze
