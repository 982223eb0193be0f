// Batch jobs with `trajectory` (a planner's joint trajectory, docs/batch.md) on the UR5e cell
// of tests/data/cells/ur5e-post-no-self.yaml (the robot of ../shared/robots, tests only):
// their reports and certificates are the bytes `grpvss verify --trajectory` writes and their
// result lines carry the verdict and step count verify prints; a trajectory the robot cannot
// run is that job's error with verify's exact message while the other jobs run; a manifest
// with both or neither of `path` and `trajectory`, or with a key that contradicts the
// trajectory, is refused naming its line.
#include <filesystem>
#include <fstream>
#include <string>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "grpvss/batch/batch_manifest.hpp"
#include "grpvss/common/input_error.hpp"
#include "support/cli_run.hpp"
#include "support/data_paths.hpp"
#include "support/text_files.hpp"

namespace {

using grpvss::test::kIbm7545Data;
using grpvss::test::kUr5ePostNoSelfCell;
using grpvss::test::kTestTrajectories;

using grpvss::test::CliRun;
using grpvss::test::run_cli;

class BatchTrajectory : public ::testing::Test {
 protected:
  void SetUp() override { directory_ = grpvss::test::make_temporary_directory("batch-trajectory"); }
  void TearDown() override { std::filesystem::remove_all(directory_); }
  std::string read(const std::string& name) const {
    return grpvss::test::read_text_file(directory_ + "/" + name);
  }
  std::string directory_;
};

std::string trajectory_job(const std::string& id, const std::string& trajectory, const std::string& extra) {
  return "  - {id: " + id + ", cell: " + kUr5ePostNoSelfCell + ", trajectory: " + kTestTrajectories + trajectory +
         extra + "}\n";
}

using grpvss::test::summary_steps;

TEST_F(BatchTrajectory, ReportsCertificatesAndResultLinesAreThoseOfVerifyTrajectory) {
  std::ofstream(directory_ + "/m.yaml")
      << "jobs:\n"
      << trajectory_job("clear", "ur5e-clear.json", ", json: clear.json, certificate: clear.cert")
      << trajectory_job("post", "ur5e-through-post.csv", ", json: post.json, certificate: post.cert");
  const CliRun batch = run_cli(directory_, "batch m.yaml -j 2");
  ASSERT_EQ(batch.exit_code, 1) << batch.out << batch.err;
  const auto lines = grpvss::test::split_lines(batch.out);
  ASSERT_EQ(lines.size(), 2u) << batch.out;
  const struct { const char* id; const char* file; const char* verdict; int exit_code; int steps; }
      expected[] = {{"clear", "ur5e-clear.json", "CLEAR", 0, 6},
                    {"post", "ur5e-through-post.csv", "COLLISION", 1, 34}};
  for (int i = 0; i < 2; ++i) {
    const std::string id = expected[i].id;
    const CliRun verify = run_cli(directory_, "verify --cell " + kUr5ePostNoSelfCell + " --trajectory " +
                                                  kTestTrajectories + expected[i].file + " --json v-" +
                                                  id + ".json --certificate v-" + id +
                                                  ".cert --no-cache");
    ASSERT_EQ(verify.exit_code, expected[i].exit_code) << verify.err;
    const nlohmann::json line = nlohmann::json::parse(lines[i]);
    EXPECT_EQ(line["id"], id);
    EXPECT_EQ(line["verdict"], expected[i].verdict);
    EXPECT_EQ(line["exit_code"], expected[i].exit_code);
    EXPECT_EQ(line["steps"], expected[i].steps);
    EXPECT_EQ(summary_steps(verify.out), expected[i].steps) << verify.out;
    EXPECT_TRUE(line["error"].is_null()) << lines[i];
    EXPECT_EQ(line["outputs"]["certificate"], id + ".cert");
    EXPECT_EQ(read(id + ".cert"), read("v-" + id + ".cert"));
    nlohmann::json batch_report = nlohmann::json::parse(read(id + ".json"));
    nlohmann::json verify_report = nlohmann::json::parse(read("v-" + id + ".json"));
    EXPECT_EQ(batch_report["generated_at"].is_string(), true);
    batch_report.erase("generated_at");
    verify_report.erase("generated_at");
    EXPECT_EQ(batch_report, verify_report);
    EXPECT_EQ(batch_report["motion_model"].get<std::string>().rfind(
                  std::string("joint trajectory ") + expected[i].file + ", ", 0),
              0u);
    // The smallest clearance of the line is the report's smallest per-link clearance.
    double smallest = 1e300;
    for (const auto& link : batch_report["link_clearances"]) {
      smallest = std::min(smallest, link["min_clearance"].get<double>());
    }
    EXPECT_EQ(line["smallest_clearance"]["clearance"].get<double>(), smallest) << lines[i];
  }
  const nlohmann::json certificate = nlohmann::json::parse(read("clear.cert"));
  EXPECT_TRUE(certificate["inputs"].contains("trajectory"));
  EXPECT_FALSE(certificate["inputs"].contains("path"));
  const CliRun check = run_cli(directory_, "check-certificate --cell " + kUr5ePostNoSelfCell + " --trajectory " +
                                               kTestTrajectories + "ur5e-clear.json clear.cert");
  EXPECT_EQ(check.exit_code, 0) << check.out << check.err;
}

TEST_F(BatchTrajectory, ATrajectoryTheRobotCannotRunIsThatJobsErrorWithVerifysMessage) {
  std::ofstream(directory_ + "/m.yaml") << "jobs:\n"
                                        << trajectory_job("limit", "ur5e-elbow-limit.csv", "")
                                        << trajectory_job("clear", "ur5e-clear.json", "");
  const CliRun batch = run_cli(directory_, "batch m.yaml");
  const CliRun verify = run_cli(directory_, "verify --cell " + kUr5ePostNoSelfCell + " --trajectory " +
                                                kTestTrajectories + "ur5e-elbow-limit.csv");
  EXPECT_EQ(batch.exit_code, 2) << batch.err;
  const auto lines = grpvss::test::split_lines(batch.out);
  ASSERT_EQ(lines.size(), 2u) << batch.out;
  const nlohmann::json limit = nlohmann::json::parse(lines[0]);
  EXPECT_TRUE(limit["verdict"].is_null());
  EXPECT_EQ(limit["exit_code"], 2);
  EXPECT_EQ(limit["error"]["file"], kTestTrajectories + "ur5e-elbow-limit.csv");
  EXPECT_EQ(limit["error"]["line"], 3);
  EXPECT_EQ("grpvss: error: " + limit["error"]["message"].get<std::string>() + "\n", verify.err);
  EXPECT_EQ(nlohmann::json::parse(lines[1])["verdict"], "CLEAR");
}

TEST_F(BatchTrajectory, AThesisRobotJobWithATrajectoryIsRefusedAtTheTrajectorysJointNames) {
  const std::string& data = kIbm7545Data;
  std::ofstream(directory_ + "/m.jsonl")
      << R"({"robot":")" << data << R"(robot.txt","env":")" << data
      << R"(environment.txt","tolerance":0.5,"trajectory":")" << kTestTrajectories
      << "ur5e-clear.json\"}\n";
  const CliRun batch = run_cli(directory_, "batch m.jsonl");
  EXPECT_EQ(batch.exit_code, 2) << batch.err;
  const nlohmann::json line = nlohmann::json::parse(batch.out);
  EXPECT_EQ(line["error"]["line"], 3);
  EXPECT_EQ(line["error"]["message"],
            kTestTrajectories + "ur5e-clear.json:3: expected a robot with named joints (a URDF robot "
                            "in a cell, --cell): a trajectory's joints are matched by name, found "
                            "a robot file without joint names");
}

