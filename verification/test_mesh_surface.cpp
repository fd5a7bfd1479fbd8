// A triangle mesh as one contact surface (issue 20; blaze/world/mesh_surface.hpp): a sphere gets
// one contact per point of the surface it touches, whatever the tessellation.
// - Flat: a tilted 1 m square tessellated into 2 x 8 x 8 triangles (normals differing in the last
//   bits) against the same square as one polygon: for spheres anywhere over it, exactly over its
//   edges and vertices included, one contact with the polygon's overlap and normal.
// - Convex closed meshes (a cube: coplanar pairs, convex edges and corners; icospheres): for
//   random centres outside within r of the surface, exactly one contact, at the surface's nearest
//   point (brute force over all triangles), overlap r - distance.
// - A valley (two faces at 120 deg): a sphere touching both gets two face contacts.
// - Bins (blaze/world/mesh_bins.hpp): the cell holding a point lists every triangle within the
//   bins' reach of it (brute force over all triangles; an icosphere and the flat grid, cells from
//   0.4 to 10 times the reach, in double and float lookups); outside the grid no triangle is that
//   close.
// - The early out (a triangle whose edge line keeps the sphere away is left at once) changes no
//   contact: with and without it, bitwise, over crumpled patches from 1e-3 to 1e3 radii large,
//   regular and sliver triangles, near and far from the origin, in double and float.
#include <boost/test/unit_test.hpp>
#include <cmath>
#include <algorithm>
#include <random>
#include "blaze/world/mesh_bins.hpp"
#include "blaze/world/mesh_surface.hpp"
#include "blaze/world/planar_polygon.hpp"
#include "verification/report.hpp"
#include "verification/tolerances.hpp"

using namespace blaze;

