#include "grpvss/geometry/gjk.hpp"

#include <random>

#include <Eigen/Geometry>
#include <gtest/gtest.h>

#include "support/random_shapes.hpp"

namespace grpvss::geometry {
namespace {

using Eigen::Vector3d;

// Lower bound of the hull distance from GJK's own direction (weak duality of the support
// function): the gap of the planes orthogonal to v that bound A and B.
double plane_gap(const std::vector<Vector3d>& a, const std::vector<Vector3d>& b,
                 const Vector3d& v) {
  const Vector3d n = -v.normalized();  // from A towards B
  double max_a = -1e300, min_b = 1e300;
  for (const auto& p : a) max_a = std::max(max_a, n.dot(p));
  for (const auto& p : b) min_b = std::min(min_b, n.dot(p));
  return min_b - max_a;
}

TEST(Gjk, FaceToFaceCubesAtDistanceThree) {
  const auto a = test::cube(Vector3d(0, 0, 0), 1.0);
  const auto b = test::cube(Vector3d(4, 0.25, -0.5), 1.0);
  const GjkResult r = gjk(a, b);
  ASSERT_EQ(r.status, GjkStatus::kSeparated);
  EXPECT_NEAR(r.distance, 3.0, 1e-12);
  EXPECT_NEAR(r.closest_vector.x(), -3.0, 1e-12);
  EXPECT_NEAR(r.closest_a.x(), 1.0, 1e-12);
  EXPECT_NEAR(r.closest_b.x(), 4.0, 1e-12);
}

TEST(Gjk, EdgeToEdgeCubesAtDiagonalDistance) {
  const auto a = test::cube(Vector3d(0, 0, 0), 1.0);
  const auto b = test::cube(Vector3d(2, 2, 0), 1.0);  // nearest features: two vertical edges
  const GjkResult r = gjk(a, b);
  ASSERT_EQ(r.status, GjkStatus::kSeparated);
  EXPECT_NEAR(r.distance, std::sqrt(2.0), 1e-12);
}

TEST(Gjk, OverlappingCubesEndWithTetrahedronAroundOrigin) {
  const auto a = test::cube(Vector3d(0, 0, 0), 1.0);
  const auto b = test::cube(Vector3d(0.5, 0.3, 0.2), 1.0);
  const GjkResult r = gjk(a, b);
  ASSERT_EQ(r.status, GjkStatus::kOverlapping);
  ASSERT_EQ(r.simplex_size, 4);
  Vector3d w[4];
  for (int k = 0; k < 4; ++k) w[k] = a[r.simplex_a[k]] - b[r.simplex_b[k]];
  // Barycentric coordinates of the origin must all be positive.
  Eigen::Matrix3d m;
  m << w[1] - w[0], w[2] - w[0], w[3] - w[0];
  const Vector3d lambda = m.colPivHouseholderQr().solve(-w[0]);
  EXPECT_GT(lambda.minCoeff(), 0.0);
  EXPECT_GT(1.0 - lambda.sum(), 0.0);
}

TEST(Gjk, EmptyInputIsRejected) {
  const std::vector<Vector3d> none;
  const std::vector<Vector3d> cube = test::cube(Vector3d::Zero(), 1.0);
  EXPECT_THROW(gjk(none, cube), std::invalid_argument);
  // A placed hull needs its vertices and their skeleton; the obstacle side must not be empty.
  EXPECT_THROW(gjk(PlacedHull{}, cube), std::invalid_argument);
  const HullSkeleton no_edges{{0, 0, 0, 0, 0, 0, 0, 0, 0}, {}};
  PlacedHull placed;
  placed.vertices_L = &cube;
  placed.skeleton = &no_edges;
  EXPECT_THROW(gjk(placed, none), std::invalid_argument);
  const HullSkeleton too_short{{0, 0}, {}};
  placed.skeleton = &too_short;
  EXPECT_THROW(gjk(placed, cube), std::invalid_argument);
}

TEST(Gjk, RandomSeparatedPairsConvergeToDualityGap) {
  std::mt19937_64 rng(20261121);
  std::uniform_real_distribution<double> unit(-1.0, 1.0);
  int separated = 0;
  for (int trial = 0; trial < 2000; ++trial) {
    const auto a = test::random_prism(rng, Vector3d::Zero(), 1.0);
    const Vector3d direction = Vector3d(unit(rng), unit(rng), unit(rng)).normalized();
    const auto b = test::random_prism(rng, direction * (2.5 + 2.0 * (unit(rng) + 1.0)), 1.0);
    const GjkResult r = gjk(a, b);
    if (r.status != GjkStatus::kSeparated) {
      // 2.5 apart with radius <= 1.0 and height <= 1.5: never touching.
      ADD_FAILURE() << "trial " << trial << " not separated";
      continue;
    }
    ++separated;
    // closest_a, closest_b are convex combinations, so |a* - b*| >= true distance >= gap.
    const double upper = (r.closest_a - r.closest_b).norm();
    const double lower = plane_gap(a, b, r.closest_vector);
    EXPECT_LE(lower, upper + 1e-12);
    EXPECT_NEAR(upper, r.distance, 1e-9);
    EXPECT_LE(upper - lower, 1e-6 * upper) << "trial " << trial;
  }
  EXPECT_EQ(separated, 2000);
}

TEST(Gjk, WarmStartFromSeparatingNormalGivesSameDistance) {
  std::mt19937_64 rng(7);
  for (int trial = 0; trial < 500; ++trial) {
    const auto a = test::random_prism(rng, Vector3d::Zero(), 1.0);
    const auto b = test::random_prism(rng, Vector3d(3.0, 0.5, -0.2), 1.0);
    const GjkResult cold = gjk(a, b);
    const Vector3d normal = -cold.closest_vector;
    const GjkResult warm = gjk(a, b, &normal);
    ASSERT_EQ(warm.status, GjkStatus::kSeparated);
    EXPECT_NEAR(warm.distance, cold.distance, 1e-9);
  }
}

TEST(Gjk, RandomDeepOverlapsAreReportedOverlapping) {
  std::mt19937_64 rng(99);
  std::uniform_real_distribution<double> unit(-1.0, 1.0);
  for (int trial = 0; trial < 2000; ++trial) {
    const auto a = test::random_prism(rng, Vector3d::Zero(), 1.0);
    // A contains the ball of radius min(0.7 cos(pi/8), 0.5/2) = 0.25 about the origin and B's
    // centre is at most 0.1 sqrt(3) < 0.25 away, so B's centre is interior to A.
    const auto b = test::random_prism(rng, 0.1 * Vector3d(unit(rng), unit(rng), unit(rng)), 1.0);
    const GjkResult r = gjk(a, b);
    EXPECT_EQ(r.status, GjkStatus::kOverlapping) << "trial " << trial;
  }
}

}  // namespace
}  // namespace grpvss::geometry

