// RunHooks::observers and keep_steps on the IBM 7545 sample: the observer sees exactly the
// steps and certificate steps a kept run holds, in order, and a run that keeps nothing has the
// same verdict, segments, errors and per-link clearance summaries.
#include "grpvss/evidence/verification_observer.hpp"

#include <algorithm>
#include <string>
#include <vector>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "grpvss/certify/verifier.hpp"
#include "grpvss/io/environment_file.hpp"
#include "grpvss/io/path_file.hpp"
#include "grpvss/io/robot_file.hpp"
#include "grpvss/motion/kinematics_adapter.hpp"
#include "support/data_paths.hpp"


namespace grpvss::certify {
namespace {

using grpvss::test::ibm7545_file;

/// Records everything it is told, as the certificate's JSON for the certificate steps.
class Recorder : public VerificationObserver {
 public:
  void on_step(const StepRecord& step) override {
    steps.push_back(step);
    events.push_back("step " + std::to_string(step.index));
  }
  void on_certificate_segment_begin(const SegmentCertificate& segment) override {
    EXPECT_TRUE(segment.steps.empty());
    segments.push_back(segment);
    events.push_back("begin " + std::to_string(segment.number));
  }
  void on_certificate_step(const StepCertificate& step) override {
    segments.back().steps.push_back(step);
    events.push_back("certificate " + std::to_string(step.step));
  }
  void on_certificate_segment_end() override { events.push_back("end"); }

  std::vector<StepRecord> steps;
  std::vector<SegmentCertificate> segments;
  std::vector<std::string> events;
};

class Observed : public ::testing::Test {
 protected:
  void SetUp() override {
    robot_ = io::read_robot_file(ibm7545_file("robot.txt"));
    environment_ = io::read_environment_file(ibm7545_file("environment.txt"));
    kinematics_ = motion::make_kinematics_access(
        robot_, motion::select_ik({}, robot_, "robot.txt"));
  }
  VerificationRun run(const std::string& path_file, Recorder* recorder, bool keep_steps) {
    const PathProgram program = io::read_path_file(ibm7545_file(path_file), robot_);
    SetupRequest options;
    options.tolerance = 0.5;
    RunHooks hooks;
    if (recorder != nullptr) hooks.observers.push_back(recorder);
    hooks.keep_steps = keep_steps;
    return verify(robot_, environment_, program, kinematics_, resolve_setup(options), hooks);
  }
  RobotModel robot_;
  Environment environment_;
  motion::KinematicsAccess kinematics_;
};

TEST_F(Observed, TheObserverSeesTheKeptStepsAndCertificateStepsInOrder) {
  for (const char* path_file : {"path.txt", "path-output-sample.txt"}) {
    Recorder recorder;
    const VerificationRun kept = run(path_file, &recorder, true);
    ASSERT_EQ(recorder.steps.size(), kept.result.steps.size()) << path_file;
    for (std::size_t i = 0; i < kept.result.steps.size(); ++i) {
      EXPECT_EQ(recorder.steps[i].index, kept.result.steps[i].index);
      EXPECT_EQ(recorder.steps[i].segment, kept.result.steps[i].segment);
      EXPECT_EQ(recorder.steps[i].path_time, kept.result.steps[i].path_time);
      EXPECT_EQ(recorder.steps[i].q, kept.result.steps[i].q);
      EXPECT_EQ(recorder.steps[i].refinement, kept.result.steps[i].refinement);
      EXPECT_EQ(recorder.steps[i].interference_points.size(),
                kept.result.steps[i].interference_points.size());
    }
    ASSERT_EQ(recorder.segments.size(), kept.certificate.segments.size());
    for (std::size_t k = 0; k < recorder.segments.size(); ++k) {
      EXPECT_EQ(certificate_segment_to_json(recorder.segments[k]),
                certificate_segment_to_json(kept.certificate.segments[k]))
          << path_file << " segment " << k + 1;
    }
  }
}

TEST_F(Observed, ACertificateStepIsPassedOnOnlyOnceItsSuccessorIsKnown) {
  Recorder recorder;
  run("path.txt", &recorder, false);
  // Segment 1 starts at step 0: its record follows step 1 (whose transition completes it),
  // step n's follows step n+1, and the last one comes at the segment's end.
  ASSERT_GE(recorder.events.size(), 6u);
  EXPECT_EQ(recorder.events[0], "begin 1");
  EXPECT_EQ(recorder.events[1], "step 1");
  EXPECT_EQ(recorder.events[2], "certificate 0");
  EXPECT_EQ(recorder.events[3], "step 2");
  EXPECT_EQ(recorder.events[4], "certificate 1");
  const auto end = std::find(recorder.events.begin(), recorder.events.end(), "end");
  ASSERT_NE(end, recorder.events.end());
  const int last_step_of_segment_1 = recorder.segments.at(0).steps.back().step;
  EXPECT_EQ(*(end - 1), "certificate " + std::to_string(last_step_of_segment_1));
  EXPECT_EQ(*(end - 2), "certificate " + std::to_string(last_step_of_segment_1 - 1));
  EXPECT_EQ(*(end - 3), "step " + std::to_string(last_step_of_segment_1));
}

TEST_F(Observed, ARunThatKeepsNoStepHasTheSameSummaries) {
  for (const char* path_file : {"path.txt", "path-output-sample.txt"}) {
    const VerificationRun kept = run(path_file, nullptr, true);
    const VerificationRun lean = run(path_file, nullptr, false);
    EXPECT_TRUE(lean.result.steps.empty());
    EXPECT_EQ(lean.result.verdict, kept.result.verdict);
    EXPECT_EQ(lean.result.collision_step, kept.result.collision_step);
    EXPECT_EQ(lean.result.total_cycle_time, kept.result.total_cycle_time);
    ASSERT_EQ(lean.result.errors.size(), kept.result.errors.size());
    for (std::size_t i = 0; i < kept.result.errors.size(); ++i) {
      EXPECT_EQ(lean.result.errors[i].code, kept.result.errors[i].code);
      EXPECT_EQ(lean.result.errors[i].step, kept.result.errors[i].step);
    }
    ASSERT_EQ(lean.result.segments.size(), kept.result.segments.size());
    for (std::size_t i = 0; i < kept.result.segments.size(); ++i) {
      EXPECT_EQ(lean.result.segments[i].first_step, kept.result.segments[i].first_step);
      EXPECT_EQ(lean.result.segments[i].last_step, kept.result.segments[i].last_step);
      EXPECT_EQ(lean.result.segments[i].start_q, kept.result.segments[i].start_q);
    }
    ASSERT_EQ(lean.result.link_clearances.size(), kept.result.link_clearances.size());
    for (std::size_t i = 0; i < kept.result.link_clearances.size(); ++i) {
      EXPECT_EQ(lean.result.link_clearances[i].min_clearance,
                kept.result.link_clearances[i].min_clearance);
      EXPECT_EQ(lean.result.link_clearances[i].step, kept.result.link_clearances[i].step);
      EXPECT_EQ(lean.result.link_clearances[i].obstacle, kept.result.link_clearances[i].obstacle);
    }
    for (const SegmentCertificate& segment : lean.certificate.segments) {
      EXPECT_TRUE(segment.steps.empty());
    }
    EXPECT_EQ(lean.certificate.segments.size(), kept.certificate.segments.size());
    EXPECT_EQ(lean.certificate.claim, kept.certificate.claim);
  }
}

}  // namespace
}  // namespace grpvss::certify
