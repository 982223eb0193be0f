// Batch jobs with `program` (a robot program, docs/batch.md, docs/robot-programs.md) on the UR5e
// cell of tests/data/cells/ur5e-post-no-self.yaml (the robot of ../shared/robots, tests only):
// their reports and certificates are the bytes `grpvss verify --program` writes, their result
// lines carry verify's verdict, step count and the reader's warnings; the certificate is
// ACCEPTED by `check-certificate --program`; a refused motion is that job's error with verify's
// exact message while the other jobs run; a manifest with a key that contradicts the program is
// refused naming its line.
#include <filesystem>
#include <fstream>
#include <string>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "grpvss/batch/batch_manifest.hpp"
#include "grpvss/common/input_error.hpp"
#include "grpvss/io/robot_program_file.hpp"
#include "support/cli_run.hpp"
#include "support/data_paths.hpp"
#include "support/text_files.hpp"

namespace {

using grpvss::test::kUr5ePostNoSelfCell;
using grpvss::test::kTestPrograms;

using grpvss::test::CliRun;
using grpvss::test::run_cli;

class BatchProgram : public ::testing::Test {
 protected:
  void SetUp() override { directory_ = grpvss::test::make_temporary_directory("batch-program"); }
  void TearDown() override { std::filesystem::remove_all(directory_); }
  std::string read(const std::string& name) const {
    return grpvss::test::read_text_file(directory_ + "/" + name);
  }
  std::string directory_;
};

std::string program_job(const std::string& id, const std::string& program, const std::string& extra) {
  return "  - {id: " + id + ", cell: " + kUr5ePostNoSelfCell + ", program: " + kTestPrograms + program + extra + "}\n";
}

using grpvss::test::summary_steps;

TEST_F(BatchProgram, ReportsCertificatesAndResultLinesAreThoseOfVerifyProgram) {
  std::ofstream(directory_ + "/m.yaml")
      << "jobs:\n"
      << program_job("clear", "ur5e-clear.script", ", json: clear.json, certificate: clear.cert")
      << program_job("post", "ur5e-through-post.script", ", json: post.json, certificate: post.cert");
  const CliRun batch = run_cli(directory_, "batch m.yaml -j 2");
  ASSERT_EQ(batch.exit_code, 1) << batch.out << batch.err;
  const auto lines = grpvss::test::split_lines(batch.out);
  ASSERT_EQ(lines.size(), 2u) << batch.out;
  const struct { const char* id; const char* file; const char* verdict; int exit_code; int steps; }
      expected[] = {{"clear", "ur5e-clear.script", "CLEAR", 0, 12},
                    {"post", "ur5e-through-post.script", "COLLISION", 1, -1}};
  for (int i = 0; i < 2; ++i) {
    const std::string id = expected[i].id;
    const CliRun verify = run_cli(directory_, "verify --cell " + kUr5ePostNoSelfCell + " --program " + kTestPrograms +
                                                  expected[i].file + " --json v-" + id +
                                                  ".json --certificate v-" + id + ".cert --no-cache");
    ASSERT_EQ(verify.exit_code, expected[i].exit_code) << verify.err;
    const nlohmann::json line = nlohmann::json::parse(lines[i]);
    EXPECT_EQ(line["id"], id);
    EXPECT_EQ(line["verdict"], expected[i].verdict);
    EXPECT_EQ(line["exit_code"], expected[i].exit_code);
    if (expected[i].steps > 0) EXPECT_EQ(line["steps"], expected[i].steps);
    EXPECT_EQ(line["steps"].get<int>(), summary_steps(verify.out)) << verify.out;
    EXPECT_TRUE(line["error"].is_null()) << lines[i];
    EXPECT_EQ(read(id + ".cert"), read("v-" + id + ".cert"));
    nlohmann::json batch_report = nlohmann::json::parse(read(id + ".json"));
    nlohmann::json verify_report = nlohmann::json::parse(read("v-" + id + ".json"));
    batch_report.erase("generated_at");
    verify_report.erase("generated_at");
    EXPECT_EQ(batch_report, verify_report);
    EXPECT_EQ(batch_report["motion_model"].get<std::string>().rfind(
                  std::string("program ") + expected[i].file + " (URScript), synchronized PTP", 0),
              0u)
        << batch_report["motion_model"];
  }
  // The reader's warning verify prints is the clear job's warning, as data.
  const nlohmann::json clear = nlohmann::json::parse(lines[0]);
  ASSERT_TRUE(clear.contains("warnings")) << lines[0];
  bool popup = false;
  for (const auto& warning : clear["warnings"]) {
    if (warning["line"] == 9 && warning["text"] == "not read: popup(\"placed\")" &&
        warning["file"].get<std::string>().find("ur5e-clear.script") != std::string::npos) {
      popup = true;
    }
  }
  EXPECT_TRUE(popup) << lines[0];
  const nlohmann::json certificate = nlohmann::json::parse(read("clear.cert"));
  EXPECT_EQ(certificate["inputs"]["program_language"], "URScript");
  EXPECT_FALSE(certificate["inputs"].contains("path"));
  const CliRun check = run_cli(directory_, "check-certificate --cell " + kUr5ePostNoSelfCell + " --program " +
                                               kTestPrograms + "ur5e-clear.script clear.cert");
  EXPECT_EQ(check.exit_code, 0) << check.out << check.err;
}

TEST_F(BatchProgram, AStartAndThesisModeGiveVerifysOutputs) {
  // `start` (rad with a cell) is where the first PTP motion starts; `mode: thesis` and `output`
  // are accepted, as verify --program accepts --mode thesis and --out.
  const std::string start = "0.3,-1.5707963267948966,1.5707963267948966,0,0,0";
  std::ofstream(directory_ + "/m.yaml")
      << "jobs:\n"
      << program_job("started", "ur5e-clear.script", ", start: \"" + start + "\", certificate: s.cert")
      << program_job("thesis", "ur5e-clear.script", ", mode: thesis, output: t.txt");
  const CliRun batch = run_cli(directory_, "batch m.yaml");
  ASSERT_EQ(batch.exit_code, 0) << batch.out << batch.err;
  const CliRun started = run_cli(directory_, "verify " + std::string("--cell ") + kUr5ePostNoSelfCell +
                                                 " --program " + kTestPrograms +
                                                 "ur5e-clear.script --start " + start +
                                                 " --certificate v-s.cert --no-cache");
  ASSERT_EQ(started.exit_code, 0) << started.err;
  EXPECT_EQ(read("s.cert"), read("v-s.cert"));
  const nlohmann::json recorded_start = nlohmann::json::parse(read("s.cert"))["start"];
  ASSERT_TRUE(recorded_start.is_array());
  EXPECT_EQ(recorded_start[0].get<double>(), 0.3);
  const CliRun thesis = run_cli(directory_, "verify --cell " + kUr5ePostNoSelfCell + " --program " + kTestPrograms +
                                                "ur5e-clear.script --mode thesis --out v-t.txt "
                                                "--no-cache");
  ASSERT_EQ(thesis.exit_code, 0) << thesis.err;
  EXPECT_EQ(read("t.txt"), read("v-t.txt"));
  const auto lines = grpvss::test::split_lines(batch.out);
  ASSERT_EQ(lines.size(), 2u) << batch.out;
  EXPECT_EQ(nlohmann::json::parse(lines[1])["steps"].get<int>(), summary_steps(thesis.out));
}

TEST_F(BatchProgram, ARefusedMotionIsThatJobsErrorWithVerifysMessage) {
  std::ofstream(directory_ + "/m.yaml") << "jobs:\n"
                                        << program_job("movel", "ur5e-movel.script", "")
                                        << program_job("clear", "ur5e-clear.script", "");
  const CliRun batch = run_cli(directory_, "batch m.yaml");
  const CliRun verify = run_cli(directory_, "verify --cell " + kUr5ePostNoSelfCell + " --program " + kTestPrograms +
                                                "ur5e-movel.script --quiet");
  EXPECT_EQ(batch.exit_code, 2) << batch.err;
  const auto lines = grpvss::test::split_lines(batch.out);
  ASSERT_EQ(lines.size(), 2u) << batch.out;
  const nlohmann::json movel = nlohmann::json::parse(lines[0]);
  EXPECT_TRUE(movel["verdict"].is_null());
  EXPECT_EQ(movel["exit_code"], 2);
  EXPECT_EQ(movel["error"]["file"], kTestPrograms + "ur5e-movel.script");
  EXPECT_GT(movel["error"]["line"].get<int>(), 0);
  EXPECT_EQ("grpvss: error: " + movel["error"]["message"].get<std::string>() + "\n", verify.err);
  EXPECT_EQ(nlohmann::json::parse(lines[1])["verdict"], "CLEAR");
}

std::string program_manifest_error(const std::string& text) {
  try {
    (void)grpvss::batch::parse_batch_manifest(text, "m.yaml");
  } catch (const grpvss::InputError& error) {
    return error.what();
  }
  return "no error";
}

TEST(BatchProgramManifest, ExactlyOneMotionAndNoKeyThatContradictsTheProgram) {
  const auto manifest = grpvss::batch::parse_batch_manifest(
      "jobs:\n  - {cell: c.yaml, program: p.script, timing: synchronized, start: \"0,0,0,0,0,0\"}\n",
      "cells/m.yaml");
  EXPECT_EQ(manifest.jobs[0].options.program_file, "cells/p.script");
  EXPECT_EQ(manifest.jobs[0].options.path_file, "");
  EXPECT_EQ(manifest.jobs[0].options.start, "0,0,0,0,0,0");
  EXPECT_EQ(program_manifest_error("jobs:\n  - {cell: c.yaml, program: p, trajectory: t}\n"),
            "m.yaml:2: expected exactly one of `path`, `trajectory` and `program`, found several");
  EXPECT_EQ(program_manifest_error("jobs:\n  - {cell: c.yaml, program: p, timing: independent}\n"),
            "m.yaml:2: expected no `timing` with `program` (a program is verified as the "
            "controller runs it: synchronized PTP, exact stops), found `timing`");
  EXPECT_EQ(program_manifest_error("jobs:\n  - {cell: c.yaml, program: p, profile_table: x.txt}\n"),
            "m.yaml:2: expected no `profile_table` with `program` (a program is verified as the "
            "controller runs it: synchronized PTP, exact stops), found `profile_table`");
}

}  // namespace