std::string trajectory_manifest_error(const std::string& text) {
  try {
    (void)grpvss::batch::parse_batch_manifest(text, "m.yaml");
  } catch (const grpvss::InputError& error) {
    return error.what();
  }
  return "no error";
}

TEST(BatchTrajectoryManifest, ExactlyOneMotionAndNoKeyThatContradictsTheTrajectory) {
  const auto manifest = grpvss::batch::parse_batch_manifest(
      "jobs:\n  - {cell: c.yaml, trajectory: t.csv, json: r.json}\n", "cells/m.yaml");
  EXPECT_EQ(manifest.jobs[0].options.trajectory_file, "cells/t.csv");
  EXPECT_EQ(manifest.jobs[0].options.path_file, "");
  EXPECT_EQ(trajectory_manifest_error("jobs:\n  - {cell: c.yaml}\n  - {cell: c.yaml, path: p, trajectory: t}\n"),
            "m.yaml:2: expected exactly one of `path`, `trajectory` and `program`, found neither");
  EXPECT_EQ(trajectory_manifest_error("jobs:\n  - {cell: c.yaml, path: p}\n  - {cell: c.yaml, path: p, trajectory: t}\n"),
            "m.yaml:3: expected exactly one of `path`, `trajectory` and `program`, found several");
  EXPECT_EQ(trajectory_manifest_error("jobs:\n  - {cell: c.yaml, trajectory: t, timing: independent}\n"),
            "m.yaml:2: expected no `timing` with `trajectory` (the trajectory's waypoint times "
            "and interpolation are the motion), found `timing`");
  EXPECT_EQ(trajectory_manifest_error("jobs:\n  - {cell: c.yaml, trajectory: t, cp_speed: 1}\n"),
            "m.yaml:2: expected no `cp_speed` with `trajectory` (the trajectory's waypoint times "
            "and interpolation are the motion), found `cp_speed`");
  EXPECT_EQ(trajectory_manifest_error("jobs:\n  - {cell: c.yaml, trajectory: t, profile_table: x.txt}\n"),
            "m.yaml:2: expected no `profile_table` with `trajectory` (the trajectory's waypoint "
            "times and interpolation are the motion), found `profile_table`");
  EXPECT_EQ(trajectory_manifest_error("jobs:\n  - {cell: c.yaml, trajectory: t, start: \"0,0,0,0,0,0\"}\n"),
            "m.yaml:2: expected no `start` with `trajectory` (a trajectory starts at its first "
            "waypoint), found `start`");
  EXPECT_EQ(trajectory_manifest_error("jobs:\n  - {cell: c.yaml, trajectory: t, output: o.txt}\n"),
            "m.yaml:2: expected no `output` with `trajectory` (the thesis output file describes "
            "path programs; use `json`), found `output`");
  EXPECT_EQ(trajectory_manifest_error("jobs:\n  - {cell: c.yaml, trajectory: t, mode: thesis}\n"),
            "m.yaml:2: expected no `mode: thesis` with `trajectory` (the thesis step rule is "
            "defined for PTP and CP segments), found mode 'thesis'");
}

}  // namespace
