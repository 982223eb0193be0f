#include "grpvss/exact/minkowski_offset.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <random>
#include <set>
#include <string>

#include "support/geometry_reference.hpp"

namespace grpvss::geometry {
namespace {

using testing::Points;

TEST(MinkowskiOffset, ShapesContainTheBallExactlyAndInflateAsStated) {
  for (double r : {1.0, 0.5, 0.1, 1e-3, 3.7}) {
    const ConvexPolytope cube = offset_shape_polytope(r, OffsetShape::kCube);
    const ConvexPolytope rbco = offset_shape_polytope(r, OffsetShape::kRhombicuboctahedron);
    EXPECT_EQ(cube.vertices().size(), 8u);
    EXPECT_EQ(cube.faces().size(), 6u);
    EXPECT_EQ(rbco.vertices().size(), 24u);
    EXPECT_EQ(rbco.faces().size(), 26u);  // 6 + 12 squares, 8 triangles
    EXPECT_TRUE(contains_ball_exactly(cube, r));
    EXPECT_TRUE(contains_ball_exactly(rbco, r));
    double circum = 0.0;
    for (const auto& v : rbco.vertices()) circum = std::max(circum, v.norm());
    EXPECT_LE(circum, 1.16 * r);
    // The ball is tight: a slightly larger ball pokes out of both shapes.
    EXPECT_FALSE(contains_ball_exactly(cube, r * (1 + 1e-12)));
    EXPECT_FALSE(contains_ball_exactly(rbco, r * (1 + 1e-12)));
  }
}

TEST(MinkowskiOffset, CubeOffsetOfABoxIsTheGrownBox) {
  const ConvexPolytope hull = ConvexPolytope::from_points(testing::box({0, 0, 0}, {1, 2, 3}));
  const ConvexPolytope grown = minkowski_offset(hull, 0.5, OffsetShape::kCube);
  std::set<std::array<double, 3>> got, expected;
  for (const auto& v : grown.vertices()) got.insert({v.x(), v.y(), v.z()});
  for (const auto& v : testing::box({-0.5, -0.5, -0.5}, {1.5, 2.5, 3.5})) {
    expected.insert({v.x(), v.y(), v.z()});
  }
  EXPECT_EQ(got, expected);
  EXPECT_EQ(grown.volume(), 2.0 * 3.0 * 4.0);
  EXPECT_TRUE(contains_ball_sum_exactly(grown, hull, 0.5));
  // Tight: the faces touch hull (+) B(0, 0.5); any larger radius fails, by exactly the excess.
  EXPECT_FALSE(contains_ball_sum_exactly(grown, hull, 0.5 + 0x1p-40));
  const auto report = ball_sum_containment_report(grown, hull.vertices(), 0.625);
  EXPECT_FALSE(report.contained);
  EXPECT_DOUBLE_EQ(report.worst_protrusion, 0.125);
}

TEST(MinkowskiOffset, RhombicuboctahedronOffsetOfABoxHasTheTwentySixNormals) {
  const ConvexPolytope hull = ConvexPolytope::from_points(testing::box({0, 0, 0}, {1, 2, 3}));
  const ConvexPolytope grown = minkowski_offset(hull, 0.25, OffsetShape::kRhombicuboctahedron);
  ASSERT_EQ(grown.faces().size(), 26u);
  std::set<std::array<int, 3>> normals;
  for (const auto& n : grown.face_normals()) {
    const double m = n.cwiseAbs().maxCoeff();
    std::array<int, 3> k{};
    for (int i = 0; i < 3; ++i) {
      const double s = n[i] / m;
      k[i] = static_cast<int>(std::lround(s));
      EXPECT_NEAR(s, k[i], 1e-9);
    }
    normals.insert(k);
  }
  EXPECT_EQ(normals.size(), 26u);
  EXPECT_TRUE(contains_ball_sum_exactly(grown, hull, 0.25));
  // Tighter than the cube offset.
  EXPECT_LT(grown.volume(), minkowski_offset(hull, 0.25, OffsetShape::kCube).volume());
}

/// Every IBM 7545 hull, in its own frame and randomly rotated: both offsets verify exactly and
/// contain sampled points of hull (+) B(0, r) (checked with an independent exact predicate).
TEST(MinkowskiOffset, Ibm7545OffsetsContainSampledBallSumPoints) {
  std::mt19937_64 rng(20240611);
  std::normal_distribution<double> g(0.0, 1.0);
  const auto hulls = testing::ibm7545_hulls();
  for (std::size_t i = 0; i < hulls.size(); ++i) {
    for (int pose = 0; pose < 2; ++pose) {
      const Points pts = pose == 0 ? hulls[i]
                                   : testing::transformed(hulls[i], testing::random_rotation(rng),
                                                          {10.0, -3.0, 7.0});
      const ConvexPolytope hull = ConvexPolytope::from_points(pts);
      for (OffsetShape shape : {OffsetShape::kCube, OffsetShape::kRhombicuboctahedron}) {
        for (double r : {0.5, 1e-3}) {
          SCOPED_TRACE("hull " + std::to_string(i) + " pose " + std::to_string(pose) + " r " +
                       std::to_string(r));
          const ConvexPolytope grown = minkowski_offset(hull, r, shape);
          ASSERT_TRUE(contains_ball_sum_exactly(grown, hull, r));
          const auto report = ball_sum_containment_report(grown, hull.vertices(), r);
          EXPECT_TRUE(report.contained);
          EXPECT_LE(report.worst_protrusion, 1e-12);
          Points xs;
          for (int s = 0; s < 40; ++s) {
            Eigen::Vector3d u(g(rng), g(rng), g(rng));
            u.normalize();
            // Shrink by 1e-9 so the rounded sample is certainly inside the ball sum.
            const Eigen::Vector3d x =
                hull.vertices()[s % hull.vertices().size()] + (r * (1.0 - 1e-9)) * u;
            xs.push_back(x);
          }
          EXPECT_EQ(testing::count_points_outside_hull_exactly(grown.vertices(), xs), 0);
          // Negative control: both shapes have an axis face at distance r, so 0.1% beyond the
          // x-extreme vertex is outside.
          Eigen::Vector3d x_max = hull.vertices().front();
          for (const auto& v : hull.vertices()) if (v.x() > x_max.x()) x_max = v;
          EXPECT_EQ(testing::count_points_outside_hull_exactly(
                        grown.vertices(), {x_max + Eigen::Vector3d(1.001 * r, 0, 0)}),
                    1);
        }
      }
    }
  }
}

TEST(MinkowskiOffset, ContainmentCheckRejectsAShrunkOuterHull) {
  const auto hulls = testing::ibm7545_hulls();
  const ConvexPolytope hull = ConvexPolytope::from_points(hulls[3]);
  const ConvexPolytope grown = minkowski_offset(hull, 0.5, OffsetShape::kRhombicuboctahedron);
  // Pull every vertex of the offset 1e-6 toward the centroid: no longer contains the sum.
  Eigen::Vector3d centroid = Eigen::Vector3d::Zero();
  for (const auto& v : grown.vertices()) centroid += v;
  centroid /= static_cast<double>(grown.vertices().size());
  Points shrunk;
  for (const auto& v : grown.vertices()) shrunk.push_back(v + 1e-6 * (centroid - v).normalized());
  const ConvexPolytope smaller = ConvexPolytope::from_points(shrunk);
  EXPECT_FALSE(contains_ball_sum_exactly(smaller, hull, 0.5));
  const auto report = ball_sum_containment_report(smaller, hull.vertices(), 0.5);
  EXPECT_FALSE(report.contained);
  EXPECT_GT(report.worst_protrusion, 0.0);
  EXPECT_LT(report.worst_protrusion, 1e-5);
  EXPECT_TRUE(contains_ball_sum_exactly(smaller, hull, 0.5 - 1e-5));
}

TEST(MinkowskiOffset, InvalidRadiusIsRejected) {
  const ConvexPolytope hull = ConvexPolytope::from_points(testing::box({0, 0, 0}, {1, 1, 1}));
  EXPECT_THROW(minkowski_offset(hull, 0.0, OffsetShape::kCube), std::invalid_argument);
  EXPECT_THROW(minkowski_offset(hull, -1.0, OffsetShape::kCube), std::invalid_argument);
  EXPECT_THROW(minkowski_offset(hull, std::nan(""), OffsetShape::kCube), std::invalid_argument);
  EXPECT_THROW(contains_ball_sum_exactly(hull, hull, -0.5), std::invalid_argument);
}

TEST(MinkowskiOffset, FilteredContainmentAgreesWithExactReferenceNearTheThreshold) {
  // Rotated IBM 7545 hulls and their offsets: radii within a few 2^-48 of the largest radius
  // the offset holds, where the interval filter cannot decide and the exact fallback must,
  // plus radii far from it, where the filter decides alone. Both must match the reference.
  std::mt19937_64 rng(2026);
  const auto hulls = testing::ibm7545_hulls();
  int near_true = 0, near_false = 0;
  for (int trial = 0; trial < 6; ++trial) {
    const auto pts = testing::transformed(hulls[trial % hulls.size()], testing::random_rotation(rng),
                                          Eigen::Vector3d(1.5, -2.25, 0.75));
    const ConvexPolytope hull = ConvexPolytope::from_points(pts);
    const auto shape = trial % 2 == 0 ? OffsetShape::kCube : OffsetShape::kRhombicuboctahedron;
    const ConvexPolytope grown = minkowski_offset(hull, 0.5, shape);
    const auto report = ball_sum_containment_report(grown, hull.vertices(), 0.5);
    const double threshold = 0.5 - report.worst_protrusion;
    for (int k = -6; k <= 6; ++k) {
      const double r = threshold * (1.0 + k * 0x1p-48);
      const bool expected = testing::reference_contains_ball_sum(grown.vertices(), hull.vertices(), r);
      EXPECT_EQ(contains_ball_sum_exactly(grown, hull, r), expected) << trial << " " << k;
      (expected ? near_true : near_false) += 1;
    }
    for (const double r : {0.25, 0.5, 0.75, 1.5}) {
      EXPECT_EQ(contains_ball_sum_exactly(grown, hull, r),
                testing::reference_contains_ball_sum(grown.vertices(), hull.vertices(), r))
          << trial << " " << r;
    }
  }
  // The radii straddle the threshold: both answers occur.
  EXPECT_GT(near_true, 0);
  EXPECT_GT(near_false, 0);
}

// contains_ball_sum_by_climbing (proofs/offset-containment.md#lemma-climbed-support) decides
// exactly what the scan decides. Near the threshold radius only the governing face's support
// value separates the answers, so a support vertex the climb claimed but that is not the
// maximum would accept a radius the reference rejects. Hulls: the IBM 7545 links (small,
// with parallel faces: tied vertex sets) and 60-240 random points on a sphere (mesh-like
// hulls of hundreds of vertices).
TEST(MinkowskiOffset, ClimbedContainmentAgreesWithTheScanAndTheReferenceAtTheThreshold) {
  std::mt19937_64 rng(20261201);
  std::vector<Points> hulls = testing::ibm7545_hulls();
  std::normal_distribution<double> gauss(0.0, 1.0);
  for (const int count : {60, 120, 240}) {
    Points sphere;
    for (int i = 0; i < count; ++i) {
      Eigen::Vector3d p(gauss(rng), gauss(rng), gauss(rng));
      sphere.push_back(0.07 * p.normalized() + Eigen::Vector3d(0.01, -0.02, 0.3));
    }
    hulls.push_back(sphere);
  }
  int near_true = 0, near_false = 0;
  int sphere_faces = 0, sphere_faces_climbed = 0;
  for (std::size_t trial = 0; trial < hulls.size(); ++trial) {
    const auto pts = testing::transformed(hulls[trial], testing::random_rotation(rng),
                                          Eigen::Vector3d(0.4, -0.25, 0.75));
    const ConvexPolytope hull = ConvexPolytope::from_points(pts);
    const double radius = 0.004;
    const auto shape = trial % 2 == 0 ? OffsetShape::kRhombicuboctahedron : OffsetShape::kCube;
    const ConvexPolytope grown = minkowski_offset(hull, radius, shape);
    const double threshold =
        radius - ball_sum_containment_report(grown, hull.vertices(), radius).worst_protrusion;
    for (int k = -3; k <= 3; ++k) {
      const double r = threshold * (1.0 + k * 0x1p-46);
      const bool expected = testing::reference_contains_ball_sum(grown.vertices(), hull.vertices(), r);
      EXPECT_EQ(contains_ball_sum_by_climbing(grown, hull, r), expected) << trial << " " << k;
      EXPECT_EQ(contains_ball_sum_exactly(grown, hull, r), expected) << trial << " " << k;
      (expected ? near_true : near_false) += 1;
    }
    if (trial >= hulls.size() - 3) {
      int climbed = 0;
      ASSERT_TRUE(contains_ball_sum_by_climbing(grown, hull, radius, &climbed));
      sphere_faces += static_cast<int>(grown.faces().size());
      sphere_faces_climbed += climbed;
    }
    for (const double r : {0.0, 0.5 * radius, radius, 2.0 * radius}) {
      EXPECT_EQ(contains_ball_sum_by_climbing(grown, hull, r),
                testing::reference_contains_ball_sum(grown.vertices(), hull.vertices(), r))
          << trial << " " << r;
    }
  }
  EXPECT_GT(near_true, 0);
  EXPECT_GT(near_false, 0);
  // The climb, not the scan, decided almost every face of the mesh-like offsets.
  EXPECT_GT(sphere_faces_climbed, 0.95 * sphere_faces) << sphere_faces_climbed << " of " << sphere_faces;
}

// Outer and inner faces parallel (a box and its cube offset): every face's support is a whole
// face of the box (four tied vertices), proven as a set, at the exact threshold radius.
TEST(MinkowskiOffset, ClimbedContainmentOfABoxInItsGrownBoxProvesTiedFaces) {
  const ConvexPolytope hull = ConvexPolytope::from_points(testing::box({0, 0, 0}, {1, 2, 3}));
  const ConvexPolytope grown = minkowski_offset(hull, 0.5, OffsetShape::kCube);
  int climbed = 0;
  EXPECT_TRUE(contains_ball_sum_by_climbing(grown, hull, 0.5, &climbed));
  EXPECT_EQ(climbed, static_cast<int>(grown.faces().size()));
  EXPECT_FALSE(contains_ball_sum_by_climbing(grown, hull, 0.5 + 0x1p-40));
  EXPECT_FALSE(contains_ball_sum_by_climbing(hull, grown, 0.0));
  EXPECT_TRUE(contains_ball_sum_by_climbing(hull, hull, 0.0));
}

}  // namespace
}  // namespace grpvss::geometry
