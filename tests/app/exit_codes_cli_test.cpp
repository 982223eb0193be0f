// `grpvss verify` as a CI gate: one exit code per verdict (0 CLEAR, 1 COLLISION, 2 bad input,
// 3 WITHIN_TOLERANCE, 4 not qualified, 5 UNDECIDED), `--json -` printing the report alone on
// standard output, and outputs that name the same file (or an input) refused before any work.
#include <sys/wait.h>

#include <cstdlib>
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

using grpvss::test::CliRun;
using grpvss::test::run_cli;

// `verify` of `path` (a file in `directory`, or a full path) in `environment` at `tolerance`.
std::string verify_arguments(const std::string& environment, const std::string& path,
                             const std::string& tolerance) {
  return "verify --robot " + kIbm7545Data + "robot.txt --env " + kIbm7545Data + environment + " --path " +
         path + " --tolerance " + tolerance;
}

class ExitCodesCli : public ::testing::Test {
 protected:
  void SetUp() override {
    directory_ = grpvss::test::make_temporary_directory("exit-codes");
    // The Table 3 PTP whose quill passes 0.62 in. above the post (bench-environment-near-miss).
    std::ofstream(directory_ + "/ptp.txt") << "1\n1\n50.,3.\n50.,3.\n4.,0.3\n50.,3.\n";
  }
  void TearDown() override { std::filesystem::remove_all(directory_); }
  std::string directory_;
};

TEST(ExitCodeOfVerdict, EveryVerdictHasItsOwnCode) {
  using grpvss::certify::Verdict;
  EXPECT_EQ(grpvss::app::exit_code_of(Verdict::kClear), 0);
  EXPECT_EQ(grpvss::app::exit_code_of(Verdict::kCollision), 1);
  EXPECT_EQ(grpvss::app::exit_code_of(Verdict::kWithinTolerance), 3);
  EXPECT_EQ(grpvss::app::exit_code_of(Verdict::kError), 4);
  EXPECT_EQ(grpvss::app::exit_code_of(Verdict::kUndecided), 5);
  EXPECT_EQ(grpvss::app::kExitInputError, 2);
}

TEST_F(ExitCodesCli, ClearCollisionWithinToleranceAndNotQualifiedExitWithTheirCodes) {
  const CliRun clear = run_cli(directory_, verify_arguments("bench-environment-near-miss.txt",
                                                            "ptp.txt", "0.5"));
  EXPECT_EQ(clear.exit_code, 0) << clear.out << clear.err;
  EXPECT_NE(clear.out.find("CLEAR"), std::string::npos) << clear.out;

  const CliRun collision =
      run_cli(directory_, verify_arguments("environment.txt", kIbm7545Data + "path.txt", "0.5"));
  EXPECT_EQ(collision.exit_code, 1) << collision.out << collision.err;
  EXPECT_NE(collision.out.find("COLLISION"), std::string::npos) << collision.out;

  // At Delta = 1 the quill's expanded hull reaches the post (0.62 below it); the nominal
  // robot is proven clear.
  const CliRun within = run_cli(directory_, verify_arguments("bench-environment-near-miss.txt",
                                                             "ptp.txt", "1"));
  EXPECT_EQ(within.exit_code, 3) << within.out << within.err;
  EXPECT_NE(within.out.find("WITHIN_TOLERANCE"), std::string::npos) << within.out;

  // The sample path's CP line makes the joints jump (error 7) before anything collides with
  // the lowered post: the path is not qualified.
  const CliRun error = run_cli(
      directory_, verify_arguments("bench-environment-near-miss.txt", kIbm7545Data + "path.txt", "0.5"));
  EXPECT_EQ(error.exit_code, 4) << error.out << error.err;
  EXPECT_NE(error.out.find("verdict: ERROR\n"), std::string::npos) << error.out;
  EXPECT_NE(error.out.find("error 7 (segment 3, step 21)"), std::string::npos) << error.out;

  const CliRun bad = run_cli(directory_, verify_arguments("environment.txt", "missing.txt", "1"));
  EXPECT_EQ(bad.exit_code, 2);
  EXPECT_NE(bad.err.find("missing.txt"), std::string::npos) << bad.err;
}