namespace {

struct Surface {
  TriangleMesh mesh;
  MeshTopology topo;
  std::vector<Vec3<double>> normals;
  MeshSurfaceView<double> view() const {
    return {mesh.vertices.data(), mesh.triangles.data()->data(), topo.neighbour.data()->data(), topo.adjacency_start.data(),
            topo.adjacency.data(), normals.data()};
  }
  explicit Surface(TriangleMesh m) : mesh(std::move(m)), topo(mesh_topology(mesh)), normals(triangle_normals(mesh)) {}
};

struct Total {
  int contacts = 0;
  double overlap = 0;  // the deepest
  Vec3<double> normal{0, 0, 0}, point{0, 0, 0};
};
// Every triangle's offer, merged as the world kernel merges them.
Total touch(const Surface& s, const Vec3<double>& x, double r) {
  Total t;
  const auto v = s.view();
  MeshContacts<double> set;
  for (std::size_t k = 0; k < s.mesh.size(); ++k) set.add(collide_sphere_mesh_triangle(x, r, v, static_cast<int>(k)), static_cast<int>(k), r);
  t.contacts = set.count;
  for (int k = 0; k < set.count; ++k)
    if (set.contact[k].overlap > t.overlap) t.overlap = set.contact[k].overlap, t.normal = set.contact[k].normal, t.point = set.contact[k].point;
  return t;
}

// Nearest point of triangle (a, b, c) to x, by brute force over a fine barycentric walk refined
// by projection: the exact one from the three edges and the plane.
Vec3<double> nearest_on_triangle(const Vec3<double>& x, const Vec3<double>& a, const Vec3<double>& b, const Vec3<double>& c) {
  const Vec3<double> n0 = cross(b - a, c - a), n = n0 * (1 / norm(n0));
  const Vec3<double> q = x - n * dot(x - a, n);
  const auto inside = [&](const Vec3<double>& p) {
    return dot(cross(b - a, p - a), n) >= 0 && dot(cross(c - b, p - b), n) >= 0 && dot(cross(a - c, p - c), n) >= 0;
  };
  if (inside(q)) return q;
  Vec3<double> best = a;
  for (const auto& [p0, p1] : {std::pair{a, b}, std::pair{b, c}, std::pair{c, a}}) {
    const double u = std::fmin(1, std::fmax(0, dot(x - p0, p1 - p0) / norm2(p1 - p0)));
    const Vec3<double> p = p0 + (p1 - p0) * u;
    if (norm2(x - p) < norm2(x - best)) best = p;
  }
  return best;
}
Vec3<double> nearest_on_mesh(const TriangleMesh& m, const Vec3<double>& x) {
  Vec3<double> best{1e300, 0, 0};
  for (std::size_t t = 0; t < m.size(); ++t) {
    const Vec3<double> p = nearest_on_triangle(x, m.corner(t, 0), m.corner(t, 1), m.corner(t, 2));
    if (norm2(x - p) < norm2(x - best)) best = p;
  }
  return best;
}

// A rotation taking +y to the unit vector u (Rodrigues), applied to points.
Vec3<double> tilt(const Vec3<double>& p) {
  const Vec3<double> axis{0.3, 0.2, 0.9};
  const double angle = 0.37;
  const Vec3<double> k = axis * (1 / norm(axis));
  return p * std::cos(angle) + cross(k, p) * std::sin(angle) + k * (dot(k, p) * (1 - std::cos(angle)));
}

TriangleMesh grid(int cells) {
  TriangleMesh m;
  for (int j = 0; j <= cells; ++j)
    for (int i = 0; i <= cells; ++i) m.vertices.push_back(tilt({-0.5 + double(i) / cells, 0, -0.5 + double(j) / cells}));
  const auto at = [&](int i, int j) { return j * (cells + 1) + i; };
  for (int j = 0; j < cells; ++j)
    for (int i = 0; i < cells; ++i) {
      // counter-clockwise seen from +y (before the tilt): (i, j) -> (i, j + 1) -> (i + 1, j + 1)
      if ((i + j) % 2) {
        m.triangles.push_back({at(i, j), at(i, j + 1), at(i + 1, j + 1)});
        m.triangles.push_back({at(i, j), at(i + 1, j + 1), at(i + 1, j)});
      } else {
        m.triangles.push_back({at(i, j), at(i, j + 1), at(i + 1, j)});
        m.triangles.push_back({at(i + 1, j), at(i, j + 1), at(i + 1, j + 1)});
      }
    }
  return m;
}

TriangleMesh cube_mesh() {
  TriangleMesh m;
  for (int k = 0; k < 8; ++k) m.vertices.push_back({double(k & 1) - 0.5, double((k >> 1) & 1) - 0.5, double((k >> 2) & 1) - 0.5});
  const int quads[6][4] = {{0, 2, 3, 1}, {4, 5, 7, 6}, {0, 1, 5, 4}, {2, 6, 7, 3}, {0, 4, 6, 2}, {1, 3, 7, 5}};
  for (const auto& q : quads) m.triangles.push_back({q[0], q[1], q[2]}), m.triangles.push_back({q[0], q[2], q[3]});
  return m;
}

TriangleMesh icosphere(int levels) {
  const double t = (1 + std::sqrt(5.0)) / 2;
  TriangleMesh m;
  for (const auto& v : std::vector<Vec3<double>>{{-1, t, 0}, {1, t, 0}, {-1, -t, 0}, {1, -t, 0}, {0, -1, t}, {0, 1, t},
                                                 {0, -1, -t}, {0, 1, -t}, {t, 0, -1}, {t, 0, 1}, {-t, 0, -1}, {-t, 0, 1}})
    m.vertices.push_back(v * (1 / norm(v)));
  m.triangles = {{0, 11, 5}, {0, 5, 1},  {0, 1, 7},   {0, 7, 10}, {0, 10, 11}, {1, 5, 9}, {5, 11, 4}, {11, 10, 2}, {10, 7, 6}, {7, 1, 8},
                 {3, 9, 4},  {3, 4, 2},  {3, 2, 6},   {3, 6, 8},  {3, 8, 9},   {4, 9, 5}, {2, 4, 11}, {6, 2, 10},  {8, 6, 7},  {9, 8, 1}};
  for (int l = 0; l < levels; ++l) {
    std::map<std::pair<int, int>, int> mid;
    const auto middle = [&](int a, int b) {
      const auto key = std::make_pair(std::min(a, b), std::max(a, b));
      const auto it = mid.find(key);
      if (it != mid.end()) return it->second;
      const Vec3<double> v = m.vertices[static_cast<std::size_t>(a)] + m.vertices[static_cast<std::size_t>(b)];
      m.vertices.push_back(v * (1 / norm(v)));
      return mid[key] = static_cast<int>(m.vertices.size()) - 1;
    };
    std::vector<std::array<int, 3>> next;
    for (const auto& tr : m.triangles) {
      const int a = middle(tr[0], tr[1]), b = middle(tr[1], tr[2]), c = middle(tr[2], tr[0]);
      next.push_back({tr[0], a, c}), next.push_back({tr[1], b, a}), next.push_back({tr[2], c, b}), next.push_back({a, b, c});
    }
    m.triangles = next;
  }
  return m;
}

}  // namespace

