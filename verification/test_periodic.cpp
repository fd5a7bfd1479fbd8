// Periodic boundaries (issue 20; grid/periodic_images.hpp, kernels/broad_phase_kernels.hpp):
// - a gas of elastic frictionless spheres periodic along x, x and z, and all three axes conserves
//   its total momentum to rounding and its energy as well as the same gas in a closed box (where
//   walls stand in for the periodic faces), for both pair evaluations; particles cross the faces;
// - a pair of spheres, and a pair of cubes, in contact across the boundary (with the tangential
//   spring, which a lost contact would reset) move as the same pair in an open box, with the list
//   rebuilt (and the particles wrapped) at every step or kept for many, pairs from both sides or once;
// - unwrapped positions are continuous: a free particle crossing the box several times is at
//   x0 + v t, also through a checkpoint restart (the image counts are in the snapshot);
// - bad `periodic` keys and periods too short for the interaction range are refused by name, and
//   so are [mill] slices that do not fit a periodic domain (end plates, too short, across the axis).
#include <boost/test/unit_test.hpp>
#include <cmath>
#include <array>
#include <filesystem>
#include <random>
#include "blaze/io/checkpoint.hpp"
#include "blaze/scene/scene_file.hpp"
#include "blaze/shapes/polyhedron_shape.hpp"
#include "blaze/shapes/shape_io.hpp"
#include "verification/scenes.hpp"
#include "verification/tolerances.hpp"

using namespace blaze;
using namespace blaze::test;

namespace {

constexpr double kR = 1e-3, kRho = 2500, kK = 1e3;

double sphere_mass() { return kRho * 4.0 / 3.0 * kPi * kR * kR * kR; }
double contact_time() { return kPi * std::sqrt(0.5 * sphere_mass() / kK); }

// Spheres at random, not overlapping, with random velocities, in [0, side)^3.
ParticleState<double> gas(int n, double side, unsigned seed) {
  std::mt19937_64 rng(seed);
  std::uniform_real_distribution<double> u(0, 1);
  ParticleState<double> s;
  while (static_cast<int>(s.size()) < n) {
    const Vec3<double> x{(0.05 + 0.9 * u(rng)) * side, (0.05 + 0.9 * u(rng)) * side, (0.05 + 0.9 * u(rng)) * side};
    bool clear = true;
    for (const auto& y : s.position) clear = clear && norm(x - y) > 2.2 * kR;
    if (clear) s.add_sphere(x, kR * (0.8 + 0.2 * u(rng)), kRho, 0, {2 * u(rng) - 1, 2 * u(rng) - 1, 2 * u(rng) - 1});  // m/s
  }
  return s;
}

// The six faces of [0, side)^3 as walls, normals inwards (right-hand rule), except those of the
// periodic axes; along a periodic axis the walls reach 2 mm past the box (as a scene's should: a
// wall's rim at the periodic face would push particles crossing there).
World<double> box_walls(double side, unsigned periodic) {
  World<double> w;
  const double e = 2e-3;
  const double lo[3] = {periodic & 1u ? -e : 0, periodic & 2u ? -e : 0, periodic & 4u ? -e : 0};
  const double hi[3] = {periodic & 1u ? side + e : side, periodic & 2u ? side + e : side, periodic & 4u ? side + e : side};
  // the wall at coordinate c across axis d, its corners over the two other axes
  auto face = [&](int d, double c, bool inward_positive) {
    const int u = (d + 1) % 3, v = (d + 2) % 3;
    auto at = [&](double pu, double pv) {
      double x[3];
      x[d] = c, x[u] = pu, x[v] = pv;
      return Vec3<double>{x[0], x[1], x[2]};
    };
    std::vector<Vec3<double>> q = {at(lo[u], lo[v]), at(hi[u], lo[v]), at(hi[u], hi[v]), at(lo[u], hi[v])};  // normal +d
    if (!inward_positive) std::swap(q[1], q[3]);
    w.polygons.push_back(PlanarPolygon<double>::make(q, 0));
  };
  for (int d = 0; d < 3; ++d)
    if (!((periodic >> d) & 1u)) face(d, 0, true), face(d, side, false);
  return w;
}

Vec3<double> momentum(const ParticleState<double>& s) {
  Vec3<double> p{0, 0, 0};
  for (std::size_t i = 0; i < s.size(); ++i) p = p + s.velocity[i] * s.mass[i];
  return p;
}
double kinetic(const ParticleState<double>& s) {
  double e = 0;
  for (std::size_t i = 0; i < s.size(); ++i) e += 0.5 * s.mass[i] * norm2(s.velocity[i]);
  return e;
}

}  // namespace

