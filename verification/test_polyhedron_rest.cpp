// Resting polyhedra stop turning (issue 17, item 10). Every shipped shape (data/shapes/*.shape;
// octahedron.obj is octahedron.shape), scaled to a bounding radius of 5 mm, glass density, is
// dropped from rest at 3 random orientations, its lowest vertex 1 mm above the surface, onto a
// planar floor and onto the top face of a cube of 4 times its bounding radius resting on that
// floor; linear spring-dashpot and Hertz laws (thesis eqs. 2.2, 3.6) with history-free friction
// mu = 0.5 and tangential damping K_T (eq. 2.3), and on the floor also mu = 0.
// A face (or edge) contact carries the weight over an area, so it resists turning about the
// normal (torsional friction) and rocking (the normal dashpot acts off the centre); reduced to
// one point under the centre it does neither (polyhedron_shape.hpp, contact_patch.hpp: the patch).
//   settled:  the first 1 ms sample, after the body has first moved up or stopped (its first
//             contact), where |v| < 1 mm/s;
//   at rest:  max |omega| over the samples in [t_settle + 0.2 s, 0.5 s] <= 1e-6 rad/s, and
//             t_settle + 0.2 s <= 0.5 s for every body.
// With mu = 0 the floor's forces are vertical: the torque about the vertical and the horizontal
// momentum stay exactly 0 from a drop at rest, so the body cannot spin about the vertical, and
// once the rocking is damped the components across it (the asserted |omega| there) vanish too.
// On another body without friction the spin about the normal that edge impacts give the body
// has nothing to resist it, so that case has no rest state to assert (kFrictionalLaws).
// Stiffness is low (contact time ~1.5 ms at the 0.14 m/s impact) so that dt = 2e-5 s resolves
// it: 2.5e4 steps per run, 10 runs of 9-12 bodies, ~8 s on one core.
#include <boost/test/unit_test.hpp>
#include <boost/test/data/test_case.hpp>
#include <algorithm>
#include <cmath>
#include <random>
#include <string>
#include <vector>
#include "blaze/shapes/polyhedron_shape.hpp"
#include "blaze/shapes/shape_io.hpp"
#include "verification/cases/single_body.hpp"
#include "verification/report.hpp"
#include "verification/scenes.hpp"

using namespace blaze;
using namespace blaze::test;
namespace bdata = boost::unit_test::data;

