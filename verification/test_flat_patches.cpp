// Flat patches of a mesh (issue 20; blaze/world/mesh_surface.hpp flat_patches, mesh_wall.hpp
// drop_flat_neighbours): a sphere's triangle list keeps, of a flat patch it lies well over, only
// the triangle under it, since the patch's other flat-interior triangles cannot offer it a contact
// before the next rebuild.
// - On a terrace (a floor, a ramp and a plateau, finely and irregularly tessellated, tilted out of
//   the axes) the flat-interior triangles are those whose corners' fans lie in one plane: the
//   creases' and the border's triangles are not; each flat region is one patch.
// - Spheres anywhere over the terrace, moved by up to the distance their lists serve for (skin / 2)
//   in any direction, get bitwise the contacts (owner triangle, normal, overlap, point) from their
//   lists that they get from all the mesh's triangles, float and double; the lists drop most of
//   the flat triangles within reach.
// - Balls under Hertz-Mindlin poured onto the terrace, still, shaken and turning, move bitwise the
//   same with the lists as without them (sums in id order); the patches drop triangles in a still
//   world and under vibration, not under rotation.
#include <boost/test/unit_test.hpp>
#include <algorithm>
#include <cmath>
#include <random>
#include "verification/report.hpp"
#include "verification/scenes.hpp"
#include "verification/tolerances.hpp"

using namespace blaze;
using namespace blaze::test;