// A KRL program reads its .dat and $config.dat too: an output naming either is refused before
// any job runs, and the file is left as it was.
TEST_F(BatchProgram, AnOutputNamingAKrlProgramsDataFileIsRefused) {
  for (const char* name : {"sixaxis_ptp.src", "sixaxis_ptp.dat", "$config.dat"}) {
    std::filesystem::copy_file(kTestPrograms + name, directory_ + "/" + name);
  }
  const std::string six_axis_cell = std::string(GRPVSS_SOURCE_DIR) + "/data/sixaxis/cell.yaml";
  for (const char* data_file : {"sixaxis_ptp.dat", "$config.dat"}) {
    std::ofstream(directory_ + "/m.yaml")
        << "jobs:\n  - {cell: " << six_axis_cell << ", program: sixaxis_ptp.src, json: '"
        << data_file << "'}\n";
    const std::string before = read(data_file);
    const CliRun batch = run_cli(directory_, "batch m.yaml --force");
    EXPECT_EQ(batch.exit_code, 2) << batch.out;
    EXPECT_EQ(batch.out, "");
    EXPECT_EQ(batch.err, std::string("grpvss: error: m.yaml:2: expected `json`: a file that is "
                                     "not an input of the batch, found ") +
                             data_file + "\n");
    EXPECT_EQ(read(data_file), before);
  }
}

TEST(RobotProgramFiles, AKrlSourceListsTheDataFilesBesideItAndOtherProgramsOnlyThemselves) {
  EXPECT_EQ(grpvss::io::robot_program_files(kTestPrograms + "sixaxis_ptp.src"),
            (std::vector<std::string>{kTestPrograms + "sixaxis_ptp.src", kTestPrograms + "$config.dat",
                                      kTestPrograms + "sixaxis_ptp.dat"}));
  EXPECT_EQ(grpvss::io::robot_program_files(kTestPrograms + "sixaxis_cptp.src"),
            (std::vector<std::string>{kTestPrograms + "sixaxis_cptp.src", kTestPrograms + "$config.dat"}));
  EXPECT_EQ(grpvss::io::robot_program_files(kTestPrograms + "ur5e-clear.script"),
            (std::vector<std::string>{kTestPrograms + "ur5e-clear.script"}));
}
