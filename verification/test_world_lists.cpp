// World lists (issue 19; pipeline/world_candidates.hpp, kernels/world_candidates.hpp): each
// particle's world objects in reach, built at the neighbour-list rebuilds, so the world kernel
// tests a few objects instead of every one (a mill's shell, end plates and lifter faces).
// - The reach test is conservative: every sphere that touches a polygon (a lifter face, a
//   triangle) or a drum cylinder passes within_reach with its own radius (random spheres near
//   and across the edges and ends, float and double); far ones do not; a polygon's bounding
//   sphere, tested first, never changes the answer (turned polygons, near and far points).
// - In a turning mill with lifters (15 objects), at every sample the lists hold every object that
//   touches a ball, for skins of 0.05 r to r, float and double: the lifters move up to skin / 2
//   between builds and the rebuild check trips when they may have (World::surface_speed); the
//   lists hold 1-3 objects on average, far fewer than 15.
// - With skin 0 (a rebuild every step, lists on or off alike) the trajectory with lists is
//   bitwise the one without, history-free and with a tangential spring, spheres and cubes (whose
//   lists come from their bounding spheres): the lists change which objects are tested, never
//   the forces or their order.
// - A sphere at rest far from a wall (beyond the skin: not in its list) that the wall comes to:
//   the rebuild check trips on the wall's motion alone, and the sphere rebounds at (1 + e) V,
//   bitwise as without lists.
#include <boost/test/unit_test.hpp>
#include <cmath>
#include <random>
#include <sstream>
#include "blaze/shapes/polyhedron_shape.hpp"
#include "blaze/shapes/shape_io.hpp"
#include "verification/mill_scenes.hpp"
#include "verification/report.hpp"
#include "verification/scenes.hpp"
#include "verification/tolerances.hpp"

using namespace blaze;
using namespace blaze::test;

