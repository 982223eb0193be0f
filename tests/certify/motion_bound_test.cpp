#include "grpvss/certify/motion_bound.hpp"

#include "grpvss/certify/exact_axis_radius.hpp"

#include <cmath>
#include <random>

#include <gtest/gtest.h>

namespace grpvss::certify {
namespace {

constexpr double kDeg = M_PI / 180.0;

// The IBM 7545 chain (thesis A.1.1.1) with one hull per link; hull points chosen so that
// the L1 norms are easy to compute by hand.
RobotModel make_scara_with_unit_hulls() {
  RobotModel robot;
  auto revolute = [](double alpha_deg, double d, double a, double min_deg, double max_deg) {
    Joint joint;
    joint.type = JointType::kRevolute;
    joint.dh = {0.0, d, a, alpha_deg * kDeg};
    joint.minimum = min_deg * kDeg;
    joint.maximum = max_deg * kDeg;
    joint.acceleration = 2 * kDeg;
    joint.deceleration = 1.8 * kDeg;
    return joint;
  };
  robot.joints.push_back(revolute(0, 25.5, 15.8, 0, 200));
  robot.joints.push_back(revolute(180, 0, 9.8, 0, 135));
  Joint prismatic;
  prismatic.type = JointType::kPrismatic;
  prismatic.minimum = 0.0;
  prismatic.maximum = 9.8;
  prismatic.acceleration = 0.7;
  prismatic.deceleration = 0.6;
  robot.joints.push_back(prismatic);
  robot.joints.push_back(revolute(0, 15.05, 0, -180, 180));
  robot.links.resize(5);
  for (auto& link : robot.links) {
    HullPoints hull;
    hull.points = {{1, 0, 0}, {0, 2, 0}, {0, 0, 3}, {-1, -1, -1}};  // max L1 norm 3
    link.hulls.push_back(hull);
  }
  return robot;
}

TEST(HullRadiusTable, RadiiFollowTheAbsoluteSumFormula) {
  const RobotModel robot = make_scara_with_unit_hulls();
  const HullRadiusTable table(robot);
  // Link 4 about joint 1: |a1| + (|a2|+|d2|) + (|a3|+dmax3) + (|a4|+|d4|) + max L1 = 15.8+9.8+9.8+15.05+3.
  EXPECT_NEAR(table.radius(4, 0, 1), 15.8 + 9.8 + 9.8 + 15.05 + 3.0, 1e-12);
  EXPECT_GE(table.radius(4, 0, 1), 15.8 + 9.8 + 9.8 + 15.05 + 3.0);
  // Link 2 about joint 2: |a2| + max L1.
  EXPECT_NEAR(table.radius(2, 0, 2), 9.8 + 3.0, 1e-12);
  // Link 4 about joint 4: |a4| + max L1 = 3.
  EXPECT_NEAR(table.radius(4, 0, 4), 3.0, 1e-12);
}

TEST(HullRadiusTable, RoundedRadiiPassTheExactCheckAndTighterClaimsFail) {
  const RobotModel robot = make_scara_with_unit_hulls();
  const HullRadiusTable table(robot);
  for (int link = 1; link <= 4; ++link) {
    for (int joint = 1; joint <= link; ++joint) {
      const double radius = table.radius(link, 0, joint);
      const mpq_class exact = exact_axis_radius(robot, link, robot.links[link].hulls[0], joint);
      EXPECT_GE(mpq_class(radius), exact);
      // ... and only by a few ulps: a claim 1e-12 smaller is below the exact value.
      EXPECT_LT(mpq_class(radius * (1.0 - 1e-12)), exact);
    }
  }
}

TEST(HullRadiusTable, MotionBoundSumsRevoluteAndPrismaticTerms) {
  const RobotModel robot = make_scara_with_unit_hulls();
  const HullRadiusTable table(robot);
  Eigen::VectorXd dq(4);
  dq << 0.1, -0.2, 0.5, 0.3;
  const double expected = 0.1 * table.radius(4, 0, 1) + 0.2 * table.radius(4, 0, 2) + 0.5 +
                          0.3 * table.radius(4, 0, 4);
  EXPECT_GE(table.hull_motion_bound(4, 0, dq), expected);
  EXPECT_NEAR(table.hull_motion_bound(4, 0, dq), expected, 1e-12);
  // Link 2 ignores joints 3 and 4.
  EXPECT_NEAR(table.hull_motion_bound(2, 0, dq),
              0.1 * table.radius(2, 0, 1) + 0.2 * table.radius(2, 0, 2), 1e-12);
  // The base never moves.
  EXPECT_EQ(table.hull_motion_bound(0, 0, dq), 0.0);
}

}  // namespace
}  // namespace grpvss::certify
