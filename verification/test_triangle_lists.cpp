// Triangle lists (issue 20; kernels/world_candidates.hpp, blaze/world/triangle_distance.hpp): at
// each neighbour-list rebuild every particle keeps the mesh triangles within its reach, and its
// mesh contacts test those instead of the triangles of its bins' cell.
// - The distance from a point to a triangle agrees with an independent form (the plane if the
//   point projects inside, else the nearest of the three edges, in long double) over regular,
//   sliver and large triangles, float and double; the reach test never drops a triangle within
//   reach and drops those beyond it and its rounding allowance.
// - In a drum whose wavy liner is a mesh turning at 40 rpm, at every sample each ball's list holds
//   every triangle it touches, for skins of 0.05 r to r, float and double, and it lists a few
//   triangles where its cell lists tens.
// - On a static relief (a bumpy mesh of 3 200 triangles), spheres under Hertz-Mindlin and cubes
//   under a linear spring tumbling down it move bitwise the same with the lists (skin 0.3 r, so
//   a list serves many steps) as without them; so do spheres on the relief shaken, with skin 0.
#include <boost/test/unit_test.hpp>
#include <algorithm>
#include <cmath>
#include <random>
#include <sstream>
#include "blaze/shapes/polyhedron_shape.hpp"
#include "blaze/shapes/shape_io.hpp"
#include "blaze/world/triangle_distance.hpp"
#include "verification/mill_scenes.hpp"
#include "verification/report.hpp"
#include "verification/scenes.hpp"
#include "verification/tolerances.hpp"

using namespace blaze;
using namespace blaze::test;

