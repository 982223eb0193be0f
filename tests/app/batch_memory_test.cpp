// `grpvss batch` at scale (issue 21): 10,000 small jobs on two threads stay under 500 MB of
// resident memory (results printed and freed, reports never held), and a sample of the results
// equals what `grpvss verify` says of the same jobs one by one. Label `heavy` (ctest_properties).
#include <sys/resource.h>
#include <sys/wait.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <regex>
#include <string>

#include <fmt/core.h>
#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "support/data_paths.hpp"
#include "support/text_files.hpp"

namespace {

using grpvss::test::kIbm7545Data;
constexpr int kJobs = 10000;

int run_shell(const std::string& command) {
  const int status = std::system(command.c_str());
  return WIFEXITED(status) ? WEXITSTATUS(status) : -1;
}

// A one-segment PTP inside the IBM 7545's joint limits (0..200, 0..135 deg, 0..9.8, +-180 deg),
// different for every job.
std::string tiny_ptp(int i) {
  return fmt::format("1\n1\n{}.,30.\n{}.,30.\n{}.,1.\n{}.,30.\n", 10 + i % 150,
                     10 + (i * 7) % 100, 1 + i % 8, (i * 13) % 300 - 150);
}

// The manifest's jobs alternate the two environments and two tolerances; every 100th writes
// its JSON report and thesis output file.
std::string job_line(int i) {
  const char* env = i % 2 == 0 ? "bench-environment-near-miss.txt" : "environment.txt";
  const std::string reports =
      i % 100 == 0 ? fmt::format(R"(,"json":"r/{}.json","output":"r/{}.out")", i, i) : "";
  return fmt::format(R"({{"id":"j{}","robot":"{}robot.txt","env":"{}{}","path":"p/{}.txt","tolerance":{}{}}})",
                     i, kIbm7545Data, kIbm7545Data, env, i, i % 3 == 0 ? "1" : "0.5", reports) + "\n";
}

TEST(BatchMemory, TenThousandJobsStayUnder500MBAndAgreeWithVerify) {
  const std::string directory = grpvss::test::make_temporary_directory("batch-memory");
  std::filesystem::create_directory(directory + "/p");
  std::filesystem::create_directory(directory + "/r");
  {
    std::ofstream manifest(directory + "/m.jsonl");
    for (int i = 0; i < kJobs; ++i) {
      std::ofstream(fmt::format("{}/p/{}.txt", directory, i)) << tiny_ptp(i);
      manifest << job_line(i);
    }
  }
  const int code = run_shell("cd " + directory + " && " + GRPVSS_CLI +
                             " batch m.jsonl -j 2 --quiet > results.jsonl 2> errors.txt");
  rusage usage{};
  ASSERT_EQ(getrusage(RUSAGE_CHILDREN, &usage), 0);
  const double max_rss_mb = static_cast<double>(usage.ru_maxrss) / 1024.0;  // ru_maxrss: KiB
  RecordProperty("max_rss_mb", std::to_string(max_rss_mb));
  EXPECT_LT(max_rss_mb, 500.0);
  EXPECT_EQ(grpvss::test::read_text_file(directory + "/errors.txt"), "");

  const auto lines = grpvss::test::split_lines(grpvss::test::read_text_file(directory + "/results.jsonl"));
  ASSERT_EQ(lines.size(), static_cast<std::size_t>(kJobs));
  int worst_seen = 0;
  for (int i = 0; i < kJobs; ++i) {
    const nlohmann::json result = nlohmann::json::parse(lines[i]);
    ASSERT_EQ(result["index"], i);
    ASSERT_EQ(result["id"], "j" + std::to_string(i));
    ASSERT_TRUE(result["error"].is_null()) << lines[i];
    ASSERT_EQ(result["outputs"].size(), i % 100 == 0 ? 2u : 0u) << lines[i];
    worst_seen = std::max(worst_seen, result["exit_code"].get<int>() == 1 ? 10 : result["exit_code"].get<int>());
  }
  EXPECT_EQ(code, worst_seen == 10 ? 1 : worst_seen);

  // Every 500th job, one by one: the same verdict, exit code and number of steps.
  const std::regex steps_line(R"(steps: (\d+))");
  for (int i = 0; i < kJobs; i += 500) {
    const nlohmann::json result = nlohmann::json::parse(lines[i]);
    const std::string out = directory + "/verify.txt";
    const char* env = i % 2 == 0 ? "bench-environment-near-miss.txt" : "environment.txt";
    const int verify_code = run_shell(fmt::format(
        "cd {} && {} verify --robot {}robot.txt --env {}{} --path p/{}.txt --tolerance {} > {}",
        directory, GRPVSS_CLI, kIbm7545Data, kIbm7545Data, env, i, i % 3 == 0 ? "1" : "0.5", out));
    const std::string summary = grpvss::test::read_text_file(out);
    EXPECT_EQ(result["exit_code"], verify_code) << i;
    // The first line states the motion model, the second the verdict.
    EXPECT_EQ(summary.rfind("motion: path " + std::to_string(i) + ".txt, ", 0), 0u) << i << summary;
    EXPECT_NE(summary.find("\nverdict: " + result["verdict"].get<std::string>() + "\n"),
              std::string::npos)
        << i << summary;
    std::smatch steps;
    ASSERT_TRUE(std::regex_search(summary, steps, steps_line)) << summary;
    EXPECT_EQ(result["steps"], std::stoi(steps[1])) << i;
  }
  EXPECT_EQ(grpvss::test::directory_entries(directory + "/r").size(), 200u);
  std::filesystem::remove_all(directory);
}

}  // namespace
