#include <stdexcept>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "grpvss/io/trajectory_file.hpp"
#include "support/input_error_expectations.hpp"

namespace grpvss::io {
namespace {

using grpvss::testing::expect_input_error;

JointTrajectory three_joints_with_velocities() {
  return parse_trajectory_csv(
      "# header on line 2\ntime,c,a,b,a.vel,b.vel,c.vel\n0,3,1,2,10,20,30\n1,6,4,5,40,50,60\n",
      "m.csv");
}

TEST(MatchJoints, ReordersPositionsAndVelocitiesIntoRobotOrder) {
  const JointTrajectory matched = match_joints(three_joints_with_velocities(), {"a", "b", "c"});
  EXPECT_EQ(matched.joint_names, (std::vector<std::string>{"a", "b", "c"}));
  EXPECT_EQ(matched.positions[0], Eigen::Vector3d(1, 2, 3));
  EXPECT_EQ(matched.positions[1], Eigen::Vector3d(4, 5, 6));
  EXPECT_EQ(matched.velocities[0], Eigen::Vector3d(10, 20, 30));
  EXPECT_EQ(matched.velocities[1], Eigen::Vector3d(40, 50, 60));
  EXPECT_EQ(matched.times, (std::vector<double>{0, 1}));
  EXPECT_EQ(matched.source_lines, (std::vector<int>{3, 4}));
}

TEST(MatchJoints, NamesMissingAndExtraJointsAtTheHeaderLine) {
  expect_input_error([] { match_joints(three_joints_with_velocities(), {"a", "b", "d", "e"}); },
                     "m.csv", 2,
                     "m.csv:2: expected the robot's joints, each once: a, b, d, e, found missing "
                     "d, e; extra c");
  expect_input_error([] { match_joints(three_joints_with_velocities(), {"a", "b"}); }, "m.csv", 2,
                     "m.csv:2: expected the robot's joints, each once: a, b, found extra c");
}

TEST(MatchJoints, NamesJointsTheTrajectoryNamesTwice) {
  // The readers reject duplicates themselves; a trajectory built in code may still have them.
  JointTrajectory trajectory = three_joints_with_velocities();
  trajectory.joint_names = {"a", "a", "c"};
  expect_input_error([&] { match_joints(trajectory, {"a", "b", "c"}); }, "m.csv", 2,
                     "m.csv:2: expected the robot's joints, each once: a, b, c, found missing b; "
                     "named twice a");
}

TEST(MatchJoints, ARobotNamingAJointTwiceIsTheCallersError) {
  EXPECT_THROW(match_joints(three_joints_with_velocities(), {"a", "a", "c"}), std::invalid_argument);
}

}  // namespace
}  // namespace grpvss::io