namespace {

const char* const kCase = "Triangle lists (issue 20)";

template <class Law>
using BallSim = Simulation<DefaultSpace, SphereShape, Law, VelocityVerlet, ContactPointVelocity, FullFeatures>;

using V = Vec3<long double>;

// The distance from p to segment ab, and to triangle abc by the plane or the edges.
long double segment_distance(const V& p, const V& a, const V& b) {
  const V e = b - a;
  const long double u = std::clamp(dot(p - a, e) / norm2(e), 0.0L, 1.0L);
  return std::sqrt(norm2(p - (a + e * u)));
}
long double reference_distance(const V& p, const V& a, const V& b, const V& c) {
  const V n = cross(b - a, c - a);
  const bool inside = dot(cross(b - a, p - a), n) >= 0 && dot(cross(c - b, p - b), n) >= 0 && dot(cross(a - c, p - c), n) >= 0;
  const long double edges = std::min({segment_distance(p, a, b), segment_distance(p, b, c), segment_distance(p, c, a)});
  return inside ? std::min(edges, std::fabs(dot(p - a, n)) / std::sqrt(norm2(n))) : edges;
}

template <class Real>
void distance_against_reference(const char* kind) {
  std::mt19937_64 rng(11);
  std::uniform_real_distribution<double> u(-1, 1);
  double worst = 0;
  long kept_far = 0, dropped_near = 0, near = 0, trials = 0;
  for (int shape = 0; shape < 3; ++shape)
    for (int k = 0; k < 20000; ++k) {
      // regular triangles of size ~1, slivers (one corner 1e-3 off the opposite edge), and large
      // ones (size 1e3) with the point within a few units of them
      const long double size = shape == 2 ? 1e3L : 1.0L;
      const auto w = [&](long double scale) { return scale * static_cast<long double>(u(rng)); };
      V a{w(1), w(1), w(1)}, b{w(1), w(1), w(1)}, c{w(1), w(1), w(1)};
      if (shape == 1) c = a + (b - a) * (0.5L + w(0.5L)) + V{w(1e-3L), w(1e-3L), w(1e-3L)};
      a = a * size, b = b * size, c = c * size;
      const V centre = (a + b + c) * (1.0L / 3);
      const V p = shape == 2 ? a + (b - a) * (0.5L + w(0.5L)) + V{w(3), w(3), w(3)} : centre + V{w(1.5L), w(1.5L), w(1.5L)};
      const Vec3<Real> pr = vec_cast<Real>(p), ar = vec_cast<Real>(a), br = vec_cast<Real>(b), cr = vec_cast<Real>(c);
      // the reference for the rounded inputs
      const long double ref = reference_distance(vec_cast<long double>(pr), vec_cast<long double>(ar), vec_cast<long double>(br),
                                                 vec_cast<long double>(cr));
      const long double got = std::sqrt(static_cast<long double>(distance2_to_triangle(pr, ar, br, cr)));
      worst = std::max(worst, static_cast<double>(std::fabs(got - ref) / size));
      ++trials;
      // within reach (just, and well): never dropped
      for (long double over : {1.0L, 1.001L}) {
        const Real reach = static_cast<Real>(ref * over);
        if (static_cast<long double>(reach) < ref) continue;
        ++near;
        dropped_near += !triangle_within(pr, ar, br, cr, reach);
      }
      // beyond reach by more than the allowance: dropped
      const long double allowance = std::sqrt(16 * static_cast<long double>(epsilon_r<Real>()) * 3 * 16 * size * size);
      if (ref > 2 * allowance) kept_far += triangle_within(pr, ar, br, cr, static_cast<Real>(0.5 * (ref - 1.5 * allowance)));
    }
  BOOST_TEST_MESSAGE("triangle distance, " << kind << ": worst error " << worst << " of the size in " << trials << " trials; " << near
                                           << " within reach, " << dropped_near << " dropped; " << kept_far << " far ones kept");
  check_at_most({kCase, std::string("point-triangle distance vs plane-or-edges, ") + kind + " (of the triangle's size)", "-",
                 "Voronoi regions (Ericson 5.1.5)"},
                worst, sizeof(Real) == 4 ? tol::triangle_distance_float : tol::triangle_distance_double);
  check_at_most({kCase, std::string("triangles within reach that the reach test drops, ") + kind, "-", "the test errs towards keeping"},
                static_cast<double>(dropped_near), 0);
  BOOST_TEST(kept_far == 0);
  BOOST_TEST(near > 50000);
}

// A drum of radius R(theta) = R0 (1 + 0.06 sin(8 theta)) (a wavy liner), length l, axis z,
// n_theta x n_z cells of two triangles facing the axis.
TriangleMesh wavy_drum(double r0, double l, int n_theta, int n_z) {
  TriangleMesh m;
  for (int j = 0; j <= n_z; ++j)
    for (int i = 0; i < n_theta; ++i) {
      const double th = 2 * kPi * i / n_theta, r = r0 * (1 + 0.06 * std::sin(8 * th));
      m.vertices.push_back({r * std::cos(th), r * std::sin(th), -0.5 * l + l * j / n_z});
    }
  const auto at = [&](int i, int j) { return j * n_theta + (i % n_theta); };
  for (int j = 0; j < n_z; ++j)
    for (int i = 0; i < n_theta; ++i) {
      const int a = at(i, j), b = at(i, j + 1), c = at(i + 1, j), d = at(i + 1, j + 1);
      m.triangles.push_back({a, b, c}), m.triangles.push_back({b, d, c});
    }
  return m;
}

template <class Real>
World<Real> drum_world(double rpm) {
  const double r0 = 0.15, l = 0.06;
  World<Real> w;
  w.meshes.push_back({"liner", wavy_drum(r0, l, 160, 8), 1});
  const double e = 0.2;  // end plates, square, wider than the drum
  w.polygons.push_back(PlanarPolygon<Real>::make({{-e, -e, -0.5 * l}, {-e, e, -0.5 * l}, {e, e, -0.5 * l}, {e, -e, -0.5 * l}}, 1));
  w.polygons.push_back(PlanarPolygon<Real>::make({{-e, -e, 0.5 * l}, {e, -e, 0.5 * l}, {e, e, 0.5 * l}, {-e, e, 0.5 * l}}, 1));
  Motion turn;
  turn.kind = MotionKind::rotation, turn.axis = {0, 0, 1}, turn.point = {0, 0, 0}, turn.omega = rpm * 2 * kPi / 60, turn.ramp = 0.1;
  w.motions.assign(3, Motion{});
  w.motions[2] = turn;  // objects: the polygons, then the mesh
  return w;
}

template <class Real>
ParticleState<Real> drum_balls(double r) {
  return mill_balls<Real>(r, -0.125, 0.12);
}

template <class Real>
void lists_hold_touching_triangles(double skin_fraction) {
  using Law = LinearLaw<Real>;
  const double r = 0.01, kn = 1e5, m = 7800 * 4.0 / 3.0 * kPi * r * r * r;
  const double dt = kPi * std::sqrt(0.5 * m / kn) / 25;
  const World<Real> w = drum_world<Real>(40);
  const Law law{LinearSpringDashpot<Real>::from_restitution(Real(kn), Real(0.8)), HistoryFreeFriction<Real>::make(Real(0.3), Real(50))};
  BallSim<Law> sim(params<Real>(dt, {0, -9.81, 0}, 0.4, skin_fraction * r), one_law(law), w, drum_balls<Real>(r));
  BOOST_TEST_REQUIRE(sim.world_lists().triangle_lists_on());
  // the liner as the kernels see it, in its reference frame
  const MeshArrays<Real> arrays = mesh_arrays<Real>(w.meshes, (r + skin_fraction * r) * 1.001);  // the bins the run has
  MeshBinsView<Real> bins = arrays.objects[0].bins;
  bins.start = arrays.bin_start.data(), bins.entry = arrays.bin_entry.data();
  const MeshSurfaceView<Real> surface{arrays.vertex.data(),         arrays.triangle.data(),  arrays.neighbour.data(),
                                      arrays.adjacency_start.data(), arrays.adjacency.data(), arrays.normal.data()};
  const int triangles = static_cast<int>(w.meshes[0].mesh.size());
  long checked = 0, missing = 0, overflowed = 0;
  double listed = 0, in_cell = 0, samples = 0;
  for (int k = 0; k < 40; ++k) {
    sim.run(static_cast<std::uint64_t>(std::llround(0.01 / dt)) + static_cast<std::uint64_t>(k % 7));
    const auto st = sim.state();
    const auto poses = sim.world_poses();
    const auto lists = sim.world_lists().triangle_lists();
    BOOST_TEST_REQUIRE(lists.size() == st.size());
    for (std::size_t i = 0; i < st.size(); ++i) {
      if (lists[i].size() == 1 && lists[i][0] == -1) {
        ++overflowed;
        continue;
      }
      const Vec3<Real> xr = poses.at(2).to_reference(st.position[i]);
      int first = 0, last = 0;
      bins.cell_of(xr, first, last);
      listed += static_cast<double>(lists[i].size()), in_cell += last - first, samples += 1;
      for (int t = 0; t < triangles; ++t)
        if (collide_sphere_mesh_triangle(xr, st.radius[i], surface, t).touching) {
          ++checked;
          missing += std::find(lists[i].begin(), lists[i].end(), t) == lists[i].end();
        }
    }
  }
  const std::string kind = std::string(", skin ") + std::to_string(skin_fraction).substr(0, 4) + " r, " + (sizeof(Real) == 4 ? "float" : "double");
  BOOST_TEST_MESSAGE("triangle lists" << kind << ": " << checked << " triangle contacts checked, " << missing << " missing, " << overflowed
                                      << " overflowed; " << listed / samples << " triangles listed per ball, "
                                      << in_cell / samples << " in its cell");
  BOOST_TEST_REQUIRE(checked > 300);  // the charge does lie on the liner
  check_at_most({kCase, "turning mesh drum: touching triangles missing from the lists" + kind, "-",
                 "lists hold every triangle within r + skin (skin / 2 each for the balls and the liner)"},
                static_cast<double>(missing), 0);
  check_at_most({kCase, "turning mesh drum: triangles listed per ball / those in its cell" + kind, "-", "the lists prune the cells"},
                listed / in_cell, tol::triangle_lists_listed_fraction);
  BOOST_TEST(overflowed == 0);
}

// A relief: the square [-a, a]^2 with heights h sin(3 x / a) cos(2 y / a) plus random bumps,
// n x n cells of two triangles (diagonals alternating), facing +z.
TriangleMesh relief(double a, int n, double h, unsigned seed) {
  TriangleMesh m;
  std::mt19937_64 rng(seed);
  std::uniform_real_distribution<double> u(-1, 1);
  const double step = 2 * a / n;
  for (int j = 0; j <= n; ++j)
    for (int i = 0; i <= n; ++i) {
      const double x = -a + i * step, y = -a + j * step;
      m.vertices.push_back({x, y, h * std::sin(3 * x / a) * std::cos(2 * y / a) + 0.3 * h * u(rng)});
    }
  const auto at = [&](int i, int j) { return j * (n + 1) + i; };
  for (int j = 0; j < n; ++j)
    for (int i = 0; i < n; ++i) {
      const int p = at(i, j), q = at(i + 1, j), r = at(i + 1, j + 1), s = at(i, j + 1);
      if ((i + j) % 2 == 0) m.triangles.push_back({p, q, r}), m.triangles.push_back({p, r, s});
      else m.triangles.push_back({p, q, s}), m.triangles.push_back({q, r, s});
    }
  return m;
}

template <class Real>
World<Real> relief_world(const Motion& motion) {
  World<Real> w;
  w.meshes.push_back({"relief", relief(0.3, 40, 0.02, 3), 1});
  if (motion.moves()) w.motions = {motion};
  return w;
}

template <class Real>
bool same_states(const ParticleState<Real>& a, const ParticleState<Real>& b) {
  bool same = a.size() == b.size();
  for (std::size_t k = 0; same && k < a.size(); ++k)
    same = a.id[k] == b.id[k] && a.position[k].x == b.position[k].x && a.position[k].y == b.position[k].y &&
           a.position[k].z == b.position[k].z && a.velocity[k].x == b.velocity[k].x && a.angular_velocity[k].y == b.angular_velocity[k].y &&
           a.orientation[k].w == b.orientation[k].w;
  return same;
}

// Runs `make_sim(mode)` with world lists on and off for `steps`; true when bitwise the same.
template <class Sim, class Make>
bool same_on_and_off(Make&& make_sim, std::uint64_t steps, double& listed, const std::string& name) {
  std::vector<decltype(std::declval<Sim&>().state())> out;
  for (WorldLists mode : {WorldLists::on, WorldLists::off}) {
    Sim sim = make_sim(mode);
    BOOST_TEST_REQUIRE(sim.world_lists().triangle_lists_on() == (mode == WorldLists::on));
    sim.run(steps);
    if (mode == WorldLists::on) {
      listed = sim.world_lists().mean_triangles_listed();
      BOOST_TEST(sim.world_lists().triangle_overflowed() == 0);
      BOOST_TEST(sim.world_lists().builds() > 2);
    }
    out.push_back(sim.state());
  }
  BOOST_TEST_MESSAGE(name << ": " << listed << " triangles listed per particle at the end");
  return same_states(out[0], out[1]);
}

}  // namespace

