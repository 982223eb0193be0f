#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "grpvss/io/trajectory_file.hpp"
#include "support/input_error_expectations.hpp"
#include "support/joint_vector.hpp"

namespace grpvss::io {
namespace {

using grpvss::test::vector;
using grpvss::testing::expect_input_error;

/// A document with joints a, b whose points are on lines 4, 5, ... (one per line).
std::string document(const std::vector<std::string>& points) {
  std::string text = "{\n\"joint_names\": [\"a\", \"b\"],\n\"points\": [\n";
  for (std::size_t k = 0; k < points.size(); ++k) text += points[k] + (k + 1 < points.size() ? ",\n" : "\n");
  return text + "]\n}\n";
}

const std::string kPoint0 = R"({"positions": [1, 2], "time_from_start": 0})";

void expect_json_error(const std::string& text, int line, const std::string& message) {
  expect_input_error([&] { parse_trajectory_json(text, "t.json"); }, "t.json", line,
                     "t.json:" + std::to_string(line) + ": " + message);
}

TEST(TrajectoryJson, ReadsTheOvershootSample) {
  const std::string path = std::string(GRPVSS_SOURCE_DIR) + "/data/trajectories/overshoot.json";
  const JointTrajectory trajectory = read_trajectory_file(path);
  EXPECT_EQ(trajectory.format, TrajectoryFormat::kRosJson);
  EXPECT_EQ(trajectory.joint_count(), 6);
  EXPECT_EQ(trajectory.joint_names[2], "elbow_joint");
  EXPECT_EQ(trajectory.joint_names_line, 3);
  EXPECT_EQ(trajectory.times, (std::vector<double>{0.5, 1.5, 2.5}));
  EXPECT_EQ(trajectory.source_lines, (std::vector<int>{6, 11, 16}));
  EXPECT_EQ(trajectory.positions[1], vector({0.4, -1.3, 2.0, -1.5, -1.5708, 0.2}));
  ASSERT_TRUE(trajectory.has_velocities());
  EXPECT_EQ(trajectory.velocities[1], vector({0.3, 0.2, 1.5, 0.05, 0.0, 0.1}));
  EXPECT_EQ(trajectory.velocities[2], vector({0, 0, 0, 0, 0, 0}));
  EXPECT_EQ(describe_waypoint(trajectory, 1), "points[1] (line 11)");
}

TEST(TrajectoryJson, TimeFromStartIsSecondsOrRosDurations) {
  const JointTrajectory trajectory = parse_trajectory_json(
      document({R"({"positions": [0, 0], "time_from_start": 0.25})",
                R"({"positions": [1, 1], "time_from_start": {"sec": 0, "nanosec": 300000000}})",
                R"({"positions": [2, 2], "time_from_start": {"secs": 2, "nsecs": 1}})",
                R"({"positions": [3, 3], "time_from_start": 7})"}),
      "d.json");
  // {sec, nanosec} is the double nearest to sec + nanosec 1e-9: 0.3 reads as the literal 0.3.
  EXPECT_EQ(trajectory.times, (std::vector<double>{0.25, 0.3, 2.000000001, 7.0}));
  EXPECT_EQ(trajectory.source_lines, (std::vector<int>{4, 5, 6, 7}));
}

TEST(TrajectoryJson, EmptyVelocitiesAndAccelerationsMeanNoneAndEffortIsIgnored) {
  const JointTrajectory trajectory = parse_trajectory_json(
      document({R"({"positions": [0, 0], "velocities": [], "accelerations": [], "effort": [9, 9], "time_from_start": 0})",
                R"({"positions": [1, 1], "velocities": [], "time_from_start": 1})"}),
      "d.json");
  EXPECT_FALSE(trajectory.has_velocities());
  EXPECT_EQ(trajectory.positions[1], vector({1, 1}));
}

TEST(TrajectoryJson, NamesTheLineOfASyntaxErrorOrAnOverflow) {
  expect_json_error(document({kPoint0, R"({"positions": [1, 2,], "time_from_start": 1})"}), 5,
                    "expected a JSON document, found parse error at line 5, column 21: syntax error "
                    "while parsing value - unexpected ']'; expected '[', '{', or a literal");
  expect_json_error(document({kPoint0, R"({"positions": [1, 1e400], "time_from_start": 1})"}), 5,
                    "expected a JSON document, found number overflow parsing '1e400'");
  expect_json_error("", 1,
                    "expected a JSON document, found parse error at line 1, column 1: syntax error "
                    "while parsing value - unexpected end of input; expected '[', '{', or a literal");
}

TEST(TrajectoryJson, RejectsBadTopLevels) {
  expect_json_error("\n[1, 2]", 2,
                    "expected a JSON object with 'joint_names' and 'points' "
                    "(trajectory_msgs/JointTrajectory), found an array of 2");
  expect_json_error("{\"joint_names\": [\"a\"],\n \"pionts\": []}", 2,
                    "expected only joint_names, points and header at the top level, found 'pionts'");
  expect_json_error("{\n\"joint_names\": [\"a\"]}", 1,
                    "expected a member 'points' in the top-level object, found none");
  expect_json_error("{\"joint_names\": [\"a\"],\n\"joint_names\": [\"b\"]}", 2,
                    "expected each top-level member once, found 'joint_names' again");
  expect_json_error("{\"joint_names\": [],\n\"points\": []}", 1,
                    "expected a non-empty array of joint names in joint_names, found an array of 0");
  expect_json_error("{\"joint_names\": [\"a\", 3],\n\"points\": []}", 1,
                    "expected a non-empty string in joint_names[1], found the number 3");
  expect_json_error("{\"joint_names\": [\"a\", \"a\"],\n\"points\": []}", 1,
                    "expected each joint named once in joint_names[1], found 'a' again");
  expect_json_error("{\"joint_names\": [\"a\"],\n\"points\": []}", 2,
                    "expected a non-empty array of points in points, found an array of 0");
}

TEST(TrajectoryJson, RejectsBadPoints) {
  expect_json_error(document({"[1, 2]"}), 4, "expected an object in points[0], found an array of 2");
  expect_json_error(document({kPoint0, R"({"positions": [1, 2], "time_from_start": 1, "postions": []})"}), 5,
                    "expected only positions, velocities, accelerations, effort and time_from_start "
                    "in points[1], found 'postions'");
  expect_json_error(document({R"({"time_from_start": 1})"}), 4,
                    "expected a member 'positions' in points[0], found none");
  expect_json_error(document({R"({"positions": [1, 2]})"}), 4,
                    "expected a member 'time_from_start' in points[0], found none");
  expect_json_error(document({R"({"positions": [1, 2], "positions": [1, 2], "time_from_start": 0})"}), 4,
                    "expected each member once in points[0], found 'positions' again");
  expect_json_error(document({R"({"positions": [1], "time_from_start": 0})"}), 4,
                    "expected an array of 2 numbers (one per joint name) in points[0].positions, "
                    "found an array of 1");
  expect_json_error(document({R"({"positions": [1, "2"], "time_from_start": 0})"}), 4,
                    "expected a number in points[0].positions[1], found the string '2'");
  expect_json_error(document({R"({"positions": [1, true], "time_from_start": 0})"}), 4,
                    "expected a number in points[0].positions[1], found true");
  expect_json_error(document({R"({"positions": [1, -2e9], "time_from_start": 0})"}), 4,
                    "expected a number of magnitude at most 1e9 in points[0].positions[1], found "
                    "the number -2000000000.0");
  expect_json_error(document({R"({"positions": [1, 2], "accelerations": [0, 0], "time_from_start": 0})"}), 4,
                    "expected no accelerations (quintic interpolation is not supported) in "
                    "points[0].accelerations, found an array of 2");
}

TEST(TrajectoryJson, ReportsTheLineOfTheMemberInAMultiLinePoint) {
  const std::string text =
      "{\"joint_names\": [\"a\"], \"points\": [\n"
      "  {\n"
      "    \"time_from_start\": 0,\n"
      "    \"positions\":\n"
      "      [\"x\"]\n"
      "  }]}";
  expect_json_error(text, 4, "expected a number in points[0].positions[0], found the string 'x'");
}

TEST(TrajectoryJson, RequiresVelocitiesInEveryPointOrInNone) {
  expect_json_error(document({R"({"positions": [1, 2], "velocities": [0, 0], "time_from_start": 0})",
                              R"({"positions": [1, 2], "time_from_start": 1})"}),
                    5,
                    "expected velocities in every point or in none (points[0] has them) in "
                    "points[1].velocities, found none");
  expect_json_error(document({kPoint0, R"({"positions": [1, 2], "velocities": [0, 0], "time_from_start": 1})"}),
                    5,
                    "expected velocities in every point or in none (points[0] has none) in "
                    "points[1].velocities, found velocities");
  expect_json_error(document({R"({"positions": [1, 2], "velocities": [0], "time_from_start": 0})"}), 4,
                    "expected an array of 2 numbers (one per joint name) in points[0].velocities, "
                    "found an array of 1");
}

TEST(TrajectoryJson, RejectsBadTimes) {
  const auto with_time = [](const std::string& time) {
    return document({kPoint0, R"({"positions": [1, 2], "time_from_start": )" + time + "}"});
  };
  expect_json_error(with_time("\"1\""), 5,
                    "expected seconds or an object {\"sec\": ..., \"nanosec\": ...} in "
                    "points[1].time_from_start, found the string '1'");
  expect_json_error(with_time(R"({"sec": 1})"), 5,
                    "expected seconds or an object {\"sec\": ..., \"nanosec\": ...} in "
                    "points[1].time_from_start, found an object");
  expect_json_error(with_time(R"({"sec": 1, "nsecs": 0})"), 5,
                    "expected an integer in points[1].time_from_start.nanosec, found nothing");
  expect_json_error(with_time(R"({"sec": 1.5, "nanosec": 0})"), 5,
                    "expected an integer in [0, 1000000000] in points[1].time_from_start.sec, "
                    "found the number 1.5");
  expect_json_error(with_time(R"({"sec": -1, "nanosec": 0})"), 5,
                    "expected an integer in [0, 1000000000] in points[1].time_from_start.sec, "
                    "found the number -1");
  expect_json_error(with_time(R"({"sec": 1, "nanosec": 1000000000})"), 5,
                    "expected an integer in [0, 999999999] in points[1].time_from_start.nanosec, "
                    "found the number 1000000000");
  expect_json_error(with_time("-0.5"), 5, "expected points[1].time_from_start >= 0 s, found -0.5 s");
  expect_json_error(with_time("0"), 5,
                    "expected points[1].time_from_start greater than 0 s (the time of the previous "
                    "waypoint, points[0] (line 4)), found 0 s");
}

}  // namespace
}  // namespace grpvss::io