namespace {

const char* const kCase = "World lists (issue 19)";

template <class Law>
using LeanSim = Simulation<DefaultSpace, SphereShape, Law, VelocityVerlet, ContactPointVelocity, FullFeatures>;

// Objects of the placed world that touch sphere (x, r), by index (every object stays present).
template <class Real>
std::vector<int> touching(const World<Real>& placed_world, const Vec3<Real>& x, Real r) {
  std::vector<int> out;
  int w = 0;
  for (const auto& p : placed_world.polygons) {
    if (collide_sphere(x, r, p).touching) out.push_back(w);
    ++w;
  }
  for (const auto& c : placed_world.cylinders) {
    if (collide_sphere(x, r, c).touching) out.push_back(w);
    ++w;
  }
  return out;
}

template <class Real>
void reach_is_conservative() {
  std::mt19937_64 rng(7);
  std::uniform_real_distribution<double> u(-1, 1);
  const auto quad = PlanarPolygon<Real>::make({{-0.1, 0, -0.02}, {0.1, 0, -0.02}, {0.1, 0.03, 0.02}, {-0.1, 0.03, 0.02}}, 0);
  const auto tri = PlanarPolygon<Real>::make({{0, 0, 0}, {0.05, 0, 0}, {0, 0.05, 0.01}}, 0);
  const auto drum = Cylinder<Real>::make({0, 0, -0.05}, {0, 0, 1}, 0.2, 0.1, 0);
  long touched = 0, far_passed = 0;
  for (int k = 0; k < 20000; ++k) {
    const double r = 0.002 + 0.02 * (0.5 + 0.5 * u(rng));
    const Vec3<Real> xq = vec_cast<Real>(Vec3<double>{0.12 * u(rng), 0.015 + 0.04 * u(rng), 0.04 * u(rng)});
    const Vec3<Real> xt = vec_cast<Real>(Vec3<double>{0.025 + 0.04 * u(rng), 0.025 + 0.04 * u(rng), 0.03 * u(rng)});
    const Vec3<Real> xc = vec_cast<Real>(Vec3<double>{0.21 * u(rng), 0.21 * u(rng), 0.07 * u(rng)});
    const Real rr = static_cast<Real>(r);
    const bool hit[3] = {collide_sphere(xq, rr, quad).touching, collide_sphere(xt, rr, tri).touching,
                         collide_sphere(xc, rr, drum).touching};
    const bool near[3] = {within_reach(xq, rr, quad), within_reach(xt, rr, tri), within_reach(xc, rr, drum)};
    for (int o = 0; o < 3; ++o) {
      touched += hit[o];
      if (hit[o] && !near[o]) BOOST_ERROR("a sphere touching object " << o << " is out of its reach (r = " << r << ")");
    }
    far_passed += within_reach(vec_cast<Real>(Vec3<double>{0, 0.5 + r, 0}), rr, quad) +
                  within_reach(vec_cast<Real>(Vec3<double>{0, 0, 0.06 + r}), rr, drum) +
                  within_reach(vec_cast<Real>(Vec3<double>{0, 0, 0}), rr, drum);
  }
  BOOST_TEST(touched > 2000);  // the sample does touch
  BOOST_TEST(far_passed == 0);
  // The bounding-sphere rejection (PlanarPolygon::bound) never changes the answer: against the
  // same polygons with no bound, turned and shifted by a pose as a moving lifter is, for points
  // from inside the polygon's reach to far beyond it.
  int changed = 0, reached = 0;
  for (int k = 0; k < 20000; ++k) {
    const double angle = 3.0 * u(rng);
    Motion m;
    m.kind = MotionKind::rotation;
    m.axis = Vec3<double>{0.3, 1, -0.2} * (1 / std::sqrt(1.13));
    m.point = {0.05, -0.02, 0.01};
    m.omega = angle;
    const Pose<Real> pose = pose_at<Real>(m, 1.0);
    for (const auto* ref : {&quad, &tri}) {
      const PlanarPolygon<Real> w = moved(*ref, pose);
      PlanarPolygon<Real> unbounded = w;
      unbounded.bound = Real(1e30);
      const Vec3<Real> x = w.centroid + vec_cast<Real>(Vec3<double>{u(rng), u(rng), u(rng)} * 0.1);
      const Real reach = static_cast<Real>(0.002 + 0.05 * (0.5 + 0.5 * u(rng)));
      const bool in = within_reach(x, reach, w);
      changed += in != within_reach(x, reach, unbounded);
      reached += in;
    }
  }
  BOOST_TEST(changed == 0);
  BOOST_TEST(reached > 2000);  // both answers occur
  BOOST_TEST(reached < 39000);
}

// Runs the small mill for `seconds` with skin s_frac r, checking every `every` steps that each
// ball's list holds every object it touches. Returns the mean listed objects at the end.
template <class Real>
void lists_hold_contacts(double skin_fraction) {
  using Law = LinearLaw<Real>;
  const double r = 0.01, kn = 1e5, m = 7800 * 4.0 / 3.0 * kPi * r * r * r;
  const double dt = kPi * std::sqrt(0.5 * m / kn) / 25;
  const World<Real> w = small_mill<Real>(40, 0.1);
  const Law law{LinearSpringDashpot<Real>::from_restitution(Real(kn), Real(0.8)), HistoryFreeFriction<Real>::make(Real(0.3), Real(50))};
  LeanSim<Law> sim(params<Real>(dt, {0, -9.81, 0}, 0.2, skin_fraction * r), one_law(law), w, mill_balls<Real>(r));
  BOOST_TEST_REQUIRE(sim.world_lists().on());  // 15 objects: on by default
  const int objects = w.object_count();
  // the lifter tops' corners are the fastest points: 0.15 m from the axis at most
  const double v_bound = 40 * 2 * kPi / 60 * 0.15;
  BOOST_TEST(sim.world_lists().valid_steps() <= static_cast<std::uint64_t>(0.5 * skin_fraction * r / (v_bound * dt)) + 1);
  long checked = 0, missing = 0;
  const std::uint64_t builds0 = sim.world_lists().builds();
  for (int k = 0; k < 60; ++k) {
    sim.run(static_cast<std::uint64_t>(std::llround(0.01 / dt)) + static_cast<std::uint64_t>(k % 7));
    const auto st = sim.state();
    const World<Real> now = placed(w, sim.world_poses());
    const auto lists = sim.world_lists().lists(objects);
    BOOST_TEST_REQUIRE(lists.size() == st.size());
    for (std::size_t i = 0; i < st.size(); ++i)
      for (int o : touching(now, st.position[i], st.radius[i])) {
        ++checked;
        missing += std::find(lists[i].begin(), lists[i].end(), o) == lists[i].end();
      }
  }
  const double mean = sim.world_lists().mean_listed(objects);
  BOOST_TEST_MESSAGE("world lists, skin " << skin_fraction << " r, " << sizeof(Real) * 8 << "-bit: " << checked
                                          << " wall contacts checked, " << missing << " missing; " << sim.world_lists().builds() - builds0
                                          << " builds, " << sim.neighbour_builds() << " neighbour builds; " << mean
                                          << " objects listed per ball of " << objects << "; valid " << sim.world_lists().valid_steps()
                                          << " steps");
  BOOST_TEST_REQUIRE(checked > 300);  // the charge does touch the shell and the lifters
  check_at_most({kCase, "turning mill: wall contacts missing from the lists, skin " + std::to_string(skin_fraction).substr(0, 4) +
                            " r, " + (sizeof(Real) == 4 ? "float" : "double"),
                 "-", "lists hold every contact (skin / 2 for the balls, skin / 2 for the lifters)"},
                missing, 0);
  check_at_most({kCase, "turning mill: objects listed per ball / objects, skin " + std::to_string(skin_fraction).substr(0, 4) + " r, " +
                            (sizeof(Real) == 4 ? "float" : "double"),
                 "-", "the lists prune"},
                mean / objects, tol::world_lists_listed_fraction);
  BOOST_TEST(sim.world_lists().overflowed() == 0);
}

// The trajectory with lists and without, skin 0: a rebuild at every step either way.
template <class Law>
bool same_with_and_without_lists(const Law& law) {
  using Real = typename Law::real_type;
  const double r = 0.01, kn = 1e5, m = 7800 * 4.0 / 3.0 * kPi * r * r * r;
  const double dt = kPi * std::sqrt(0.5 * m / kn) / 25;
  const World<Real> w = small_mill<Real>(40, 0.1);
  auto prm = params<Real>(dt, {0, -9.81, 0}, 0.2, 0);
  std::vector<ParticleState<Real>> out;
  for (WorldLists mode : {WorldLists::on, WorldLists::off}) {
    prm.world_lists = mode;
    LeanSim<Law> sim(prm, one_law(law), w, mill_balls<Real>(r));
    BOOST_TEST_REQUIRE(sim.world_lists().on() == (mode == WorldLists::on));
    sim.run(static_cast<std::uint64_t>(std::llround(0.4 / dt)));
    out.push_back(sim.state());
  }
  const auto &a = out[0], &b = out[1];
  bool same = a.size() == b.size();
  for (std::size_t k = 0; same && k < a.size(); ++k)
    same = a.id[k] == b.id[k] && a.position[k].x == b.position[k].x && a.position[k].y == b.position[k].y &&
           a.position[k].z == b.position[k].z && a.velocity[k].x == b.velocity[k].x && a.velocity[k].y == b.velocity[k].y &&
           a.angular_velocity[k].z == b.angular_velocity[k].z;
  return same;
}

}  // namespace

