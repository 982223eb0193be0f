#include "grpvss/exact/circumscribed_shapes.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <random>
#include <set>
#include <stdexcept>
#include <tuple>

#include <boost/multiprecision/cpp_int.hpp>

#include "grpvss/exact/convex_polytope.hpp"
#include "grpvss/exact/shape_containment.hpp"
#include "support/angles.hpp"
#include "support/geometry_reference.hpp"

namespace grpvss::geometry {
namespace {

using Q = boost::multiprecision::cpp_rational;
using grpvss::test::kPi;

/// Exact (cpp_rational) max over vertices of x^2 + y^2 (with_z: + z^2).
Q max_square_radius(const std::vector<Eigen::Vector3d>& vertices, bool with_z) {
  Q best = 0;
  for (const auto& v : vertices) {
    Q s = Q(v.x()) * Q(v.x()) + Q(v.y()) * Q(v.y());
    if (with_z) s += Q(v.z()) * Q(v.z());
    if (s > best) best = s;
  }
  return best;
}

TEST(CircumscribedBox, IsExactlyTheEightCornersAndNothingLarger) {
  const Eigen::Vector3d size(0.3, 1.25, 2.0);
  const auto corners = circumscribed_box(size);
  std::set<std::tuple<double, double, double>> got;
  for (const auto& v : corners) got.emplace(v.x(), v.y(), v.z());
  std::set<std::tuple<double, double, double>> expected;
  for (double x : {-0.15, 0.15}) {
    for (double y : {-0.625, 0.625}) {
      for (double z : {-1.0, 1.0}) expected.emplace(x, y, z);
    }
  }
  EXPECT_EQ(got, expected);
  const ConvexPolytope box = ConvexPolytope::from_points(corners);
  EXPECT_TRUE(box_inside_exactly(box, size));
  // Tight: any larger box pokes out.
  EXPECT_FALSE(box_inside_exactly(box, Eigen::Vector3d(0.3, 1.25, std::nextafter(2.0, 3.0))));
  EXPECT_THROW(circumscribed_box(Eigen::Vector3d(1, 0, 1)), std::invalid_argument);
  EXPECT_THROW(circumscribed_box(Eigen::Vector3d(1, 2e6, 1)), std::invalid_argument);
}

TEST(CircumscribedCylinder, SideCountFollowsTheOvershoot) {
  // Smallest multiple of 4 with 1/cos(pi/n) - 1 <= eps: 4 (0.414), 8 (0.082), 24 (0.0086),
  // 72 (0.00095).
  EXPECT_EQ(cylinder_polygon_sides(1.0), 4);
  EXPECT_EQ(cylinder_polygon_sides(0.1), 8);
  EXPECT_EQ(cylinder_polygon_sides(0.01), 24);
  EXPECT_EQ(cylinder_polygon_sides(0.001), 72);
  EXPECT_THROW(cylinder_polygon_sides(1e-4), std::invalid_argument);
  EXPECT_THROW(cylinder_polygon_sides(2.0), std::invalid_argument);
  EXPECT_THROW(cylinder_polygon_sides(std::nan("")), std::invalid_argument);
}

TEST(CircumscribedCylinder, ContainsTheCylinderWithTheStatedOvershootExactly) {
  for (const auto& [r, l] : {std::pair{0.05, 0.2}, {1.0, 3.0}, {37.5, 0.001}}) {
    const auto vertices = circumscribed_cylinder(r, l, 0.01);
    ASSERT_EQ(vertices.size(), 48u);
    for (const auto& v : vertices) EXPECT_TRUE(v.z() == l / 2 || v.z() == -l / 2);
    const ConvexPolytope prism = ConvexPolytope::from_points(vertices);
    EXPECT_EQ(prism.faces().size(), 26u);  // 24 sides + 2 caps
    EXPECT_TRUE(cylinder_inside_exactly(prism, r, l));
    // Overshoot between 1/cos(7.5 deg) - 1 = 0.0086289 and 1%, in exact arithmetic here.
    const Q rr = Q(r) * Q(r);
    EXPECT_LE(max_square_radius(vertices, false), rr * Q(101) * Q(101) / 10000);
    EXPECT_GE(max_square_radius(vertices, false), rr * Q(100862) * Q(100862) / Q(10000000000LL));
    // Tight: a slightly wider or longer cylinder does not fit.
    EXPECT_FALSE(cylinder_inside_exactly(prism, r * (1 + 1e-9), l));
    EXPECT_FALSE(cylinder_inside_exactly(prism, r, std::nextafter(l, 1e9)));
  }
}

TEST(CircumscribedCylinder, IsSymmetricUnderTheSquaresSymmetries) {
  const auto vertices = circumscribed_cylinder(2.0, 1.0, 0.001);
  std::set<std::tuple<double, double, double>> set;
  for (const auto& v : vertices) set.emplace(v.x(), v.y(), v.z());
  for (const auto& v : vertices) {
    EXPECT_TRUE(set.count({-v.x(), v.y(), v.z()}));
    EXPECT_TRUE(set.count({v.x(), -v.y(), v.z()}));
    EXPECT_TRUE(set.count({v.y(), v.x(), v.z()}));
  }
  EXPECT_EQ(vertices.size(), 144u);
}

TEST(CircumscribedCylinder, SampledCylinderPointsAreInsideByAnIndependentHull) {
  std::mt19937_64 rng(7);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  const double r = 0.8, l = 2.5;
  const auto vertices = circumscribed_cylinder(r, l, 0.05);
  testing::Points samples;
  for (int i = 0; i < 400; ++i) {
    // Rim points (the worst case) and interior points.
    const double angle = 2 * kPi * unit(rng);
    const double rho = (i % 2 == 0) ? r * (1 - 1e-12) : r * std::sqrt(unit(rng));
    const double z = (i % 4 == 0) ? l / 2 : l * (unit(rng) - 0.5);
    samples.emplace_back(rho * std::cos(angle), rho * std::sin(angle), z);
  }
  // The tangent points of the side faces, exactly on the circle: angles 2 pi k / n.
  samples.emplace_back(r, 0.0, l / 2);
  samples.emplace_back(0.0, -r, -l / 2);
  EXPECT_EQ(testing::count_points_outside_hull_exactly(vertices, samples), 0);
}

TEST(CircumscribedSphere, FrequencyFollowsTheOvershoot) {
  EXPECT_EQ(sphere_subdivision_frequency(1.0), 1);   // icosahedron: 0.258
  EXPECT_EQ(sphere_subdivision_frequency(0.1), 2);   // 0.070
  EXPECT_EQ(sphere_subdivision_frequency(0.01), 6);  // 0.0079
  EXPECT_EQ(sphere_subdivision_frequency(0.001), 18);
  EXPECT_THROW(sphere_subdivision_frequency(5e-4), std::invalid_argument);
}

TEST(CircumscribedSphere, ContainsTheBallWithTheStatedOvershootExactly) {
  for (const double r : {0.01, 1.0, 250.0}) {
    const auto vertices = circumscribed_sphere(r, 0.01);
    EXPECT_EQ(vertices.size(), 362u);  // 10 nu^2 + 2, nu = 6
    const ConvexPolytope p = ConvexPolytope::from_points(vertices);
    EXPECT_TRUE(sphere_inside_exactly(p, r));
    EXPECT_TRUE(testing::reference_contains_ball_sum(vertices, {Eigen::Vector3d::Zero()}, r));
    const Q rr = Q(r) * Q(r);
    EXPECT_LE(max_square_radius(vertices, true), rr * Q(101) * Q(101) / 10000);
    EXPECT_GE(max_square_radius(vertices, true), rr * Q(1007) * Q(1007) / 1000000);
    EXPECT_FALSE(sphere_inside_exactly(p, r * (1 + 1e-9)));
  }
}

TEST(CircumscribedSphere, SampledBallPointsAreInsideByAnIndependentHull) {
  std::mt19937_64 rng(11);
  std::normal_distribution<double> gauss(0.0, 1.0);
  const double r = 3.0;
  const auto vertices = circumscribed_sphere(r, 0.1);
  EXPECT_EQ(vertices.size(), 42u);
  testing::Points samples;
  for (int i = 0; i < 400; ++i) {
    Eigen::Vector3d d(gauss(rng), gauss(rng), gauss(rng));
    samples.push_back(d.normalized() * r * (1 - 1e-12));  // on the sphere
  }
  EXPECT_EQ(testing::count_points_outside_hull_exactly(vertices, samples), 0);
  EXPECT_THROW(circumscribed_sphere(0.0), std::invalid_argument);
  EXPECT_THROW(circumscribed_sphere(std::nan("")), std::invalid_argument);
}

// The shapes are kept per process by their arguments: a second call returns exactly what a
// fresh build (with its exact check) returns, and invalid arguments are refused before any
// lookup (a NaN overshoot must not match a kept entry).
TEST(CircumscribedShapes, KeptResultsAreTheFreshBuildsAndBadArgumentsStillThrow) {
  for (int round = 0; round < 2; ++round) {
    EXPECT_EQ(circumscribed_sphere(0.09, 0.01), build_circumscribed_sphere(0.09, 0.01));
    EXPECT_EQ(circumscribed_sphere(0.055, 0.1), build_circumscribed_sphere(0.055, 0.1));
    EXPECT_EQ(circumscribed_cylinder(0.04, 1.2, 0.01), build_circumscribed_cylinder(0.04, 1.2, 0.01));
    EXPECT_EQ(circumscribed_cylinder(0.04, 0.6, 0.01), build_circumscribed_cylinder(0.04, 0.6, 0.01));
  }
  EXPECT_NE(circumscribed_cylinder(0.04, 1.2, 0.01), circumscribed_cylinder(0.04, 0.6, 0.01));
  EXPECT_THROW(circumscribed_cylinder(0.04, 1.2, std::nan("")), std::invalid_argument);
  EXPECT_THROW(circumscribed_sphere(0.09, std::nan("")), std::invalid_argument);
  EXPECT_THROW(circumscribed_cylinder(0.04, 1.2, 0.0005), std::invalid_argument);
  EXPECT_THROW(build_circumscribed_sphere(-1.0, 0.01), std::invalid_argument);
  EXPECT_THROW(build_circumscribed_cylinder(0.04, 0.0, 0.01), std::invalid_argument);
}

}  // namespace
}  // namespace grpvss::geometry