namespace {

const char* const kCase = "Flat patches (issue 20)";

template <class Law>
using BallSim = Simulation<DefaultSpace, SphereShape, Law, VelocityVerlet, ContactPointVelocity, FullFeatures>;

// The terrace: over [-a, a]^2 a floor (z = 0) up to column 8, a ramp to z = h at column 10, a
// plateau beyond; n x n cells of two triangles (diagonals alternating), inner vertices moved in
// the plane by up to a quarter of a cell (those on the creases only along them); then turned about
// (1, 2, 0) by 0.3 rad so that no normal is an axis.
constexpr int kTerraceCells = 20, kFloorEnd = 8, kRampEnd = 10;
struct Terrace {
  TriangleMesh mesh;
  Quat<double> turn;
  double a, h;
  // The height of the surface at (x, y) of the unturned terrace.
  double z(double x) const {
    const double step = 2 * a / kTerraceCells, x1 = -a + kFloorEnd * step, x2 = -a + kRampEnd * step;
    return x <= x1 ? 0 : x >= x2 ? h : h * (x - x1) / (x2 - x1);
  }
};

// Two triangles per cell of a grid of (nx + 1) x (ny + 1) vertices (row by row), diagonals alternating.
void grid_triangles(TriangleMesh& m, int nx, int ny) {
  const auto at = [&](int i, int j) { return j * (nx + 1) + i; };
  for (int j = 0; j < ny; ++j)
    for (int i = 0; i < nx; ++i) {
      const int p = at(i, j), q = at(i + 1, j), r = at(i + 1, j + 1), s = at(i, j + 1);
      if ((i + j) % 2 == 0) m.triangles.push_back({p, q, r}), m.triangles.push_back({p, r, s});
      else m.triangles.push_back({p, q, s}), m.triangles.push_back({q, r, s});
    }
}

Terrace terrace(double a, double h, unsigned seed) {
  const double sn = std::sin(0.15) / std::sqrt(5.0);
  Terrace t{{}, Quat<double>{std::cos(0.15), sn, 2 * sn, 0}, a, h};
  std::mt19937_64 rng(seed);
  std::uniform_real_distribution<double> u(-0.25, 0.25);
  const int n = kTerraceCells;
  const double step = 2 * a / n;
  for (int j = 0; j <= n; ++j)
    for (int i = 0; i <= n; ++i) {
      const bool fixed_x = i == 0 || i == n || i == kFloorEnd || i == kRampEnd, fixed_y = j == 0 || j == n;
      const double x = -a + i * step + (fixed_x || fixed_y ? 0 : u(rng) * step);
      const double y = -a + j * step + (fixed_y ? 0 : u(rng) * step);
      t.mesh.vertices.push_back(rotate(t.turn, Vec3<double>{x, y, t.z(x)}));
    }
  grid_triangles(t.mesh, n, n);
  return t;
}

// A floor (z = 0) over [-a, a]^2 with a V-groove along y at x = 0, w wide and g deep, from a
// quarter to three quarters of its length: n x n cells, plus two narrow columns at x = +-w/2 for
// the groove's sides; the floor around it is one plane patch that is not convex, and the far rim
// of a groove narrower than a sphere's reach offers it an edge contact from the patch's own
// triangles (which are not flat-interior: their corners' fans hold the groove's sides). Turned as
// the terrace is; z(x) is the floor's height (0).
Terrace grooved_floor(double a, double w, double g) {
  Terrace t = terrace(a, 0, 1);
  t.mesh = TriangleMesh{};
  const int n = kTerraceCells;
  std::vector<double> xs;
  for (int i = 0; i <= n; ++i) xs.push_back(-a + 2 * a * i / n);
  xs.push_back(-0.5 * w), xs.push_back(0.5 * w);
  std::sort(xs.begin(), xs.end());
  const int nx = static_cast<int>(xs.size()) - 1;
  for (int j = 0; j <= n; ++j)
    for (int i = 0; i <= nx; ++i) {
      const bool groove = xs[static_cast<std::size_t>(i)] == 0 && j >= n / 4 && j <= 3 * n / 4;
      t.mesh.vertices.push_back(rotate(t.turn, Vec3<double>{xs[static_cast<std::size_t>(i)], -a + 2 * a * j / n, groove ? -g : 0}));
    }
  grid_triangles(t.mesh, nx, n);
  return t;
}

// Spheres over the terrace at heights from half a radius into it to past their reach, at |x| <= spread a.
template <class Real>
ParticleState<Real> spheres_over(const Terrace& t, double r, int count, unsigned seed, double spread = 0.95) {
  std::mt19937_64 rng(seed);
  std::uniform_real_distribution<double> u(0, 1);
  ParticleState<Real> s;
  for (int k = 0; k < count; ++k) {
    const double x = (2 * u(rng) - 1) * spread * t.a, y = (2 * u(rng) - 1) * 0.95 * t.a;
    const Vec3<double> p = rotate(t.turn, Vec3<double>{x, y, t.z(x) + r * (1.4 * u(rng) - 0.3)});
    s.add_sphere(vec_cast<Real>(p), Real(r), Real(2500), 0);
  }
  return s;
}

// Over the terrace (spread 0.95) or the grooved floor (spheres within `spread` a of the groove).
template <class Real>
void lists_give_the_contacts_of_all_triangles(const Terrace& t, double spread, std::string kind) {
  kind += sizeof(Real) == 4 ? ", float" : ", double";
  const double r = 0.012, skin = 0.3 * r, move = 0.5 * skin;
  World<Real> w;
  w.meshes.push_back({"terrace", t.mesh, 1});
  const auto balls = spheres_over<Real>(t, r, 1500, 17, spread);
  using Law = LinearLaw<Real>;
  const Law law{LinearSpringDashpot<Real>::from_restitution(Real(1e5), Real(0.8)), HistoryFreeFriction<Real>::make(Real(0.3), Real(50))};
  auto prm = params<Real>(1e-5, {0, 0, 0}, 0.4, skin);
  prm.world_lists = WorldLists::on;
  BallSim<Law> sim(prm, one_law(law), w, balls);
  const auto lists = sim.world_lists().triangle_lists();
  const auto st = sim.state();
  // the mesh as the kernels read it
  MeshArrays<Real> arrays = mesh_arrays<Real>(w.meshes, (r + skin) * 1.001);
  MeshObject<Real> m = arrays.objects[0];
  m.bins.start = arrays.bin_start.data(), m.bins.entry = arrays.bin_entry.data();
  MeshSurfaceView<Real> surface{arrays.vertex.data(),         arrays.triangle.data(),  arrays.neighbour.data(),
                                arrays.adjacency_start.data(), arrays.adjacency.data(), arrays.normal.data(), arrays.corner.data(),
                                arrays.patch.data()};
  const int triangles = static_cast<int>(t.mesh.size());
  std::vector<int> all(static_cast<std::size_t>(triangles));
  for (int k = 0; k < triangles; ++k) all[static_cast<std::size_t>(k)] = k;
  std::mt19937_64 rng(3);
  std::normal_distribution<double> g(0, 1);
  std::uniform_real_distribution<double> u(0, 1);
  long compared = 0, differ = 0, touching = 0, overflowed = 0;
  double listed = 0, in_reach = 0;
  for (std::size_t i = 0; i < st.size(); ++i) {
    if (lists[i].size() == 1 && lists[i][0] == -1) {
      ++overflowed;
      continue;
    }
    const Vec3<Real> x = st.position[i];
    int near = 0;  // the triangles within the list's reach (before the flat patches dropped some)
    for (int k = 0; k < triangles; ++k) near += triangle_near(surface, k, x, Real((r + move) * 1.0001));
    listed += static_cast<double>(lists[i].size()), in_reach += near;
    const TriangleList own{lists[i].data(), 1, static_cast<int>(lists[i].size())}, every{all.data(), 1, triangles};
    for (int k = 0; k < 24; ++k) {
      // a displacement of up to `move` (the first at exactly `move`)
      Vec3<double> d{g(rng), g(rng), g(rng)};
      d = d * ((k == 0 ? 1.0 : std::cbrt(u(rng))) * move / norm(d));
      const Vec3<Real> xd = x + vec_cast<Real>(d);
      MeshContacts<Real, 8> a, b;
      collide_sphere_mesh(xd, Real(r), surface, m, static_cast<const Pose<Real>*>(nullptr), a, own);
      collide_sphere_mesh(xd, Real(r), surface, m, static_cast<const Pose<Real>*>(nullptr), b, every);
      bool same = a.count == b.count && a.dropped == b.dropped;
      for (int c = 0; same && c < a.count; ++c) {
        const auto &p = a.contact[c], &q = b.contact[c];
        same = a.owner[c] == b.owner[c] && p.overlap == q.overlap && p.normal.x == q.normal.x && p.normal.y == q.normal.y &&
               p.normal.z == q.normal.z && p.point.x == q.point.x && p.point.y == q.point.y && p.point.z == q.point.z;
      }
      ++compared, differ += !same, touching += b.count > 0;
    }
  }
  const double kept = listed / in_reach;
  BOOST_TEST_MESSAGE("flat patches, " << kind << ": " << compared << " moved spheres (" << touching << " touching) compared, " << differ
                                      << " differ; " << listed / static_cast<double>(st.size()) << " triangles listed per sphere of "
                                      << in_reach / static_cast<double>(st.size()) << " within reach");
  BOOST_TEST_REQUIRE(touching > compared / 4);  // the spheres do lie on the terrace
  BOOST_TEST(overflowed == 0);
  check_at_most({kCase, std::string("contacts from the lists unlike those from all triangles, spheres moved up to skin / 2, ") + kind, "-",
                 "dropped triangles offer nothing: bitwise"},
                static_cast<double>(differ), 0);
  if (spread > 0.5)  // the terrace
    check_at_most({kCase, std::string("triangles listed / triangles within reach, ") + kind, "-",
                   "a flat patch keeps the triangle under the sphere"},
                  kept, tol::flat_patches_listed_fraction);
}

template <class Real>
bool same_states(const ParticleState<Real>& a, const ParticleState<Real>& b) {
  bool same = a.size() == b.size();
  for (std::size_t k = 0; same && k < a.size(); ++k)
    same = a.id[k] == b.id[k] && a.position[k].x == b.position[k].x && a.position[k].y == b.position[k].y &&
           a.position[k].z == b.position[k].z && a.velocity[k].x == b.velocity[k].x && a.angular_velocity[k].y == b.angular_velocity[k].y;
  return same;
}

template <class Real>
void pour_on_and_off(const Motion& motion, double skin_fraction, double most_listed, const std::string& name) {
  const double r = 0.012;
  const Terrace t = terrace(0.2, 0.02, 8);
  World<Real> w;
  w.meshes.push_back({"terrace", t.mesh, 1});
  if (motion.moves()) w.motions = {motion};
  ParticleState<Real> balls;
  for (double x = -0.17; x < 0.171; x += 0.034)
    for (double y = -0.17; y < 0.171; y += 0.034)
      balls.add_sphere(vec_cast<Real>(rotate(t.turn, Vec3<double>{x, y, t.z(x) + 1.5 * r})), Real(r), Real(2500), 0,
                       vec_cast<Real>(Vec3<double>{0.4, -0.2, 0}));
  using Hm = HertzMindlinLaw<Real>;
  const auto hertz = Hertz<Real>::from_restitution(Real(5e7), Real(0.5));
  const Hm hm{hertz, TangentialSpring<Real>::mindlin(0.4, 5e7 / 1.5 / 2.5, 0.5)};
  const Vec3<double> down = rotate(t.turn, Vec3<double>{0.8, 0.3, -9.81});
  std::vector<ParticleState<Real>> out;
  double listed = 0;
  for (WorldLists mode : {WorldLists::on, WorldLists::off}) {
    auto prm = params<Real>(2e-5, down, 0.4, skin_fraction * r);
    prm.world_lists = mode;
    // sums in permanent-id order: a moving world's lists add rebuilds (their validity), and a
    // rebuild's sort would otherwise change the order of the pair sums (rounding), lists or not
    prm.canonical_order = true;
    BallSim<Hm> sim(prm, one_law(hm), w, balls);
    sim.run(12000);
    if (mode == WorldLists::on) {
      listed = sim.world_lists().mean_triangles_listed();
      BOOST_TEST(sim.world_lists().builds() > 2);
      BOOST_TEST(sim.world_lists().triangle_overflowed() == 0);
    }
    out.push_back(sim.state());
  }
  BOOST_TEST_MESSAGE(name << ": " << listed << " triangles listed per ball at the end");
  // dropped in a still world and under translation or vibration (the mesh's frame moves as its
  // surface does), not under rotation (balls beyond its vertices move faster in its frame)
  auto prm = params<Real>(2e-5, down, 0.4, skin_fraction * r);
  BOOST_TEST(BallSim<Hm>(prm, one_law(hm), w, balls).world_lists().drops_flat_patches() == (motion.kind != MotionKind::rotation));
  BOOST_TEST(same_states(out[0], out[1]), name << ": bitwise the same with triangle lists");
  BOOST_TEST((listed > 0.3 && listed < most_listed));
}

}  // namespace

