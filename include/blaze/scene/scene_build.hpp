// From a validated Scene to what a Simulation takes: particles (lattice blocks, explicit lists,
// random non-overlapping fills), the world, the contact-law table and, for polyhedra, the shape
// table. Templated on precision and law; host code, usable in CUDA translation units (no TOML).
//
// Random fill: random sequential addition, uniform positions in the box, rejected while the
// bounding sphere overlaps any particle already placed (a hash grid of cell 2 r_max finds them);
// at most 1000 tries per particle, then a SceneError. After all placements, any overlap between
// particles of different placements is an error naming both.
#pragma once
#include <chrono>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <random>
#include "blaze/shapes/polyhedron_shape.hpp"
#include "blaze/laws/standard_laws.hpp"
#include "blaze/scene/critical_step.hpp"
#include "blaze/scene/run_size.hpp"
#include "blaze/scene/sphere_grid.hpp"
#include "blaze/scene/world_overlap.hpp"
#include "blaze/shapes/shape_io.hpp"
#include "blaze/world/world.hpp"

namespace blaze {

// Contact laws for every material pair of the scene: each Law is built from its parts, the
// normal law (linear or Hertz), the tangential law (history-free, or the spring) and, for the
// rolling laws, the rolling resistance. The scene parser has paired them (tangential with law,
// rolling with a spring).
template <class Law>
PairTable<Law> build_laws(const Scene& s) {
  using Real = typename Law::real_type;
  using Normal = decltype(Law::normal);
  using Tangential = decltype(Law::tangential);
  constexpr bool linear = std::is_same_v<Normal, LinearSpringDashpot<Real>>;
  PairTable<Law> table;
  for (const auto& p : s.pairs) {
    const MaterialSpec &ma = s.materials[static_cast<std::size_t>(p.a)], &mb = s.materials[static_cast<std::size_t>(p.b)];
    const double kn = linear ? linear_stiffness(s, p) : 0;
    Normal normal;
    if constexpr (linear) {
      normal = LinearSpringDashpot<Real>::from_restitution(kn, p.restitution);
      normal.no_tension = p.no_tension;
    } else {
      normal = Hertz<Real>::from_restitution(pair_physics(s, p.a, p.b, false).e_star, p.restitution, p.no_tension);
    }
    Tangential tangential;
    if constexpr (std::is_same_v<Tangential, HistoryFreeFriction<Real>>) {
      tangential = HistoryFreeFriction<Real>::make(p.friction, p.tangential_damping, p.tangential_rate);
    } else if constexpr (linear) {
      const double kt = p.tangential_stiffness > 0 ? p.tangential_stiffness : 2.0 / 7.0 * kn;
      tangential = TangentialSpring<Real>::linear(p.friction, kt, static_cast<double>(normal.beta));
    } else {
      const double g_star = TangentialSpring<Real>::effective_shear_modulus(ma.youngs_modulus, ma.poisson_ratio,
                                                                             mb.youngs_modulus, mb.poisson_ratio);
      tangential = TangentialSpring<Real>::mindlin(p.friction, g_star, p.restitution);
    }
    Law law{normal, tangential};
    if constexpr (Law::kRolling) {
      const RollingModel model = s.rolling == RollingKind::cdt    ? RollingModel::cdt
                                 : s.rolling == RollingKind::epsd ? RollingModel::epsd
                                                                  : RollingModel::none;
      law.rolling = RollingResistance<Real>::make(model, p.rolling_friction, p.rolling_damping);
    }
    table.set(p.a, p.b, law);
  }
  return table;
}

// The scene with the wall named `name` removed at t (s; blaze/world/motion.hpp): a gate opened as
// a timed event of one run, so the contacts keep their history across it (the hopper and repose
// studies). The scene must have exactly one wall of that name.
inline Scene with_wall_removed_at(Scene s, const std::string& name, double t) {
  int found = 0;
  for (auto& w : s.walls)
    if (w.name == name) w.motion.remove = t, ++found;
  if (found != 1)
    throw SceneError(s.path + ": needs exactly one [[wall]] with name = \"" + name + "\" (found " + std::to_string(found) + ")");
  return s;
}

template <class Real>
World<Real> build_world(const Scene& s) {
  World<Real> w;
  for (const auto& p : s.walls)
    w.polygons.push_back(PlanarPolygon<Real>::make(p.vertices, static_cast<std::uint8_t>(p.material), p.rim_edges));
  for (const auto& c : s.cylinders)
    w.cylinders.push_back(Cylinder<Real>::make(c.origin, c.axis, c.radius, c.length, static_cast<std::uint8_t>(c.material)));
  for (const auto& m : s.meshes) w.meshes.push_back({m.name, m.mesh, static_cast<std::uint8_t>(m.material)});
  // motions and classes in object order (polygons, cylinders, meshes)
  std::vector<Motion> motions;
  std::vector<ContactClass> classes;
  for (const auto& p : s.walls) motions.push_back(p.motion), classes.push_back(p.contact_class);
  for (const auto& c : s.cylinders) motions.push_back(c.motion), classes.push_back(c.contact_class);
  for (const auto& m : s.meshes) motions.push_back(m.motion), classes.push_back(m.contact_class);
  // motions only where an object moves or leaves (a static world carries none: no cost), classes
  // only where some object is not a plain wall
  if (std::any_of(motions.begin(), motions.end(), [](const Motion& m) { return !m.is_static(); })) w.motions = motions;
  if (std::any_of(classes.begin(), classes.end(), [](ContactClass c) { return c != ContactClass::wall; })) w.classes = classes;
  return w;
}

// Body-frame shapes, one per particle type in the scene's order (a sphere type: no vertices).
inline std::vector<ConvexShape> build_shapes(const Scene& s) {
  std::vector<ConvexShape> shapes;
  for (const auto& t : s.types) shapes.push_back(t.is_sphere() || t.derived ? ConvexShape{} : load_scaled_shape(t.shape, t.bounding_radius));
  return shapes;
}

// Shape table of a scene with polyhedra: one entry per particle type, in the scene's order (the
// types derived from feeds' size distributions, last, have none: no particle is of them).
template <class Real>
PolyhedronTable<Real> build_shape_table(const Scene& s, const std::vector<ConvexShape>& shapes) {
  PolyhedronTable<Real> table;
  for (std::size_t k = 0; k < s.types.size(); ++k) {
    const ParticleTypeSpec& t = s.types[k];
    if (t.derived) continue;
    const double rho = s.materials[static_cast<std::size_t>(t.material)].density;
    if (t.is_sphere()) table.add_sphere(t.radius, rho);
    else table.add(shapes[k], rho);
  }
  return table;
}

namespace scene_detail {

// Set-up of large scenes reports its progress on stderr (a 1e9-particle fill takes minutes): every
// few seconds, from 1e6 particles on.
class SetupProgress {
 public:
  explicit SetupProgress(double total) : total_(total), on_(total >= 1e6), last_(clock::now()) {}
  void tick(double placed) {
    if (!on_ || (static_cast<long>(placed) & 0xffff) != 0) return;
    const auto now = clock::now();
    if (std::chrono::duration<double>(now - last_).count() < 5) return;
    last_ = now;
    std::fprintf(stderr, "placing particles: %.3g of %.3g (%.0f%%)\n", placed, total_, 100 * placed / total_);
  }