BOOST_AUTO_TEST_SUITE(periodic)

BOOST_AUTO_TEST_CASE(a_periodic_gas_conserves_momentum_and_energy) {
  const double side = 0.03, dt = contact_time() / 50;
  const auto law = one_law(LinearLaw<double>{LinearSpringDashpot<double>::from_restitution(kK, 1.0), HistoryFreeFriction<double>{0, 0}}, 1);
  for (const unsigned axes : {1u, 5u, 7u})
    for (const PairEvaluation pairs : {PairEvaluation::both_sides, PairEvaluation::once}) {
      const ParticleState<double> start = gas(300, side, 7 + axes);
      double worst[2] = {0, 0};  // closed box, periodic
      Vec3<double> drift{0, 0, 0};
      long crossings = 0;
      for (const unsigned periodic : {0u, axes}) {
        SimulationParams<double> prm{dt, {0, 0, 0}, {0, 0, 0}, {side, side, side}, 0.3 * kR};
        prm.pairs = pairs, prm.periodic = periodic;
        SphereSim<LinearLaw<double>> sim(prm, law, box_walls(side, periodic), start);
        // kinetic plus the elastic energy held in the contacts (walls included)
        const double e0 = kinetic(sim.state()) + sim.contact_energy().total();
        const Vec3<double> p0 = momentum(sim.state());
        for (int k = 0; k < 20; ++k) {
          sim.run(100);
          const auto s = sim.state();
          worst[periodic ? 1 : 0] = std::max(worst[periodic ? 1 : 0], std::fabs(kinetic(s) + sim.contact_energy().total() - e0) / e0);
          if (periodic) drift = momentum(s) - p0;  // along the periodic axes: the walls' normals lie across them
        }
        BOOST_TEST(sim.size() == 300);  // nothing lost at the faces
        if (periodic) {
          const auto s = sim.state();
          const auto u = sim.unwrapped_positions(s);
          for (std::size_t i = 0; i < s.size(); ++i) crossings += norm(u[i] - s.position[i]) > 0.5 * side;
        }
      }
      double scale = 0;
      for (std::size_t i = 0; i < start.size(); ++i) scale += start.mass[i] * norm(start.velocity[i]);
      BOOST_TEST_CONTEXT("periodic axes " << axes << ", pairs " << (pairs == PairEvaluation::once ? "once" : "both sides")) {
        BOOST_TEST(crossings > 10);
        const double along = std::sqrt((axes & 1u ? drift.x * drift.x : 0) + (axes & 2u ? drift.y * drift.y : 0) + (axes & 4u ? drift.z * drift.z : 0));
        BOOST_TEST(along / scale < tol::periodic_momentum);
        BOOST_TEST(worst[1] < tol::energy_conservation);
        BOOST_TEST(worst[1] < 3 * worst[0] + 1e-9);  // as well as the closed box
      }
    }
}

