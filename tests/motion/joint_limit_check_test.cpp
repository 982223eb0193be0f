#include "grpvss/motion/joint_limit_check.hpp"

#include <cfenv>
#include <cmath>
#include <limits>
#include <random>
#include <stdexcept>

#include <gtest/gtest.h>

#include "grpvss/io/trajectory_file.hpp"

namespace grpvss::motion {
namespace {

constexpr double kNone = std::numeric_limits<double>::infinity();

JointLimits limits(std::initializer_list<double> lower, std::initializer_list<double> upper,
                   std::initializer_list<double> speed) {
  const auto vector = [](std::initializer_list<double> values) {
    Eigen::VectorXd v(static_cast<Eigen::Index>(values.size()));
    Eigen::Index i = 0;
    for (double x : values) v[i++] = x;
    return v;
  };
  return {vector(lower), vector(upper), vector(speed)};
}

JointLimits wide_limits(int joints) {
  return {Eigen::VectorXd::Constant(joints, -10), Eigen::VectorXd::Constant(joints, 10),
          Eigen::VectorXd::Constant(joints, kNone)};
}

JointTrajectoryMotion motion_from_csv(const std::string& text) {
  return JointTrajectoryMotion(io::parse_trajectory_csv(text, "l.csv"));
}

TEST(JointLimitCheck, OvershootLeavesAnUpperLimitBetweenInLimitWaypoints) {
  const JointTrajectoryMotion motion(
      io::read_trajectory_file(std::string(GRPVSS_SOURCE_DIR) + "/data/trajectories/overshoot.json"));
  JointLimits bounds = wide_limits(6);
  bounds.upper[2] = 2.1;  // the elbow's waypoints are 1, 2, 2; it peaks at 2 + 2/9
  const std::optional<LimitViolation> violation = first_limit_violation(motion, bounds);
  ASSERT_TRUE(violation.has_value());
  EXPECT_EQ(violation->joint, 2);
  EXPECT_EQ(violation->joint_name, "elbow_joint");
  EXPECT_EQ(violation->kind, LimitKind::kAboveUpper);
  EXPECT_EQ(violation->piece, 1);
  EXPECT_NEAR(violation->time, 1.5 + 1.0 / 3.0, 1e-15);
  EXPECT_NEAR(violation->value, 2.0 + 2.0 / 9.0, 1e-15);
  EXPECT_EQ(violation->limit, 2.1);
  EXPECT_EQ(describe(*violation, motion.trajectory()),
            "joint 'elbow_joint' (3) is above its upper position limit 2.1 at t = "
            "1.8333333333333333 s: 2.2222222222222223 (piece 2, between points[1] (line 11) "
            "and points[2] (line 16))");
  bounds.upper[2] = 2.23;
  EXPECT_FALSE(first_limit_violation(motion, bounds).has_value());
}

TEST(JointLimitCheck, TouchingALimitIsWithinItExactly) {
  // p 0 -> 0, v 1 -> -1 over 1 s: q = s - s^2, maximum exactly 1/4 at s = 1/2.
  const JointTrajectoryMotion motion = motion_from_csv("time,a,a.vel\n0,0,1\n1,0,-1\n");
  EXPECT_FALSE(first_limit_violation(motion, limits({-1}, {0.25}, {kNone})).has_value());
  const auto violation = first_limit_violation(motion, limits({-1}, {std::nextafter(0.25, 0.0)}, {kNone}));
  ASSERT_TRUE(violation.has_value());
  EXPECT_EQ(violation->time, 0.5);
  EXPECT_EQ(violation->value, 0.25);
}

TEST(JointLimitCheck, AnIrrationalExtremumIsDecidedExactly) {
  // p 0 -> 0.3, v 2 -> -1 over 1 s: c1 = 2, c2 = 3 p1 - 4 + 1, c3 = -2 p1 + 2 - 1, and
  // q' = c1 + 2 c2 s + 3 c3 s^2 has an irrational root near s = 0.569 (a maximum, q = 0.53).
  const JointTrajectoryMotion motion = motion_from_csv("time,a,a.vel\n0,0,2\n1,0.3,-1\n");
  const long double p1 = 0.3;  // the double 0.3, exactly
  const long double c1 = 2.0L, c2 = 3 * p1 - 4 + 1, c3 = -2 * p1 + 2 - 1;
  const long double root = (-c2 - std::sqrt(c2 * c2 - 3 * c1 * c3)) / (3 * c3);
  const long double peak = root * (c1 + root * (c2 + root * c3));
  ASSERT_GT(root, 0.0L);
  ASSERT_LT(root, 1.0L);
  const double nearest = static_cast<double>(peak);
  EXPECT_FALSE(first_limit_violation(motion, limits({-1}, {std::nextafter(nearest, 9.0)}, {kNone})));
  const auto violation = first_limit_violation(motion, limits({-1}, {std::nextafter(nearest, 0.0)}, {kNone}));
  ASSERT_TRUE(violation.has_value());
  EXPECT_NEAR(violation->time, static_cast<double>(root), 1e-15);
  EXPECT_NEAR(violation->value, nearest, 1e-15);
}

TEST(JointLimitCheck, BelowTheLowerLimit) {
  const JointTrajectoryMotion motion = motion_from_csv("time,a,a.vel\n0,0,-1\n1,0,1\n");
  const auto violation = first_limit_violation(motion, limits({-0.2}, {1}, {kNone}));
  ASSERT_TRUE(violation.has_value());
  EXPECT_EQ(violation->kind, LimitKind::kBelowLower);
  EXPECT_EQ(violation->time, 0.5);
  EXPECT_EQ(violation->value, -0.25);
  EXPECT_EQ(violation->limit, -0.2);
}

TEST(JointLimitCheck, TheSpeedPeaksInsideAPieceAtTheVertexOfTheDerivative) {
  // p 0 -> 1 at rest at both ends over 1 s: q' = 6 s - 6 s^2, 1.5 at s = 1/2.
  const JointTrajectoryMotion motion = motion_from_csv("time,a,a.vel\n2,0,0\n3,1,0\n");
  EXPECT_FALSE(first_limit_violation(motion, limits({-1}, {2}, {1.5})).has_value());
  const auto violation = first_limit_violation(motion, limits({-1}, {2}, {1.4}));
  ASSERT_TRUE(violation.has_value());
  EXPECT_EQ(violation->kind, LimitKind::kOverSpeed);
  EXPECT_EQ(violation->time, 2.5);
  EXPECT_EQ(violation->value, 1.5);
  EXPECT_EQ(violation->limit, 1.4);
  EXPECT_EQ(describe(*violation, motion.trajectory()),
            "joint 'a' (1) is faster than its speed limit 1.4 at t = 2.5 s: 1.5 (piece 1, "
            "between line 2 and line 3)");
}

TEST(JointLimitCheck, ALinearPieceMovesAtItsSlope) {
  const JointTrajectoryMotion motion = motion_from_csv("time,a\n0,0\n0.5,1\n1.5,0\n");
  EXPECT_FALSE(first_limit_violation(motion, limits({-1}, {1}, {2})).has_value());
  const auto violation = first_limit_violation(motion, limits({-1}, {1}, {1.999}));
  ASSERT_TRUE(violation.has_value());
  EXPECT_EQ(violation->piece, 0);
  EXPECT_EQ(violation->time, 0.0);
  EXPECT_EQ(violation->value, 2.0);
}

TEST(JointLimitCheck, ReportsTheEarliestPieceAndWithinItTheEarliestWorstPoint) {
  // Joint a leaves its limit at the end of piece 1 (t = 1); joint b peaks inside piece 1 at
  // t = 0.5 and joint a goes further out later (piece 2): piece 1 is reported, b's point first.
  const JointTrajectoryMotion motion =
      motion_from_csv("time,a,b,a.vel,b.vel\n0,0,0,0,1\n1,1.5,0,0,-1\n2,3,0,0,0\n");
  const auto violation = first_limit_violation(motion, limits({-1, -1}, {1, 0.2}, {kNone, kNone}));
  ASSERT_TRUE(violation.has_value());
  EXPECT_EQ(violation->piece, 0);
  EXPECT_EQ(violation->joint, 1);
  EXPECT_EQ(violation->time, 0.5);
  EXPECT_EQ(violation->value, 0.25);
}

TEST(JointLimitCheck, AgreesWithAnIndependentExtremumOnRandomPieces) {
  // The reference: the extrema of each cubic from its derivative's roots in long double.
  std::mt19937 rng(20240607);
  std::uniform_real_distribution<double> value(-2, 2), rate(-6, 6), step(0.1, 2);
  int violations_found = 0;
  for (int trial = 0; trial < 300; ++trial) {
    const double h = step(rng), p0 = value(rng), p1 = value(rng), m0 = rate(rng), m1 = rate(rng);
    JointTrajectory trajectory;
    trajectory.joint_names = {"a"};
    trajectory.times = {0.0, h};
    trajectory.positions = {Eigen::VectorXd::Constant(1, p0), Eigen::VectorXd::Constant(1, p1)};
    trajectory.velocities = {Eigen::VectorXd::Constant(1, m0), Eigen::VectorXd::Constant(1, m1)};
    const JointTrajectoryMotion motion(trajectory);
    const long double c1 = static_cast<long double>(h) * m0;
    const long double c2 = 3.0L * (static_cast<long double>(p1) - p0) - 2 * c1 - static_cast<long double>(h) * m1;
    const long double c3 = 2.0L * (static_cast<long double>(p0) - p1) + c1 + static_cast<long double>(h) * m1;
    long double highest = std::max<long double>(p0, p1);
    const long double discriminant = c2 * c2 - 3 * c1 * c3;
    for (const int sign : {-1, 1}) {
      if (c3 == 0 || discriminant < 0) break;
      const long double r = (-c2 + sign * std::sqrt(discriminant)) / (3 * c3);
      if (r > 0 && r < 1) highest = std::max(highest, p0 + r * (c1 + r * (c2 + r * c3)));
    }
    const double margin = 1e-9;
    EXPECT_FALSE(first_limit_violation(
        motion, limits({-100}, {static_cast<double>(highest) + margin}, {kNone})));
    const auto violation =
        first_limit_violation(motion, limits({-100}, {static_cast<double>(highest) - margin}, {kNone}));
    ASSERT_TRUE(violation.has_value()) << trial;
    EXPECT_NEAR(violation->value, static_cast<double>(highest), 1e-12);
    if (violation->time > 0 && violation->time < h) ++violations_found;
  }
  EXPECT_GT(violations_found, 50);  // many maxima are interior overshoots
}

TEST(JointLimitCheck, TheControlPointPrefilterNeverChangesTheAnswer) {
  // The prefilter runs only in round-to-nearest; in another mode every piece takes the exact
  // path. Both must give the same first violation on random trajectories and limits.
  std::mt19937 rng(77);
  std::uniform_real_distribution<double> value(-2, 2), rate(-6, 6), step(0.1, 2), margin(-0.3, 0.6);
  int violations = 0, clear = 0;
  for (int trial = 0; trial < 200; ++trial) {
    JointTrajectory trajectory;
    trajectory.joint_names = {"a", "b"};
    double t = 0;
    for (int k = 0; k < 4; ++k, t += step(rng)) {
      trajectory.times.push_back(t);
      trajectory.positions.push_back(Eigen::Vector2d(value(rng), value(rng)));
      if (trial % 3 != 0) trajectory.velocities.push_back(Eigen::Vector2d(rate(rng), rate(rng)));
    }
    const JointTrajectoryMotion motion(trajectory);
    const JointLimits bounds = limits({-2 - margin(rng), -2 - margin(rng)}, {2 + margin(rng), 2 + margin(rng)},
                                      {trial % 2 ? kNone : 8 + 10 * margin(rng), 8 + 10 * margin(rng)});
    const auto with_prefilter = first_limit_violation(motion, bounds);
    std::fesetround(FE_DOWNWARD);
    const auto exact_only = first_limit_violation(motion, bounds);
    std::fesetround(FE_TONEAREST);
    ASSERT_EQ(with_prefilter.has_value(), exact_only.has_value()) << trial;
    if (!with_prefilter) {
      ++clear;
      continue;
    }
    ++violations;
    EXPECT_EQ(with_prefilter->joint, exact_only->joint);
    EXPECT_EQ(with_prefilter->kind, exact_only->kind);
    EXPECT_EQ(with_prefilter->piece, exact_only->piece);
    EXPECT_NEAR(with_prefilter->time, exact_only->time, 1e-12);
  }
  EXPECT_GT(violations, 30);  // both outcomes are exercised
  EXPECT_GT(clear, 30);
}

TEST(JointLimitCheck, OneWaypointIsCheckedAsItStands) {
  const JointTrajectoryMotion motion = motion_from_csv("time,a,a.vel\n1,0.5,3\n");
  EXPECT_FALSE(first_limit_violation(motion, limits({0}, {1}, {3})).has_value());
  const auto violation = first_limit_violation(motion, limits({0}, {0.4}, {3}));
  ASSERT_TRUE(violation.has_value());
  EXPECT_EQ(violation->piece, -1);
  EXPECT_EQ(violation->time, 1.0);
  EXPECT_EQ(describe(*violation, motion.trajectory()),
            "joint 'a' (1) is above its upper position limit 0.4 at t = 1 s: 0.5");
  EXPECT_EQ(first_limit_violation(motion, limits({0}, {1}, {2}))->kind, LimitKind::kOverSpeed);
}

TEST(JointLimitCheck, PositionLimitsComeFromTheRobotModel) {
  RobotModel robot;
  robot.joints.resize(2);
  robot.joints[0].minimum = -1.5;
  robot.joints[0].maximum = 2.5;
  robot.joints[1].type = JointType::kPrismatic;
  robot.joints[1].minimum = 0;
  robot.joints[1].maximum = 10;
  const JointLimits from_robot = position_limits_of(robot);
  EXPECT_EQ(from_robot.lower, Eigen::Vector2d(-1.5, 0));
  EXPECT_EQ(from_robot.upper, Eigen::Vector2d(2.5, 10));
  EXPECT_TRUE(std::isinf(from_robot.max_speed[0]) && std::isinf(from_robot.max_speed[1]));
}

TEST(JointLimitCheck, SpeedLimitsComeFromTheJointsMaxVelocity) {
  RobotModel robot;
  robot.joints.resize(2);
  robot.joints[0].minimum = -1;
  robot.joints[0].maximum = 1;
  robot.joints[0].max_velocity = 2.5;
  robot.joints[1].minimum = -1;
  robot.joints[1].maximum = 1;  // max_velocity left at its default: no limit
  const JointLimits from_robot = joint_limits_of(robot);
  EXPECT_EQ(from_robot.lower, Eigen::Vector2d(-1, -1));
  EXPECT_EQ(from_robot.max_speed[0], 2.5);
  EXPECT_TRUE(std::isinf(from_robot.max_speed[1]));
  // 0 -> 1 in 0.5 s at rest at both ends (cubic): peak 1.5 * 1 / 0.5 = 3 rad/s at t = 0.25 s,
  // beyond joint 1's 2.5; joint 2 moves as fast unchecked.
  const JointTrajectoryMotion motion =
      motion_from_csv("time,a,b,a.vel,b.vel\n0,0,0,0,0\n0.5,1,1,0,0\n");
  const auto violation = first_limit_violation(motion, from_robot);
  ASSERT_TRUE(violation);
  EXPECT_EQ(violation->joint, 0);
  EXPECT_EQ(violation->kind, LimitKind::kOverSpeed);
  EXPECT_EQ(violation->time, 0.25);
  EXPECT_EQ(violation->value, 3.0);
  EXPECT_EQ(violation->limit, 2.5);
  robot.joints[0].max_velocity = 3.0;  // touching the limit is within it
  EXPECT_FALSE(first_limit_violation(motion, joint_limits_of(robot)));
}

TEST(JointLimitCheck, RejectsMalformedLimits) {
  const JointTrajectoryMotion motion = motion_from_csv("time,a\n0,0\n1,1\n");
  EXPECT_THROW(first_limit_violation(motion, limits({0, 0}, {1, 1}, {1, 1})), std::invalid_argument);
  EXPECT_THROW(first_limit_violation(motion, limits({2}, {1}, {1})), std::invalid_argument);
  EXPECT_THROW(first_limit_violation(motion, limits({0}, {1}, {-1})), std::invalid_argument);
  EXPECT_THROW(first_limit_violation(motion, limits({0}, {1}, {std::nan("")})), std::invalid_argument);
}

}  // namespace
}  // namespace grpvss::motion
