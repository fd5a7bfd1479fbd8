// World geometry: planar polygon containment and rim contact (thesis section 3.2.4), seams
// between coplanar plates, the internal cylinder, and input validation.
#include <boost/test/unit_test.hpp>
#include "verification/scenes.hpp"

using namespace blaze;
using namespace blaze::test;
using V = Vec3<double>;

BOOST_AUTO_TEST_SUITE(world_contact)

BOOST_AUTO_TEST_CASE(polygon_normal_and_centroid_are_derived) {
  const auto p = PlanarPolygon<double>::make({{0, 0, 0}, {2, 0, 0}, {2, 1, 0}, {0, 1, 0}}, 0);
  BOOST_TEST(p.normal.z == 1.0);
  BOOST_TEST(p.centroid.x == 1.0);
  BOOST_TEST(p.centroid.y == 0.5);
}

BOOST_AUTO_TEST_CASE(face_contact_inside_the_polygon) {
  const auto floor = floor_square<double>(0.0, 1.0);
  const auto g = collide_sphere(V{0.3, 0.4, -0.2}, 0.5, floor);
  BOOST_TEST(g.touching);
  BOOST_TEST(g.overlap == 0.1, boost::test_tools::tolerance(tol::geometry_double));
  BOOST_TEST(g.normal.y == -1.0);  // from the particle into the wall
  BOOST_TEST(g.r_eff == 0.5);
}

BOOST_AUTO_TEST_CASE(no_contact_beyond_the_edges_behind_or_above) {
  const auto floor = floor_square<double>(0.0, 1.0, 0);
  const auto inactive = PlanarPolygon<double>::make({{-1, 0, 1}, {1, 0, 1}, {1, 0, -1}, {-1, 0, -1}}, 0, 0u);
  BOOST_TEST(!collide_sphere(V{1.6, 0.1, 0}, 0.5, floor).touching);   // beyond the rim, out of reach
  BOOST_TEST(!collide_sphere(V{1.2, 0.1, 0}, 0.5, inactive).touching); // over an inactive edge
  BOOST_TEST(!collide_sphere(V{0, -0.1, 0}, 0.5, floor).touching);    // centre behind the wall
  BOOST_TEST(!collide_sphere(V{0, 0.6, 0}, 0.5, floor).touching);     // above
}

BOOST_AUTO_TEST_CASE(rim_contact_at_an_active_edge) {
  const auto floor = floor_square<double>(0.0, 1.0);
  // Centre beside the edge x = 1, level with the plate: touches the rim sideways.
  const auto g = collide_sphere(V{1.3, 0.0, 0.2}, 0.5, floor);
  BOOST_TEST(g.touching);
  BOOST_TEST(g.overlap == 0.2, boost::test_tools::tolerance(tol::geometry_double));
  BOOST_TEST(g.normal.x == -1.0, boost::test_tools::tolerance(tol::geometry_double));
  // Centre slightly below the plane still touches the rim (a plate's rim is two-sided).
  BOOST_TEST(collide_sphere(V{1.3, -0.1, 0.2}, 0.5, floor).touching);
}

// A sphere resting across the seam of two coplanar plates must feel one floor, not two.
BOOST_AUTO_TEST_CASE(seam_between_coplanar_plates_pushes_once) {
  const std::uint32_t all_but_edge1 = ~(1u << 1), all_but_edge3 = ~(1u << 3);
  // Left plate x in [-1, 0], right plate x in [0, 1]; edge 1 of the left and edge 3 of the right is the seam.
  const auto left = PlanarPolygon<double>::make({{-1, 0, 1}, {0, 0, 1}, {0, 0, -1}, {-1, 0, -1}}, 1, all_but_edge1);
  const auto right = PlanarPolygon<double>::make({{0, 0, 1}, {1, 0, 1}, {1, 0, -1}, {0, 0, -1}}, 1, all_but_edge3);
  const V x{-0.05, 0.45, 0};
  const auto gl = collide_sphere(x, 0.5, left), gr = collide_sphere(x, 0.5, right);
  BOOST_TEST(gl.touching);
  BOOST_TEST(!gr.touching);
}

BOOST_AUTO_TEST_CASE(cylinder_inside_contact) {
  const auto drum = Cylinder<double>::make({0, 0, 0}, {0, 0, 2}, 1.0, 1.0, 0);
  const auto g = collide_sphere(V{0, -0.7, 0.5}, 0.4, drum);
  BOOST_TEST(g.touching);
  BOOST_TEST(g.overlap == 0.1, boost::test_tools::tolerance(tol::geometry_double));
  BOOST_TEST(g.normal.y == -1.0);
  BOOST_TEST(g.r_eff == 0.4 * 1.0 / 0.6, boost::test_tools::tolerance(tol::geometry_double));
  BOOST_TEST(!collide_sphere(V{0, -0.5, 0.5}, 0.4, drum).touching);  // clear of the wall
  BOOST_TEST(!collide_sphere(V{0, -0.7, 1.5}, 0.4, drum).touching);  // past the end
}

BOOST_AUTO_TEST_CASE(bad_polygons_are_rejected_with_the_defect) {
  auto message_of = [](auto&& f) {
    try {
      f();
    } catch (const std::invalid_argument& e) {
      return std::string(e.what());
    }
    return std::string();
  };
  BOOST_TEST(message_of([] { PlanarPolygon<double>::make({{0, 0, 0}, {1, 0, 0}}, 0); }).find("3 to 8 vertices") != std::string::npos);
  BOOST_TEST(message_of([] { PlanarPolygon<double>::make({{0, 0, 0}, {1, 0, 0}, {2, 0, 0}}, 0); }).find("zero area") != std::string::npos);
  BOOST_TEST(message_of([] { PlanarPolygon<double>::make({{0, 0, 0}, {1, 0, 0}, {1, 1, 0.5}, {0, 1, 0}}, 0); }).find("off the plane") != std::string::npos);
  BOOST_TEST(message_of([] { PlanarPolygon<double>::make({{0, 0, 0}, {2, 0, 0}, {1, 0.2, 0}, {2, 2, 0}, {0, 2, 0}}, 0); }).find("not convex") != std::string::npos);
  BOOST_TEST(message_of([] { Cylinder<double>::make({0, 0, 0}, {0, 0, 0}, 1, 1, 0); }).find("axis") != std::string::npos);
}

// A contact law must exist for every material pair the scene can bring together.
BOOST_AUTO_TEST_CASE(missing_material_pair_is_an_error) {
  ParticleState<double> s;
  s.add_sphere({0, 0.1, 0}, 0.01, 2500, 0);
  World<double> w;
  w.polygons.push_back(floor_square<double>(0.0, 1.0, 3));
  PairTable<LinearLaw<double>> t;
  t.set(0, 0, {LinearSpringDashpot<double>::from_restitution(1e5, 0.5), HistoryFreeFriction<double>::make(0.3, 1)});
  BOOST_CHECK_EXCEPTION((SphereSim<LinearLaw<double>>(params<double>(1e-6), t, w, s)), std::invalid_argument,
                        [](const std::invalid_argument& e) { return std::string(e.what()).find("(0, 3)") != std::string::npos; });
}

BOOST_AUTO_TEST_SUITE_END()