BOOST_AUTO_TEST_SUITE(mesh_surface)

BOOST_AUTO_TEST_CASE(a_flat_tessellation_pushes_as_one_polygon) {
  const int cells = 8;
  const Surface s(grid(cells));
  const auto square = PlanarPolygon<double>::make({tilt({-0.5, 0, -0.5}), tilt({-0.5, 0, 0.5}), tilt({0.5, 0, 0.5}), tilt({0.5, 0, -0.5})}, 0);
  BOOST_TEST_REQUIRE(dot(square.normal, tilt({0, 1, 0})) > 0.999999);
  std::mt19937_64 rng(3);
  std::uniform_real_distribution<double> u(-0.4, 0.4), h(0.001, 0.099);
  const double r = 0.1;
  long samples = 0, wrong_count = 0;
  double worst = 0;
  for (int k = 0; k < 6000; ++k) {
    double a = u(rng), b = u(rng);
    if (k % 3 == 1) a = std::round(a * cells) / cells;            // over a grid line
    if (k % 3 == 2) a = std::round(a * cells) / cells, b = std::round(b * cells) / cells;  // over a vertex
    if (k % 5 == 0) b = a + (std::round((b - a) * cells) / cells);  // over a diagonal (some are edges)
    const Vec3<double> x = tilt({a, h(rng), b});
    const auto ref = collide_sphere(x, r, square);
    const Total t = touch(s, x, r);
    ++samples;
    wrong_count += t.contacts != 1;
    if (t.contacts == 1) worst = std::fmax(worst, std::fmax(std::fabs(t.overlap - ref.overlap) / ref.overlap, norm(t.normal - ref.normal)));
  }
  BOOST_TEST_MESSAGE("flat tessellation: " << samples << " spheres, " << wrong_count << " without exactly one contact, worst difference "
                                            << worst);
  BOOST_TEST(wrong_count == 0);
  BOOST_TEST(worst < tol::mesh_flat_as_polygon);
}

BOOST_AUTO_TEST_CASE(a_convex_mesh_is_touched_once_at_its_nearest_point) {
  std::mt19937_64 rng(5);
  for (int which = 0; which < 3; ++which) {
    const Surface s(which == 0 ? cube_mesh() : icosphere(which));
    const double r = which == 0 ? 0.2 : 0.15;
    std::uniform_real_distribution<double> u(-0.5 - r, 0.5 + r), w(-1 - r, 1 + r);
    long tested = 0, wrong_count = 0;
    double worst = 0;
    while (tested < 3000) {
      const Vec3<double> x = which == 0 ? Vec3<double>{u(rng), u(rng), u(rng)} : Vec3<double>{w(rng), w(rng), w(rng)};
      // outside: in front of some face
      bool outside = false;
      for (std::size_t f = 0; f < s.mesh.size(); ++f) outside |= dot(x - s.mesh.corner(f, 0), s.mesh.area_vector(f)) > 0;
      if (!outside) continue;
      const Vec3<double> p = nearest_on_mesh(s.mesh, x);
      const double dist = norm(x - p);
      if (!(dist < r)) continue;
      ++tested;
      const Total t = touch(s, x, r);
      wrong_count += t.contacts != 1;
      if (t.contacts == 1) worst = std::fmax(worst, std::fmax(std::fabs(t.overlap - (r - dist)) / r, norm(t.normal - (p - x) * (1 / dist))));
    }
    BOOST_TEST_MESSAGE((which == 0 ? "cube" : "icosphere") << ": " << tested << " spheres, " << wrong_count
                                                          << " without exactly one contact, worst difference " << worst);
    BOOST_TEST(wrong_count == 0, which);
    BOOST_TEST(worst < tol::mesh_nearest_point, which);
  }
}

