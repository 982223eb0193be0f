#include "grpvss/io/path_file.hpp"

#include <string>

#include <gtest/gtest.h>

#include "grpvss/io/robot_file.hpp"
#include "grpvss/io/units.hpp"
#include "support/input_error_expectations.hpp"

namespace grpvss::io {
namespace {

using grpvss::testing::expect_input_error;
using grpvss::testing::first_lines;
using grpvss::testing::source_file_text;
using grpvss::testing::with_line_replaced;

const RobotModel& ibm7545() {
  static const RobotModel robot =
      read_robot_file(std::string(GRPVSS_SOURCE_DIR) + "/data/ibm7545/robot.txt");
  return robot;
}

std::string sample_path_text() { return source_file_text("data/ibm7545/path.txt"); }

void parse_path_text(const std::string& text) { parse_path_file(text, "path.txt", ibm7545()); }

constexpr double kDeg = kRadiansPerDegree;

/// Joint values of the IBM 7545 in library units: joints 1, 2, 4 degrees -> rad, joint 3 as is.
Eigen::VectorXd ibm_units(double q1, double q2, double q3, double q4) {
  Eigen::VectorXd q(4);
  q << q1 * kDeg, q2 * kDeg, q3, q4 * kDeg;
  return q;
}

void expect_world_target(const WorldTarget& target, const Eigen::Vector3d& position_W,
                         const Eigen::Vector3d& axis_W, double angle_degrees) {
  EXPECT_EQ(target.position_W, position_W);
  EXPECT_EQ(target.axis_W, axis_W);
  EXPECT_EQ(target.angle, angle_degrees * kDeg);
}

TEST(PathFile, ReadsTheAppendixA13Sample) {
  const PathProgram program =
      read_path_file(std::string(GRPVSS_SOURCE_DIR) + "/data/ibm7545/path.txt", ibm7545());
  ASSERT_EQ(program.segments.size(), 3u);
  EXPECT_EQ(program.segments[0].source_line, 2);
  EXPECT_EQ(program.segments[1].source_line, 7);
  EXPECT_EQ(program.segments[2].source_line, 13);

  const auto& jcs = std::get<PtpJointSegment>(program.segments[0].spec);
  EXPECT_EQ(jcs.target, ibm_units(50, 50, 5, 50));
  EXPECT_EQ(jcs.velocity, ibm_units(3, 3, 0.3, 3));

  const auto& wcs = std::get<PtpWorldSegment>(program.segments[1].spec);
  expect_world_target(wcs.target, {0, 20, 8}, {0, 0, -1}, 30);
  EXPECT_EQ(wcs.velocity, ibm_units(3, 3, 0.3, 3));

  const auto& cp = std::get<CpLineSegment>(program.segments[2].spec);
  expect_world_target(cp.target, {-20, -5, 2}, {0, 0, -1}, 30);
}

TEST(PathFile, ReadsTheOutputSamplePath) {
  const PathProgram program = read_path_file(
      std::string(GRPVSS_SOURCE_DIR) + "/data/ibm7545/path-output-sample.txt", ibm7545());
  ASSERT_EQ(program.segments.size(), 4u);
  const std::vector<int> lines{2, 8, 10, 15};
  for (std::size_t s = 0; s < 4; ++s) EXPECT_EQ(program.segments[s].source_line, lines[s]);

  const auto& first = std::get<PtpWorldSegment>(program.segments[0].spec);
  expect_world_target(first.target, {0, 20, 8}, {0, 0, -1}, 30);
  EXPECT_EQ(first.velocity, ibm_units(3, 3, 0.3, 3));
  expect_world_target(std::get<CpLineSegment>(program.segments[1].spec).target, {-20, -5, 2},
                      {0, 0, -1}, 30);
  const auto& third = std::get<PtpJointSegment>(program.segments[2].spec);
  EXPECT_EQ(third.target, ibm_units(50, 50, 5, 50));
  EXPECT_EQ(third.velocity, ibm_units(3, 3, 0.3, 3));
  expect_world_target(std::get<CpLineSegment>(program.segments[3].spec).target, {15, 2, 8},
                      {0, 0, -1}, 30);
}

TEST(PathFile, LeavesJointTargetsOutsideTheLimitsToTheMotionStage) {
  // Joint 1's limits are [0, 200] degrees; thesis error 3 is decided later, not here.
  const PathProgram program =
      parse_path_file(with_line_replaced(sample_path_text(), 3, "-30.,3."), "path.txt", ibm7545());
  EXPECT_EQ(std::get<PtpJointSegment>(program.segments[0].spec).target[0], -30 * kDeg);
}

TEST(PathFile, ReplacesAZeroAxisByUnitZWhenTheAngleIsZero) {
  const PathProgram program = parse_path_file("1\n3\n1,2,3,0,0,0,0\n", "path.txt", ibm7545());
  expect_world_target(std::get<CpLineSegment>(program.segments[0].spec).target, {1, 2, 3},
                      {0, 0, 1}, 0);
}

TEST(PathFile, RejectsAZeroAxisWithANonzeroAngle) {
  expect_input_error([] { parse_path_text(with_line_replaced(sample_path_text(), 14, "-20.,-5.,2.,0.,0.,0.,30.")); },
                     "path.txt", 14,
                     "path.txt:14: expected a rotation axis (KX, KY, KZ) of nonzero length for "
                     "KTHETA = 30 in segment 3, found (0, 0, 0)");
}

TEST(PathFile, RejectsASegmentTypeOtherThanOneTwoOrThreeAsThesisError6) {
  expect_input_error([] { parse_path_text(with_line_replaced(sample_path_text(), 7, "4")); }, "path.txt", 7,
                     "path.txt:7: expected segment type 1, 2 or 3 (thesis error 6 in segment 2), "
                     "found 4");
  expect_input_error([] { parse_path_text(with_line_replaced(sample_path_text(), 2, "0")); }, "path.txt", 2,
                     "path.txt:2: expected segment type 1, 2 or 3 (thesis error 6 in segment 1), "
                     "found 0");
}

TEST(PathFile, RejectsZeroOrNegativeVelocities) {
  expect_input_error([] { parse_path_text(with_line_replaced(sample_path_text(), 5, "5.,0")); }, "path.txt", 5,
                     "path.txt:5: expected a positive desired velocity VELDES_3 in segment 1, "
                     "found 0");
  expect_input_error([] { parse_path_text(with_line_replaced(sample_path_text(), 12, "-3.")); }, "path.txt", 12,
                     "path.txt:12: expected a positive desired velocity VELDES_4 in segment 2, "
                     "found -3");
}

TEST(PathFile, RejectsAJointLineWithOneNumber) {
  expect_input_error([] { parse_path_text(with_line_replaced(sample_path_text(), 4, "50.")); }, "path.txt", 4,
                     "path.txt:4: expected 2 numbers for joint 2 of segment 1 (q_target, VELDES), "
                     "found 1 number");
}

TEST(PathFile, RejectsAWorldTargetWithSixNumbers) {
  expect_input_error([] { parse_path_text(with_line_replaced(sample_path_text(), 8, "0.,20.,8.,0.,0.,-1.")); },
                     "path.txt", 8,
                     "path.txt:8: expected 7 numbers for the target of segment 2 (XEND, YEND, ZEND, "
                     "KX, KY, KZ, KTHETA), found 6 numbers");
}

TEST(PathFile, RejectsATruncatedFile) {
  expect_input_error([] { parse_path_text(first_lines(sample_path_text(), 10)); }, "path.txt", 11,
                     "path.txt:11: expected 1 number for the desired velocity VELDES_3 of segment "
                     "2, found end of file");
  expect_input_error([] { parse_path_text(first_lines(sample_path_text(), 13)); }, "path.txt", 14,
                     "path.txt:14: expected 7 numbers for the target of segment 3 (XEND, YEND, "
                     "ZEND, KX, KY, KZ, KTHETA), found end of file");
}

TEST(PathFile, RejectsBadSegmentCounts) {
  expect_input_error([] { parse_path_text(with_line_replaced(sample_path_text(), 1, "0")); }, "path.txt", 1,
                     "path.txt:1: expected the number of motion segments NOMS between 1 and "
                     "1000000, found 0");
  expect_input_error([] { parse_path_text(with_line_replaced(sample_path_text(), 1, "three")); }, "path.txt", 1,
                     "path.txt:1: expected an integer for the number of motion segments NOMS, "
                     "found 'three'");
}

TEST(PathFile, RejectsNonNumbersAndInfinity) {
  expect_input_error([] { parse_path_text(with_line_replaced(sample_path_text(), 3, "50.,fast")); }, "path.txt", 3,
                     "path.txt:3: expected a number for joint 1 of segment 1 (q_target, VELDES), "
                     "found 'fast'");
  expect_input_error([] { parse_path_text(with_line_replaced(sample_path_text(), 14, "-20.,-5.,2.,0.,0.,-1.,inf")); },
                     "path.txt", 14,
                     "path.txt:14: expected a finite number for the target of segment 3 (XEND, "
                     "YEND, ZEND, KX, KY, KZ, KTHETA), found 'inf'");
}

TEST(PathFile, RejectsTrailingGarbage) {
  // A fourth segment that NOMS = 3 does not announce.
  expect_input_error([] { parse_path_text(sample_path_text() + "3\n15.,2.,8.,0.,0.,-1.,30.\n"); }, "path.txt", 15,
                     "path.txt:15: expected end of file after segment 3, found '3'");
}

}  // namespace
}  // namespace grpvss::io
