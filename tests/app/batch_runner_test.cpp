// run_batch() (docs/batch.md): results in manifest order whatever the threads, the same lines
// with one thread or two, each robot cell built once and shared, a bad job's error in its own
// result while the others run, outputs checked before any job, and the worst exit code.
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "app/exit_codes.hpp"
#include "batch/batch_job.hpp"
#include "grpvss/batch/batch_manifest.hpp"
#include "grpvss/batch/batch_result_json.hpp"
#include "grpvss/batch/batch_runner.hpp"
#include "grpvss/common/input_error.hpp"
#include "support/data_paths.hpp"
#include "support/text_files.hpp"

namespace {

using grpvss::batch::BatchManifest;
using grpvss::batch::BatchOptions;
using grpvss::batch::BatchStatistics;
using grpvss::batch::JobResult;
using grpvss::batch::job_result_json;
using grpvss::batch::parse_batch_manifest;
using grpvss::batch::run_batch;
using grpvss::batch::verdict_exit_code;
using grpvss::batch::worst_exit_code;

using grpvss::test::kIbm7545Data;

// The Table 3 PTP whose quill passes 0.62 in. above the post of bench-environment-near-miss.
const char* const kShortPtp = "1\n1\n50.,3.\n50.,3.\n4.,0.3\n50.,3.\n";

class BatchRunner : public ::testing::Test {
 protected:
  void SetUp() override {
    directory_ = grpvss::test::make_temporary_directory("batch-runner");
    std::ofstream(directory_ + "/ptp.txt") << kShortPtp;
  }
  void TearDown() override { std::filesystem::remove_all(directory_); }

  // One JSON line per job: `environment` and `path` relative to the data or the temp folder.
  std::string job(const std::string& environment, const std::string& path, double tolerance,
                  const std::string& extra = "") const {
    return "{\"robot\":\"" + kIbm7545Data + "robot.txt\",\"env\":\"" + kIbm7545Data + environment +
           "\",\"path\":\"" + path + "\",\"tolerance\":" + std::to_string(tolerance) + extra +
           "}\n";
  }

  BatchManifest manifest(const std::string& lines) const {
    return parse_batch_manifest(lines, directory_ + "/m.jsonl");
  }

  // The result lines of run_batch() with `threads` workers, and its statistics.
  std::vector<std::string> run(const BatchManifest& jobs, unsigned threads,
                               BatchStatistics* statistics = nullptr) const {
    std::vector<std::string> lines;
    BatchOptions options;
    options.threads = threads;
    options.window_per_thread = 2;  // small, so that the window is exercised
    const BatchStatistics stats =
        run_batch(jobs, options, [&](const JobResult& r) { lines.push_back(job_result_json(r)); });
    if (statistics) *statistics = stats;
    return lines;
  }