namespace {

// Runs `pair` (two bodies, the second beyond x = L in the open box) in a box periodic along x of
// period L, and in an open box; returns the largest difference of the unwrapped positions (over
// the radius) and of the velocities and spins (over their scales) over the run.
template <class Shape, class Law>
std::array<double, 3> periodic_against_open(const Shape& shape, const Law& law, const ParticleState<double>& pair, double skin,
                                            PairEvaluation pairs, int steps, double dt) {
  const double l = 20 * kR;
  ParticleState<double> wrapped = pair;
  for (auto& x : wrapped.position)
    if (x.x >= l) x.x -= l;
  SimulationParams<double> open{dt, {0, 0, 0}, {-l, -5 * kR, -5 * kR}, {3 * l, 5 * kR, 5 * kR}, skin}, per = open;
  per.domain_lo = {0, -5 * kR, -5 * kR}, per.domain_hi = {l, 5 * kR, 5 * kR}, per.periodic = 1;
  open.pairs = per.pairs = pairs;
  Simulation<DefaultSpace, Shape, Law, VelocityVerlet> a(open, one_law(law, 1), World<double>{}, pair, shape);
  Simulation<DefaultSpace, Shape, Law, VelocityVerlet> b(per, one_law(law, 1), World<double>{}, wrapped, shape);
  std::array<double, 3> worst{0, 0, 0};
  double v_scale = 0, w_scale = 1e-300;
  // displacements from the start: the periodic run's second body began wrapped (image 0)
  const auto a0 = a.state(), b0 = b.state();
  const auto ub0 = b.unwrapped_positions(b0);
  for (int k = 0; k < steps; ++k) {
    a.step(), b.step();
    auto sa = a.state(), sb = b.state();
    const auto ub = b.unwrapped_positions(sb);
    for (std::size_t i = 0; i < sa.size(); ++i)
      for (std::size_t j = 0; j < sb.size(); ++j) {
        if (sa.id[i] != sb.id[j]) continue;
        Vec3<double> from_a, from_b;
        for (std::size_t q = 0; q < a0.size(); ++q) {
          if (a0.id[q] == sa.id[i]) from_a = sa.position[i] - a0.position[q];
          if (b0.id[q] == sb.id[j]) from_b = ub[j] - ub0[q];
        }
        v_scale = std::max(v_scale, norm(sa.velocity[i])), w_scale = std::max(w_scale, norm(sa.angular_velocity[i]));
        worst[0] = std::max(worst[0], norm(from_a - from_b) / kR);
        worst[1] = std::max(worst[1], norm(sa.velocity[i] - sb.velocity[j]));
        worst[2] = std::max(worst[2], norm(sa.angular_velocity[i] - sb.angular_velocity[j]));
      }
  }
  worst[1] /= v_scale, worst[2] /= w_scale;
  return worst;
}

}  // namespace

BOOST_AUTO_TEST_CASE(a_contact_across_the_boundary_is_kept) {
  const auto normal = LinearSpringDashpot<double>::from_restitution(kK, 0.5);
  const LinearSpringLaw<double> law{normal, TangentialSpring<double>::linear(0.5, 2.0 / 7.0 * kK, normal.beta)};
  const double dt = contact_time() / 50, l = 20 * kR;
  // spheres: A just inside the face x = L, B beyond it, overlapping, sliding past each other
  ParticleState<double> spheres;
  spheres.add_sphere({l - 0.02 * kR, 0, 0}, kR, kRho, 0, {0.5, 0.05, 0});
  spheres.add_sphere({l - 0.02 * kR + 1.95 * kR, 0.2 * kR, 0.1 * kR}, kR, kRho, 0, {0.45, -0.05, 0.02});
  // cubes (bounding radius R): face to face across the face, B a little turned
  PolyhedronShape<double> cubes;
  const ConvexShape cube = load_scaled_shape("data/shapes/cube.shape", kR);
  cubes.table.add(cube, kRho);
  const double half = kR / std::sqrt(3.0);
  ParticleState<double> boxes;
  add_polyhedron(boxes, cubes.table, 0, Vec3<double>{l - 0.02 * kR, 0, 0}, Quat<double>::identity(), 0, Vec3<double>{0.5, 0.05, 0});
  add_polyhedron(boxes, cubes.table, 0, Vec3<double>{l - 0.02 * kR + 1.98 * half, 0.3 * half, 0.1 * half},
                 normalized(Quat<double>{1, 0.02, 0.03, 0.01}), 0, Vec3<double>{0.45, -0.05, 0.02});
  for (const double skin : {0.0, 0.5 * kR})
    for (const PairEvaluation pairs : {PairEvaluation::both_sides, PairEvaluation::once}) {
      const auto s = periodic_against_open(SphereShape{}, law, spheres, skin, pairs, 300, dt);
      const auto c = periodic_against_open(cubes, law, boxes, skin, pairs, 300, dt);
      BOOST_TEST_CONTEXT("skin " << skin << ", pairs " << (pairs == PairEvaluation::once ? "once" : "both sides")) {
        for (int q = 0; q < 3; ++q) {
          BOOST_TEST(s[q] < tol::periodic_pair_over_radius);
          BOOST_TEST(c[q] < tol::periodic_pair_over_radius);
        }
      }
    }
}