// `--json -`: standard output is the report and nothing else; the summary goes to stderr.
// The report is the one `--json FILE` writes (all but `generated_at`, the time of rendering).
TEST_F(ExitCodesCli, JsonDashPrintsTheReportAloneOnStandardOutput) {
  const std::string arguments =
      verify_arguments("bench-environment-near-miss.txt", "ptp.txt", "0.5");
  const CliRun to_stdout = run_cli(directory_, arguments + " --json -");
  ASSERT_EQ(to_stdout.exit_code, 0) << to_stdout.err;
  EXPECT_FALSE(std::filesystem::exists(directory_ + "/-"));
  const CliRun to_file = run_cli(directory_, arguments + " --json report.json");
  ASSERT_EQ(to_file.exit_code, 0) << to_file.err;

  nlohmann::json printed = nlohmann::json::parse(to_stdout.out);  // throws on anything extra
  nlohmann::json written =
      nlohmann::json::parse(grpvss::test::read_text_file(directory_ + "/report.json"));
  printed.erase("generated_at");
  written.erase("generated_at");
  EXPECT_EQ(printed, written);
  EXPECT_NE(to_stdout.err.find("CLEAR"), std::string::npos) << to_stdout.err;
  EXPECT_NE(to_stdout.err.find("JSON report: standard output\n"), std::string::npos)
      << to_stdout.err;
  // No scratch or temporary file is left in the working folder.
  EXPECT_EQ(grpvss::test::directory_entries(directory_),
            (std::vector<std::string>{"ptp.txt", "report.json"}));
}

// A run that fails prints nothing on standard output, even with `--json -`.
TEST_F(ExitCodesCli, JsonDashPrintsNothingWhenTheRunFails) {
  const CliRun failed =
      run_cli(directory_, verify_arguments("environment.txt", "missing.txt", "1") + " --json -");
  EXPECT_EQ(failed.exit_code, 2);
  EXPECT_EQ(failed.out, "");
}

// Two outputs naming one file, written differently, are refused before anything is verified
// or written; so is an output that is an input file, even with --force.
TEST_F(ExitCodesCli, OutputsNamingTheSameFileOrAnInputAreRefusedBeforeAnyWork) {
  const std::string arguments =
      verify_arguments("bench-environment-near-miss.txt", "ptp.txt", "0.5");
  const CliRun same = run_cli(directory_, arguments + " --json x.json --certificate ./x.json");
  EXPECT_EQ(same.exit_code, 2);
  EXPECT_EQ(same.err,
            "grpvss: error: --certificate:0: expected an output different from --json, found "
            "./x.json\n");
  EXPECT_FALSE(std::filesystem::exists(directory_ + "/x.json"));

  const CliRun both_stdout = run_cli(directory_, arguments + " --json - --out -");
  EXPECT_EQ(both_stdout.exit_code, 2);
  EXPECT_EQ(both_stdout.out, "");
  EXPECT_NE(both_stdout.err.find("--json:0: expected an output different from --out"),
            std::string::npos)
      << both_stdout.err;

  const std::string path_before = grpvss::test::read_text_file(directory_ + "/ptp.txt");
  const CliRun over_input = run_cli(directory_, arguments + " --json ptp.txt --force");
  EXPECT_EQ(over_input.exit_code, 2);
  EXPECT_EQ(over_input.err,
            "grpvss: error: --json:0: expected an output that is not one of the input files, "
            "found ptp.txt\n");
  EXPECT_EQ(grpvss::test::read_text_file(directory_ + "/ptp.txt"), path_before);
}

}  // namespace
