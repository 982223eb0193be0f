// The one `motion:` line of a path run (issue #20 point 1): `verify` prints it first, the JSON
// report carries the same text as `motion_model`, batch and verify agree; the thesis output file
// of thesis inputs does not carry it (its layout is the thesis's).
#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <string>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "app/exit_codes.hpp"
#include "support/cli_run.hpp"
#include "support/data_paths.hpp"
#include "support/text_files.hpp"

namespace {

using grpvss::test::kIbm7545Data;
using grpvss::test::kTestCells;
const std::string kSample = "--robot " + kIbm7545Data + "robot.txt --env " + kIbm7545Data +
                            "environment.txt --path " + kIbm7545Data + "path.txt --tolerance 0.5";
const std::string kClaim = "claim: CLEAR = robot + tolerance clear along the whole motion";
const std::string kStepsClaim =
    "claim: CLEAR = robot clear along the whole motion and robot + tolerance clear at every step";

using grpvss::test::CliRun;
using grpvss::test::run_cli;

class MotionLineCli : public ::testing::Test {
 protected:
  void SetUp() override {
    directory_ = std::filesystem::temp_directory_path() /
                 ("grpvss-motion-line-cli-" + std::to_string(::getpid()));
    std::filesystem::create_directories(directory_);
  }
  void TearDown() override { std::filesystem::remove_all(directory_); }
  std::string dir() const { return directory_.string(); }
  std::string read(const std::string& name) const {
    return grpvss::test::read_text_file(dir() + "/" + name);
  }
  std::filesystem::path directory_;
};

std::string first_line(const std::string& text) { return text.substr(0, text.find('\n')); }

TEST_F(MotionLineCli, TheThesisSampleStatesIndependentTimingTheIbmIkAndTheClaim) {
  const CliRun verify = run_cli(dir(), "verify " + kSample + " --json r.json --out o.txt");
  ASSERT_EQ(verify.exit_code, grpvss::app::kExitFinding) << verify.err;
  const std::string line =
      "path path.txt, independent PTP timing (trapezoid profiles, each joint on its own), CP "
      "lines at 1 length units/s, IK IBM 7545 closed form (solution nearest the previous "
      "joints), exact stops (no blending), " + kClaim;
  EXPECT_EQ(first_line(verify.out), "motion: " + line);
  EXPECT_EQ(nlohmann::json::parse(read("r.json"))["motion_model"], line);
  EXPECT_EQ(read("o.txt").find("motion"), std::string::npos);  // the thesis layout, unchanged
}

TEST_F(MotionLineCli, TimingTableCpSpeedAndModeChangeTheirParts) {
  const CliRun verify = run_cli(
      dir(), "verify " + kSample + " --timing synchronized --cp-speed 2 --mode thesis "
             "--profile-table " GRPVSS_SOURCE_DIR "/data/motion/example-table.txt");
  EXPECT_EQ(first_line(verify.out),
            "motion: path path.txt, synchronized PTP timing (profile table example-table.txt, "
            "straight line in joint space), CP lines at 2 length units/s, IK IBM 7545 closed "
            "form (solution nearest the previous joints), exact stops (no blending), claim: "
            "none (thesis mode, not certified)")
      << verify.out << verify.err;
}

TEST_F(MotionLineCli, ACellRunStatesSynchronizedTimingTheUrIkAndItsCpSpeed) {
  const CliRun verify = run_cli(dir(), "verify --cell " + kTestCells + "ur5e-post-no-self.yaml --path " +
                                           kTestCells + "ur5e-clear.txt");
  ASSERT_EQ(verify.exit_code, grpvss::app::kExitOk) << verify.err;
  EXPECT_EQ(first_line(verify.out),
            "motion: path ur5e-clear.txt, synchronized PTP timing (trapezoid profiles, straight "
            "line in joint space), CP lines at 1 length units/s, IK UR closed form (solution "
            "nearest the previous joints), exact stops (no blending), " + kClaim);
}

TEST_F(MotionLineCli, BatchReportsStateTheSameLine) {
  std::filesystem::copy_file(kIbm7545Data + "path.txt", dir() + "/path.txt");
  std::ofstream(dir() + "/m.jsonl") << R"({"robot": ")" << kIbm7545Data << R"(robot.txt", "env": ")"
                                    << kIbm7545Data << R"(environment.txt", "path": "path.txt", )"
                                    << R"("tolerance": 0.5, "json": "b.json"})" << "\n";
  const CliRun batch = run_cli(dir(), "batch m.jsonl --quiet");
  ASSERT_EQ(batch.exit_code, grpvss::app::kExitFinding) << batch.err;
  const CliRun verify = run_cli(dir(), "verify " + kSample + " --json v.json --quiet");
  EXPECT_EQ(nlohmann::json::parse(read("b.json"))["motion_model"],
            nlohmann::json::parse(read("v.json"))["motion_model"]);
}

TEST_F(MotionLineCli, ClaimStepsStatesTheClaimAtTheSteps) {
  const CliRun verify = run_cli(dir(), "verify " + kSample + " --claim steps --json r.json");
  ASSERT_EQ(verify.exit_code, grpvss::app::kExitFinding) << verify.err;
  const std::string line = first_line(verify.out);
  EXPECT_EQ(line.substr(line.size() - kStepsClaim.size()), kStepsClaim);
  const nlohmann::json report = nlohmann::json::parse(read("r.json"));
  EXPECT_EQ(report["claim"], "steps");
  EXPECT_EQ(report["motion_model"], line.substr(std::string("motion: ").size()));
  const CliRun refused = run_cli(dir(), "verify " + kSample + " --claim everywhere");
  EXPECT_EQ(refused.exit_code, grpvss::app::kExitInputError);
}

TEST_F(MotionLineCli, BatchKeyClaimStatesTheSameLineAsVerify) {
  std::filesystem::copy_file(kIbm7545Data + "path.txt", dir() + "/path.txt");
  std::ofstream(dir() + "/m.jsonl") << R"({"robot": ")" << kIbm7545Data << R"(robot.txt", "env": ")"
                                    << kIbm7545Data << R"(environment.txt", "path": "path.txt", )"
                                    << R"("tolerance": 0.5, "claim": "steps", "json": "b.json"})"
                                    << "\n";
  const CliRun batch = run_cli(dir(), "batch m.jsonl --quiet");
  ASSERT_EQ(batch.exit_code, grpvss::app::kExitFinding) << batch.err;
  const nlohmann::json report = nlohmann::json::parse(read("b.json"));
  const std::string line = report["motion_model"];
  EXPECT_EQ(line.substr(line.size() - kStepsClaim.size()), kStepsClaim);
  EXPECT_EQ(report["claim"], "steps");
}

}  // namespace