 private:
  using clock = std::chrono::steady_clock;
  double total_;
  bool on_;
  clock::time_point last_;
};

template <class Rng>
Quat<double> random_orientation(Rng& rng) {
  std::normal_distribution<double> g;
  return normalized(Quat<double>{g(rng), g(rng), g(rng), g(rng)});
}

}  // namespace scene_detail

// All particles of the scene, in placement order (lattices, lists, fills); ids follow that order.
// `shapes` is the scene's shape table for polyhedral scenes, null for spheres.
template <class Real>
ParticleState<Real> build_particles(const Scene& s, const PolyhedronTable<Real>* shapes) {
  double r_max = 0;
  for (const auto& t : s.types) r_max = std::max(r_max, t.size());
  const double total = scene_particles(s);
  // cells 4 r_max wide: a query reaches r + r_max <= half a cell, 8 cells at most
  SphereGrid placed(s.domain_lo, s.domain_hi, r_max > 0 ? 4 * r_max : 1.0, r_max, total);
  std::vector<std::string> origin;  // which placement each particle came from, for messages
  std::mt19937_64 rng(s.seed);
  ParticleState<Real> out;
  const double touch_slack = 1e-9 * r_max;  // lattices at exactly 2 r spacing touch, they do not overlap
  WorldOverlapCheck world(s, touch_slack);
  out.reserve(static_cast<std::size_t>(total));
  scene_detail::SetupProgress progress(total);
  std::vector<Vec3<double>> vertices;

  auto add = [&](int type, const Vec3<double>& x, const Vec3<double>& v, bool orient, const std::string& where) {
    const ParticleTypeSpec& t = s.types[static_cast<std::size_t>(type)];
    const long j = placed.overlapping(x, t.size(), touch_slack);
    if (j >= 0)
      throw SceneError(s.path + ": " + where + " overlaps particle " + std::to_string(j) + " of " +
                       origin[static_cast<std::size_t>(j)] + " at the start; move or shrink one of the placements");
    placed.add(x, t.size());
    origin.push_back(where);
    progress.tick(static_cast<double>(origin.size()));
    const auto mat = static_cast<std::uint8_t>(t.material);
    const double rho = s.materials[static_cast<std::size_t>(t.material)].density;
    vertices.clear();
    if (shapes == nullptr) {
      world.check(x, t.size(), vertices, where);
      out.add_sphere(vec_cast<Real>(x), static_cast<Real>(t.radius), static_cast<Real>(rho), mat, vec_cast<Real>(v));
    } else {
      const Quat<double> q = orient && !t.is_sphere() ? scene_detail::random_orientation(rng) : Quat<double>::identity();
      const PolyhedronData<Real>& data = shapes->type[type];
      for (int k = 0; k < data.vertex_count; ++k) vertices.push_back(x + rotate(q, vec_cast<double>(data.vertex[k])));
      world.check(x, t.size(), vertices, where);
      add_polyhedron(out, *shapes, type, vec_cast<Real>(x), Quat<Real>{Real(q.w), Real(q.x), Real(q.y), Real(q.z)}, mat,
                     vec_cast<Real>(v));
    }
  };

  std::uniform_real_distribution<double> u(-1, 1);
  for (std::size_t k = 0; k < s.lattices.size(); ++k) {
    const LatticeSpec& l = s.lattices[k];
    const double gap = 0.5 * (l.spacing - 2 * s.types[static_cast<std::size_t>(l.type)].size());
    for (long iz = 0; iz < l.count[2]; ++iz)
      for (long iy = 0; iy < l.count[1]; ++iy)
        for (long ix = 0; ix < l.count[0]; ++ix) {
          Vec3<double> x = l.origin + Vec3<double>{double(ix), double(iy), double(iz)} * l.spacing;
          if (l.jitter > 0) x += Vec3<double>{u(rng), u(rng), u(rng)} * (l.jitter * gap / std::sqrt(3.0));
          add(l.type, x, l.velocity, l.random_orientation, "[[lattice]] #" + std::to_string(k + 1));
        }
  }
  for (std::size_t k = 0; k < s.lists.size(); ++k) {
    const ListSpec& l = s.lists[k];
    for (std::size_t i = 0; i < l.position.size(); ++i)
      add(l.type, l.position[i], l.velocity.empty() ? Vec3<double>{0, 0, 0} : l.velocity[i], false,
          "[[particles]] #" + std::to_string(k + 1) + " point " + std::to_string(i));
  }
  // Fills: random sequential placement in the box, where a particle overlaps no earlier particle
  // and no wall, lies in front of every wall it is over and inside every drum along its length
  // (WorldOverlapCheck::blocked: a box wider than a mill is clipped to the space between its
  // shell, lifters and end plates). Polyhedra are tested with their bounding sphere against the
  // world, so they keep clear of the walls by their bounding radius.
  for (std::size_t k = 0; k < s.fills.size(); ++k) {
    const FillSpec& f = s.fills[k];
    const double r = s.types[static_cast<std::size_t>(f.type)].size();
    const std::string name = "[[fill]] #" + std::to_string(k + 1);
    std::uniform_real_distribution<double> ux(f.lo.x + r, f.hi.x - r), uy(f.lo.y + r, f.hi.y - r), uz(f.lo.z + r, f.hi.z - r);
    const std::vector<Vec3<double>> no_vertices;
    for (long i = 0; i < f.count; ++i) {
      int tries = 0;
      Vec3<double> x;
      do {
        if (++tries > 1000)
          throw SceneError(s.path + ": " + name + ": no free place for particle " + std::to_string(i) + " of " +
                           std::to_string(f.count) + " after 1000 random tries (the box, less the walls and the particles "
                           "placed before, is full); enlarge the box or lower count");
        x = {ux(rng), uy(rng), uz(rng)};
      } while (placed.overlapping(x, r, 0) >= 0 || world.blocked(x, r, no_vertices));  // (the cheaper refusal first)
      add(f.type, x, f.velocity, true, name);
    }
  }
  for (std::size_t k = 0; k < s.feeds.size(); ++k) {
    const FeedSpec& f = s.feeds[k];
    world.look_from_region(f.region, f.size.largest(), f.velocity, "the feed at " + s.place("feed[" + std::to_string(k) + "].velocity"));
  }
  world.finish();
  return out;
}

// The placements checked without a run (blaze run --check): built in double on the host, which
// checks every particle-particle and particle-world overlap, and discarded.
inline std::size_t check_placements(const Scene& s) {
  if (s.all_spheres()) return build_particles<double>(s, nullptr).size();
  const std::vector<ConvexShape> shapes = build_shapes(s);
  const PolyhedronTable<double> table = build_shape_table<double>(s, shapes);
  return build_particles<double>(s, &table).size();
}

}  // namespace blaze
