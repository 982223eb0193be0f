// The audit library: Steiner ball-sum volume against closed forms, and the audit's rows.
#include "grpvss/exact/expansion_audit.hpp"
#include "support/angles.hpp"

#include <cmath>
#include <stdexcept>

#include <gtest/gtest.h>


namespace grpvss::geometry {
namespace {

using grpvss::test::kPi;

std::vector<Eigen::Vector3d> box_corners(double a, double b, double c) {
  std::vector<Eigen::Vector3d> points;
  for (double x : {0.0, a})
    for (double y : {0.0, b})
      for (double z : {0.0, c}) points.emplace_back(x, y, z);
  return points;
}

TEST(BallSumVolume, BoxMatchesClosedForm) {
  // V(box + B_r) = abc + 2(ab + bc + ca) r + pi (a + b + c) r^2 + 4/3 pi r^3.
  const double a = 3, b = 2, c = 7, r = 0.5;
  const double expected = a * b * c + 2 * (a * b + b * c + c * a) * r +
                          kPi * (a + b + c) * r * r + 4.0 / 3.0 * kPi * r * r * r;
  EXPECT_NEAR(ball_sum_volume(ConvexPolytope::from_points(box_corners(a, b, c)), r), expected,
              1e-12 * expected);
}

TEST(BallSumVolume, RegularTetrahedronMatchesClosedForm) {
  // Edge s: V = s^3/(6 sqrt2), A = sqrt3 s^2, 6 edges with exterior angle pi - acos(1/3).
  const std::vector<Eigen::Vector3d> tetra = {{1, 1, 1}, {1, -1, -1}, {-1, 1, -1}, {-1, -1, 1}};
  const double s = 2 * std::sqrt(2.0), r = 0.3;
  const double expected = s * s * s / (6 * std::sqrt(2.0)) + std::sqrt(3.0) * s * s * r +
                          0.5 * 6 * s * (kPi - std::acos(1.0 / 3.0)) * r * r +
                          4.0 / 3.0 * kPi * r * r * r;
  EXPECT_NEAR(ball_sum_volume(ConvexPolytope::from_points(tetra), r), expected,
              1e-12 * expected);
}

TEST(ExpansionAudit, NonPrismHullGetsExactOffsetsOnly) {
  RobotModel robot;
  robot.links.resize(1);
  HullPoints hull;
  hull.points = box_corners(2, 2, 2);  // 8 points: not the thesis's 16-vertex prism
  hull.source_line = 7;
  robot.links[0].hulls.push_back(hull);
  const ExpansionAudit audit = audit_expansions(robot, 0.25);
  ASSERT_EQ(audit.hulls.size(), 1u);
  const HullExpansionAudit& row = audit.hulls[0];
  EXPECT_EQ(row.source_line, 7);
  EXPECT_EQ(row.point_count, 8);
  EXPECT_EQ(row.vertex_count, 8);
  EXPECT_EQ(row.volume, 8.0);
  ASSERT_EQ(row.expansions.size(), 4u);
  EXPECT_FALSE(row.expansions[0].applicable);
  EXPECT_FALSE(row.expansions[1].applicable);
  // Cube offset of a cube of side 2 by 0.25: a cube of side 2.5, tight on every face.
  EXPECT_TRUE(row.expansions[2].contains_ball_sum);
  EXPECT_EQ(row.expansions[2].volume, 2.5 * 2.5 * 2.5);
  EXPECT_EQ(row.expansions[2].worst_protrusion, 0.0);
  EXPECT_TRUE(row.expansions[3].contains_ball_sum);
  EXPECT_LT(row.expansions[3].volume, row.expansions[2].volume);
  EXPECT_GE(row.expansions[3].over_inflation, 1.0);
}

TEST(ExpansionAudit, RejectsNonPositiveTolerance) {
  RobotModel robot;
  EXPECT_THROW(audit_expansions(robot, 0.0), std::invalid_argument);
  EXPECT_THROW(audit_expansions(robot, -1.0), std::invalid_argument);
  EXPECT_THROW(audit_expansions(robot, std::nan("")), std::invalid_argument);
}

}  // namespace
}  // namespace grpvss::geometry
