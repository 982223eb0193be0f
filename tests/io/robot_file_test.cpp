#include "grpvss/io/robot_file.hpp"

#include <string>

#include <gtest/gtest.h>

#include "grpvss/io/units.hpp"
#include "support/input_error_expectations.hpp"

namespace grpvss::io {
namespace {

using grpvss::testing::expect_input_error;
using grpvss::testing::first_lines;
using grpvss::testing::source_file_text;
using grpvss::testing::with_line_replaced;

const std::string kRobotPath = std::string(GRPVSS_SOURCE_DIR) + "/data/ibm7545/robot.txt";

std::string sample_robot_text() { return source_file_text("data/ibm7545/robot.txt"); }

/// Parses `text` as "robot.txt" (the name every message below starts with).
void parse_robot_text(const std::string& text) { parse_robot_file(text, "robot.txt"); }

TEST(RobotFile, ReadsTheIbm7545Joints) {
  const RobotModel robot = read_robot_file(kRobotPath);
  EXPECT_EQ(robot.name, kRobotPath);
  ASSERT_EQ(robot.joint_count(), 4);
  EXPECT_EQ(robot.joints[0].type, JointType::kRevolute);
  EXPECT_EQ(robot.joints[1].type, JointType::kRevolute);
  EXPECT_EQ(robot.joints[2].type, JointType::kPrismatic);
  EXPECT_EQ(robot.joints[3].type, JointType::kRevolute);

  const Joint& j1 = robot.joints[0];  // 0.0,25.5,15.8,0.0,0.0,200.0,2.,1.8
  EXPECT_EQ(j1.dh.alpha, 0.0);
  EXPECT_EQ(j1.dh.d, 25.5);
  EXPECT_EQ(j1.dh.a, 15.8);
  EXPECT_EQ(j1.dh.theta, 0.0);
  EXPECT_EQ(j1.home, 0.0);
  EXPECT_EQ(j1.minimum, 0.0);
  EXPECT_EQ(j1.maximum, 200.0 * kRadiansPerDegree);
  EXPECT_NEAR(j1.maximum, 3.4906585039886591, 1e-15);
  EXPECT_EQ(j1.acceleration, 2.0 * kRadiansPerDegree);
  EXPECT_EQ(j1.deceleration, 1.8 * kRadiansPerDegree);

  const Joint& j2 = robot.joints[1];  // 180.0,0.0,9.8,0.0,0.0,135.0,2.,1.8
  EXPECT_NEAR(j2.dh.alpha, M_PI, 1e-15);
  EXPECT_EQ(j2.dh.d, 0.0);
  EXPECT_EQ(j2.dh.a, 9.8);
  EXPECT_EQ(j2.maximum, 135.0 * kRadiansPerDegree);

  const Joint& j3 = robot.joints[2];  // prismatic: 0.0,0.0,0.0,0.0,0.0,9.8,0.7,0.6 (inches)
  EXPECT_EQ(j3.dh.theta, 0.0);
  EXPECT_EQ(j3.dh.alpha, 0.0);
  EXPECT_EQ(j3.dh.a, 0.0);
  EXPECT_EQ(j3.dh.d, 0.0);
  EXPECT_EQ(j3.minimum, 0.0);
  EXPECT_EQ(j3.maximum, 9.8);
  EXPECT_EQ(j3.acceleration, 0.7);
  EXPECT_EQ(j3.deceleration, 0.6);

  const Joint& j4 = robot.joints[3];  // 0.0,15.05,0.0,0.0,-180.0,180.0,2.,1.8
  EXPECT_EQ(j4.dh.d, 15.05);
  EXPECT_EQ(j4.minimum, -180.0 * kRadiansPerDegree);
  EXPECT_EQ(j4.maximum, 180.0 * kRadiansPerDegree);
}

TEST(RobotFile, ReadsTheIbm7545Links) {
  const RobotModel robot = read_robot_file(kRobotPath);
  ASSERT_EQ(robot.links.size(), 5u);
  const std::vector<double> thickness{0.0, 3.23, 4.0, 1.0, 1.5};
  const std::vector<std::size_t> hull_counts{4, 2, 2, 2, 1};
  const std::vector<std::vector<int>> first_lines{
      {11, 27, 43, 59}, {77, 93}, {111, 127}, {145, 161}, {179}};
  std::size_t points = 0;
  for (std::size_t i = 0; i < robot.links.size(); ++i) {
    EXPECT_EQ(robot.links[i].thickness, thickness[i]) << "link " << i;
    ASSERT_EQ(robot.links[i].hulls.size(), hull_counts[i]) << "link " << i;
    for (std::size_t h = 0; h < hull_counts[i]; ++h) {
      EXPECT_EQ(robot.links[i].hulls[h].points.size(), 16u);
      EXPECT_EQ(robot.links[i].hulls[h].source_line, first_lines[i][h]);
      points += robot.links[i].hulls[h].points.size();
    }
  }
  EXPECT_EQ(points, 176u);
  EXPECT_EQ(robot.links[0].hulls[0].points[0], Eigen::Vector3d(5.875, 2.125, 0));
  // The two printed -5.125 base points (lines 34 and 42) are kept as printed.
  EXPECT_EQ(robot.links[0].hulls[1].points[7], Eigen::Vector3d(2.5, -5.125, 30.5));
  EXPECT_EQ(robot.links[0].hulls[1].points[15], Eigen::Vector3d(3.25, -5.125, 2.0));
  EXPECT_EQ(robot.links[4].hulls[0].points[15], Eigen::Vector3d(0.5, 0, -7.0));
}

TEST(RobotFile, ReportsAnUnreadableFile) {
  expect_input_error([] { read_robot_file("/nonexistent/robot.txt"); }, "/nonexistent/robot.txt",
                     0, "/nonexistent/robot.txt:0: expected a readable file, found No such file or directory");
}

TEST(RobotFile, RejectsAFileEndingInsideAHull) {
  expect_input_error([] { parse_robot_text(first_lines(sample_robot_text(), 100)); }, "robot.txt", 101,
                     "robot.txt:101: expected 3 numbers for point 9 of hull 2 of link 1 (x, y, z), "
                     "found end of file");
}

TEST(RobotFile, RejectsAFileEndingBeforeTheHullCount) {
  expect_input_error([] { parse_robot_text(first_lines(sample_robot_text(), 9)); }, "robot.txt", 10,
                     "robot.txt:10: expected an integer for the number of hulls NOBAR_0 of link 0, "
                     "found end of file");
}

TEST(RobotFile, RejectsAFileEndingInsideTheJointRows) {
  expect_input_error([] { parse_robot_text(first_lines(sample_robot_text(), 4)); }, "robot.txt", 5,
                     "robot.txt:5: expected 8 numbers for joint 2 (alpha, d, a, home, MIN, MAX, "
                     "acc, dec), found end of file");
}

TEST(RobotFile, RejectsAnEmptyFile) {
  expect_input_error([] { parse_robot_text(""); }, "robot.txt", 1,
                     "robot.txt:1: expected an integer for the number of joints N, found end of file");
}

TEST(RobotFile, RejectsAHullPointWithTwoNumbers) {
  expect_input_error([] { parse_robot_text(with_line_replaced(sample_robot_text(), 20, "1,2")); }, "robot.txt", 20,
                     "robot.txt:20: expected 3 numbers for point 10 of hull 1 of link 0 (x, y, z), "
                     "found 2 numbers");
}

TEST(RobotFile, RejectsAJointRowWithSevenNumbers) {
  expect_input_error(
      [] { parse_robot_text(with_line_replaced(sample_robot_text(), 7, "0.0,0.0,0.0,0.0,0.0,9.8,0.7")); }, "robot.txt", 7,
      "robot.txt:7: expected 8 numbers for joint 3 (theta, alpha, a, home, MIN, MAX, acc, dec), "
      "found 7 numbers");
}

TEST(RobotFile, RejectsANonNumber) {
  expect_input_error(
      [] { parse_robot_text(with_line_replaced(sample_robot_text(), 3, "0.0,25.5,abc,0.0,0.0,200.0,2.,1.8")); },
      "robot.txt", 3,
      "robot.txt:3: expected a number for joint 1 (alpha, d, a, home, MIN, MAX, acc, dec), "
      "found 'abc'");
}

TEST(RobotFile, RejectsNaNAndInfinity) {
  expect_input_error([] { parse_robot_text(with_line_replaced(sample_robot_text(), 150, "1.,NaN,7")); }, "robot.txt", 150,
                     "robot.txt:150: expected a finite number for point 6 of hull 1 of link 3 "
                     "(x, y, z), found 'NaN'");
  expect_input_error([] { parse_robot_text(with_line_replaced(sample_robot_text(), 75, "inf")); }, "robot.txt", 75,
                     "robot.txt:75: expected a finite number for the thickness D_1 of link 1, "
                     "found 'inf'");
}

TEST(RobotFile, RejectsGiganticMagnitude) {
  expect_input_error([] { parse_robot_text(with_line_replaced(sample_robot_text(), 11, "5.875,2e9,0")); }, "robot.txt", 11,
                     "robot.txt:11: expected a number of magnitude at most 1e9 for point 1 of hull 1 "
                     "of link 0 (x, y, z), found '2e9'");
}

TEST(RobotFile, RejectsMinAboveMax) {
  expect_input_error(
      [] { parse_robot_text(with_line_replaced(sample_robot_text(), 3, "0.0,25.5,15.8,0.0,10.0,0.0,2.,1.8")); },
      "robot.txt", 3, "robot.txt:3: expected MIN <= MAX for joint 1, found MIN 10 > MAX 0");
}

TEST(RobotFile, RejectsHomeOutsideTheLimits) {
  expect_input_error(
      [] { parse_robot_text(with_line_replaced(sample_robot_text(), 3, "0.0,25.5,15.8,250,0.0,200.0,2.,1.8")); },
      "robot.txt", 3,
      "robot.txt:3: expected home within [MIN, MAX] = [0, 200] for joint 1, found home 250");
  expect_input_error(
      [] { parse_robot_text(with_line_replaced(sample_robot_text(), 7, "0.0,0.0,0.0,-0.5,0.0,9.8,0.7,0.6")); },
      "robot.txt", 7,
      "robot.txt:7: expected home within [MIN, MAX] = [0, 9.8] for joint 3, found home -0.5");
}

TEST(RobotFile, RejectsZeroOrNegativeAccelerationAndDeceleration) {
  expect_input_error(
      [] { parse_robot_text(with_line_replaced(sample_robot_text(), 5, "180.0,0.0,9.8,0.0,0.0,135.0,0,1.8")); },
      "robot.txt", 5, "robot.txt:5: expected a positive maximum acceleration acc for joint 2, found 0");
  expect_input_error(
      [] { parse_robot_text(with_line_replaced(sample_robot_text(), 9, "0.0,15.05,0.0,0.0,-180.0,180.0,2.,-1.8")); },
      "robot.txt", 9,
      "robot.txt:9: expected a positive maximum deceleration dec for joint 4, found -1.8");
}

TEST(RobotFile, RejectsAJointIndicatorOtherThanZeroOrOne) {
  expect_input_error([] { parse_robot_text(with_line_replaced(sample_robot_text(), 4, "2")); }, "robot.txt", 4,
                     "robot.txt:4: expected the joint type IND_2: 0 (revolute) or 1 (prismatic), "
                     "found 2");
}

TEST(RobotFile, RejectsANonIntegerCount) {
  expect_input_error([] { parse_robot_text(with_line_replaced(sample_robot_text(), 1, "4.5")); }, "robot.txt", 1,
                     "robot.txt:1: expected an integer for the number of joints N, found '4.5'");
  expect_input_error([] { parse_robot_text(with_line_replaced(sample_robot_text(), 76, "2.")); }, "robot.txt", 76,
                     "robot.txt:76: expected an integer for the number of hulls NOBAR_1 of link 1, "
                     "found '2.'");
}

TEST(RobotFile, RejectsZeroAndAbsurdJointCounts) {
  expect_input_error([] { parse_robot_text(with_line_replaced(sample_robot_text(), 1, "0")); }, "robot.txt", 1,
                     "robot.txt:1: expected the number of joints N between 1 and 64, found 0");
  expect_input_error([] { parse_robot_text(with_line_replaced(sample_robot_text(), 1, "65")); }, "robot.txt", 1,
                     "robot.txt:1: expected the number of joints N between 1 and 64, found 65");
}

TEST(RobotFile, RejectsNegativeAndAbsurdHullCounts) {
  expect_input_error([] { parse_robot_text(with_line_replaced(sample_robot_text(), 10, "-1")); }, "robot.txt", 10,
                     "robot.txt:10: expected the number of hulls NOBAR_0 of link 0 between 0 and "
                     "100000, found -1");
  // Rejected before any hull is read or allocated.
  expect_input_error([] { parse_robot_text("1\n0\n0,0,0,0,0,90,1,1\n100001\n"); }, "robot.txt", 4,
                     "robot.txt:4: expected the number of hulls NOBAR_0 of link 0 between 0 and "
                     "100000, found 100001");
}

TEST(RobotFile, RejectsZeroThickness) {
  expect_input_error([] { parse_robot_text(with_line_replaced(sample_robot_text(), 143, "0")); }, "robot.txt", 143,
                     "robot.txt:143: expected a positive thickness D_3 of link 3, found 0");
}

TEST(RobotFile, RejectsTrailingGarbage) {
  expect_input_error([] { parse_robot_text(sample_robot_text() + "\n7\n"); }, "robot.txt", 196,
                     "robot.txt:196: expected end of file after the hulls of link 4, found '7'");
}

TEST(RobotFile, RejectsACoplanarHullAtItsFirstLine) {
  std::string text = sample_robot_text();
  for (int line = 187; line <= 194; ++line) {  // lower octagon of link 4's hull onto z = 0
    text = with_line_replaced(text, line, "0.5,0.5,0");
  }
  expect_input_error([&] { parse_robot_text(text); }, "robot.txt", 179,
                     "robot.txt:179: expected hull 1 of link 4 to span 3-D (four points not in "
                     "one plane), found all 16 points coplanar");
}

TEST(RobotFile, RejectsACollinearHull) {
  std::string text = sample_robot_text();
  for (int line = 179; line <= 194; ++line) {
    text = with_line_replaced(text, line, std::to_string(line - 179) + ",0,0");
  }
  expect_input_error([&] { parse_robot_text(text); }, "robot.txt", 179,
                     "robot.txt:179: expected hull 1 of link 4 to span 3-D (four points not in "
                     "one plane), found all 16 points collinear");
}

TEST(RobotFile, AcceptsAPrismaticJointWithDegreesForItsAngles) {
  const std::string text =
      "1\n1\n90, -90, 2, 1, 0, 5, 0.5, 0.25\n"
      "1\nHULL 4\n0,0,0\n1,0,0\n0,1,0\n0,0,1\n"
      "1.5\n1\nHULL 4\n0,0,0\n2,0,0\n0,2,0\n0,0,2\n";
  const RobotModel robot = parse_robot_file(text, "prismatic.txt");
  ASSERT_EQ(robot.joint_count(), 1);
  EXPECT_EQ(robot.joints[0].type, JointType::kPrismatic);
  EXPECT_EQ(robot.joints[0].dh.theta, 90 * kRadiansPerDegree);
  EXPECT_EQ(robot.joints[0].dh.alpha, -90 * kRadiansPerDegree);
  EXPECT_EQ(robot.joints[0].dh.a, 2.0);
  EXPECT_EQ(robot.joints[0].home, 1.0);
  EXPECT_EQ(robot.joints[0].maximum, 5.0);
  EXPECT_EQ(robot.joints[0].acceleration, 0.5);
  EXPECT_EQ(robot.joints[0].deceleration, 0.25);
  EXPECT_EQ(robot.links[1].thickness, 1.5);
  EXPECT_EQ(robot.links[1].hulls[0].points.size(), 4u);
  EXPECT_EQ(robot.links[1].hulls[0].source_line, 13);
}

}  // namespace
}  // namespace grpvss::io

