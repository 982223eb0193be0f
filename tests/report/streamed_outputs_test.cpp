// The streaming writers (thesis output, JSON report with scene, certificate) against the
// whole-document writers on real runs of the IBM 7545 sample: byte-identical files, from a
// verification that kept no step (VerifyOptions::keep_steps = false). Runs: certified with a
// collision, certified with error 7 (CP joint jump), thesis mode CLEAR, thesis mode with a
// refused segment (error 3).
#include <filesystem>
#include <optional>
#include <string>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "grpvss/certify/verifier.hpp"
#include "grpvss/io/environment_file.hpp"
#include "grpvss/io/path_file.hpp"
#include "grpvss/io/robot_file.hpp"
#include "grpvss/motion/kinematics_adapter.hpp"
#include "grpvss/report/certificate_output.hpp"
#include "grpvss/report/file_units.hpp"
#include "grpvss/report/json_report.hpp"
#include "grpvss/report/json_report_stream.hpp"
#include "grpvss/report/scene_json.hpp"
#include "grpvss/report/thesis_output.hpp"
#include "support/data_paths.hpp"
#include "support/text_files.hpp"

namespace grpvss::report {
namespace {

using grpvss::test::ibm7545_file;

const nlohmann::json kInputs = {{"robot", "r"}, {"environment", "e"}, {"path", "p"}, {"ik", "ik"}};
const InputDigests kDigests = {{"robot.txt", "aa"}, {"environment.txt", "bb"}, {"path.txt", "cc"}};
const char* const kGeneratedAt = "2026-11-21T00:00:00Z";

struct Case {
  const char* name;
  const char* path_file;
  certify::ResolutionMode mode;
  double tolerance;
};

class StreamedOutputs : public ::testing::TestWithParam<Case> {
 protected:
  void SetUp() override {
    robot_ = io::read_robot_file(ibm7545_file("robot.txt"));
    environment_ = io::read_environment_file(ibm7545_file("environment.txt"));
    program_ = io::read_path_file(ibm7545_file(GetParam().path_file), robot_);
    kinematics_ = motion::make_kinematics_access(
        robot_, motion::select_ik({}, robot_, "robot.txt"));
    certify::SetupRequest request;
    request.tolerance = GetParam().tolerance;
    request.mode = GetParam().mode;
    setup_ = certify::resolve_setup(request);
    cell_.emplace(robot_, environment_, setup_.cell);
    directory_ = test::make_temporary_directory("streamed");
  }
  void TearDown() override { std::filesystem::remove_all(directory_); }

  bool certified() const { return GetParam().mode == certify::ResolutionMode::kCertified; }

  RobotModel robot_;
  Environment environment_;
  PathProgram program_;
  motion::KinematicsAccess kinematics_;
  certify::VerificationSetup setup_;
  std::optional<certify::RobotCell> cell_;
  std::string directory_;
};

TEST_P(StreamedOutputs, AreByteIdenticalToTheWholeDocumentWriters) {
  // Reference: every step kept, each document built whole.
  const certify::VerificationRun kept = certify::verify(*cell_, program_, kinematics_, setup_.run);
  ASSERT_FALSE(kept.result.steps.empty());
  const std::string thesis_expected = render_thesis_output(kept.result, robot_);
  nlohmann::json report = report_to_json(kept.result, robot_, kDigests, kGeneratedAt);
  report["scene"] = scene_to_json(kept.result, *cell_);
  const std::string report_expected = render_json_report(report);

  // Streamed: nothing kept.
  ThesisOutputStream thesis(directory_ + "/out.txt", false, joint_types_of(robot_));
  JsonReportStream json(robot_, {directory_ + "/report.json", false, directory_ + "/report.json", false});
  std::optional<CertificateStream> certificate;
  certify::RunHooks streaming;
  streaming.keep_steps = false;
  streaming.observers = {&thesis, &json};
  if (certified()) {
    certificate.emplace(directory_ + "/certificate.json", false);
    streaming.observers.push_back(&*certificate);
  }
  const certify::VerificationRun run =
      certify::verify(*cell_, program_, kinematics_, setup_.run, streaming);
  EXPECT_TRUE(run.result.steps.empty());
  for (const auto& segment : run.certificate.segments) EXPECT_TRUE(segment.steps.empty());
  EXPECT_EQ(run.result.verdict, kept.result.verdict);
  EXPECT_EQ(run.result.collision_step, kept.result.collision_step);
  EXPECT_EQ(run.result.segments.size(), kept.result.segments.size());

  thesis.finish(run.result);
  json.finish(run.result, *cell_, kDigests, kGeneratedAt);
  EXPECT_EQ(test::read_text_file(directory_ + "/out.txt"), thesis_expected);
  EXPECT_EQ(test::read_text_file(directory_ + "/report.json"), report_expected);
  if (certified()) {
    certificate->finish(run.certificate, kInputs);
    EXPECT_EQ(test::read_text_file(directory_ + "/certificate.json"),
              render_certificate(kept.certificate, kInputs));
  }
  // Only the outputs: the scratch files had no name, the temporaries are gone.
  std::vector<std::string> expected_files = {"out.txt", "report.json"};
  if (certified()) expected_files.insert(expected_files.begin(), "certificate.json");
  EXPECT_EQ(test::directory_entries(directory_), expected_files);
}

INSTANTIATE_TEST_SUITE_P(
    Ibm7545, StreamedOutputs,
    ::testing::Values(
        Case{"CertifiedCollision", "path.txt", certify::ResolutionMode::kCertified, 0.5},
        Case{"CertifiedErrorSeven", "path-output-sample.txt", certify::ResolutionMode::kCertified, 0.5},
        Case{"ThesisClear", "path.txt", certify::ResolutionMode::kThesis, 0.5},
        Case{"ThesisRefusedSegment", "path-output-sample.txt", certify::ResolutionMode::kThesis, 1.0}),
    [](const ::testing::TestParamInfo<Case>& info) { return std::string(info.param.name); });

}  // namespace
}  // namespace grpvss::report
