// Bounded resources: 10,000 obstacles (small boxes far from the IBM 7545 plus the sample's two
// near ones) and a path of 100,000 short PTP moves (100,000 certified steps) run through
// `grpvss verify`; the child's peak resident set (wait4 rusage) must stay under the bound
// documented in docs/reliability.md#resource-bounds. The verifier keeps every step record and
// the in-memory certificate, so this bound is what 100,000 steps cost the verifier itself.
// Writing the JSON report, the thesis output file or the certificate costs more (measured and
// documented there; the certificate's cost was reported to the lead). Time is bounded by the
// ctest TIMEOUT (tests/ctest_properties.cmake), never asserted; label `heavy`.
#include <fcntl.h>
#include <sys/resource.h>
#include <sys/wait.h>
#include <unistd.h>

#include <fstream>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "support/text_files.hpp"

namespace {

const std::string kData = std::string(GRPVSS_SOURCE_DIR) + "/data/ibm7545/";

constexpr int kFarObstacles = 10'000;
constexpr int kSegments = 100'000;
/// docs/reliability.md#resource-bounds: peak RSS of the whole CLI run, 1 GiB (measured about
/// 0.6 GiB: about 6 KiB per step).
constexpr long kPeakResidentBoundKiB = 1024L * 1024;

/// The sample environment's two obstacles plus kFarObstacles 1x1x2 boxes on a grid at
/// x in [300, 800): far outside the IBM 7545's reach (about 60 inches).
std::string many_obstacle_environment() {
  const std::string sample = grpvss::test::read_text_file(kData + "environment.txt");
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

/// kSegments PTP joint moves swinging joint 1 between 0 and 2 degrees, the other joints at
/// home: about 12 inches clear of the sample obstacles, one certified step per move.
std::string long_path() {
  std::string text = std::to_string(kSegments) + "\n";
  for (int s = 0; s < kSegments; ++s) {
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
ChildRun run_cli(const std::vector<std::string>& arguments, const std::string& stdout_file) {
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

TEST(ResourceBounds, TenThousandObstaclesAndHundredThousandStepsStayUnderTheMemoryBound) {
  const std::string directory = grpvss::test::make_temporary_directory("resource-bounds");
  std::ofstream(directory + "/environment.txt") << many_obstacle_environment();
  std::ofstream(directory + "/path.txt") << long_path();
  const ChildRun run = run_cli({"verify", "--robot", kData + "robot.txt", "--env",
                                directory + "/environment.txt", "--path", directory + "/path.txt",
                                "--tolerance", "0.5"},
                               directory + "/summary.txt");
  ASSERT_EQ(run.exit_code, 0);  // CLEAR: the far boxes and the path never meet
  // The summary names the last step index; enough steps make the bound mean something.
  const std::string summary = grpvss::test::read_text_file(directory + "/summary.txt");
  const std::size_t at = summary.find("steps: ");
  ASSERT_NE(at, std::string::npos) << summary;
  const long steps = std::stol(summary.substr(at + 7));
  EXPECT_GE(steps, 100'000);
  RecordProperty("peak_rss_kib", std::to_string(run.peak_resident_kib));
  RecordProperty("steps", std::to_string(steps));
  EXPECT_LT(run.peak_resident_kib, kPeakResidentBoundKiB)
      << "peak RSS " << run.peak_resident_kib << " KiB for " << steps << " steps";
}

}  // namespace