namespace grpvss::io {
namespace {

TEST(RobotFile, ReadsCrLfLineEndingsAndCommentsToTheSameModel) {
  const std::string original = grpvss::testing::source_file_text("data/ibm7545/robot.txt");
  std::string converted = "# IBM 7545, thesis Appendix A.1.1.1\r\n";
  for (const char c : original) {
    if (c == '\n') converted += "\r";
    converted += c;
  }
  const RobotModel expected = parse_robot_file(original, "robot.txt");
  const RobotModel actual = parse_robot_file(converted, "robot.txt");
  ASSERT_EQ(actual.links.size(), expected.links.size());
  for (std::size_t i = 0; i < expected.joints.size(); ++i) {
    EXPECT_EQ(actual.joints[i].dh.d, expected.joints[i].dh.d);
    EXPECT_EQ(actual.joints[i].maximum, expected.joints[i].maximum);
  }
  for (std::size_t i = 0; i < expected.links.size(); ++i) {
    ASSERT_EQ(actual.links[i].hulls.size(), expected.links[i].hulls.size());
    for (std::size_t h = 0; h < expected.links[i].hulls.size(); ++h) {
      EXPECT_EQ(actual.links[i].hulls[h].points, expected.links[i].hulls[h].points);
      // One comment line was added at the top.
      EXPECT_EQ(actual.links[i].hulls[h].source_line, expected.links[i].hulls[h].source_line + 1);
    }
  }
}

TEST(RobotFile, TreatsHull16AsTheThesisDefault) {
  const std::string original = grpvss::testing::source_file_text("data/ibm7545/robot.txt");
  // Line 178 is NOBAR_4 = 1; declare its hull explicitly with the extension.
  const std::string extended =
      grpvss::testing::with_line_replaced(original, 178, "1\nHULL 16");
  const RobotModel expected = parse_robot_file(original, "robot.txt");
  const RobotModel actual = parse_robot_file(extended, "robot.txt");
  EXPECT_EQ(actual.links[4].hulls[0].points, expected.links[4].hulls[0].points);
  EXPECT_EQ(actual.links[4].hulls[0].source_line, 180);
}

}  // namespace
}  // namespace grpvss::io