BOOST_AUTO_TEST_CASE(unwrapped_positions_are_continuous_through_a_restart) {
  const double l = 20 * kR, dt = 1e-5;
  for (const Vec3<double> v : {Vec3<double>{3.0, 0, 0}, Vec3<double>{-2.0, 0, 1.5}, Vec3<double>{0.7, -2.5, -1.1}}) {
    ParticleState<double> one;
    const Vec3<double> x0{0.3 * l, 0.4 * l, 0.5 * l};
    one.add_sphere(x0, kR, kRho, 0, v);
    SimulationParams<double> prm{dt, {0, 0, 0}, {0, 0, 0}, {l, l, l}, 0.2 * kR};
    prm.periodic = 7;
    const auto law = one_law(LinearLaw<double>{LinearSpringDashpot<double>::from_restitution(kK, 0.5), HistoryFreeFriction<double>{0, 0}}, 1);
    SphereSim<LinearLaw<double>> sim(prm, law, World<double>{}, one);
    sim.run(1000);  // 0.01 s: up to 1.5 periods
    const std::string path = (std::filesystem::temp_directory_path() / "blaze_periodic.blz").string();
    write_checkpoint(path, sim.snapshot(), "periodic");
    SphereSim<LinearLaw<double>> again(prm, law, World<double>{}, read_checkpoint<double>(path).snapshot);
    std::filesystem::remove(path);
    again.run(2000);
    const auto s = again.state();
    const Vec3<double> u = again.unwrapped_positions(s)[0], expected = x0 + v * (3000 * dt);
    BOOST_TEST_CONTEXT("v = " << v.x << ", " << v.y << ", " << v.z) {
      BOOST_TEST(norm(u - expected) < 1e-12);
      for (const double c : {s.position[0].x, s.position[0].y, s.position[0].z}) BOOST_TEST((c >= 0 && c < l + 0.5 * 0.2 * kR));
      BOOST_TEST(norm(u - s.position[0]) > 0.5 * l);  // it crossed
    }
  }
}

// A ball falling through the periodic faces along gravity (stop 49: its potential energy was that
// of the wrapped height, m g L handed back at every crossing, and the energy guard stopped such
// runs as unstable): the sampled total energy holds, for gravity along an axis and oblique.
BOOST_AUTO_TEST_CASE(a_fall_through_periodic_faces_keeps_its_energy) {
  const double l = 20 * kR, dt = 1e-5;
  for (const Vec3<double> g : {Vec3<double>{0, -9.81, 0}, Vec3<double>{4.9, -8.5, 0}, Vec3<double>{-3, 2, -9}})
    for (const unsigned periodic : {2u, 7u}) {
      ParticleState<double> one;
      one.add_sphere({0.5 * l, 0.5 * l, 0.5 * l}, kR, kRho, 0, {0, 0, 0});
      SimulationParams<double> prm{dt, g, {0, 0, 0}, {l, l, l}, 0.2 * kR};
      prm.periodic = periodic;
      if (periodic == 2u) prm.gravity = {0, -norm(g), 0};  // along the one periodic axis only
      const auto law = one_law(LinearLaw<double>{LinearSpringDashpot<double>::from_restitution(kK, 0.5), HistoryFreeFriction<double>{0, 0}}, 1);
      SphereSim<LinearLaw<double>> sim(prm, law, World<double>{}, one);
      const double e0 = sim.sample(1).energies.total(), scale = sphere_mass() * norm(prm.gravity) * l;
      double worst = 0;
      for (int k = 0; k < 20; ++k) {
        sim.run(500);
        worst = std::max(worst, std::fabs(sim.sample(1).energies.total() - e0) / scale);
      }
      const Vec3<double> u = sim.unwrapped_positions(sim.state())[0];
      BOOST_TEST_CONTEXT("g = " << prm.gravity.x << ", " << prm.gravity.y << ", " << prm.gravity.z << ", periodic " << periodic) {
        BOOST_TEST(norm(u - Vec3<double>{0.5 * l, 0.5 * l, 0.5 * l}) > 2 * l);  // 0.049 m in 0.1 s: through ~2 periods
        BOOST_TEST(worst < tol::periodic_fall_energy);
      }
    }
}

