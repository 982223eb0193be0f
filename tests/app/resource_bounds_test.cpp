// Bounded resources: 10,000 obstacles (small boxes far from the IBM 7545 plus the sample's two
// near ones) and a path of 100,000 short PTP moves (100,000 certified steps) run through
// `grpvss verify` WITH the thesis output file, the JSON report and the certificate; the child's
// peak resident set (wait4 rusage) must stay under the bound documented in
// docs/reliability.md#resource-bounds. The outputs are streamed (no step is kept in memory), so
// the bound does not grow with the steps. `grpvss check-certificate` reads a certificate one
// segment at a time: checked on a 10,000-step certificate (the exact checker costs time per
// step and obstacle; 100,000 steps are measured in the docs), its peak RSS must stay under a
// bound far below the file's size. Time is bounded by the ctest TIMEOUT
// (tests/ctest_properties.cmake), never asserted; label `heavy`.
#include <fcntl.h>
#include <sys/resource.h>
#include <sys/wait.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "support/data_paths.hpp"
#include "support/text_files.hpp"

namespace {

using grpvss::test::kIbm7545Data;

constexpr int kFarObstacles = 10'000;
constexpr int kSegments = 100'000;
/// docs/reliability.md#resource-bounds: peak RSS of the whole CLI run with every output,
/// 256 MiB (measured 206 MiB, most of it per-segment data: this path has 100,000 segments;
/// before streaming, 2 GB without the certificate).
constexpr long kPeakResidentBoundKiB = 256L * 1024;
constexpr int kCheckedSegments = 10'000;
/// check-certificate of the 10,000-step certificate (about 195 MB): 64 MiB (measured 22 MiB).
constexpr long kCheckPeakResidentBoundKiB = 64L * 1024;

/// The sample environment's two obstacles plus kFarObstacles 1x1x2 boxes on a grid at
/// x in [300, 800): far outside the IBM 7545's reach (about 60 inches).
std::string many_obstacle_environment() {
  const std::string sample = grpvss::test::read_text_file(kIbm7545Data + "environment.txt");
  std::string text = "90.\n1.\n" + std::to_string(kFarObstacles + 2) + "\n";
  // Skip the sample's three header lines, keep its two 16-point hulls.
  std::size_t start = 0;
  for (int line = 0; line < 3; ++line) start = sample.find('\n', start) + 1;
  text += sample.substr(start);
  if (text.back() != '\n') text += '\n';
  for (int i = 0; i < kFarObstacles; ++i) {
    const int x = 300 + 5 * (i % 100), y = -250 + 5 * (i / 100);
    text += "HULL 8\n";
    for (int corner = 0; corner < 8; ++corner) {
      text += std::to_string(x + (corner & 1)) + "," + std::to_string(y + ((corner >> 1) & 1)) +
              "," + std::to_string(2 * ((corner >> 2) & 1)) + "\n";
    }
  }
  return text;
}

/// `segments` PTP joint moves swinging joint 1 between 0 and 2 degrees, the other joints at
/// home: about 12 inches clear of the sample obstacles, one certified step per move.
std::string long_path(int segments) {
  std::string text = std::to_string(segments) + "\n";
  for (int s = 0; s < segments; ++s) {
    text += "1\n";
    text += (s % 2 == 0 ? "2.,3.\n" : "0.,3.\n");
    text += "0.,3.\n0.,0.3\n0.,3.\n";
  }
  return text;
}

struct ChildRun {
  int exit_code = -1;
  long peak_resident_kib = 0;
};

/// Runs `grpvss ARGS...` as a child with stdout to `stdout_file`; the child's own peak RSS
/// comes from wait4's rusage.
ChildRun run_child_cli(const std::vector<std::string>& arguments, const std::string& stdout_file) {
  std::vector<char*> argv;
  std::string program = GRPVSS_CLI;
  argv.push_back(program.data());
  std::vector<std::string> copies = arguments;
  for (std::string& argument : copies) argv.push_back(argument.data());
  argv.push_back(nullptr);
  ChildRun result;
  const pid_t child = fork();
  if (child == 0) {
    const int out = open(stdout_file.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
    dup2(out, STDOUT_FILENO);
    execv(argv[0], argv.data());
    _exit(127);
  }
  int status = 0;
  rusage usage{};
  if (child < 0 || wait4(child, &status, 0, &usage) != child) return result;
  result.exit_code = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
  result.peak_resident_kib = usage.ru_maxrss;
  return result;
}

/// Removes a test's directory however the test ends (the outputs take about 2 GB).
struct RemovedAtExit {
  ~RemovedAtExit() { std::filesystem::remove_all(directory); }
  std::string directory;
};

long steps_in_summary(const std::string& summary_file) {
  const std::string summary = grpvss::test::read_text_file(summary_file);
  const std::size_t at = summary.find("steps: ");
  if (at == std::string::npos) {
    ADD_FAILURE() << summary;
    return 0;
  }
  return std::stol(summary.substr(at + 7));
}

TEST(ResourceBounds, TenThousandObstaclesAndHundredThousandStepsWithEveryOutputStayUnderTheBound) {
  const std::string directory = grpvss::test::make_temporary_directory("resource-bounds");
  const RemovedAtExit cleanup{directory};
  std::ofstream(directory + "/environment.txt") << many_obstacle_environment();
  std::ofstream(directory + "/path.txt") << long_path(kSegments);
  const ChildRun run = run_child_cli({"verify", "--robot", kIbm7545Data + "robot.txt", "--env",
                                directory + "/environment.txt", "--path", directory + "/path.txt",
                                "--tolerance", "0.5", "--out", directory + "/out.txt", "--json",
                                directory + "/report.json", "--certificate",
                                directory + "/certificate.json"},
                               directory + "/summary.txt");
  ASSERT_EQ(run.exit_code, 0);  // CLEAR: the far boxes and the path never meet
  // The summary names the last step index; enough steps make the bound mean something.
  const long steps = steps_in_summary(directory + "/summary.txt");
  EXPECT_GE(steps, 100'000);
  // The outputs were written in full: the thesis file ends with its total, the report and the
  // certificate end where their documents end.
  const std::string out = grpvss::test::read_text_file(directory + "/out.txt");
  EXPECT_NE(out.find("TOTAL " + std::to_string(steps) + " STEPS IN THIS PATH\n"), std::string::npos);
  const auto report_size = std::filesystem::file_size(directory + "/report.json");
  const auto certificate_size = std::filesystem::file_size(directory + "/certificate.json");
  EXPECT_GT(report_size, 100'000'000u);        // about 4 kB per step
  // About 4.8 kB per step: the obstacles inside the broadphase margin (a quarter of the
  // last link's joint-1 axis radius, ~8.8 in.) each carry a witness.
  EXPECT_GT(certificate_size, 400'000'000u);
  RecordProperty("peak_rss_kib", std::to_string(run.peak_resident_kib));
  RecordProperty("steps", std::to_string(steps));
  EXPECT_LT(run.peak_resident_kib, kPeakResidentBoundKiB)
      << "peak RSS " << run.peak_resident_kib << " KiB for " << steps << " steps";
}

TEST(ResourceBounds, CheckCertificateReadsOneSegmentAtATime) {
  const std::string directory = grpvss::test::make_temporary_directory("resource-bounds-check");
  const RemovedAtExit cleanup{directory};
  std::ofstream(directory + "/path.txt") << long_path(kCheckedSegments);
  const std::vector<std::string> inputs = {"--robot", kIbm7545Data + "robot.txt", "--env",
                                           kIbm7545Data + "environment.txt", "--path",
                                           directory + "/path.txt"};
  std::vector<std::string> verify = {"verify"};
  verify.insert(verify.end(), inputs.begin(), inputs.end());
  for (const char* argument : {"--tolerance", "0.5", "--quiet", "--certificate"}) verify.push_back(argument);
  verify.push_back(directory + "/certificate.json");
  ASSERT_EQ(run_child_cli(verify, directory + "/verify.txt").exit_code, 0);
  const auto certificate_size = std::filesystem::file_size(directory + "/certificate.json");
  EXPECT_GT(certificate_size, 100'000'000u);
  std::vector<std::string> check = {"check-certificate"};
  check.insert(check.end(), inputs.begin(), inputs.end());
  check.push_back(directory + "/certificate.json");
  const ChildRun run = run_child_cli(check, directory + "/check.txt");
  EXPECT_EQ(run.exit_code, 0) << grpvss::test::read_text_file(directory + "/check.txt");
  EXPECT_EQ(grpvss::test::read_text_file(directory + "/check.txt").rfind("ACCEPTED: claim CLEAR", 0), 0u);
  RecordProperty("check_peak_rss_kib", std::to_string(run.peak_resident_kib));
  EXPECT_LT(run.peak_resident_kib, kCheckPeakResidentBoundKiB)
      << "peak RSS " << run.peak_resident_kib << " KiB for a " << certificate_size
      << "-byte certificate";
}

}  // namespace