namespace grpvss::geometry {
namespace {

/// The definition: the first index of the largest (x dx + y dy) + z dz.
int first_maximum(const std::vector<Eigen::Vector3d>& points, const Eigen::Vector3d& d) {
  int best = 0;
  for (int i = 1; i < static_cast<int>(points.size()); ++i) {
    if (points[i].dot(d) > points[best].dot(d)) best = i;
  }
  return best;
}

TEST(SupportIndex, IsTheFirstMaximumForEveryCountAndWithTies) {
  std::mt19937_64 rng(3);
  std::uniform_real_distribution<double> coordinate(-10.0, 10.0);
  std::uniform_int_distribution<int> small(-2, 2);
  int ties = 0;
  for (int trial = 0; trial < 20000; ++trial) {
    const int n = 1 + trial % 60;
    const bool on_grid = trial % 3 == 0;  // small integers: many equal dot products
    std::vector<Eigen::Vector3d> points;
    for (int i = 0; i < n; ++i) {
      points.emplace_back(on_grid ? Eigen::Vector3d(small(rng), small(rng), small(rng))
                                  : Eigen::Vector3d(coordinate(rng), coordinate(rng),
                                                    coordinate(rng)));
    }
    if (trial % 7 == 0 && n > 2) points[static_cast<std::size_t>(n) - 1] = points[1];
    const Eigen::Vector3d d = on_grid ? Eigen::Vector3d(small(rng), small(rng), small(rng))
                                      : Eigen::Vector3d(coordinate(rng), coordinate(rng),
                                                        coordinate(rng));
    const int expected = first_maximum(points, d);
    for (int i = expected + 1; i < n; ++i) ties += points[i].dot(d) == points[expected].dot(d);
    ASSERT_EQ(support_index(points, d), expected) << "trial " << trial << ", " << n << " points";
  }
  EXPECT_GT(ties, 1000);  // the tie rule was exercised
}

}  // namespace
}  // namespace grpvss::geometry