BOOST_AUTO_TEST_SUITE(world_lists)

BOOST_AUTO_TEST_CASE(reach_test_is_conservative) {
  reach_is_conservative<float>();
  reach_is_conservative<double>();
}

BOOST_AUTO_TEST_CASE(surface_speeds_bound_the_objects_motion) {
  const World<double> w = small_mill<double>(40, 0.1);
  const double omega = 40 * 2 * kPi / 60;
  // the drum turns about its own axis: its surface stays put
  BOOST_TEST(w.surface_speed(w.object_count() - 1) == 0.0);
  // a lifter's top corners sit at sqrt(0.13^2 + 0.01^2) from the axis
  const double top = omega * std::hypot(0.15 * std::sqrt(1 - 0.01 * 0.01 / (0.15 * 0.15)) - 0.02, 0.01);
  BOOST_TEST(std::fabs(w.surface_speed(2) - top) < tol::surface_speed_closed_form * top);
  // the same drum turning about another axis moves: at least omega times its radius
  World<double> tilted = w;
  Motion m = tilted.motions.back();
  m.point = {0.05, 0, 0};
  tilted.motions.back() = m;
  BOOST_TEST(tilted.surface_speed(w.object_count() - 1) >= omega * 0.15);
  // a vibration's ramp adds A / T_r to 2 pi f A
  Motion v;
  v.kind = MotionKind::vibration, v.amplitude = 1e-3, v.frequency = 20, v.ramp = 0.5;
  BOOST_TEST(std::fabs(peak_speed(v, {}) - 1e-3 * (2 * kPi * 20 + 2)) < tol::surface_speed_closed_form * 1e-3 * (2 * kPi * 20 + 2));
}

