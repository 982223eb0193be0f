// `grpvss batch` from the command line: one JSON line per job on standard output, the summary
// on standard error, exit code = the worst job's; each job's reports are the bytes
// `grpvss verify` writes for the same inputs; a bad manifest or clashing outputs stop the
// batch with exit code 2 before any job runs.
#include <sys/wait.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <string>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "support/cli_run.hpp"
#include "support/data_paths.hpp"
#include "support/text_files.hpp"

namespace {

using grpvss::test::kIbm7545Data;

using grpvss::test::CliRun;
using grpvss::test::run_cli;

class BatchCli : public ::testing::Test {
 protected:
  void SetUp() override {
    directory_ = grpvss::test::make_temporary_directory("batch-cli");
    std::ofstream(directory_ + "/ptp.txt") << "1\n1\n50.,3.\n50.,3.\n4.,0.3\n50.,3.\n";
    std::filesystem::copy_file(kIbm7545Data + "robot.txt", directory_ + "/robot.txt");
    for (const char* env : {"environment.txt", "bench-environment-near-miss.txt"}) {
      std::filesystem::copy_file(kIbm7545Data + env, directory_ + "/" + env);
    }
  }
  void TearDown() override { std::filesystem::remove_all(directory_); }
  std::string directory_;
};

const char* const kYamlManifest =
    "jobs:\n"
    "  - {id: clear, robot: robot.txt, env: bench-environment-near-miss.txt, path: ptp.txt,"
    " tolerance: 0.5, json: clear.json, output: clear.out, certificate: clear.cert}\n"
    "  - {id: within, robot: robot.txt, env: bench-environment-near-miss.txt, path: ptp.txt,"
    " tolerance: 1}\n"
    "  - {id: collision, robot: robot.txt, env: environment.txt, path: ptp.txt, tolerance: 0.5}\n";

TEST_F(BatchCli, PrintsOneLinePerJobInOrderAndExitsWithTheWorstVerdict) {
  std::ofstream(directory_ + "/m.yaml") << kYamlManifest;
  const CliRun run = run_cli(directory_, "batch m.yaml -j 2");
  EXPECT_EQ(run.exit_code, 1) << run.err;
  const auto lines = grpvss::test::split_lines(run.out);
  ASSERT_EQ(lines.size(), 3u) << run.out;
  const char* const ids[] = {"clear", "within", "collision"};
  const char* const verdicts[] = {"CLEAR", "WITHIN_TOLERANCE", "COLLISION"};
  const int codes[] = {0, 3, 1};
  for (int i = 0; i < 3; ++i) {
    const nlohmann::json line = nlohmann::json::parse(lines[i]);
    EXPECT_EQ(line["index"], i);
    EXPECT_EQ(line["line"], i + 2);
    EXPECT_EQ(line["id"], ids[i]);
    EXPECT_EQ(line["verdict"], verdicts[i]);
    EXPECT_EQ(line["exit_code"], codes[i]);
    EXPECT_TRUE(line["error"].is_null());
  }
  EXPECT_NE(run.err.find("batch: 3 jobs in "), std::string::npos) << run.err;
  EXPECT_NE(run.err.find(" s: 1 CLEAR, 1 COLLISION, 1 WITHIN_TOLERANCE; exit code 1\n"),
            std::string::npos)
      << run.err;
}

// The reports of a batch job are those of `grpvss verify` with the same inputs (the JSON
// report's `generated_at` aside: the time of rendering).
TEST_F(BatchCli, ReportsAreTheBytesVerifyWrites) {
  std::ofstream(directory_ + "/m.yaml") << kYamlManifest;
  ASSERT_EQ(run_cli(directory_, "batch m.yaml --quiet").exit_code, 1);
  const CliRun verify = run_cli(
      directory_,
      "verify --robot robot.txt --env bench-environment-near-miss.txt --path ptp.txt "
      "--tolerance 0.5 --json v.json --out v.out --certificate v.cert --quiet");
  ASSERT_EQ(verify.exit_code, 0) << verify.err;
  const auto read = [&](const std::string& name) {
    return grpvss::test::read_text_file(directory_ + "/" + name);
  };
  EXPECT_EQ(read("clear.out"), read("v.out"));
  EXPECT_EQ(read("clear.cert"), read("v.cert"));
  nlohmann::json batch_report = nlohmann::json::parse(read("clear.json"));
  nlohmann::json verify_report = nlohmann::json::parse(read("v.json"));
  batch_report.erase("generated_at");
  verify_report.erase("generated_at");
  EXPECT_EQ(batch_report, verify_report);
}

TEST_F(BatchCli, ABadManifestStopsTheBatchBeforeAnyJob) {
  std::ofstream(directory_ + "/m.jsonl")
      << R"({"robot":"robot.txt","env":"environment.txt","path":"ptp.txt","tolerance":1,"json":"a.json"})"
      << "\n"
      << R"({"robot":"robot.txt","env":"environment.txt","path":"ptp.txt","tolerance":1,"tolerence":2})"
      << "\n";
  const CliRun run = run_cli(directory_, "batch m.jsonl");
  EXPECT_EQ(run.exit_code, 2);
  EXPECT_EQ(run.out, "");
  EXPECT_EQ(run.err,
            "grpvss: error: m.jsonl:2: expected one of the job keys id, robot, env, cell, path, "
            "trajectory, program, tolerance, mode, offset, claim, timing, profile_table, ik, cp_speed, start, "
            "output, json, html, certificate, found `tolerence`\n");
  EXPECT_FALSE(std::filesystem::exists(directory_ + "/a.json"));
}

TEST_F(BatchCli, TwoJobsNamingOneOutputAreRefusedBeforeAnyJob) {
  std::ofstream(directory_ + "/m.jsonl")
      << R"({"robot":"robot.txt","env":"environment.txt","path":"ptp.txt","tolerance":1,"json":"a.json"})"
      << "\n"
      << R"({"robot":"robot.txt","env":"environment.txt","path":"ptp.txt","tolerance":2,"output":"a.json"})"
      << "\n";
  const CliRun run = run_cli(directory_, "batch m.jsonl");
  EXPECT_EQ(run.exit_code, 2);
  EXPECT_EQ(run.out, "");
  EXPECT_EQ(run.err,
            "grpvss: error: m.jsonl:2: expected `output`: a file no other output names (line 1 "
            "`json` names it), found a.json\n");
  EXPECT_EQ(grpvss::test::directory_entries(directory_),
            (std::vector<std::string>{"bench-environment-near-miss.txt", "environment.txt",
                                      "m.jsonl", "ptp.txt", "robot.txt"}));
}

}  // namespace
