#include "grpvss/io/environment_file.hpp"

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

std::string sample_environment_text() { return source_file_text("data/ibm7545/environment.txt"); }

void parse_environment_text(const std::string& text) { parse_environment_file(text, "environment.txt"); }

/// k lines "x,y,z" of a tetrahedron-like point set: (0,0,0), (1,0,0), (0,1,0), (0,0,1), ...
std::string tetrahedron_lines(int k) {
  std::string text = "0,0,0\n1,0,0\n0,1,0\n0,0,1\n";
  for (int i = 4; i < k; ++i) text += "0.25,0.25,0.25\n";
  return text;
}

TEST(EnvironmentFile, ReadsTheIbm7545Sample) {
  const std::string path = std::string(GRPVSS_SOURCE_DIR) + "/data/ibm7545/environment.txt";
  const Environment environment = read_environment_file(path);
  EXPECT_EQ(environment.smallest_angle, 90.0 * kRadiansPerDegree);
  EXPECT_NEAR(environment.smallest_angle, M_PI / 2, 1e-15);
  EXPECT_EQ(environment.smallest_thickness, 5.0);
  ASSERT_EQ(environment.obstacles.size(), 2u);
  EXPECT_EQ(environment.obstacles[0].source_line, 4);
  EXPECT_EQ(environment.obstacles[1].source_line, 20);
  ASSERT_EQ(environment.obstacles[0].points.size(), 16u);
  ASSERT_EQ(environment.obstacles[1].points.size(), 16u);
  EXPECT_EQ(environment.obstacles[0].points[0], Eigen::Vector3d(15, 15, 15));
  EXPECT_EQ(environment.obstacles[0].points[5], Eigen::Vector3d(17.5, 21, 15));
  EXPECT_EQ(environment.obstacles[1].points[15], Eigen::Vector3d(-11, 12.5, 20));
}

TEST(EnvironmentFile, AcceptsHullsOfAnyPointCountWithTheHullKeyword) {
  // A 4-point hull, a thesis 16-point hull, and a 5-point hull, in one file.
  const std::string body = first_lines(sample_environment_text(), 19);  // angle, L, NOB = 2, first hull
  const std::string text = with_line_replaced(body, 3, "3") + "HULL 4\n" +
                           tetrahedron_lines(4) + "# a comment line\nhull 5\n" +
                           tetrahedron_lines(5);
  const Environment environment = parse_environment_file(text, "mixed.txt");
  ASSERT_EQ(environment.obstacles.size(), 3u);
  EXPECT_EQ(environment.obstacles[0].points.size(), 16u);
  EXPECT_EQ(environment.obstacles[1].points.size(), 4u);
  EXPECT_EQ(environment.obstacles[1].source_line, 21);
  EXPECT_EQ(environment.obstacles[2].points.size(), 5u);
  EXPECT_EQ(environment.obstacles[2].source_line, 27);
  EXPECT_EQ(environment.obstacles[2].points[4], Eigen::Vector3d(0.25, 0.25, 0.25));
}

TEST(EnvironmentFile, AcceptsAnEmptyEnvironment) {
  const Environment environment = parse_environment_file("45\n1\n0\n", "empty.txt");
  EXPECT_TRUE(environment.obstacles.empty());
  EXPECT_EQ(environment.smallest_angle, 45.0 * kRadiansPerDegree);
}

TEST(EnvironmentFile, RejectsAHullOfFewerThanFourPoints) {
  expect_input_error([] { parse_environment_text("90\n5\n1\nHULL 3\n0,0,0\n1,0,0\n0,1,0\n"); }, "environment.txt",
                     4,
                     "environment.txt:4: expected the number of points of hull 1 of the "
                     "environment between 4 and 1000000, found 3");
}

TEST(EnvironmentFile, RejectsMorePointsThanTheFileBudgetBeforeReadingThem) {
  const std::string text = first_lines(sample_environment_text(), 19) + "HULL 1000000\n";
  expect_input_error([&] { parse_environment_text(text); }, "environment.txt", 20,
                     "environment.txt:20: expected at most 1000000 hull points in the file, "
                     "found 1000016 points by the end of hull 2 of the environment");
}

TEST(EnvironmentFile, RejectsADeclaredHullThatEndsEarly) {
  expect_input_error([] { parse_environment_text("90\n5\n1\nHULL 6\n" + tetrahedron_lines(4)); }, "environment.txt",
                     9,
                     "environment.txt:9: expected 3 numbers for point 5 of hull 1 of the "
                     "environment (x, y, z), found end of file");
}

TEST(EnvironmentFile, RejectsAFileEndingInsideAHull) {
  expect_input_error([] { parse_environment_text(first_lines(sample_environment_text(), 30)); }, "environment.txt", 31,
                     "environment.txt:31: expected 3 numbers for point 12 of hull 2 of the "
                     "environment (x, y, z), found end of file");
}

