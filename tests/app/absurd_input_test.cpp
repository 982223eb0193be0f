// Absurd inputs fail fast with a clear InputError (exit code 2) instead of exhausting memory or
// time: every declared count is range-checked before anything is allocated, numbers are
// bounded by 1e9, lines by 4096 characters, files by 256 MiB. "Fast" is enforced by ctest
// TIMEOUT properties (tests/ctest_properties.cmake), never by a timed assertion.
#include <sys/wait.h>

#include <cstdio>
#include <filesystem>
#include <fstream>
#include <string>

#include <gtest/gtest.h>

#include "support/data_paths.hpp"
#include "support/text_files.hpp"

namespace {

using grpvss::test::kIbm7545Data;

struct StderrRun {
  int exit_code = -1;
  std::string error;  ///< what the CLI printed on stderr
};

StderrRun run_cli_stderr(const std::string& arguments) {
  const std::string command = std::string(GRPVSS_CLI) + " " + arguments + " 2>&1 >/dev/null";
  StderrRun result;
  FILE* pipe = popen(command.c_str(), "r");
  if (!pipe) return result;
  char buffer[4096];
  std::size_t n;
  while ((n = fread(buffer, 1, sizeof buffer, pipe)) > 0) result.error.append(buffer, n);
  const int status = pclose(pipe);
  result.exit_code = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
  return result;
}

class AbsurdInput : public ::testing::Test {
 protected:
  std::string directory_ = grpvss::test::make_temporary_directory("absurd-input");

  std::string write(const std::string& name, const std::string& text) {
    const std::string path = directory_ + "/" + name;
    std::ofstream(path, std::ios::binary) << text;
    return path;
  }

  /// `grpvss verify` with the sample files except those given.
  StderrRun verify(const std::string& robot, const std::string& environment,
                const std::string& path) {
    return run_cli_stderr("verify --robot " + robot + " --env " + environment + " --path " + path +
                   " --tolerance 0.5 --quiet");
  }

