#include "io/affine_dimension.hpp"

#include <cmath>
#include <random>
#include <vector>

#include <Eigen/Geometry>
#include <gtest/gtest.h>

namespace grpvss::io {
namespace {

using Points = std::vector<Eigen::Vector3d>;

TEST(AffineDimension, ClassifiesSmallConfigurations) {
  EXPECT_EQ(affine_dimension({}), -1);
  EXPECT_EQ(affine_dimension({{1, 2, 3}}), 0);
  EXPECT_EQ(affine_dimension({{1, 2, 3}, {1, 2, 3}, {1, 2, 3}, {1, 2, 3}}), 0);
  EXPECT_EQ(affine_dimension({{0, 0, 0}, {1, 1, 1}, {2, 2, 2}, {-3, -3, -3}}), 1);
  EXPECT_EQ(affine_dimension({{0, 0, 5}, {1, 0, 5}, {0, 1, 5}, {7, -2, 5}}), 2);
  EXPECT_EQ(affine_dimension({{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, 1}}), 3);
  // Repeated points before the spanning ones do not hide them.
  EXPECT_EQ(affine_dimension({{0, 0, 0}, {0, 0, 0}, {1, 0, 0}, {2, 0, 0}, {0, 1, 0}, {0, 0, 1}}),
            3);
}

TEST(AffineDimension, HandlesTinyAndLargeCoordinatesExactly) {
  // The fourth point leaves the plane z = 0 by 1e-300: double products would underflow.
  EXPECT_EQ(affine_dimension({{0, 0, 0}, {1e-200, 0, 0}, {0, 1e-200, 0}, {1e9, 1e9, 1e-300}}), 3);
  EXPECT_EQ(affine_dimension({{0, 0, 0}, {1e-200, 0, 0}, {0, 1e-200, 0}, {1e9, 1e9, 0}}), 2);
}

/// Points on the plane z = x + y with coordinates that are multiples of 2^-30 below 2^10:
/// x + y is exact, but products of differences need ~80 bits, so a double determinant
/// rounds. The exact answer is 2; moving one point up by one ulp makes it 3.
TEST(AffineDimension, DecidesNearCoplanarSetsExactlyAgainstConstruction) {
  std::mt19937_64 random(20261121);
  std::uniform_int_distribution<long long> grid(0, (1LL << 39) - 1);
  int double_determinant_disagreed = 0;
  for (int trial = 0; trial < 500; ++trial) {
    Points points;
    for (int k = 0; k < 6; ++k) {
      const double x = std::ldexp(static_cast<double>(grid(random)), -30);
      const double y = std::ldexp(static_cast<double>(grid(random)), -30);
      points.emplace_back(x, y, x + y);
    }
    ASSERT_EQ(affine_dimension(points), 2) << "trial " << trial;
    const Eigen::Vector3d u = points[1] - points[0];
    const Eigen::Vector3d v = points[2] - points[0];
    const Eigen::Vector3d w = points[5] - points[0];
    if (u.cross(v).dot(w) != 0.0) ++double_determinant_disagreed;

    points[5].z() = std::nextafter(points[5].z(), 1e10);
    EXPECT_EQ(affine_dimension(points), 3) << "trial " << trial;
  }
  // The property is not vacuous: plain double arithmetic gets some of these wrong.
  EXPECT_GT(double_determinant_disagreed, 0);
}

}  // namespace
}  // namespace grpvss::io