BOOST_AUTO_TEST_CASE(a_valley_touches_with_both_faces) {
  TriangleMesh m;  // two faces meeting at the z axis at 120 deg, opening upwards (+y)
  const double c = std::cos(3.14159265358979 / 6), sn = std::sin(3.14159265358979 / 6);
  m.vertices = {{0, 0, -1}, {0, 0, 1}, {-c, sn, -1}, {-c, sn, 1}, {c, sn, -1}, {c, sn, 1}};
  m.triangles = {{0, 3, 1}, {0, 2, 3}, {0, 5, 4}, {0, 1, 5}};
  const Surface s(m);
  for (double y : {0.06, 0.09, 0.11}) {
    const Total t = touch(s, {0, y, 0}, 0.1);
    // distance to each face: y sin(60 deg)
    BOOST_TEST(t.contacts == 2, y);
    BOOST_TEST(std::fabs(t.overlap - (0.1 - y * std::sin(3.14159265358979 / 3))) < tol::mesh_valley_overlap, y);
  }
}

BOOST_AUTO_TEST_CASE(bins_list_every_triangle_within_reach) {
  std::mt19937_64 rng(9);
  for (int which = 0; which < 2; ++which) {
    const TriangleMesh m = which == 0 ? icosphere(3) : grid(8);
    for (double cell : {0.02, 0.1, 0.5}) {
      const double reach = 0.05;
      const MeshBinsHost b = bin_mesh(m, reach, cell);
      const MeshBinsView<double> vd{b.origin, 1 / b.cell, b.nx, b.ny, b.nz, b.start.data(), b.entry.data()};
      const MeshBinsView<float> vf{vec_cast<float>(b.origin), float(1 / b.cell), b.nx, b.ny, b.nz, b.start.data(), b.entry.data()};
      std::uniform_real_distribution<double> u(-1.2, 1.2);
      long missing = 0, listed = 0, near = 0, outside_near = 0;
      for (int k = 0; k < 4000; ++k) {
        const Vec3<double> x{u(rng), which == 0 ? u(rng) : 0.3 * u(rng), u(rng)};
        int f0, f1, g0, g1;
        vd.cell_of(x, f0, f1);
        vf.cell_of(vec_cast<float>(x), g0, g1);
        listed += f1 - f0;
        for (std::size_t t = 0; t < m.size(); ++t) {
          if (!(norm(x - nearest_on_triangle(x, m.corner(t, 0), m.corner(t, 1), m.corner(t, 2))) < 0.999 * reach)) continue;
          ++near;
          if (f1 == f0) ++outside_near;
          const bool in_d = std::find(b.entry.begin() + f0, b.entry.begin() + f1, static_cast<int>(t)) != b.entry.begin() + f1;
          const bool in_f = std::find(b.entry.begin() + g0, b.entry.begin() + g1, static_cast<int>(t)) != b.entry.begin() + g1;
          missing += !in_d + !in_f;
        }
      }
      BOOST_TEST_MESSAGE("bins, " << (which == 0 ? "icosphere" : "grid") << ", cell " << b.cell << " m: " << b.nx * b.ny * b.nz
                                  << " cells, at most " << b.longest << " triangles in one, " << double(listed) / 4000
                                  << " listed per point; " << near << " triangles within reach, " << missing << " missing");
      BOOST_TEST(near > 100);
      BOOST_TEST(missing == 0);
      BOOST_TEST(outside_near == 0);
    }
  }
}