BOOST_AUTO_TEST_CASE(bad_periodic_keys_are_refused) {
  const auto scene = [](const std::string& periodic, const std::string& hi) {
    return std::string(R"(
[simulation]
law = "linear"
dt = 1e-5
end_time = 0.01
gravity = [0, 0, 0]
domain_lo = [0, 0, 0]
domain_hi = )") + hi + "\n" + periodic + R"(
[[material]]
name = "glass"
density = 2500
[[pair]]
materials = ["glass", "glass"]
stiffness = 1e3
restitution = 0.5
friction = 0.3
[[particle_type]]
name = "bead"
material = "glass"
radius = 1e-3
[[lattice]]
type = "bead"
origin = [0.0015, 0.0015, 0.0015]
count = [2, 1, 2]
spacing = 2.5e-3
)";
  };
  // the scene text is refused, with every one of `parts` in the message
  const auto refused_text = [](const std::string& text, const std::string& file, std::initializer_list<const char*> parts) {
    std::string what = "(accepted)";
    try {
      parse_scene(text, file);
    } catch (const SceneError& e) {
      what = e.what();
    }
    for (const char* p : parts) BOOST_TEST(what.find(p) != std::string::npos, "'" << p << "' in: " << what);
  };
  const auto refused = [&](const std::string& periodic, const std::string& hi, std::initializer_list<const char*> parts) {
    refused_text(scene(periodic, hi), "periodic.toml", parts);
  };
  BOOST_TEST(parse_scene(scene("periodic = [\"x\", \"z\"]", "[0.02, 0.02, 0.02]"), "ok.toml").periodic == 5u);
  BOOST_TEST(parse_scene(scene("", "[0.02, 0.02, 0.02]"), "ok.toml").periodic == 0u);
  refused("periodic = [\"x\", \"x\"]", "[0.02, 0.02, 0.02]", {"periodic.toml", "'periodic'", "distinct axes"});
  refused("periodic = [\"w\"]", "[0.02, 0.02, 0.02]", {"'periodic'", "\"x\", \"y\", \"z\""});
  refused("periodic = \"x\"", "[0.02, 0.02, 0.02]", {"'periodic'", "an array"});
  refused("periodic = [\"y\"]", "[0.02, 0.005, 0.02]", {"periodic.toml:9", "key 'periodic'", "along y", "less than 3 cells"});
  // a [mill] slice: the drum along the periodic axis, without end plates, reaching past the faces
  const auto mill = [](const std::string& keys) {
    return "[mill]\nmaterial = \"glass\"\ncentre = [0.01, 0.01, 0.01]\ndiameter = 0.02\nrpm = 10\n" + keys + "\n";  // the domain's width
  };
  const auto with_mill = [&](const std::string& periodic, const std::string& keys) {
    return scene(periodic, "[0.02, 0.02, 0.02]") + mill(keys);
  };
  const auto refused_mill = [&](const std::string& periodic, const std::string& keys, std::initializer_list<const char*> parts) {
    refused_text(with_mill(periodic, keys), "slice.toml", parts);
  };
  const Scene slice = parse_scene(with_mill("periodic = [\"z\"]", "axis = [0, 0, 1]\nlength = 0.03\nend_plates = false"), "slice.toml");
  BOOST_TEST(slice.periodic == 4u);
  for (const auto& w : slice.walls) BOOST_TEST(w.name.find("end plate") == std::string::npos, w.name);
  refused_mill("periodic = [\"z\"]", "axis = [0, 0, 1]\nlength = 0.03", {"slice.toml", "'end_plates'", "false", "periodic along the drum's axis"});
  refused_mill("periodic = [\"z\"]", "axis = [0, 0, 1]\nlength = 0.021\nend_plates = false", {"'length'", "a particle diameter past"});
  refused_mill("periodic = [\"x\"]", "axis = [0, 0, 1]\nlength = 0.03\nend_plates = false", {"'axis'", "not across one"});
  refused_mill("", "axis = [0, 0, 1]\nlength = 0.03\nend_plates = false", {"'end_plates'", "spills its charge"});
  refused_mill("periodic = [\"z\"]", "axis = [0, 1, 1]\nlength = 0.03\nend_plates = false", {"'axis'", "\"z\""});
}

BOOST_AUTO_TEST_SUITE_END()
