// The verifier on the thesis's own IBM 7545 sample (data/ibm7545): what each mode finds.
#include <algorithm>
#include <string>

#include <gtest/gtest.h>

#include "grpvss/checker/certificate_checker.hpp"
#include "grpvss/certify/verifier.hpp"
#include "grpvss/io/environment_file.hpp"
#include "grpvss/io/path_file.hpp"
#include "grpvss/io/robot_file.hpp"
#include "grpvss/motion/kinematics_adapter.hpp"
#include "support/data_paths.hpp"


namespace grpvss::certify {
namespace {

using grpvss::test::ibm7545_file;

class Ibm7545Sample : public ::testing::Test {
 protected:
  void load(const std::string& path_file) {
    robot_ = io::read_robot_file(ibm7545_file("robot.txt"));
    environment_ = io::read_environment_file(ibm7545_file("environment.txt"));
    program_ = io::read_path_file(ibm7545_file(path_file), robot_);
    kinematics_ = motion::make_kinematics_access(robot_, motion::select_ik({}, robot_, "robot.txt"));
  }
  VerificationRun run(ResolutionMode mode, double tolerance = 0.5) {
    SetupRequest options;
    options.tolerance = tolerance;
    options.mode = mode;
    return verify(robot_, environment_, program_, kinematics_, resolve_setup(options));
  }
  RobotModel robot_;
  Environment environment_;
  PathProgram program_;
  motion::KinematicsAccess kinematics_;
};

TEST_F(Ibm7545Sample, CertifiedModeFindsTheColumnHittingObstacleOneThatTheThesisRuleSteppedOver) {
  load("path.txt");
  const VerificationRun certified = run(ResolutionMode::kCertified);
  ASSERT_EQ(certified.result.verdict, Verdict::kCollision);
  const StepRecord& hit = certified.result.steps.at(*certified.result.collision_step - 1);
  EXPECT_EQ(hit.segment, 1);
  // Segment 1 is PTP(JCS) to (50, 50, 5, 50); the contact starts about 9.08 s in, when the
  // independent profiles have all joints near 25 degrees / 2.66 in. The step before the hit
  // is clear and no later than that; the hit is at most one basic step past it (every point
  // of a hull its clearances do not cover moves at most 2 Delta = 1 in.).
  const StepRecord& before = certified.result.steps.at(*certified.result.collision_step - 2);
  EXPECT_FALSE(before.unexpanded_collides);
  EXPECT_LE(before.path_time, 9.08);
  EXPECT_GE(hit.path_time, 9.07);
  EXPECT_LE(hit.path_time, 9.5);
  for (int link = 1; link <= 4; ++link) {
    EXPECT_LE(hit.links[link].motion_bound, std::max(hit.links[link].allowance, 1.0));
  }
  bool link3_on_obstacle0 = false;
  for (const auto& point : hit.interference_points) link3_on_obstacle0 |= point.link == 3 && point.obstacle == 0;
  EXPECT_TRUE(link3_on_obstacle0);
  // The checker re-decides the collision exactly from the inputs alone.
  const CheckReport report = check_certificate(robot_, environment_, program_, kinematics_, certified.certificate);
  EXPECT_TRUE(report.accepted) << (report.failures.empty() ? "" : report.failures.front());

  // The thesis rule at link-frame origins with Dmin takes segment 1 in one step and sees nothing.
  const VerificationRun thesis = run(ResolutionMode::kThesis);
  EXPECT_EQ(thesis.result.verdict, Verdict::kClear);
  int segment1_steps = 0;
  for (const StepRecord& step : thesis.result.steps) segment1_steps += step.segment == 1;
  EXPECT_EQ(segment1_steps, 1);
}

TEST_F(Ibm7545Sample, JointFourWrapOnTheCpLineIsErrorSeven) {
  // The output sample's CP segment 2 needs joint 4 beyond +180 deg: the nearest in-limit IK
  // solution wraps by 360 deg, which sweeps the tool although no frame origin moves.
  load("path-output-sample.txt");
  const VerificationRun certified = run(ResolutionMode::kCertified);
  ASSERT_FALSE(certified.result.errors.empty());
  EXPECT_EQ(certified.result.errors.front().code, kErrorCpJointJump);
  EXPECT_EQ(certified.result.errors.front().segment, 2);
  EXPECT_GT(certified.result.errors.front().step, 0);
  // The message names the joint whose branch flips: joint 4 wraps by about 360 deg.
  EXPECT_NE(certified.result.errors.front().message.find("IN MOTION SEGMENT 2: JOINT 4 CHANGES BY "),
            std::string::npos)
      << certified.result.errors.front().message;
}

TEST_F(Ibm7545Sample, OutputSampleSegmentFourIsRefusedWithErrorThreeInThesisMode) {
  load("path-output-sample.txt");
  const VerificationRun thesis = run(ResolutionMode::kThesis, 1.0);
  ASSERT_EQ(thesis.result.errors.size(), 1u);
  EXPECT_EQ(thesis.result.errors.front().code, 3);
  EXPECT_EQ(thesis.result.errors.front().segment, 4);
  EXPECT_EQ(thesis.result.verdict, Verdict::kError);
}

}  // namespace
}  // namespace grpvss::certify

namespace grpvss::certify {
namespace {

TEST_F(Ibm7545Sample, SegmentRecordsNameTheirFirstAndLastSteps) {
  load("path.txt");
  const VerificationRun certified = run(ResolutionMode::kCertified);
  const auto& segments = certified.result.segments;
  ASSERT_GE(segments.size(), 3u);
  int expected_first = 1;
  for (const SegmentRecord& segment : segments) {
    if (segment.first_step == 0) continue;
    EXPECT_EQ(segment.first_step, expected_first) << "segment " << segment.number;
    for (const StepRecord& step : certified.result.steps) {
      const bool inside = step.index >= segment.first_step && step.index <= segment.last_step;
      EXPECT_EQ(inside, step.segment == segment.number) << "step " << step.index;
    }
    expected_first = segment.last_step + 1;
  }
  EXPECT_EQ(segments.back().last_step, certified.result.steps.back().index);
}

}  // namespace
}  // namespace grpvss::certify