TEST(EnvironmentFile, RejectsAHullLineWithTwoNumbers) {
  expect_input_error([] { parse_environment_text(with_line_replaced(sample_environment_text(), 6, "20,15")); }, "environment.txt", 6,
                     "environment.txt:6: expected 3 numbers for point 3 of hull 1 of the "
                     "environment (x, y, z), found 2 numbers");
}

TEST(EnvironmentFile, RejectsAnAngleOutsideTheOpenInterval) {
  expect_input_error([] { parse_environment_text(with_line_replaced(sample_environment_text(), 1, "0")); }, "environment.txt", 1,
                     "environment.txt:1: expected a smallest angle theta strictly between 0 and "
                     "180 degrees, found 0");
  expect_input_error([] { parse_environment_text(with_line_replaced(sample_environment_text(), 1, "180.")); }, "environment.txt", 1,
                     "environment.txt:1: expected a smallest angle theta strictly between 0 and "
                     "180 degrees, found 180");
}

TEST(EnvironmentFile, RejectsANonPositiveThickness) {
  expect_input_error([] { parse_environment_text(with_line_replaced(sample_environment_text(), 2, "-5")); }, "environment.txt", 2,
                     "environment.txt:2: expected a positive smallest thickness L, found -5");
}

TEST(EnvironmentFile, RejectsNegativeNonIntegerAndAbsurdHullCounts) {
  expect_input_error([] { parse_environment_text(with_line_replaced(sample_environment_text(), 3, "-2")); }, "environment.txt", 3,
                     "environment.txt:3: expected the number of obstacle hulls NOB between 0 and "
                     "100000, found -2");
  expect_input_error([] { parse_environment_text(with_line_replaced(sample_environment_text(), 3, "2.0")); }, "environment.txt", 3,
                     "environment.txt:3: expected an integer for the number of obstacle hulls "
                     "NOB, found '2.0'");
  expect_input_error([] { parse_environment_text("90\n5\n100001\n"); }, "environment.txt", 3,
                     "environment.txt:3: expected the number of obstacle hulls NOB between 0 and "
                     "100000, found 100001");
}

TEST(EnvironmentFile, RejectsCoincidentPoints) {
  std::string text = "90\n5\n1\n";
  for (int i = 0; i < 16; ++i) text += "1,2,3\n";
  expect_input_error([&] { parse_environment_text(text); }, "environment.txt", 4,
                     "environment.txt:4: expected hull 1 of the environment to span 3-D (four "
                     "points not in one plane), found all 16 points coincident");
}

TEST(EnvironmentFile, RejectsAHullWhosePointsAreCoplanar) {
  std::string text = sample_environment_text();
  for (int line = 28; line <= 35; ++line) {  // top octagon of hull 2 down onto z = 15
    text = with_line_replaced(text, line, "-12,10,15");
  }
  expect_input_error([&] { parse_environment_text(text); }, "environment.txt", 20,
                     "environment.txt:20: expected hull 2 of the environment to span 3-D (four "
                     "points not in one plane), found all 16 points coplanar");
}

TEST(EnvironmentFile, RejectsAMalformedHullLine) {
  expect_input_error([] { parse_environment_text("90\n5\n1\nHULL\n" + tetrahedron_lines(4)); }, "environment.txt",
                     4,
                     "environment.txt:4: expected 'HULL k' with one integer k for the number of "
                     "points of hull 1 of the environment, found 1 field");
  expect_input_error([] { parse_environment_text("90\n5\n1\nHULL 4.0\n" + tetrahedron_lines(4)); },
                     "environment.txt", 4,
                     "environment.txt:4: expected an integer for the number of points of hull 1 "
                     "of the environment, found '4.0'");
}

TEST(EnvironmentFile, ParsesTheExtensionExampleOfTheDocumentation) {
  // docs/input-formats.md, "Extension: hulls with any number of points".
  const std::string text =
      "60.\n2.\n2\nHULL 4\n0,0,0\n1,0,0\n0,1,0\n0,0,1\n"
      "HULL 5\n0,0,0\n2,0,0\n2,2,0\n0,2,0\n1,1,3\n";
  const Environment environment = parse_environment_file(text, "doc.txt");
  EXPECT_EQ(environment.smallest_angle, 60.0 * kRadiansPerDegree);
  EXPECT_EQ(environment.smallest_thickness, 2.0);
  ASSERT_EQ(environment.obstacles.size(), 2u);
  EXPECT_EQ(environment.obstacles[0].points.size(), 4u);
  EXPECT_EQ(environment.obstacles[1].points.size(), 5u);
  EXPECT_EQ(environment.obstacles[1].points[4], Eigen::Vector3d(1, 1, 3));
  EXPECT_EQ(environment.obstacles[1].source_line, 10);
}

TEST(EnvironmentFile, RejectsTrailingGarbage) {
  expect_input_error([] { parse_environment_text(sample_environment_text() + "1,2,3\n"); }, "environment.txt", 36,
                     "environment.txt:36: expected end of file after the last obstacle hull, "
                     "found '1'");
}

}  // namespace
}  // namespace grpvss::io