BOOST_AUTO_TEST_CASE(lists_hold_every_wall_contact_in_a_turning_mill) {
  for (double skin : {0.05, 0.3, 1.0}) {
    lists_hold_contacts<double>(skin);
    lists_hold_contacts<float>(skin);
  }
}

BOOST_AUTO_TEST_CASE(lists_change_no_trajectory) {
  const auto normal = LinearSpringDashpot<double>::from_restitution(1e5, 0.8);
  BOOST_TEST(same_with_and_without_lists(LinearLaw<double>{normal, HistoryFreeFriction<double>::make(0.3, 50)}),
             "history-free: bitwise the same with lists");
  BOOST_TEST(same_with_and_without_lists(LinearSpringLaw<double>{normal, TangentialSpring<double>::linear(0.3, 2.0 / 7.0 * 1e5, normal.beta)}),
             "linear spring: bitwise the same with lists");
  const auto normal_f = LinearSpringDashpot<float>::from_restitution(1e5f, 0.8f);
  BOOST_TEST(same_with_and_without_lists(LinearLaw<float>{normal_f, HistoryFreeFriction<float>::make(0.3f, 50.0f)}),
             "history-free, float: bitwise the same with lists");
}

BOOST_AUTO_TEST_CASE(cubes_in_a_turning_mill_move_the_same_with_lists) {
  using Law = LinearLaw<double>;
  std::istringstream text("vertices 8\n0 0 0\n0.016 0 0\n0.016 0.016 0\n0 0.016 0\n0 0 0.016\n0.016 0 0.016\n0.016 0.016 0.016\n"
                          "0 0.016 0.016\nfaces 6\n4 0 3 2 1\n4 4 5 6 7\n4 0 1 5 4\n4 1 2 6 5\n4 2 3 7 6\n4 3 0 4 7\n");
  PolyhedronShape<double> shape;
  shape.table.add(parse_blaze_shape(text, "cube-16mm"), 7800);
  ParticleState<double> s;
  std::mt19937_64 rng(4);
  std::uniform_real_distribution<double> angle(0, 6.28318530718);
  for (double x = -0.1; x < 0.101; x += 0.03)
    for (double y = -0.11; y < -0.01; y += 0.03)
      for (double z : {-0.014, 0.014})
        if (std::hypot(x, y) < 0.11) {
          const double a = angle(rng);
          add_polyhedron(s, shape.table, 0, Vec3<double>{x, y, z}, Quat<double>{std::cos(a / 2), 0.6 * std::sin(a / 2), 0.8 * std::sin(a / 2), 0}, 0,
                         Vec3<double>{0, 0, 0});
        }
  const World<double> w = small_mill<double>(40, 0.1);
  const Law law{LinearSpringDashpot<double>::from_restitution(1e5, 0.6), HistoryFreeFriction<double>::make(0.4, 20)};
  const double m = 7800 * std::pow(0.016, 3), dt = kPi * std::sqrt(0.5 * m / 1e5) / 25;
  auto prm = params<double>(dt, {0, -9.81, 0}, 0.2, 0);
  std::vector<ParticleState<double>> out;
  for (WorldLists mode : {WorldLists::on, WorldLists::off}) {
    prm.world_lists = mode;
    Simulation<DefaultSpace, PolyhedronShape<double>, Law, VelocityVerlet> sim(prm, one_law(law), w, s, shape);
    sim.run(static_cast<std::uint64_t>(std::llround(0.25 / dt)));
    out.push_back(sim.state());
  }
  bool same = out[0].size() == out[1].size() && out[0].size() == s.size();
  for (std::size_t k = 0; same && k < out[0].size(); ++k)
    same = out[0].position[k].x == out[1].position[k].x && out[0].position[k].y == out[1].position[k].y &&
           out[0].orientation[k].w == out[1].orientation[k].w && out[0].angular_velocity[k].z == out[1].angular_velocity[k].z;
  BOOST_TEST(same, s.size() << " cubes: bitwise the same with lists");
  double moved = 0;
  for (std::size_t k = 0; k < s.size(); ++k) moved = std::fmax(moved, norm(out[0].position[k] - s.position[k]));
  BOOST_TEST(moved > 0.01);  // the charge did tumble against the lifters
}

