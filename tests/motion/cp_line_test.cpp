#include "grpvss/motion/cp_line.hpp"

#include <cmath>

#include <gtest/gtest.h>

#include "motion/cartesian_robot.hpp"

namespace grpvss::motion {
namespace {

Eigen::Isometry3d pose(double x, double y, double z, double yaw) {
  Eigen::Isometry3d X = Eigen::Isometry3d::Identity();
  X.translation() << x, y, z;
  X.linear() = Eigen::AngleAxisd(yaw, Eigen::Vector3d::UnitZ()).toRotationMatrix();
  return X;
}

WorldTarget target(double x, double y, double z, Eigen::Vector3d axis, double angle) {
  WorldTarget t;
  t.position_W << x, y, z;
  t.axis_W = axis;
  t.angle = angle;
  return t;
}

TEST(CpLine, FollowsEq417AndEq418) {
  // Start tilted about x so that a world-z rotation and a tool-z rotation differ.
  Eigen::Isometry3d X_WE_start = pose(1, 2, 3, 0.3);
  X_WE_start.linear() = Eigen::AngleAxisd(0.4, Eigen::Vector3d::UnitX()) * X_WE_start.linear();
  // Non-unit axis: K is normalised.
  const CpLine line(X_WE_start, target(4, 6, 3, Eigen::Vector3d(0, 0, -2), 0.6));
  EXPECT_DOUBLE_EQ(line.length(), 5.0);
  const Eigen::Isometry3d X_mid = line.pose_at(2.0);
  EXPECT_TRUE(X_mid.translation().isApprox(Eigen::Vector3d(1 + 3 * 0.4, 2 + 4 * 0.4, 3), 1e-15));
  const Eigen::Matrix3d R_expected =
      Eigen::AngleAxisd(-0.6 * 0.4, Eigen::Vector3d::UnitZ()).toRotationMatrix() * X_WE_start.linear();
  EXPECT_TRUE(X_mid.linear().isApprox(R_expected, 1e-14));
  // o_f = Rot(K, theta) o_s, the same as the PTP(WCS) target pose.
  const Eigen::Isometry3d X_end = line.end_pose();
  const Eigen::Isometry3d X_target = world_target_pose(X_WE_start, target(4, 6, 3, Eigen::Vector3d(0, 0, -2), 0.6));
  EXPECT_TRUE(X_end.isApprox(X_target, 1e-14));
  EXPECT_EQ(X_end.translation(), Eigen::Vector3d(4, 6, 3));
  EXPECT_TRUE(line.pose_at(-1).isApprox(X_WE_start, 1e-15));
}

TEST(CpLine, AxisMinusZThirtyDegreesLowersYawByThirty) {
  const Eigen::Isometry3d X = world_target_pose(pose(0, 0, 0, 0.5), target(0, 0, 0, -Eigen::Vector3d::UnitZ(), M_PI / 6));
  EXPECT_TRUE(X.linear().isApprox(pose(0, 0, 0, 0.5 - M_PI / 6).linear(), 1e-15));
}

// A YAML path's absolute orientation: the target pose ignores the start orientation, and the
// line turns the shortest way about one world axis, from the start to exactly that orientation.
TEST(CpLine, AnAbsoluteOrientationIsReachedByTheShortestTurnFromTheStart) {
  Eigen::Isometry3d X_WE_start = pose(1, 2, 3, 0.3);
  X_WE_start.linear() = Eigen::AngleAxisd(0.4, Eigen::Vector3d::UnitX()) * X_WE_start.linear();
  WorldTarget absolute = target(4, 6, 3, Eigen::Vector3d(0, 1, 1), 2.0);
  absolute.orientation_is_absolute = true;
  const Eigen::Matrix3d R_WE_target =
      Eigen::AngleAxisd(2.0, Eigen::Vector3d(0, 1, 1).normalized()).toRotationMatrix();
  EXPECT_TRUE(world_target_pose(X_WE_start, absolute).linear().isApprox(R_WE_target, 1e-15));
  const CpLine line(X_WE_start, absolute);
  EXPECT_TRUE(line.end_pose().linear().isApprox(R_WE_target, 1e-14));
  const Eigen::AngleAxisd change = orientation_change_W(X_WE_start, absolute);
  EXPECT_TRUE((change.toRotationMatrix() * X_WE_start.linear()).isApprox(R_WE_target, 1e-14));
  EXPECT_LE(change.angle(), M_PI);
  // Halfway, the orientation is the start turned by half the angle about the same axis.
  const Eigen::Matrix3d R_half = Eigen::AngleAxisd(change.angle() / 2, change.axis()) * X_WE_start.linear();
  EXPECT_TRUE(line.pose_at(line.length() / 2).linear().isApprox(R_half, 1e-14));
  // The start orientation itself as the target: no turn at all.
  WorldTarget same = target(4, 6, 3, Eigen::Vector3d::UnitZ(), 0.0);
  same.orientation_is_absolute = true;
  const Eigen::AngleAxisd start_as_axis_angle(X_WE_start.linear());
  same.axis_W = start_as_axis_angle.axis();
  same.angle = start_as_axis_angle.angle();
  EXPECT_LT(orientation_change_W(X_WE_start, same).angle(), 1e-15);
}

TEST(CpLine, SamplesAreUniformNoWiderThanTheSpacingAndSolveIk) {
  const RobotModel robot = testing::cartesian_robot();
  const Eigen::Vector4d q_start(0, 0, 1, 0.2);
  const CpLine line(pose(0, 0, 1, 0.2), target(3, 0, 1, Eigen::Vector3d::UnitZ(), 1.0));
  const CpSampling sampling = sample_cp_line(robot, testing::cartesian_kinematics(), line, q_start, 0.4, 7);
  ASSERT_FALSE(sampling.error);
  ASSERT_EQ(sampling.samples.size(), 9u);  // ceil(3 / 0.4) = 8 pieces
  for (std::size_t k = 0; k < sampling.samples.size(); ++k) {
    const double l = 3.0 * k / 8;
    EXPECT_NEAR(sampling.samples[k].l, l, 1e-15);
    EXPECT_NEAR(sampling.samples[k].q[0], l, 1e-12);
    EXPECT_NEAR(sampling.samples[k].q[3], 0.2 + l / 3.0, 1e-12);
  }
}

TEST(CpLine, ZeroLengthIsError4InAPathAndError1Alone) {
  const RobotModel robot = testing::cartesian_robot();
  const CpLine line(pose(1, 1, 1, 0), target(1, 1, 1, Eigen::Vector3d::UnitZ(), 0.5));
  EXPECT_TRUE(line.is_zero_length());
  const Eigen::Vector4d q(1, 1, 1, 0);
  const auto in_path = sample_cp_line(robot, testing::cartesian_kinematics(), line, q, 0.5, 3);
  ASSERT_TRUE(in_path.error);
  EXPECT_EQ(in_path.error->code, 4);
  EXPECT_EQ(in_path.error->segment, 3);
  EXPECT_EQ(in_path.error->message,
            "The movement of the end effector in the CP operation of motion segment 3 in the input "
            "path file is zero. PTP operation is suggested if the error is not caused by a mistake.");
  const auto alone = sample_cp_line(robot, testing::cartesian_kinematics(), line, q, 0.5, 0);
  ASSERT_TRUE(alone.error);
  EXPECT_EQ(alone.error->code, 1);
}

TEST(CpLine, UnreachableEndIsError3) {
  const RobotModel robot = testing::cartesian_robot(10.0);
  const CpLine line(pose(0, 0, 0, 0), target(12, 0, 0, Eigen::Vector3d::UnitZ(), 0));
  const auto result = sample_cp_line(robot, testing::cartesian_kinematics(), line, Eigen::Vector4d::Zero(), 0.5, 2);
  ASSERT_TRUE(result.error);
  EXPECT_EQ(result.error->code, 3);
  EXPECT_EQ(result.error->segment, 2);
  EXPECT_TRUE(result.samples.empty());
}

TEST(CpLine, UnreachableIntermediatePointIsError5) {
  // The yaw turns by 1.8 pi over the line: the end pose (yaw 1.8 pi = -0.2 pi) is reachable
  // from q = 0, but the samples, each IK nearest the previous, walk continuously past the
  // yaw limit +pi.
  const RobotModel robot = testing::cartesian_robot(10.0);
  const CpLine line(pose(0, 0, 0, 0), target(4, 0, 0, Eigen::Vector3d::UnitZ(), 1.8 * M_PI));
  const auto result = sample_cp_line(robot, testing::cartesian_kinematics(), line, Eigen::Vector4d::Zero(), 0.5, 5);
  ASSERT_TRUE(result.error);
  EXPECT_EQ(result.error->code, 5);
  EXPECT_EQ(result.error->segment, 5);
  // Samples stop before the unreachable one: the yaw crosses pi at l = 4 * pi / (1.8 pi) = 2.22.
  ASSERT_FALSE(result.samples.empty());
  EXPECT_LT(result.samples.back().l, 2.23);
  EXPECT_GT(result.samples.back().l, 2.22 - 0.5);
}

TEST(ThesisError, WordingFollowsAppendixA4) {
  EXPECT_EQ(thesis_error_text(3, 4),
            "The final position of the motion segment 4 in the path input file is out of workspace. "
            "This motion segment was not simulated. The simulation terminated when this motion "
            "segment was encountered.");
  EXPECT_EQ(thesis_error_text(5, 2),
            "Unreachable intermediate point was encountered in the motion segment 2 in the input "
            "file. Simulation terminated at that point. This motion segment is out of the workspace.");
  EXPECT_EQ(thesis_error_text(6, 1),
            "Undefined operation type data was encountered in motion segment 1 in the input file. "
            "Simulation terminated at that point. Check the path input file.");
  EXPECT_EQ(thesis_error_text(2, 0),
            "Unreachable intermediate point was encountered. Simulation terminated at that point. "
            "This path is out of the workspace.");
  EXPECT_THROW(thesis_error_text(7, 1), std::invalid_argument);
}

}  // namespace
}  // namespace grpvss::motion