  std::string directory_;
};

TEST_F(BatchRunner, ResultsComeInManifestOrderAndEqualOneThreadsWithTwo) {
  std::string lines;
  for (int i = 0; i < 6; ++i) {
    lines += job("environment.txt", kIbm7545Data + "path.txt", 0.5);       // COLLISION, 32 steps
    lines += job("bench-environment-near-miss.txt", "ptp.txt", 0.5);  // CLEAR, short
    lines += job("bench-environment-near-miss.txt", "ptp.txt", 1.0);  // WITHIN_TOLERANCE
  }
  const BatchManifest jobs = manifest(lines);
  const std::vector<std::string> one = run(jobs, 1);
  const std::vector<std::string> two = run(jobs, 2);
  ASSERT_EQ(one.size(), 18u);
  EXPECT_EQ(one, two);
  for (std::size_t i = 0; i < one.size(); ++i) {
    EXPECT_EQ(one[i].rfind("{\"index\":" + std::to_string(i) + ",\"line\":" + std::to_string(i + 1) + ",", 0), 0u)
        << one[i];
  }
  // `grpvss verify` of the same job: "steps: 23", "first collision at step 4" (link 3, post 0).
  EXPECT_NE(one[0].find("\"verdict\":\"COLLISION\",\"exit_code\":1,\"steps\":23,\"smallest_clearance\":"
                        "{\"clearance\":0.0,\"link\":3,\"obstacle\":0,\"step\":4}"),
            std::string::npos)
      << one[0];
  EXPECT_NE(one[1].find("\"verdict\":\"CLEAR\",\"exit_code\":0,"), std::string::npos) << one[1];
  EXPECT_NE(one[2].find("\"verdict\":\"WITHIN_TOLERANCE\",\"exit_code\":3,"), std::string::npos)
      << one[2];
}

TEST_F(BatchRunner, EachDistinctCellIsBuiltOnceAndEachFileReadOnce) {
  const std::string copy = directory_ + "/robot-copy.txt";
  std::filesystem::copy_file(kIbm7545Data + "robot.txt", copy);
  std::string lines;
  for (int i = 0; i < 4; ++i) {
    lines += job("environment.txt", "ptp.txt", 0.5);
    lines += job("bench-environment-near-miss.txt", "ptp.txt", 0.5);
  }
  lines += job("environment.txt", "ptp.txt", 1.0);                      // another tolerance
  lines += job("environment.txt", "ptp.txt", 0.5, ",\"offset\":\"cube\"");  // another shape
  lines += "{\"robot\":\"robot-copy.txt\",\"env\":\"" + kIbm7545Data +
           "environment.txt\",\"path\":\"ptp.txt\",\"tolerance\":0.5}\n";  // same content
  BatchStatistics statistics;
  const auto results = run(manifest(lines), 2, &statistics);
  ASSERT_EQ(results.size(), 11u);
  EXPECT_EQ(statistics.cells_built, 4u);
  EXPECT_EQ(statistics.robots_parsed, 2u);  // two paths, one content
  EXPECT_EQ(statistics.environments_parsed, 2u);
}

TEST_F(BatchRunner, ABadJobCarriesItsErrorAndTheOthersStillRun) {
  std::ofstream(directory_ + "/bad.txt") << "1\n1\n50.,3.\n";
  const BatchManifest jobs = manifest(job("bench-environment-near-miss.txt", "ptp.txt", 0.5) +
                                      job("environment.txt", "missing.txt", 0.5) +
                                      job("environment.txt", "bad.txt", 0.5) +
                                      job("bench-environment-near-miss.txt", "ptp.txt", 1.0));
  const auto lines = run(jobs, 2);
  ASSERT_EQ(lines.size(), 4u);
  const std::string missing = directory_ + "/missing.txt";
  EXPECT_EQ(lines[1],
            "{\"index\":1,\"line\":2,\"id\":null,\"verdict\":null,\"exit_code\":2,\"steps\":0,"
            "\"smallest_clearance\":null,\"outputs\":{},\"error\":{\"file\":\"" + missing +
                "\",\"line\":0,\"message\":\"" + missing +
                ":0: expected a readable file, found No such file or directory\"}}");
  EXPECT_NE(lines[2].find("\"exit_code\":2,"), std::string::npos) << lines[2];
  EXPECT_NE(lines[2].find("\"file\":\"" + directory_ + "/bad.txt\",\"line\":"), std::string::npos)
      << lines[2];
  EXPECT_NE(lines[0].find("\"verdict\":\"CLEAR\""), std::string::npos) << lines[0];
  EXPECT_NE(lines[3].find("\"verdict\":\"WITHIN_TOLERANCE\""), std::string::npos) << lines[3];
}

TEST_F(BatchRunner, OutputsAreCheckedBeforeAnyJobRuns) {
  std::ofstream(directory_ + "/exists.json") << "{}";
  const std::string base = job("bench-environment-near-miss.txt", "ptp.txt", 0.5);
  const auto refused = [&](const std::string& lines, bool force) -> std::string {
    int results = 0;
    BatchOptions options;
    options.force = force;
    try {
      run_batch(manifest(lines), options, [&](const JobResult&) { ++results; });
    } catch (const grpvss::InputError& error) {
      EXPECT_EQ(results, 0);
      return error.what();
    }
    return "";
  };
  const std::string m = directory_ + "/m.jsonl";
  EXPECT_EQ(refused(job("bench-environment-near-miss.txt", "ptp.txt", 0.5, ",\"json\":\"a.json\"") +
                        job("environment.txt", "ptp.txt", 0.5, ",\"certificate\":\"./a.json\""),
                    false),
            m + ":2: expected `certificate`: a file no other output names (line 1 `json` names "
                "it), found " + directory_ + "/a.json");
  EXPECT_EQ(refused(job("environment.txt", "ptp.txt", 0.5, ",\"json\":\"x.json\",\"output\":\"x.json\""), false),
            m + ":1: expected `json`: a file no other output names (line 1 `output` names it), "
                "found " + directory_ + "/x.json");
  EXPECT_EQ(refused(base + job("environment.txt", "ptp.txt", 0.5, ",\"json\":\"exists.json\""), false),
            m + ":2: expected `json`: a file that does not exist yet (or --force), found " +
                directory_ + "/exists.json");
  EXPECT_EQ(grpvss::test::read_text_file(directory_ + "/exists.json"), "{}");
  EXPECT_EQ(refused(base + job("environment.txt", "ptp.txt", 0.5, ",\"json\":\"exists.json\""), true), "");
  EXPECT_EQ(grpvss::test::read_text_file(directory_ + "/exists.json").rfind("{\n  \"", 0), 0u);  // replaced
  EXPECT_EQ(refused(base + job("environment.txt", "ptp.txt", 0.5, ",\"output\":\"ptp.txt\""), true),
            m + ":2: expected `output`: a file that is not an input of the batch, found " +
                directory_ + "/ptp.txt");
  EXPECT_EQ(refused(job("environment.txt", "ptp.txt", 0.5, ",\"html\":\"a.html\""), false),
            m + ":1: expected `html`: a caller that can write the viewer page, found " +
                directory_ + "/a.html");
}

TEST_F(BatchRunner, ReportFilesAreWrittenAndListedInTheResult) {
  const auto lines = run(manifest(job("environment.txt", "ptp.txt", 0.5,
                                      ",\"json\":\"a.json\",\"output\":\"a.out\","
                                      "\"certificate\":\"a.cert\",\"id\":\"a\"")),
                         1);
  ASSERT_EQ(lines.size(), 1u);
  EXPECT_NE(lines[0].find("\"outputs\":{\"output\":\"" + directory_ + "/a.out\",\"json\":\"" +
                          directory_ + "/a.json\",\"certificate\":\"" + directory_ + "/a.cert\"}"),
            std::string::npos)
      << lines[0];
  EXPECT_NE(lines[0].find("\"id\":\"a\""), std::string::npos);
  // Published, and nothing else left behind (no scratch or temporary file).
  EXPECT_EQ(grpvss::test::directory_entries(directory_),
            (std::vector<std::string>{"a.cert", "a.json", "a.out", "ptp.txt"}));
}

TEST_F(BatchRunner, ProgressCountsEveryJobAndASinkErrorEndsTheBatch) {
  std::string lines;
  for (int i = 0; i < 8; ++i) lines += job("bench-environment-near-miss.txt", "ptp.txt", 0.5);
  const BatchManifest jobs = manifest(lines);
  BatchOptions options;
  options.threads = 2;
  std::vector<std::size_t> done;
  run_batch(jobs, options, [](const JobResult&) {},
            [&](std::size_t finished, std::size_t total) {
              EXPECT_EQ(total, 8u);
              done.push_back(finished);
            });
  EXPECT_EQ(done, (std::vector<std::size_t>{1, 2, 3, 4, 5, 6, 7, 8}));

  options.window_per_thread = 1;
  std::vector<std::size_t> printed;
  EXPECT_THROW(run_batch(jobs, options,
                         [&](const JobResult& result) {
                           printed.push_back(result.index);
                           if (result.index == 2) throw std::runtime_error("stdout closed");
                         }),
               std::runtime_error);
  EXPECT_EQ(printed, (std::vector<std::size_t>{0, 1, 2}));  // nothing after the failure
}

// A manifest `cell` job is `grpvss verify --cell` of the same files: the cell's tolerance and
// synchronized timing, the same verdicts and step counts (6 and 21, as the CLI prints for
// data/sixaxis), the smallest clearance named, one cell built for both paths.
TEST_F(BatchRunner, CellJobsVerifyAsVerifyDoesWithTheCellsDefaultsAndNames) {
  const std::string six = std::string(GRPVSS_SOURCE_DIR) + "/data/sixaxis/";
  const BatchManifest jobs = manifest(
      "{\"cell\":\"" + six + "cell.yaml\",\"path\":\"" + six + "path-clear.txt\"}\n" +
      "{\"cell\":\"" + six + "cell.yaml\",\"path\":\"" + six + "path-collision.txt\","
      "\"certificate\":\"c.cert\"}\n");
  BatchStatistics statistics;
  const std::vector<std::string> lines = run(jobs, 2, &statistics);
  ASSERT_EQ(lines.size(), 2u);
  EXPECT_NE(lines[0].find("\"verdict\":\"CLEAR\",\"exit_code\":0,\"steps\":4,"), std::string::npos)
      << lines[0];
  EXPECT_NE(lines[0].find("\"link\":4,\"obstacle\":"), std::string::npos) << lines[0];
  EXPECT_NE(lines[0].find("\"link_name\":\"link_4\",\"obstacle_name\":\"post\"}"),
            std::string::npos)
      << lines[0];
  EXPECT_NE(lines[1].find("\"verdict\":\"COLLISION\",\"exit_code\":1,\"steps\":8,"),
            std::string::npos)
      << lines[1];
  EXPECT_EQ(statistics.cells_built, 1u);
  // The certificate binds the cell file as robot and environment, like `verify --cell`.
  const std::string certificate = grpvss::test::read_text_file(directory_ + "/c.cert");
  EXPECT_NE(certificate.find("\"timing\": \"synchronized\""), std::string::npos);
}

TEST_F(BatchRunner, ACellJobWithoutAToleranceAnywhereIsThatJobsError) {
  std::ofstream(directory_ + "/cell.yaml")
      << "units: m\nrobot:\n  thesis: " << kIbm7545Data << "robot.txt\nobstacles:\n"
      << "  - {name: block, box: [1, 1, 1], pose: {xyz: [50, 0, 0]}}\n";
  const auto lines = run(manifest(R"({"cell":"cell.yaml","path":"ptp.txt"})" "\n"), 1);
  ASSERT_EQ(lines.size(), 1u);
  EXPECT_NE(lines[0].find("\"exit_code\":2"), std::string::npos) << lines[0];
  EXPECT_NE(lines[0].find("expected --tolerance, or `tolerance` in the cell file"),
            std::string::npos)
      << lines[0];
}

TEST(BatchExitCode, TheWorstFollowsTheDocumentedOrder) {
  const std::vector<int> order{0, 3, 5, 4, 1, 2, 70};  // best to worst
  for (std::size_t i = 0; i < order.size(); ++i) {
    for (std::size_t j = 0; j < order.size(); ++j) {
      EXPECT_EQ(worst_exit_code(order[i], order[j]), order[std::max(i, j)])
          << order[i] << " vs " << order[j];
    }
  }
}

TEST(BatchExitCode, AJobsVerdictExitsAsVerifyWould) {
  using grpvss::certify::Verdict;
  for (Verdict verdict : {Verdict::kClear, Verdict::kCollision, Verdict::kWithinTolerance,
                          Verdict::kUndecided, Verdict::kError}) {
    EXPECT_EQ(verdict_exit_code(verdict), grpvss::app::exit_code_of(verdict));
  }
}

}  // namespace