BOOST_AUTO_TEST_CASE(a_wall_that_comes_to_a_still_sphere_finds_it) {
  using Law = LinearLaw<double>;
  const double r = 5e-3, kn = 1e4, e = 0.7;
  const Law law{LinearSpringDashpot<double>::from_restitution(kn, e), HistoryFreeFriction<double>::make(0, 0)};
  const double m = 2500 * 4.0 / 3.0 * kPi * r * r * r, t_c = kPi * std::sqrt(m / kn), dt = t_c / 200;
  for (double skin : {0.1 * r, r, 2 * r})
    for (double speed : {0.5, 2.0}) {
      ParticleState<double> s;
      s.add_sphere({0, 0.02 + 2 * skin, 0}, r, 2500, 0);
      World<double> world;
      world.polygons.push_back(floor_square<double>(0, 0.05));
      world.set_motion(0, Motion{MotionKind::translation, {0, 0, 1}, {0, 0, 0}, 0, 0, {0, speed, 0}});
      double v[2];
      std::uint64_t builds[2];
      for (int on = 0; on < 2; ++on) {
        auto prm = params<double>(dt, {0, 0, 0}, 0.5, skin);
        prm.world_lists = on ? WorldLists::on : WorldLists::off;
        LeanSim<Law> sim(prm, one_law(law), world, s);
        if (on) BOOST_TEST_REQUIRE(sim.world_lists().lists(1).at(0).empty());  // out of reach at the start
        sim.run(static_cast<std::uint64_t>(std::llround(((0.02 + 2 * skin - r) / speed + 3 * t_c) / dt)));
        v[on] = sim.state().velocity[0].y;
        builds[on] = sim.neighbour_builds();
      }
      BOOST_TEST_MESSAGE("wall to a still sphere, skin " << skin / r << " r, V = " << speed << ": leaves at " << v[1]
                                                         << " m/s with lists (" << builds[1] << " builds), " << v[0] << " without ("
                                                         << builds[0] << ")");
      check_relative({kCase, "still sphere hit by a wall beyond its list's reach: rebound vs (1 + e) V", "-",
                      "the rebuild check trips on the wall's motion"},
                     v[1], (1 + e) * speed, tol::moving_wall_restitution);
      BOOST_TEST(v[1] == v[0]);
    }
}

BOOST_AUTO_TEST_SUITE_END()