BOOST_AUTO_TEST_SUITE(mesh_flat_patches)

BOOST_AUTO_TEST_CASE(flat_interior_triangles_are_those_of_flat_fans) {
  const Terrace t = terrace(0.2, 0.02, 5);
  const MeshTopology topo = mesh_topology(t.mesh);
  const std::vector<int> code = flat_patches(t.mesh, topo);
  const int n = kTerraceCells;
  long wrong = 0, flat = 0;
  std::vector<int> patch_of_region(3, -1);
  bool one_patch_each = true;
  for (int j = 0; j < n; ++j)
    for (int i = 0; i < n; ++i)
      for (int h = 0; h < 2; ++h) {
        const std::size_t k = static_cast<std::size_t>(2 * (j * n + i) + h);
        // every corner inside one flat region, off the border and the creases
        const bool expect = i >= 1 && i + 1 < n && j >= 1 && j + 1 < n && i + 1 != kFloorEnd && i != kFloorEnd &&
                            i + 1 != kRampEnd && i != kRampEnd;
        wrong += (code[k] >= 0) != expect;
        flat += code[k] >= 0;
        const int region = i < kFloorEnd ? 0 : i < kRampEnd ? 1 : 2;
        const int p = code[k] >= 0 ? code[k] : -1 - code[k];
        if (patch_of_region[static_cast<std::size_t>(region)] < 0) patch_of_region[static_cast<std::size_t>(region)] = p;
        one_patch_each = one_patch_each && patch_of_region[static_cast<std::size_t>(region)] == p;
      }
  BOOST_TEST_MESSAGE("terrace: " << flat << " of " << t.mesh.size() << " triangles flat-interior, " << wrong << " misjudged");
  check_at_most({kCase, "terrace triangles misjudged flat-interior (corners off the border and creases) or not", "-",
                 "fans in one plane, closed"},
                static_cast<double>(wrong), 0);
  BOOST_TEST(one_patch_each);
  BOOST_TEST(patch_of_region[0] != patch_of_region[1]);
  BOOST_TEST(patch_of_region[1] != patch_of_region[2]);
  BOOST_TEST(patch_of_region[0] != patch_of_region[2]);  // parallel planes at different heights
  // A fan of six triangles around a corner is flat there when its angles make one turn (60
  // degrees each), not when they make two (120 degrees each, each ring corner met twice: the
  // fan is closed and in one plane, but it covers the plane twice).
  for (int turns : {1, 2}) {
    TriangleMesh fan;
    fan.vertices.push_back({0, 0, 0});
    for (int k = 0; k < 6; ++k) fan.vertices.push_back({std::cos(kPi * turns * k / 3), std::sin(kPi * turns * k / 3), 0});
    for (int k = 0; k < 6; ++k) fan.triangles.push_back({0, 1 + k, 1 + (k + 1) % 6});
    const MeshTopology ft = mesh_topology(fan);
    const std::vector<char> corners = flat_corners(fan, ft, plane_patches(fan, ft));
    BOOST_TEST((corners[0] != 0) == (turns == 1), "a fan of " << turns << " turn(s): its corner flat");
    BOOST_TEST(std::count(corners.begin() + 1, corners.end(), 0) == 6);  // the ring: the fan's border
  }
}