namespace {

constexpr double kR = 5e-3;           // m, bounding radius of every dropped body
constexpr double kDensity = 2500;     // kg/m^3
constexpr double kG = 9.81;           // m/s^2
constexpr double kDrop = 1e-3;        // m, lowest vertex above the surface at the start
constexpr double kDt = 2e-5;          // s
constexpr double kEnd = 0.5;          // s
constexpr double kSample = 1e-3;      // s between samples
constexpr double kVSettle = 1e-3;     // m/s: settled below this speed
constexpr double kRestWindow = 0.2;   // s after settling (the 0.2 s)
constexpr int kOrientations = 3;      // random orientations per shape and case
constexpr double kKT = 0.1;           // kg/s, tangential damping K_T of eq. 2.3

struct LawCase {
  const char* name;
  bool hertz;
  double mu;
};
std::ostream& operator<<(std::ostream& o, const LawCase& c) { return o << c.name; }
const LawCase kLaws[] = {{"linear, mu = 0.5", false, 0.5}, {"linear, mu = 0", false, 0.0},
                         {"Hertz, mu = 0.5", true, 0.5},   {"Hertz, mu = 0", true, 0.0}};
// On another body without friction the spin about the normal stays (header comment).
const LawCase kFrictionalLaws[] = {{"linear, mu = 0.5", false, 0.5}, {"Hertz, mu = 0.5", true, 0.5}};

// One law for every material pair. Linear: k = 2e3 N/m (t_c ~ 1.5 ms for the cube, 4.8e-4 kg),
// e = 0.3. Hertz: E* = 1.5 MPa, K_n = 4/3 E* sqrt(R*) (delta_max ~ 0.1 mm at 0.14 m/s, t_c ~ 2 ms),
// e = 0.3 exact (delta^(1/4) damping). Both without tension (Hertz's scene-file default; for the
// linear law polyhedron_shape.hpp explains why damped flat contacts want it: a tensile dashpot force
// at the lifting vertices drives the rocking, and a tetrahedron kept rocking at 0.08 rad/s).
// K_T = 0.1 kg/s: below the Coulomb cap the history-free law is viscous, so a resting spin decays
// as exp(-K_T sum_k w_k r_k^2 / I t) (r_k: the patch's vertices from its centre), at ~110 /s for
// the dodecahedron (the slowest); 0.02 kg/s left 7e-4 rad/s 0.2 s after settling. The explicit
// limit 2 m_eff / dt is ~1 kg/s for the lightest (tetrahedron, m_eff ~ 1.6e-5 kg at a vertex).
template <class Law>
Law make_law(const LawCase& c);
template <>
LinearLaw<double> make_law(const LawCase& c) {
  return {LinearSpringDashpot<double>::from_restitution(2e3, 0.3).without_tension(), HistoryFreeFriction<double>::make(c.mu, c.mu > 0 ? kKT : 0.0)};
}
template <>
HertzLaw<double> make_law(const LawCase& c) {
  return {Hertz<double>::from_restitution(1.5e6, 0.3, true), HistoryFreeFriction<double>::make(c.mu, c.mu > 0 ? kKT : 0.0)};
}

Quat<double> random_orientation(std::mt19937_64& rng) {
  std::normal_distribution<double> n;
  return normalized(Quat<double>{n(rng), n(rng), n(rng), n(rng)});
}
double lowest_vertex(const ConvexShape& s, const Quat<double>& q) {
  double low = 0;
  for (const auto& p : s.vertices) low = std::min(low, rotate(q, Vec3<double>{p.x(), p.y(), p.z()}).y);
  return low;
}

struct Outcome {
  std::string shape;
  double t_settle = -1;  // s, -1: never settled
  double max_spin = 0;   // rad/s over [t_settle + window, end]
  double spin_at_settle = 0;
};

// Bodies of up to three shapes (plus the base cube: the table holds 4 types), kOrientations each,
// spaced along x; on a floor, or each onto its own base cube (lower index: the base's face wins
// ties of the separating-axis test, so it is the reference face). Returns one outcome per body.
template <class Law>
std::vector<Outcome> drop(const LawCase& c, const std::vector<std::string>& names, bool on_cube, std::uint64_t seed) {
  PolyhedronShape<double> shape;
  std::vector<ConvexShape> shapes;
  for (const auto& n : names) {
    shapes.push_back(load_scaled_shape("data/shapes/" + n + ".shape", kR));
    shape.table.add(shapes.back(), kDensity);
  }
  const ConvexShape base = load_scaled_shape("data/shapes/cube.shape", 4 * kR);
  const int base_type = on_cube ? shape.table.add(base, kDensity) : -1;
  const double base_h = on_cube ? base.normals[0].dot(base.centroids[0]) : 0;  // half edge, m
  const int bodies = static_cast<int>(names.size()) * kOrientations;
  const double spacing = 10 * kR;
  std::mt19937_64 rng(seed);
  ParticleState<double> s;
  if (on_cube) {
    // Flat, a quarter of a mm above the floor.
    const Quat<double> flat = cases::cube_facing<double>(base, Eigen::Vector3d(0, -1, 0), Eigen::Vector3d(1, 0, 0));
    const double low = lowest_vertex(base, flat);
    for (int b = 0; b < bodies; ++b)
      add_polyhedron(s, shape.table, base_type, Vec3<double>{b * spacing, -low + 2.5e-4, 0}, flat, 2);
  }
  const double surface = on_cube ? 2 * base_h + 2.5e-4 : 0.0;
  for (int b = 0; b < bodies; ++b) {
    const int type = b / kOrientations;
    const Quat<double> q = random_orientation(rng);
    add_polyhedron(s, shape.table, type, Vec3<double>{b * spacing, surface - lowest_vertex(shapes[type], q) + kDrop, 0}, q, 0);
  }
  const Law law = make_law<Law>(c);
  // The base (material 2) is held by its floor: mu = 0.5 and K_T = 1 kg/s there whatever the
  // case, so that what the dropped body gives it (it is 25 times heavier, and 45 times the
  // moment of inertia about the vertical) decays as fast as the body's own motion would.
  PairTable<Law> laws = one_law(law, 3);
  Law held = make_law<Law>({"held", c.hertz, 0.5});
  held.tangential = HistoryFreeFriction<double>::make(0.5, 2.0);
  laws.set(1, 2, held);
  World<double> world;
  world.polygons.push_back(PlanarPolygon<double>::make(
      {{-spacing, 0, spacing}, {bodies * spacing, 0, spacing}, {bodies * spacing, 0, -spacing}, {-spacing, 0, -spacing}}, 1));
  const SimulationParams<double> prm{kDt, {0, -kG, 0}, {-2 * spacing, -spacing, -2 * spacing},
                                     {(bodies + 1) * spacing, 10 * kR, 2 * spacing}, 0.2 * kR};
  Simulation<DefaultSpace, PolyhedronShape<double>, Law, VelocityVerlet> sim(prm, laws, world, s, shape);
  const Index first = on_cube ? bodies : 0;  // ids of the dropped bodies
  std::vector<Outcome> out(bodies);
  std::vector<bool> touched(bodies, false);
  for (int b = 0; b < bodies; ++b) out[b].shape = names[b / kOrientations];
  const long every = std::lround(kSample / kDt), steps = std::lround(kEnd / kDt);
  for (long k = every; k <= steps; k += every) {
    sim.run(static_cast<std::uint64_t>(every));
    const auto st = sim.state();
    const double t = sim.time();
    for (std::size_t i = 0; i < st.size(); ++i) {
      if (st.id[i] < first) continue;
      const int b = static_cast<int>(st.id[i] - first);
      // Without friction nothing resists turning about the normal (vertical, on the floor and on
      // the base's top face): there only the rocking, the components across it, must stop.
      const Vec3<double> w = st.angular_velocity[i];
      const double speed = norm(st.velocity[i]), spin = c.mu > 0 ? norm(w) : std::hypot(w.x, w.z);
      touched[b] = touched[b] || st.velocity[i].y > 0;  // first rebound (or stop) after the first contact
      if (touched[b] && out[b].t_settle < 0 && speed < kVSettle) out[b].t_settle = t, out[b].spin_at_settle = spin;
      if (out[b].t_settle >= 0 && t >= out[b].t_settle + kRestWindow) out[b].max_spin = std::max(out[b].max_spin, spin);
    }
  }
  return out;
}

template <class Law>
void check_case(const LawCase& c, bool on_cube) {
  const std::vector<std::vector<std::string>> groups = {{"box", "corn", "cube"}, {"dodecahedron", "icosahedron", "octahedron"},
                                                        {"prism", "tetrahedron"}};
  double worst = 0, latest = 0;
  std::uint64_t seed = on_cube ? 101 : 1;
  for (const auto& g : groups) {
    for (const Outcome& o : drop<Law>(c, g, on_cube, seed++)) {
      BOOST_TEST_MESSAGE(c.name << (on_cube ? ", onto a cube: " : ", on a floor: ") << o.shape << " settled at " << o.t_settle
                                << " s (|w| " << o.spin_at_settle << " rad/s), max |w| from 0.2 s later " << o.max_spin
                                << " rad/s");
      BOOST_TEST(o.t_settle >= 0, o.shape << " never settled");
      latest = std::max(latest, o.t_settle);
      worst = std::max(worst, o.max_spin);
    }
  }
  check_at_most({"Resting polyhedra (issue 17.10)",
                 std::string("every shape x ") + std::to_string(kOrientations) + " random orientations dropped " +
                     (on_cube ? "onto a cube" : "on a floor") + ", " + c.name +
                     ": latest settling time (s; |v| < 1 mm/s) + 0.2 s, of the " + std::to_string(kEnd) + " s run",
                 "-", "settles"},
                latest + kRestWindow, kEnd);
  check_at_most({"Resting polyhedra (issue 17.10)",
                 std::string("every shape x 3 orientations dropped ") + (on_cube ? "onto a cube" : "on a floor") + ", " +
                     c.name + ": max |omega| from 0.2 s after settling (rad/s), double, dt = 2e-5 s",
                 "-", "contact patch: torsional friction and rocking damping"},
                worst, tol::resting_spin);
}

}  // namespace

BOOST_AUTO_TEST_SUITE(polyhedron_rest)

BOOST_DATA_TEST_CASE(dropped_on_floor_stops_turning, bdata::make(kLaws), c) {
  if (c.hertz) check_case<HertzLaw<double>>(c, false);
  else check_case<LinearLaw<double>>(c, false);
}

BOOST_DATA_TEST_CASE(dropped_onto_cube_stops_turning, bdata::make(kFrictionalLaws), c) {
  if (c.hertz) check_case<HertzLaw<double>>(c, true);
  else check_case<LinearLaw<double>>(c, true);
}

BOOST_AUTO_TEST_SUITE_END()
