#include "grpvss/exact/points_in_polytope.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "support/geometry_reference.hpp"

namespace grpvss::geometry {
namespace {

TEST(PointsInsideExactly, AgreesWithTheIndependentHullOnRandomAndBoundaryPoints) {
  std::mt19937_64 rng(77);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  for (int trial = 0; trial < 20; ++trial) {
    testing::Points pts;
    for (int i = 0; i < 25; ++i) pts.emplace_back(u(rng), u(rng), u(rng));
    const ConvexPolytope p = ConvexPolytope::from_points(pts);
    EXPECT_TRUE(points_inside_exactly(p, pts));  // its own input, vertices skipped per face
    testing::Points queries;
    for (int i = 0; i < 40; ++i) queries.emplace_back(u(rng), u(rng), u(rng));
    for (const auto& v : p.vertices()) {
      // Points on and next to the boundary: a vertex pushed one ulp out along each axis.
      for (int k = 0; k < 3; ++k) {
        Eigen::Vector3d w = v;
        w[k] = std::nextafter(v[k], v[k] > 0 ? 2.0 : -2.0);
        queries.push_back(w);
      }
      queries.push_back(v);
    }
    for (const auto& x : queries) {
      EXPECT_EQ(points_inside_exactly(p, {x}), testing::point_in_hull_exactly(pts, x))
          << "trial " << trial << " x = " << x.transpose();
    }
  }
}

TEST(PointsInsideExactly, DecidesPointsExactlyOnAFaceAndOneUlpOutside) {
  const testing::Points cube = testing::box({0, 0, 0}, {1, 1, 1});
  const ConvexPolytope p = ConvexPolytope::from_points(cube);
  EXPECT_TRUE(points_inside_exactly(p, {{0.3, 0.7, 1.0}}));                    // on the top face
  EXPECT_FALSE(points_inside_exactly(p, {{0.3, 0.7, std::nextafter(1.0, 2.0)}}));  // just above
  EXPECT_TRUE(points_inside_exactly(p, {{1e-300, 0.5, 0.5}}));  // tiny coordinates: exact path
  EXPECT_FALSE(points_inside_exactly(p, {{-1e-300, 0.5, 0.5}}));
}

}  // namespace
}  // namespace grpvss::geometry
