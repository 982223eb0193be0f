#include <string>

#include <gtest/gtest.h>

#include "grpvss/io/trajectory_file.hpp"
#include "support/input_error_expectations.hpp"
#include "support/joint_vector.hpp"

namespace grpvss::io {
namespace {

using grpvss::test::vector;
using grpvss::testing::expect_input_error;

void expect_csv_error(const std::string& text, int line, const std::string& message) {
  expect_input_error([&] { parse_trajectory_csv(text, "t.csv"); }, "t.csv", line,
                     "t.csv:" + std::to_string(line) + ": " + message);
}

TEST(TrajectoryCsv, ReadsTheSixJointSample) {
  const std::string path = std::string(GRPVSS_SOURCE_DIR) + "/data/trajectories/ur5e-pick.csv";
  const JointTrajectory trajectory = read_trajectory_file(path);
  EXPECT_EQ(trajectory.format, TrajectoryFormat::kCsv);
  EXPECT_EQ(trajectory.source_file, path);
  EXPECT_EQ(trajectory.joint_names,
            (std::vector<std::string>{"shoulder_pan_joint", "shoulder_lift_joint", "elbow_joint",
                                      "wrist_1_joint", "wrist_2_joint", "wrist_3_joint"}));
  EXPECT_EQ(trajectory.joint_names_line, 4);
  EXPECT_EQ(trajectory.times, (std::vector<double>{0.0, 0.5, 1.0, 1.5, 2.0, 2.5}));
  EXPECT_EQ(trajectory.source_lines, (std::vector<int>{5, 6, 7, 8, 9, 10}));
  ASSERT_EQ(trajectory.positions.size(), 6u);
  EXPECT_EQ(trajectory.positions[0], vector({0.0, -1.5708, 1.5708, -1.5708, -1.5708, 0.0}));
  EXPECT_EQ(trajectory.positions[3], vector({0.6, -1.2, 1.05, -1.42, -1.5708, 0.3}));
  EXPECT_FALSE(trajectory.has_velocities());
  EXPECT_EQ(describe_waypoint(trajectory, 3), "line 8");
}

TEST(TrajectoryCsv, VelocityColumnsMayComeInAnyOrderAfterTime) {
  const JointTrajectory trajectory = parse_trajectory_csv(
      "time, b.vel, a, b, a.vel\n0.5, 1, 2, 3, 4\n1.5e0, -1, -2, -3, -4\n", "v.csv");
  EXPECT_EQ(trajectory.joint_names, (std::vector<std::string>{"a", "b"}));
  EXPECT_EQ(trajectory.times, (std::vector<double>{0.5, 1.5}));
  EXPECT_EQ(trajectory.positions[0], vector({2, 3}));
  EXPECT_EQ(trajectory.velocities[0], vector({4, 1}));
  EXPECT_EQ(trajectory.velocities[1], vector({-4, -1}));
}

TEST(TrajectoryCsv, SkipsCommentsBlankLinesCarriageReturnsAndAByteOrderMark) {
  const JointTrajectory trajectory = parse_trajectory_csv(
      "\xEF\xBB\xBF# planner output\r\n\r\ntime,j1   # header\r\n  \r\n0,+0.25\r\n# end\r\n1,-.5",
      "c.csv");
  EXPECT_EQ(trajectory.joint_names_line, 3);
  EXPECT_EQ(trajectory.source_lines, (std::vector<int>{5, 7}));
  EXPECT_EQ(trajectory.positions[0][0], 0.25);
  EXPECT_EQ(trajectory.positions[1][0], -0.5);
}

TEST(TrajectoryCsv, RejectsBadHeaders) {
  expect_csv_error("", 1, "expected a header line 'time,<joint names>', found end of file");
  expect_csv_error("# only a comment\n", 2,
                   "expected a header line 'time,<joint names>', found end of file");
  expect_csv_error("t,a\n0,1\n", 1, "expected 'time' as the first column of the header, found 't'");
  expect_csv_error("time,a,,b\n", 1, "expected a column name (column 3), found an empty field");
  expect_csv_error("time,\"a\"\n", 1,
                   "expected a column name without quotes or blanks (column 2), found '\"a\"'");
  expect_csv_error("time,a b\n", 1,
                   "expected a column name without quotes or blanks (column 2), found 'a b'");
  expect_csv_error("time,a,b,a\n", 1, "expected every column named once, found 'a' in columns 2 and 4");
  expect_csv_error("time\n0\n", 1, "expected at least one joint column after 'time', found 1 column");
  expect_csv_error("time,a,b.vel\n", 1,
                   "expected a position column 'b' for the velocity column 'b.vel', found none");
  expect_csv_error("time,a,b,c,b.vel\n", 1,
                   "expected a velocity column for every joint or for none, found velocity "
                   "columns for 1 of 3 joints (no a.vel, c.vel)");
}

TEST(TrajectoryCsv, RejectsBadRows) {
  const std::string header = "time,a,b\n";
  expect_csv_error(header, 2, "expected at least one waypoint row after the header, found end of file");
  expect_csv_error(header + "0,1\n", 2,
                   "expected 3 comma-separated values (one per header column), found 2 values");
  expect_csv_error(header + "0,1,2,3\n", 2,
                   "expected 3 comma-separated values (one per header column), found 4 values");
  expect_csv_error(header + "0,1,2,\n", 2,
                   "expected 3 comma-separated values (one per header column), found 4 values");
  expect_csv_error(header + "0,1,x\n", 2, "expected a number for column 'b', found 'x'");
  expect_csv_error(header + "0,1,\n", 2, "expected a number for column 'b', found ''");
}

TEST(TrajectoryCsv, RejectsNonFiniteAndHugeNumbers) {
  const std::string header = "time,a,b\n";
  expect_csv_error(header + "0,nan,1\n", 2, "expected a finite number for column 'a', found 'nan'");
  expect_csv_error(header + "0,1,-inf\n", 2, "expected a finite number for column 'b', found '-inf'");
  expect_csv_error(header + "0,1,2e9\n", 2,
                   "expected a number of magnitude at most 1e9 for column 'b', found '2e9'");
  expect_csv_error(header + "1e400,1,2\n", 2,
                   "expected a number of magnitude at most 1e9 for column 'time', found '1e400'");
}

TEST(TrajectoryCsv, RejectsNegativeAndNonIncreasingTimes) {
  const std::string header = "time,a\n";
  expect_csv_error(header + "-0.5,1\n", 2, "expected time >= 0 s, found -0.5 s");
  expect_csv_error(header + "0,1\n# gap\n0,2\n", 4,
                   "expected time greater than 0 s (the time of the previous waypoint, line 2), "
                   "found 0 s");
  expect_csv_error(header + "0,1\n1.5,2\n1.25,3\n", 4,
                   "expected time greater than 1.5 s (the time of the previous waypoint, line 3), "
                   "found 1.25 s");
}

TEST(TrajectoryFile, NamesAnUnreadableFileOnLineZero) {
  const std::string path = std::string(GRPVSS_SOURCE_DIR) + "/data/trajectories/missing.csv";
  try {
    read_trajectory_file(path);
    ADD_FAILURE() << "no InputError";
  } catch (const InputError& error) {
    EXPECT_EQ(error.file(), path);
    EXPECT_EQ(error.line(), 0);
    EXPECT_EQ(error.expected(), "a readable file");
  }
}

}  // namespace
}  // namespace grpvss::io
