// The repose study's geometry, derived from [study] in bead diameters d (studies/repose/main.cpp):
//   base      a regular octagon of circumradius R_b = base_radius d in the plane y = 0 (normal +y);
//             inscribed radius R_in = R_b cos(pi/8); a lip of base_lip d around it (eight
//             rectangles, rim contact on their top edge) keeps the first layer of beads, which then
//             serves as the rough base of the pile, as glued beads do in experiments
//   outlet    a square of side D = orifice d at height y_o = R_in tan(45 deg) + outlet_clearance d,
//             closed by the wall "gate" until gate_open_time
//   funnel    four trapezoids from the outlet up to a square of side W = hopper_width d at
//             y_f = y_o + (W - D)/2 tan(funnel_angle), rim contact on their lip; above it four
//             vertical walls around the fill
//   fill      a bcc block (two [[lattice]] blocks, spacing a = (1 + lattice_gap) 4 r / sqrt(3)), n
//             corner sites across the funnel's top, as many layers as `particles` needs
//   domain    the base and the funnel with 2 d to spare sideways, 3 d below the base: beads that
//             roll off the base leave it and are removed
// The scene is parsed twice: once as written (for [study]), then with the derived walls appended as
// TOML and the fill and domain given as overrides, so the parser validates the result (placements,
// walls, the critical time step) as it does any scene.
#pragma once
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <map>
#include <sstream>
#include <string>
#include <vector>
#include "blaze/scene/scene_build.hpp"
#include "blaze/scene/scene_file.hpp"
#include "blaze/sim/repose_angle.hpp"
#include "pipeline/scene_params.hpp"

namespace blaze {

struct ReposeSetup {
  Scene scene;
  double d = 0;          // m, bead diameter
  double r_in = 0;       // m, the base's inscribed radius (the pile's radius)
  double outlet_y = 0;   // m, the outlet's height above the base
  long particles = 0;    // beads in the fill
  std::map<std::string, double> derived;  // for the manifest and the LIGGGHTS template