BOOST_AUTO_TEST_CASE(lists_give_spheres_the_contacts_of_all_triangles) {
  const double r = 0.012;
  const Terrace t = terrace(0.2, 0.02, 5), groove = grooved_floor(0.2, 0.6 * r, r);
  lists_give_the_contacts_of_all_triangles<double>(t, 0.95, "the terrace");
  lists_give_the_contacts_of_all_triangles<float>(t, 0.95, "the terrace");
  lists_give_the_contacts_of_all_triangles<double>(groove, 0.2, "the grooved floor");
  lists_give_the_contacts_of_all_triangles<float>(groove, 0.2, "the grooved floor");
}

BOOST_AUTO_TEST_CASE(balls_on_a_terrace_move_bitwise_the_same_with_lists) {
  pour_on_and_off<double>(Motion{}, 0.3, 4, "balls on the terrace, double, skin 0.3 r");
  pour_on_and_off<float>(Motion{}, 0.3, 4, "balls on the terrace, float, skin 0.3 r");
  Motion shake;
  shake.kind = MotionKind::vibration, shake.amplitude = 1e-3, shake.frequency = 20, shake.direction = {0.2, 0.1, 0.97}, shake.ramp = 0.05;
  pour_on_and_off<double>(shake, 0.5, 10, "balls on the shaken terrace, double, skin 0.5 r");  // a moving mesh: reach r + skin
  Motion turn;
  turn.kind = MotionKind::rotation, turn.axis = {0, 0, 1}, turn.point = {0, 0, 0}, turn.omega = 2, turn.ramp = 0.05;
  pour_on_and_off<double>(turn, 0.5, 12, "balls on the turning terrace, double, skin 0.5 r");
}

BOOST_AUTO_TEST_SUITE_END()
