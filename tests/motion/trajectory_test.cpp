#include "grpvss/motion/trajectory.hpp"

#include <cmath>

#include <gtest/gtest.h>

#include "motion/cartesian_robot.hpp"

namespace grpvss::motion {
namespace {

PathSegment joint_segment(Eigen::Vector4d target, Eigen::Vector4d velocity) {
  return PathSegment{PtpJointSegment{target, velocity}, 0};
}

WorldTarget world(double x, double y, double z, double angle) {
  WorldTarget t;
  t.position_W << x, y, z;
  t.axis_W = Eigen::Vector3d(0, 0, -1);
  t.angle = angle;
  return t;
}

PathProgram sample_program() {
  PathProgram program;
  program.segments.push_back(PathSegment{PtpWorldSegment{world(2, 3, 1, 0.5), Eigen::Vector4d(1, 1, 1, 1)}, 0});
  program.segments.push_back(PathSegment{CpLineSegment{world(2, -1, 4, 0.2)}, 0});  // length 5
  program.segments.push_back(joint_segment(Eigen::Vector4d(0, 0, 0, 0), Eigen::Vector4d(2, 2, 2, 2)));
  return program;
}

TEST(Trajectory, SegmentsChainFromHomeWithTheirCycleTimes) {
  const RobotModel robot = testing::cartesian_robot();
  MotionModel options;
  options.cp_speed = 2.0;
  options.cp_spacing = 0.25;
  const Trajectory trajectory =
      Trajectory::plan(robot, sample_program(), testing::cartesian_kinematics(), options);
  ASSERT_TRUE(trajectory.errors().empty());
  ASSERT_EQ(trajectory.segments().size(), 3u);
  const auto& s = trajectory.segments();
  // Segment 1: IK of (2,3,1), yaw 0 - 0.5 (axis -z lowers the yaw).
  EXPECT_TRUE(s[0].q_end.isApprox(Eigen::Vector4d(2, 3, 1, -0.5), 1e-15));
  EXPECT_EQ(s[0].kind, SegmentKind::kPtpWorld);
  // Segment 2: CP, 5 units at 2 units/s = 2.5 s; 20 pieces of 0.25.
  EXPECT_EQ(s[1].kind, SegmentKind::kCpLine);
  EXPECT_DOUBLE_EQ(s[1].duration, 2.5);
  EXPECT_EQ(s[1].cp_samples.size(), 21u);
  EXPECT_TRUE(s[1].q_end.isApprox(Eigen::Vector4d(2, -1, 4, -0.7), 1e-14));
  EXPECT_EQ(s[2].q_end, Eigen::Vector4d::Zero().eval());
  for (std::size_t i = 1; i < s.size(); ++i) {
    EXPECT_EQ(s[i].start_time, s[i - 1].end_time());
    EXPECT_EQ(s[i].q_start, s[i - 1].q_end);
  }
  EXPECT_DOUBLE_EQ(trajectory.duration(), s[0].duration + 2.5 + s[2].duration);
  // joints_at: continuous across segment boundaries, CP point halfway along the line.
  for (const auto& piece : s) {
    EXPECT_TRUE(trajectory.joints_at(piece.start_time)->isApprox(piece.q_start, 1e-12));
    EXPECT_TRUE(trajectory.joints_at(piece.end_time())->isApprox(piece.q_end, 1e-12));
  }
  const Eigen::VectorXd mid = *trajectory.joints_at(s[1].start_time + 1.25);
  EXPECT_TRUE(mid.isApprox(Eigen::Vector4d(2, 1, 2.5, -0.6), 1e-14));
  EXPECT_EQ(*trajectory.joints_at(1e9), s[2].q_end);
}

TEST(Trajectory, ErrorStopsThePathAndKeepsEarlierSegments) {
  const RobotModel robot = testing::cartesian_robot(10.0);
  PathProgram program = sample_program();
  program.segments.insert(program.segments.begin() + 2,
                          PathSegment{CpLineSegment{world(2, -1, 4, 0.0)}, 0});  // zero length
  const Trajectory trajectory =
      Trajectory::plan(robot, program, testing::cartesian_kinematics(), MotionModel{});
  ASSERT_EQ(trajectory.errors().size(), 1u);
  EXPECT_EQ(trajectory.errors()[0].code, 4);
  EXPECT_EQ(trajectory.errors()[0].segment, 3);
  EXPECT_EQ(trajectory.segments().size(), 2u);
}

TEST(Trajectory, JointTargetOutsideLimitsIsError3) {
  const RobotModel robot = testing::cartesian_robot(10.0);
  PathProgram program;
  program.segments.push_back(joint_segment(Eigen::Vector4d(1, 1, 1, 0), Eigen::Vector4d(1, 1, 1, 1)));
  program.segments.push_back(joint_segment(Eigen::Vector4d(1, 11, 1, 0), Eigen::Vector4d(1, 1, 1, 1)));
  const Trajectory trajectory =
      Trajectory::plan(robot, program, testing::cartesian_kinematics(), MotionModel{});
  ASSERT_EQ(trajectory.errors().size(), 1u);
  EXPECT_EQ(trajectory.errors()[0].code, 3);
  EXPECT_EQ(trajectory.errors()[0].segment, 2);
  EXPECT_NE(trajectory.errors()[0].detail.find("joint 2"), std::string::npos);
  EXPECT_EQ(trajectory.segments().size(), 1u);
}

TEST(Trajectory, UnreachableWorldTargetIsError3) {
  const RobotModel robot = testing::cartesian_robot(10.0);
  PathProgram program;
  program.segments.push_back(PathSegment{PtpWorldSegment{world(0, 0, 20, 0), Eigen::Vector4d(1, 1, 1, 1)}, 0});
  const Trajectory trajectory =
      Trajectory::plan(robot, program, testing::cartesian_kinematics(), MotionModel{});
  ASSERT_EQ(trajectory.errors().size(), 1u);
  EXPECT_EQ(trajectory.errors()[0].code, 3);
  EXPECT_EQ(trajectory.errors()[0].segment, 1);
  EXPECT_TRUE(trajectory.segments().empty());
  EXPECT_EQ(trajectory.duration(), 0.0);
}

TEST(Trajectory, SynchronizedTimingReachesEveryJointTogether) {
  const RobotModel robot = testing::cartesian_robot();
  PathProgram program;
  program.segments.push_back(joint_segment(Eigen::Vector4d(4, 1, -2, 0.5), Eigen::Vector4d(1, 1, 1, 1)));
  MotionModel options;
  options.timing = PtpTiming::kSynchronized;
  const Trajectory trajectory = Trajectory::plan(robot, program, testing::cartesian_kinematics(), options);
  const auto& ptp = *trajectory.segments()[0].ptp;
  for (const auto& joint : ptp.joints()) EXPECT_EQ(joint.duration(), trajectory.duration());
}

}  // namespace
}  // namespace grpvss::motion