  ReposeGeometry measure() const {
    ReposeGeometry g;
    g.pile_radius = r_in, g.bin = d, g.base_y = 0;
    return g;
  }
  std::map<std::string, std::string> manifest() const {
    std::map<std::string, std::string> m;
    for (const auto& [k, v] : derived) {
      char b[40];
      std::snprintf(b, sizeof b, "%.6g", v);
      m["derived_" + k] = b;
    }
    return m;
  }
};

// The scene without the wall named "gate".
inline Scene without_gate(Scene s) {
  s.walls.erase(std::remove_if(s.walls.begin(), s.walls.end(), [](const WallSpec& w) { return w.name == "gate"; }),
                s.walls.end());
  return s;
}

namespace repose_detail {

using V = Vec3<double>;
inline std::string real(double x) {
  char b[40];
  std::snprintf(b, sizeof b, "%.17g", x);
  return b;
}
inline std::string vec(const V& v) {
  char b[128];
  std::snprintf(b, sizeof b, "[%.17g, %.17g, %.17g]", v.x, v.y, v.z);
  return b;
}
// A [[wall]] whose normal (right-hand rule) points along `inward`; rim on the edges that lie in the
// plane y = rim_y (NaN: none; +inf: all).
inline std::string wall(std::vector<V> v, const V& inward, const std::string& material, double rim_y,
                        const std::string& name = "") {
  if (dot(cross(v[1] - v[0], v[2] - v[0]), inward) < 0) std::reverse(v.begin(), v.end());
  std::string t = "\n[[wall]]\nmaterial = \"" + material + "\"\n";
  if (!name.empty()) t += "name = \"" + name + "\"\n";
  t += "vertices = [";
  for (std::size_t k = 0; k < v.size(); ++k) t += (k ? ", " : "") + vec(v[k]);
  t += "]\nrim = ";
  if (std::isinf(rim_y)) return t + "true\n";
  std::string edges;
  for (std::size_t k = 0; k < v.size(); ++k)
    if (std::abs(v[k].y - rim_y) < 1e-12 && std::abs(v[(k + 1) % v.size()].y - rim_y) < 1e-12)
      edges += (edges.empty() ? "" : ", ") + std::to_string(k);
  return t + (edges.empty() ? "false" : "[" + edges + "]") + "\n";
}

}  // namespace repose_detail

inline ReposeSetup derive_repose(const std::string& path, const std::vector<std::string>& overrides) {
  using namespace repose_detail;
  std::ifstream in(path);
  if (!in) throw SceneError("cannot read " + path);
  std::stringstream text;
  text << in.rdbuf();
  const Scene first = parse_scene(text.str(), path, overrides);
  if (first.types.size() != 1 || !first.all_spheres()) throw SceneError(path + ": the repose study takes one sphere type");
  if (first.law != LawKind::hertz || first.tangential != TangentialKind::mindlin || first.rolling == RollingKind::none)
    throw SceneError(path + ": the repose study runs law = \"hertz\", tangential = \"mindlin\", rolling = \"epsd\" or \"cdt\"");
  if (first.precision != PrecisionKind::float64) throw SceneError(path + ": the repose study runs in double");
  const double r = first.types[0].radius, d = 2 * r, pi = 3.14159265358979323846;
  const double Rb = d * first.study_value("base_radius", 3, 1000, "d"), Rin = Rb * std::cos(pi / 8);
  const double D = d * first.study_value("orifice", 3, 100, "d");
  const double W = d * first.study_value("hopper_width", 4, 1000, "d");
  const double alpha = first.study_value("funnel_angle", 30, 89, "deg") * pi / 180;
  const double clearance = d * first.study_value("outlet_clearance", 0, 100, "d");
  const double lip = d * first.study_value("base_lip", 0, 10, "d");
  const double wanted = first.study_value("particles", 10, 1e8, "beads");
  const double gap = first.study_value("lattice_gap", 0, 1, "x the spacing");
  if (!(W > D)) throw SceneError(path + ": [study] hopper_width must exceed orifice");
  const double yo = Rin + clearance, yf = yo + (W - D) / 2 * std::tan(alpha);
  const double a = (1 + gap) * 4 * r / std::sqrt(3.0);
  const long n = static_cast<long>(std::floor((W - d - 0.1 * d) / a)) + 1;  // corner sites across
  const long per_layer = n * n + (n - 1) * (n - 1);
  const long layers = static_cast<long>(std::ceil(wanted / static_cast<double>(per_layer)));
  const double x0 = -(n - 1) * a / 2, y0 = yf + r + 0.1 * d, ytop = y0 + (layers - 1) * a + a / 2 + r;
  const double top = ytop + d, half = std::max(Rb, W / 2) + 2 * d;

  std::string walls;
  std::vector<V> oct;
  for (int k = 0; k < 8; ++k) oct.push_back({Rb * std::cos(2 * pi * k / 8), 0, Rb * std::sin(2 * pi * k / 8)});
  walls += wall(oct, {0, 1, 0}, "wall", NAN, "base");
  for (int k = 0; k < 8 && lip > 0; ++k) {  // the lip: eight rectangles on the octagon's edges, facing the axis
    const V a0 = oct[k], a1 = oct[(k + 1) % 8], up{0, lip, 0};
    walls += wall({a0, a1, a1 + up, a0 + up}, V{0, 0, 0} - (a0 + a1), "wall", lip);
  }
  const double h = D / 2, w = W / 2;
  walls += wall({{-h, yo, -h}, {h, yo, -h}, {h, yo, h}, {-h, yo, h}}, {0, 1, 0}, "wall", NAN, "gate");
  for (int side = 0; side < 4; ++side) {  // side k: the wall facing -x, +x, -z, +z
    const double s = side % 2 ? 1 : -1;
    const bool x = side < 2;
    auto at = [&](double across, double along, double y) { return x ? V{s * across, y, along} : V{along, y, s * across}; };
    const V inward = x ? V{-s, 0, 0} : V{0, 0, -s};
    walls += wall({at(h, -h, yo), at(h, h, yo), at(w, w, yf), at(w, -w, yf)}, inward + V{0, 1, 0}, "wall", yo);
    walls += wall({at(w, -w, yf), at(w, w, yf), at(w, w, top), at(w, -w, top)}, inward, "wall", NAN);
  }
  std::vector<std::string> all = overrides;
  const auto set = [&](const std::string& k, const std::string& v) { all.push_back(k + "=" + v); };
  set("lattice[0].origin", vec({x0, y0, x0}));
  set("lattice[0].count", "[" + std::to_string(n) + ", " + std::to_string(layers) + ", " + std::to_string(n) + "]");
  set("lattice[0].spacing", real(a));
  set("lattice[1].origin", vec({x0 + a / 2, y0 + a / 2, x0 + a / 2}));
  set("lattice[1].count", "[" + std::to_string(n - 1) + ", " + std::to_string(layers) + ", " + std::to_string(n - 1) + "]");
  set("lattice[1].spacing", real(a));
  set("domain_lo", vec({-half, -3 * d, -half}));
  set("domain_hi", vec({half, top + d, half}));

  ReposeSetup g;
  g.scene = parse_scene(text.str() + walls, path, all);
  refuse_feeds(g.scene, "the repose study");
  g.d = d, g.r_in = Rin, g.outlet_y = yo, g.particles = layers * per_layer;
  g.derived = {{"base_circumradius_m", Rb}, {"base_inscribed_radius_m", Rin}, {"outlet_side_m", D},
               {"outlet_height_m", yo}, {"funnel_top_height_m", yf}, {"funnel_top_side_m", W},
               {"fill_spacing_m", a}, {"fill_sites_across", static_cast<double>(n)},
               {"fill_layers", static_cast<double>(layers)}, {"beads", static_cast<double>(g.particles)}};
  // The [study] keys read here are geometry; main.cpp reads the rest and checks that none is left.
  for (const char* k : {"base_radius", "base_lip", "orifice", "hopper_width", "funnel_angle", "outlet_clearance", "particles", "lattice_gap"})
    g.scene.study_value(k, -1e300, 1e300, "");
  return g;
}

// The same pile for LIGGGHTS (tools/repose_liggghts.sh fills studies/repose/repose.liggghts.in):
// DIR/walls.stl (base and funnel), DIR/gate.stl, DIR/beads.data (read_data: id type diameter
// density x y z) and DIR/params.txt (NAME=value, 17 digits, for the template's @NAME@ fields).
inline int export_liggghts(const ReposeSetup& g, const std::string& dir) {
  const Scene& s = g.scene;
  std::filesystem::create_directories(dir);
  const auto stl = [&](const std::string& file, bool gate) {
    std::ofstream o(dir + "/" + file);
    o.precision(17);
    o << "solid " << (gate ? "gate" : "walls") << "\n";
    for (const auto& w : s.walls) {
      if ((w.name == "gate") != gate) continue;
      const auto& v = w.vertices;
      const Vec3<double> c = cross(v[1] - v[0], v[2] - v[0]), nrm = c * (1 / norm(c));
      for (std::size_t k = 1; k + 1 < v.size(); ++k) {  // fan triangles, the polygon's winding
        o << " facet normal " << nrm.x << ' ' << nrm.y << ' ' << nrm.z << "\n  outer loop\n";
        for (const auto* p : {&v[0], &v[k], &v[k + 1]}) o << "   vertex " << p->x << ' ' << p->y << ' ' << p->z << "\n";
        o << "  endloop\n endfacet\n";
      }
    }
    o << "endsolid\n";
  };
  stl("walls.stl", false);
  stl("gate.stl", true);
  const ParticleState<double> beads = build_particles<double>(s, nullptr);
  const double rho = s.materials[0].density;
  std::ofstream data(dir + "/beads.data");
  data.precision(17);
  data << "LIGGGHTS data file: the repose study's fill (study_repose --export-liggghts)\n\n" << beads.size()
       << " atoms\n2 atom types\n" << s.domain_lo.x << ' ' << s.domain_hi.x << " xlo xhi\n" << s.domain_lo.y << ' '
       << s.domain_hi.y << " ylo yhi\n" << s.domain_lo.z << ' ' << s.domain_hi.z << " zlo zhi\n\nAtoms\n\n";
  for (std::size_t i = 0; i < beads.size(); ++i)
    data << i + 1 << " 1 " << 2 * beads.radius[i] << ' ' << rho << ' ' << beads.position[i].x << ' ' << beads.position[i].y
         << ' ' << beads.position[i].z << '\n';
  const double m = beads.mass.empty() ? 0 : beads.mass[0];
  std::map<std::string, double> p = {
      {"DT", s.dt}, {"YOUNG", s.materials[0].youngs_modulus}, {"POISSON", s.materials[0].poisson_ratio},
      {"REST", s.pairs[0].restitution}, {"MU_PP", s.pairs[0].friction}, {"MU_PW", s.pairs[1].friction},
      {"MUR_PP", s.pairs[0].rolling_friction}, {"MUR_PW", s.pairs[1].rolling_friction},
      {"ETA_PP", s.pairs[0].rolling_damping}, {"ETA_PW", s.pairs[1].rolling_damping}, {"MASS", m},
      {"SKIN", s.skin * g.d / 2}, {"G", -s.gravity.y}, {"OUTLET_Y", g.outlet_y},
      {"GATE_STEPS", std::round(s.study_value("gate_open_time", 0, 1e9, "s") / s.dt)},
      {"CHECK_STEPS", std::round(s.study_value("check_interval", 0, 1e9, "s") / s.dt)},
      {"END_CHECKS", std::ceil(s.end_time / s.study_value("check_interval", 0, 1e9, "s"))},
      {"REST_SPEED", s.study_value("rest_speed", 0, 1e9, "m/s")}, {"XLO", s.domain_lo.x}, {"XHI", s.domain_hi.x},
      {"YLO", s.domain_lo.y}, {"YHI", s.domain_hi.y}, {"ZLO", s.domain_lo.z}, {"ZHI", s.domain_hi.z}};
  std::ofstream params(dir + "/params.txt");
  params.precision(17);
  for (const auto& [k, v] : p) params << k << '=' << v << '\n';
  std::printf("wrote %s/{walls.stl, gate.stl, beads.data (%zu beads), params.txt}\n", dir.c_str(), beads.size());
  return 0;
}

}  // namespace blaze