BOOST_AUTO_TEST_SUITE(triangle_lists)

BOOST_AUTO_TEST_CASE(point_triangle_distance_matches_the_plane_or_edges) {
  distance_against_reference<double>("double");
  distance_against_reference<float>("float");
}

BOOST_AUTO_TEST_CASE(lists_hold_every_triangle_a_ball_touches_in_a_turning_mesh_drum) {
  for (double skin : {0.05, 0.3, 1.0}) {
    lists_hold_touching_triangles<double>(skin);
    lists_hold_touching_triangles<float>(skin);
  }
}

BOOST_AUTO_TEST_CASE(lists_change_no_trajectory_on_a_relief) {
  const double r = 0.012, dt = 2e-5;
  ParticleState<double> balls;
  for (double x = -0.2; x < 0.201; x += 0.05)
    for (double y = -0.2; y < 0.201; y += 0.05) balls.add_sphere({x, y, 0.06 + 0.1 * std::fabs(x * y)}, r, 2500, 0);
  using Hm = HertzMindlinLaw<double>;
  const auto hertz = Hertz<double>::from_restitution(5e7, 0.5);
  const Hm hm{hertz, TangentialSpring<double>::mindlin(0.4, 5e7 / 1.5 / 2.5, 0.5)};
  double listed = 0;
  const auto spheres = [&](double skin, const Motion& motion) {
    return [&, skin, motion](WorldLists mode) {
      auto prm = params<double>(dt, {1.5, 0.8, -9.81}, 0.7, skin);
      prm.world_lists = mode;
      return BallSim<Hm>(prm, one_law(hm), relief_world<double>(motion), balls);
    };
  };
  BOOST_TEST(same_on_and_off<BallSim<Hm>>(spheres(0.3 * r, Motion{}), 15000, listed, "spheres on the relief, skin 0.3 r"),
             "spheres, Hertz-Mindlin, skin 0.3 r: bitwise the same with triangle lists");
  BOOST_TEST((listed > 0.5 && listed < 12));
  Motion shake;
  shake.kind = MotionKind::vibration, shake.amplitude = 2e-3, shake.frequency = 15, shake.direction = {0.3, 0, 0.954}, shake.ramp = 0.05;
  BOOST_TEST(same_on_and_off<BallSim<Hm>>(spheres(0, shake), 10000, listed, "spheres on the shaken relief, skin 0"),
             "spheres, Hertz-Mindlin, shaken relief, skin 0: bitwise the same with triangle lists");
  BOOST_TEST((listed > 0.2 && listed < 4));  // skin 0: the triangles touching (a third of the balls bounce clear)

  using Law = LinearSpringLaw<double>;
  std::istringstream text("vertices 8\n0 0 0\n0.02 0 0\n0.02 0.02 0\n0 0.02 0\n0 0 0.02\n0.02 0 0.02\n0.02 0.02 0.02\n"
                          "0 0.02 0.02\nfaces 6\n4 0 3 2 1\n4 4 5 6 7\n4 0 1 5 4\n4 1 2 6 5\n4 2 3 7 6\n4 3 0 4 7\n");
  PolyhedronShape<double> shape;
  shape.table.add(parse_blaze_shape(text, "cube-20mm"), 2500);
  ParticleState<double> cubes;
  std::mt19937_64 rng(9);
  std::uniform_real_distribution<double> angle(0, 2 * kPi);
  for (double x = -0.2; x < 0.201; x += 0.06)
    for (double y = -0.2; y < 0.201; y += 0.06) {
      const double a = angle(rng);
      add_polyhedron(cubes, shape.table, 0, Vec3<double>{x, y, 0.07}, Quat<double>{std::cos(a / 2), 0.6 * std::sin(a / 2), 0, 0.8 * std::sin(a / 2)},
                     0, Vec3<double>{0.3, 0, 0});
    }
  const auto normal = LinearSpringDashpot<double>::from_restitution(2e5, 0.5);
  const Law law{normal, TangentialSpring<double>::linear(0.4, 2.0 / 7.0 * 2e5, normal.beta)};
  const double m = 2500 * 8e-6, dt_c = kPi * std::sqrt(0.5 * m / 2e5) / 25;
  using CubeSim = Simulation<DefaultSpace, PolyhedronShape<double>, Law, VelocityVerlet>;
  const auto make_cubes = [&](WorldLists mode) {
    auto prm = params<double>(dt_c, {1.5, 0.8, -9.81}, 0.7, 0.3 * 0.0173);
    prm.world_lists = mode;
    return CubeSim(prm, one_law(law), relief_world<double>(Motion{}), cubes, shape);
  };
  BOOST_TEST(same_on_and_off<CubeSim>(make_cubes, static_cast<std::uint64_t>(std::llround(0.4 / dt_c)), listed, "cubes on the relief"),
             "cubes, linear spring, skin 0.3 r: bitwise the same with triangle lists");
  BOOST_TEST((listed > 0.5 && listed < 16));
}

BOOST_AUTO_TEST_SUITE_END()
