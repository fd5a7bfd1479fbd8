// Polyhedron contact detection (issue 3, acceptance 3): the kernel's separating-axis collide()
// against the brute-force reference, on 10^5 random pairs of every combination of the shipped
// shapes at random orientations near contact (centre distance between the sum of the inradii and
// the sum of the bounding radii): no missed contact deeper than 1e-6 of the size, no false
// contact, the same overlap, and normals within 1 degree where the reference defines one (its
// least-penetration axis is shallower than every other axis by more than rounding).
#include <boost/test/unit_test.hpp>
#include <random>
#include "blaze/contact/polyhedron.hpp"
#include "blaze/shapes/shape_io.hpp"
#include "verification/reference_sat.hpp"
#include "verification/tolerances.hpp"

using namespace blaze;
using namespace blaze::test;

namespace {

const char* kShapes[] = {"cube", "box", "tetrahedron", "octahedron", "icosahedron", "dodecahedron", "prism", "corn"};

Eigen::Quaterniond random_rotation(std::mt19937_64& rng) {
  std::normal_distribution<double> g;
  Eigen::Quaterniond q(g(rng), g(rng), g(rng), g(rng));
  return q.normalized();
}

double inradius(const ConvexShape& s) {
  double r = 1e300;
  for (std::size_t f = 0; f < s.faces.size(); ++f) r = std::min(r, s.normals[f].dot(s.centroids[f]));
  return r;
}

struct Tally {
  long pairs = 0, touching = 0, missed = 0, false_contacts = 0, depth_off = 0, normals_checked = 0, normals_off = 0;
  double worst_angle = 0;
};

}  // namespace

BOOST_AUTO_TEST_SUITE(polyhedron_contact)

BOOST_AUTO_TEST_CASE(agrees_with_brute_force_separating_axes) {
  std::vector<ConvexShape> shapes;
  for (const char* f : kShapes) shapes.push_back(load_shape(std::string("data/shapes/") + f + ".shape"));
  const int n_shapes = static_cast<int>(shapes.size());
  Tally total;
  for (int ta = 0; ta < n_shapes; ++ta)
    for (int tb = ta; tb < n_shapes; ++tb) {
      PolyhedronShape<double> shape;
      shape.table.add(shapes[ta], 1000);
      shape.table.add(shapes[tb], 1000);
      const ConvexShape &a = shapes[ta], &b = shapes[tb];
      const double size = a.bounding_radius + b.bounding_radius;
      const double d_min = inradius(a) + inradius(b), d_max = size;
      Tally t;
#pragma omp parallel
      {
        Tally mine;
        auto& t_ = mine;
#pragma omp for schedule(static)
        for (int k = 0; k < static_cast<int>(tol::contact_pairs_per_combination); ++k) {
          std::mt19937_64 rng(1000003ull * (100 * ta + tb) + static_cast<unsigned long long>(k));  // per pair: thread-count independent
          std::uniform_real_distribution<double> u(0, 1);
          std::normal_distribution<double> g;
          const Eigen::Quaterniond qa = random_rotation(rng), qb = random_rotation(rng);
          Eigen::Vector3d dir(g(rng), g(rng), g(rng));
          dir.normalize();
          const Eigen::Vector3d xa(0.3 * (u(rng) - 0.5), 0.3 * (u(rng) - 0.5), 0.3 * (u(rng) - 0.5));
          const Eigen::Vector3d xb = xa + (d_min + (d_max - d_min) * u(rng)) * dir;
          const auto ref = reference_contact(a, xa, qa.toRotationMatrix(), b, xb, qb.toRotationMatrix());
          const PolyhedronShape<double>::Body ba{{xa.x(), xa.y(), xa.z()}, {qa.w(), qa.x(), qa.y(), qa.z()}, 0, 0};
          const PolyhedronShape<double>::Body bb{{xb.x(), xb.y(), xb.z()}, {qb.w(), qb.x(), qb.y(), qb.z()}, 1, 1};
          const auto c = shape.collide(ba, bb);
          ++t_.pairs;
          t_.touching += c.touching;
          if (ref.touching && -ref.separation > tol::contact_missed_depth * size && !c.touching) ++t_.missed;
          if (c.touching && ref.separation > tol::contact_false_gap * size) ++t_.false_contacts;
          if (c.touching && ref.touching &&
              std::fabs(c.overlap + ref.separation) > tol::contact_axis_tie * size + tol::contact_false_gap * size)
            ++t_.depth_off;
          // The reference defines the normal when its axis beats all others by more than rounding.
          if (c.touching && ref.touching && ref.second - (-ref.separation) > 2 * tol::contact_axis_tie * size) {
            ++t_.normals_checked;
            const double cosine = c.normal.x * ref.normal.x() + c.normal.y * ref.normal.y() + c.normal.z * ref.normal.z();
            const double angle = std::acos(std::min(1.0, cosine)) * 180 / 3.14159265358979323846;
            t_.worst_angle = std::max(t_.worst_angle, angle);
            if (angle > tol::contact_normal_degrees) ++t_.normals_off;
          }
        }
#pragma omp critical
        {
          t.pairs += mine.pairs, t.touching += mine.touching, t.missed += mine.missed;
          t.false_contacts += mine.false_contacts, t.depth_off += mine.depth_off;
          t.normals_checked += mine.normals_checked, t.normals_off += mine.normals_off;
          t.worst_angle = std::max(t.worst_angle, mine.worst_angle);
        }
      }
      BOOST_TEST_CONTEXT(kShapes[ta] << "-" << kShapes[tb] << ": " << t.pairs << " pairs, " << t.touching
                                     << " touching, " << t.normals_checked << " normals checked") {
        BOOST_TEST(t.missed == 0);
        BOOST_TEST(t.false_contacts == 0);
        BOOST_TEST(t.depth_off == 0);
        BOOST_TEST(t.normals_off == 0);
        BOOST_TEST(t.touching > t.pairs / 10);  // the sample does reach contact
      }
      total.pairs += t.pairs;
      total.touching += t.touching;
      total.normals_checked += t.normals_checked;
      total.worst_angle = std::max(total.worst_angle, t.worst_angle);
    }
  BOOST_TEST_MESSAGE("polyhedron contact vs reference: " << total.pairs << " pairs, " << total.touching << " touching, "
                                                         << total.normals_checked << " normals checked, worst angle "
                                                         << total.worst_angle << " deg");
}

BOOST_AUTO_TEST_SUITE_END()