BOOST_AUTO_TEST_CASE(the_early_out_changes_no_contact) {
  // A 3 x 3 grid patch (18 triangles: open rims, convex and concave edges and vertices once its
  // vertices are shaken off the plane), stretched to slivers and scaled from 1e-3 to 1e3 sphere
  // radii, placed at the origin or 1e3 sizes away; spheres anywhere within 2 r of it.
  std::mt19937_64 rng(21);
  long compared = 0, left_early = 0, left_near_r = 0, touching = 0, differ = 0;
  const auto same = [](const auto& a, const auto& b) {
    if (a.touching != b.touching) return false;
    if (!a.touching) return true;
    return a.overlap == b.overlap && a.normal.x == b.normal.x && a.normal.y == b.normal.y && a.normal.z == b.normal.z &&
           a.point.x == b.point.x && a.point.y == b.point.y && a.point.z == b.point.z && a.r_eff == b.r_eff;
  };
  for (int patch = 0; patch < 48; ++patch) {
    const double size = std::pow(10.0, -3.0 + 6.0 * (patch % 8) / 7.0), stretch = patch % 3 == 0 ? 40 : 1;
    const double shake = (patch / 8) % 3 == 0 ? 0 : 0.15;
    const Vec3<double> offset = (patch / 24) ? Vec3<double>{1e3 * size, -7e2 * size, 3e2 * size} : Vec3<double>{0, 0, 0};
    TriangleMesh m = grid(3);
    std::uniform_real_distribution<double> jiggle(-shake, shake);
    for (auto& v : m.vertices) v = Vec3<double>{v.x * stretch, v.y + jiggle(rng) / 3, v.z} * size + offset;
    const Surface s(m);
    std::vector<Vec3<float>> vf, nf;
    for (const auto& v : m.vertices) vf.push_back(vec_cast<float>(v));
    for (const auto& n : s.normals) nf.push_back(vec_cast<float>(n));
    const MeshSurfaceView<double> vd = s.view();
    const MeshSurfaceView<float> vff{vf.data(), vd.triangle, vd.neighbour, vd.adjacency_start, vd.adjacency, nf.data()};
    const double r = 1.0;
    std::uniform_real_distribution<double> across(-0.6 * size * stretch - 2 * r, 0.6 * size * stretch + 2 * r),
        along(-0.6 * size - 2 * r, 0.6 * size + 2 * r), up(-2 * r, 2 * r);
    for (int k = 0; k < 3000; ++k) {
      const Vec3<double> x = tilt({across(rng), up(rng), along(rng)}) + offset;
      for (int t = 0; t < static_cast<int>(m.size()); ++t) {
        const auto a = collide_sphere_mesh_triangle<double, true>(x, r, vd, t);
        const auto b = collide_sphere_mesh_triangle<double, false>(x, r, vd, t);
        const auto af = collide_sphere_mesh_triangle<float, true>(vec_cast<float>(x), float(r), vff, t);
        const auto bf = collide_sphere_mesh_triangle<float, false>(vec_cast<float>(x), float(r), vff, t);
        compared += 2;
        differ += !same(a, b) + !same(af, bf);
        touching += b.touching + bf.touching;
        // How often it left early, and how close to r: the distance to the triangle.
        const Vec3<double> p = nearest_on_triangle(x, m.corner(static_cast<std::size_t>(t), 0), m.corner(static_cast<std::size_t>(t), 1),
                                                   m.corner(static_cast<std::size_t>(t), 2));
        const double dist = norm(x - p), d = dot(x - m.corner(static_cast<std::size_t>(t), 0), s.normals[static_cast<std::size_t>(t)]);
        if (std::fabs(d) < r && dist > r) {  // past the plane test, no contact: the early out's cases
          ++left_early;
          left_near_r += dist < 1.01 * r;
        }
      }
    }
  }
  BOOST_TEST_MESSAGE("early out: " << compared << " sphere-triangle tests (" << touching << " touching), " << left_early
                                   << " within the plane's reach but not the triangle's (" << left_near_r << " within 1.01 r), "
                                   << differ << " different");
  BOOST_TEST(touching > 10000);
  BOOST_TEST(left_near_r > 1000);
  test::check_at_most({"Mesh surface (issue 20)", "sphere-triangle tests whose contact the early out changes (double and float)", "-",
                       "blaze/world/mesh_surface.hpp: a lower bound of the distance"},
                      static_cast<double>(differ), tol::mesh_early_out_changes);
}

BOOST_AUTO_TEST_SUITE_END()
