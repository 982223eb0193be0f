#include "grpvss/report/thesis_output.hpp"

#include <algorithm>
#include <cstdlib>
#include <fstream>
#include <stdexcept>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "support/text_files.hpp"
#include "support/thesis_sample_result.hpp"

namespace grpvss::report {
namespace {

const std::string kGoldenDir = std::string(GRPVSS_SOURCE_DIR) + "/tests/report/golden/";

std::string without_leading_blanks(const std::string& line) {
  const std::size_t first = line.find_first_not_of(' ');
  return first == std::string::npos ? std::string() : line.substr(first);
}

bool is_number_line(const std::string& line) {
  return !line.empty() && (line[0] == '-' || (line[0] >= '0' && line[0] <= '9'));
}

/// A.3 as the thesis program wrote it, undoing what the PDF-to-text conversion did: leading
/// blanks (7 lines), blank lines inside a block of numbers (between "... JOINT VALUES ARE"
/// and its numbers in steps 42-45, and amid the points of step 45), and the elision marks
/// "." / ". ." where the thesis left steps out.
std::vector<std::string> thesis_a3_as_written() {
  std::vector<std::string> lines;
  for (const std::string& raw : test::split_lines(
           test::read_text_file(kGoldenDir + "thesis_a3_output_sample.txt"))) {
    const std::string line = without_leading_blanks(raw);
    if (line != "." && line != ". .") lines.push_back(line);
  }
  std::vector<std::string> kept;
  for (std::size_t i = 0; i < lines.size(); ++i) {
    const bool inside_numbers =
        lines[i].empty() && i > 0 && i + 1 < lines.size() && is_number_line(lines[i + 1]) &&
        (lines[i - 1].find("JOINT VALUES ARE") != std::string::npos ||
         lines[i - 1].find('\t') != std::string::npos);
    if (!inside_numbers) kept.push_back(lines[i]);
  }
  return kept;
}

TEST(ThesisOutput, SampleRendersAsTheGoldenFile) {
  const std::string rendered =
      render_thesis_output(test::thesis_a3_sample_result(), test::ibm7545_joint_types());
  const std::string golden_path = kGoldenDir + "thesis_output_sample.txt";
  if (std::getenv("GRPVSS_UPDATE_GOLDEN") != nullptr) std::ofstream(golden_path) << rendered;
  EXPECT_EQ(rendered, test::read_text_file(golden_path));
}

// The golden file against the thesis itself, line by line: A.3 prints steps 1-4, 33-36,
// 40-47 and 82-83; the sample result mirrors every printed step, so apart from the conversion
// artefacts removed above the golden file must BE Appendix A.3.
TEST(ThesisOutput, GoldenFileIsThesisAppendixA3LineByLine) {
  const std::vector<std::string> thesis = thesis_a3_as_written();
  std::vector<std::string> golden;
  for (const std::string& line :
       test::split_lines(test::read_text_file(kGoldenDir + "thesis_output_sample.txt"))) {
    golden.push_back(without_leading_blanks(line));
  }
  ASSERT_EQ(thesis.size(), 201u);  // 210 extracted lines - 4 elision marks - 5 stray blanks
  ASSERT_EQ(golden.size(), thesis.size());
  for (std::size_t i = 0; i < thesis.size(); ++i) {
    EXPECT_EQ(golden[i], thesis[i]) << "line " << i + 1;
  }
}

// The one leading blank kept from A.3 (the column heading of the joint-space block) is the
// only line of the golden file that starts with a blank.
TEST(ThesisOutput, OnlyTheJointSpaceHeadingIsIndented) {
  int indented = 0;
  for (const std::string& line :
       test::split_lines(test::read_text_file(kGoldenDir + "thesis_output_sample.txt"))) {
    if (!line.empty() && line[0] == ' ') {
      ++indented;
      EXPECT_EQ(line, " STARTING JOINT VALUE FINAL JOINT VALUE DESIRED VELOCITY");
    }
  }
  EXPECT_EQ(indented, 1);
}

TEST(ThesisOutput, SameResultFromRobotModelOverload) {
  const auto result = test::thesis_a3_sample_result();
  EXPECT_EQ(render_thesis_output(result, test::ibm7545_joint_type_model()),
            render_thesis_output(result, test::ibm7545_joint_types()));
}

certify::VerificationResult one_step_result() {
  certify::VerificationResult result;
  result.tolerance = 0.5;
  result.mode = certify::ResolutionMode::kThesis;
  result.path_file_label = "p.txt";
  certify::SegmentRecord segment;
  segment.number = 1;
  PtpJointSegment spec;
  spec.target = Eigen::Vector2d(3.14159265358979323846 / 2, 4.0);
  spec.velocity = Eigen::Vector2d(3.14159265358979323846 / 60, 0.25);
  segment.input.spec = spec;
  segment.start_q = Eigen::Vector2d(-1e-9, 1.0);
  segment.simulated = true;
  result.segments.push_back(segment);
  certify::StepRecord step;
  step.index = 1;
  step.segment = 1;
  step.q = Eigen::Vector2d(3.14159265358979323846 / 4, 2.5);
  result.steps.push_back(step);
  return result;
}

const std::vector<JointType> kRevolutePrismatic = {JointType::kRevolute, JointType::kPrismatic};

TEST(ThesisOutput, JointSpaceBlockConvertsOnlyRevoluteJointsToDegrees) {
  const std::string text = render_thesis_output(one_step_result(), kRevolutePrismatic);
  EXPECT_EQ(text,
            "THE TOLERANCE VALUE = 0.50\n"
            "\n"
            "THE 1TH SEGMENT OF THE PATH INPUT FROM FILE p.txt\n"
            "\n"
            "--- PTP (JCS)---\n"
            " STARTING JOINT VALUE FINAL JOINT VALUE DESIRED VELOCITY\n"
            "\n"
            "JOINT 1\t0.00\t90.00\t3.00\n"  // -1e-9 rad prints 0.00, never -0.00
            "JOINT 2\t1.00\t4.00\t0.25\n"
            "\n"
            "IN 1TH STEP, THE JOINT VALUES ARE\n"
            "45.00 2.50\n"
            "\n"
            "THERE ARE 0 INTERFERENCE POINTS IN THIS STEP\n"
            "\n"
            "TOTAL 1 STEPS IN THIS PATH\n"
            "NO COLLISION DETECTED IN THIS PATH\n");
}

TEST(ThesisOutput, CertifiedModeAddsOneModeLineAfterTheTolerance) {
  auto result = one_step_result();
  result.mode = certify::ResolutionMode::kCertified;
  const auto lines = test::split_lines(render_thesis_output(result, kRevolutePrismatic));
  ASSERT_GE(lines.size(), 4u);
  EXPECT_EQ(lines[0], "THE TOLERANCE VALUE = 0.50");
  EXPECT_EQ(lines[1], "");
  EXPECT_EQ(lines[2], "THE RESOLUTION MODE = CERTIFIED");
  EXPECT_EQ(lines[3], "");
  EXPECT_EQ(lines[4], "THE 1TH SEGMENT OF THE PATH INPUT FROM FILE p.txt");
}

TEST(ThesisOutput, UnexpandedCollisionWithoutPointsStillReportsCollision) {
  auto result = one_step_result();
  EXPECT_FALSE(thesis_reports_collision(result));
  result.steps[0].unexpanded_collides = true;
  EXPECT_TRUE(thesis_reports_collision(result));
  const auto lines = test::split_lines(render_thesis_output(result, kRevolutePrismatic));
  EXPECT_EQ(lines.back(), "COLLISIONS DETECTED IN THIS PATH");
}

TEST(ThesisOutput, ErrorWithoutSegmentPrecedesTheTotals) {
  auto result = one_step_result();
  certify::PathError error;
  error.code = 2;
  error.segment = 0;
  error.step = 1;
  result.errors.push_back(error);
  const auto lines = test::split_lines(render_thesis_output(result, kRevolutePrismatic));
  ASSERT_GE(lines.size(), 6u);
  const std::vector<std::string> tail(lines.end() - 6, lines.end());
  EXPECT_EQ(tail, (std::vector<std::string>{"THIS PATH IS NOT QUALIFIED.", "THE ERROR IS TYPE 2",
                                            "CHECK THE USER GUIDE FOR DETAILED ERROR DESCRIPTIONS",
                                            "", "TOTAL 1 STEPS IN THIS PATH",
                                            "NO COLLISION DETECTED IN THIS PATH"}));
}

/// one_step_result() with two interference points: link 1 hull 0 and link 1 hull 1 against
/// obstacle hull 1 (the second piece of a two-piece shape).
certify::VerificationResult result_with_points() {
  auto result = one_step_result();
  certify::InterferencePoint a;
  a.link = 1;
  a.hull = 0;
  a.obstacle = 1;
  a.p_W = Eigen::Vector3d(1.0, 2.0, 3.0);
  certify::InterferencePoint b = a;
  b.hull = 1;
  b.p_W = Eigen::Vector3d(-0.001, 0.5, 0.25);
  result.steps[0].interference_points = {a, b};
  return result;
}

TEST(ThesisOutput, ACellRunNamesEachInterferencePointsPairAfterItsNumbers) {
  RobotModel robot;
  robot.links.resize(2);
  robot.links[1].name = "forearm<1>";
  Environment environment;
  environment.obstacles.resize(2);
  environment.names = {"fixture", "fixture"};
  const ThesisNames names = ThesisNames::of(robot, environment);
  EXPECT_EQ(names.links, (std::vector<std::string>{"link 0", "forearm<1>"}));
  EXPECT_EQ(names.obstacles, (std::vector<std::string>{"fixture piece 0", "fixture piece 1"}));
  const auto lines =
      test::split_lines(render_thesis_output(result_with_points(), kRevolutePrismatic, names));
  const auto count = std::find(lines.begin(), lines.end(), "THERE ARE 2 INTERFERENCE POINTS IN THIS STEP");
  ASSERT_NE(count, lines.end());
  // A tab and the pair after the three numbers; the file is plain text, nothing escaped.
  EXPECT_EQ(*(count + 2), "1.00\t2.00\t3.00\tforearm<1> hull 0 / fixture piece 1");
  EXPECT_EQ(*(count + 3), "0.00\t0.50\t0.25\tforearm<1> hull 1 / fixture piece 1");
}

TEST(ThesisOutput, WithoutNamesThePointLinesKeepTheThesisThreeNumbers) {
  RobotModel robot;
  robot.links.resize(2);
  Environment environment;
  environment.obstacles.resize(2);
  EXPECT_TRUE(ThesisNames::of(robot, environment).empty());
  const std::string with_empty_names = render_thesis_output(
      result_with_points(), kRevolutePrismatic, ThesisNames::of(robot, environment));
  EXPECT_EQ(with_empty_names, render_thesis_output(result_with_points(), kRevolutePrismatic));
  EXPECT_NE(with_empty_names.find("\n1.00\t2.00\t3.00\n"), std::string::npos);
}

TEST(ThesisOutput, InconsistentResultsAreLogicErrors) {
  auto wrong_size = one_step_result();
  wrong_size.steps[0].q = Eigen::Vector3d(0, 0, 0);
  EXPECT_THROW(render_thesis_output(wrong_size, kRevolutePrismatic), std::logic_error);

  auto orphan = one_step_result();
  orphan.steps[0].segment = 7;
  EXPECT_THROW(render_thesis_output(orphan, kRevolutePrismatic), std::logic_error);

  auto unordered = one_step_result();
  unordered.steps.push_back(unordered.steps[0]);  // index 1 twice
  EXPECT_THROW(render_thesis_output(unordered, kRevolutePrismatic), std::logic_error);
}

}  // namespace
}  // namespace grpvss::report