  void expect_input_error(const StderrRun& run, const std::string& message) {
    EXPECT_EQ(run.exit_code, 2) << run.error;
    EXPECT_NE(run.error.find("grpvss: error: " + message), std::string::npos) << run.error;
  }
};

// A one-joint robot up to its first link's hull count, which the test appends.
const std::string kOneJointRobotHead = "1\n0\n0,0,0,0,-180,180,2,2\n";

TEST_F(AbsurdInput, BillionJointsAreRefusedAtTheCount) {
  const std::string robot = write("robot.txt", "1000000000\n");
  expect_input_error(verify(robot, kIbm7545Data + "environment.txt", kIbm7545Data + "path.txt"),
                     robot + ":1: expected the number of joints N between 1 and 64, found "
                             "1000000000");
}

TEST_F(AbsurdInput, BillionDeclaredLinkHullsAreRefusedAtTheCount) {
  const std::string robot = write("robot.txt", kOneJointRobotHead + "1000000000\n");
  expect_input_error(verify(robot, kIbm7545Data + "environment.txt", kIbm7545Data + "path.txt"),
                     robot + ":4: expected the number of hulls NOBAR_0 of link 0 between 0 and "
                             "100000, found 1000000000");
}

TEST_F(AbsurdInput, BillionDeclaredObstacleHullsAreRefusedAtTheCount) {
  const std::string environment = write("environment.txt", "30\n1\n1000000000\n");
  expect_input_error(verify(kIbm7545Data + "robot.txt", environment, kIbm7545Data + "path.txt"),
                     environment + ":3: expected the number of obstacle hulls NOB between 0 and "
                                   "100000, found 1000000000");
}

TEST_F(AbsurdInput, BillionPointHullIsRefusedBeforeAllocating) {
  const std::string robot = write("robot.txt", kOneJointRobotHead + "1\nHULL 1000000000\n");
  expect_input_error(verify(robot, kIbm7545Data + "environment.txt", kIbm7545Data + "path.txt"),
                     robot + ":5: expected the number of points of hull 1 of link 0 between 4 "
                             "and 1000000, found 1000000000");
}

TEST_F(AbsurdInput, MaximalDeclaredCountsWithAShortFileEndAtTheEndOfFile) {
  // The largest accepted counts, but the file stops: nothing of the declared size is built.
  const std::string environment = write("environment.txt", "30\n1\n100000\nHULL 1000000\n1,2,3\n");
  expect_input_error(verify(kIbm7545Data + "robot.txt", environment, kIbm7545Data + "path.txt"),
                     environment + ":6: expected 3 numbers for point 2 of hull 1 of the "
                                   "environment (x, y, z), found end of file");
}

TEST_F(AbsurdInput, HugePathSegmentCountIsRefusedAtTheCount) {
  const std::string path = write("path.txt", "1000000000000\n1\n");
  expect_input_error(verify(kIbm7545Data + "robot.txt", kIbm7545Data + "environment.txt", path),
                     path + ":1: expected the number of motion segments NOMS between 1 and "
                            "1000000, found 1000000000000");
}

TEST_F(AbsurdInput, MaximalPathSegmentCountWithOneSegmentEndsAtTheEndOfFile) {
  const std::string path = write("path.txt", "1000000\n1\n5,3\n5,3\n0.5,0.3\n5,3\n");
  expect_input_error(verify(kIbm7545Data + "robot.txt", kIbm7545Data + "environment.txt", path),
                     path + ":7: expected an integer for the segment type IND of segment 2, found end "
                            "of file");
}

TEST_F(AbsurdInput, GiganticNumbersAreRefused) {
  const std::string robot =
      write("robot.txt", kOneJointRobotHead + "1\n1e300,0,0\n");
  expect_input_error(verify(robot, kIbm7545Data + "environment.txt", kIbm7545Data + "path.txt"),
                     robot + ":5: expected a number of magnitude at most 1e9 for point 1 of "
                             "hull 1 of link 0 (x, y, z), found '1e300'");
}

TEST_F(AbsurdInput, NumbersBeyondDoubleRangeAreRefused) {
  const std::string robot = write("robot.txt", kOneJointRobotHead + "1\n1e999999,0,0\n");
  expect_input_error(verify(robot, kIbm7545Data + "environment.txt", kIbm7545Data + "path.txt"),
                     robot + ":5: expected a number of magnitude at most 1e9 for point 1 of "
                             "hull 1 of link 0 (x, y, z), found '1e999999'");
}

TEST_F(AbsurdInput, HugeIntegerLiteralIsRefusedAndQuotedShort) {
  const std::string robot = write("robot.txt", std::string(4000, '9') + "\n");
  expect_input_error(verify(robot, kIbm7545Data + "environment.txt", kIbm7545Data + "path.txt"),
                     robot + ":1: expected an integer for the number of joints N, found '" +
                         std::string(40, '9') + "...'");
}

TEST_F(AbsurdInput, EndlessLineIsRefusedAtItsLength) {
  // 64 MiB without a newline: one "line" far beyond the 4096-character limit.
  std::string endless(std::size_t{64} << 20, '1');
  for (std::size_t i = 1; i < endless.size(); i += 2) endless[i] = ',';
  const std::string path = write("path.txt", endless);
  expect_input_error(verify(kIbm7545Data + "robot.txt", kIbm7545Data + "environment.txt", path),
                     path + ":1: expected a line of at most 4096 characters, found 67108864 "
                            "characters");
}

TEST_F(AbsurdInput, FileLargerThanTheLimitIsRefusedBeforeReading) {
  // A sparse 300 MB file: refused from its size, its bytes are never read.
  const std::string environment = directory_ + "/environment.txt";
  { std::ofstream(environment, std::ios::binary) << ""; }
  std::filesystem::resize_file(environment, 300'000'000);
  expect_input_error(verify(kIbm7545Data + "robot.txt", environment, kIbm7545Data + "path.txt"),
                     environment + ":0: expected a file of at most 268435456 bytes, found "
                                   "300000000 bytes");
}

TEST_F(AbsurdInput, EndlesslyNestedCertificateIsRefused) {
  const std::string certificate = write("certificate.json", std::string(1'000'000, '['));
  const StderrRun run = run_cli_stderr("check-certificate --robot " + kIbm7545Data + "robot.txt --env " + kIbm7545Data +
                             "environment.txt --path " + kIbm7545Data + "path.txt " + certificate);
  expect_input_error(run, certificate + ":0: expected a JSON document");
}

TEST_F(AbsurdInput, CertificateNumberBeyondDoubleRangeIsAnInputError) {
  // Found by fuzzing: json::parse throws out_of_range (not parse_error) for 1e9999, which the
  // CLI reported as an internal error (exit 3).
  const std::string certificate =
      write("certificate.json", "{\"format\": \"grpvss-certificate\", \"tolerance\": 1e9999}");
  const StderrRun run = run_cli_stderr("check-certificate --robot " + kIbm7545Data + "robot.txt --env " + kIbm7545Data +
                             "environment.txt --path " + kIbm7545Data + "path.txt " + certificate);
  expect_input_error(run, certificate + ":0: expected a JSON document, found "
                                        "[json.exception.out_of_range.406] number overflow");
}

}  // namespace
