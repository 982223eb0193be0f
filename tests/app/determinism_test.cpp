// Determinism: the same inputs give byte-identical outputs across two runs of the CLI. The
// program has no threads and no randomness; the only intended difference between runs is the
// JSON report's `generated_at` time stamp, removed before comparing (docs/reliability.md).
#include <sys/wait.h>

#include <cstdlib>
#include <string>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "support/data_paths.hpp"
#include "support/text_files.hpp"

namespace {

using grpvss::test::kIbm7545Data;

/// Runs `grpvss ARGUMENTS` quietly; returns the exit code (-1 when it did not exit).
int run_cli_exit_code(const std::string& arguments) {
  const std::string command = std::string(GRPVSS_CLI) + " " + arguments + " >/dev/null 2>&1";
  const int status = std::system(command.c_str());
  return WIFEXITED(status) ? WEXITSTATUS(status) : -1;
}

std::string inputs(const std::string& path_file) {
  return "--robot " + kIbm7545Data + "robot.txt --env " + kIbm7545Data + "environment.txt --path " + kIbm7545Data +
         path_file;
}

/// The JSON report without its one intentionally time-dependent field.
std::string report_without_time_stamp(const std::string& file) {
  nlohmann::json report = nlohmann::json::parse(grpvss::test::read_text_file(file));
  EXPECT_TRUE(report.contains("generated_at")) << file;
  report.erase("generated_at");
  return report.dump(1);
}

struct RunOutputs {
  int exit_code = -1;
  std::string thesis_output, report, certificate;
};

RunOutputs verify_into(const std::string& directory, const std::string& arguments,
                       bool with_certificate) {
  RunOutputs outputs;
  std::string command = "verify " + arguments + " --out " + directory + "/out.txt --json " +
                        directory + "/report.json";
  if (with_certificate) command += " --certificate " + directory + "/certificate.json";
  outputs.exit_code = run_cli_exit_code(command);
  outputs.thesis_output = grpvss::test::read_text_file(directory + "/out.txt");
  outputs.report = report_without_time_stamp(directory + "/report.json");
  if (with_certificate) {
    outputs.certificate = grpvss::test::read_text_file(directory + "/certificate.json");
  }
  return outputs;
}

void expect_identical_runs(const std::string& tag, const std::string& arguments,
                           bool with_certificate) {
  const std::string first = grpvss::test::make_temporary_directory(tag + "-1");
  const std::string second = grpvss::test::make_temporary_directory(tag + "-2");
  const RunOutputs a = verify_into(first, arguments, with_certificate);
  const RunOutputs b = verify_into(second, arguments, with_certificate);
  EXPECT_EQ(a.exit_code, b.exit_code);
  ASSERT_FALSE(a.thesis_output.empty());
  ASSERT_FALSE(a.report.empty());
  // Byte-for-byte: EXPECT_TRUE on == keeps a mismatch from printing megabytes.
  EXPECT_TRUE(a.thesis_output == b.thesis_output) << "thesis output files differ";
  EXPECT_TRUE(a.report == b.report) << "JSON reports differ beyond generated_at";
  if (with_certificate) {
    ASSERT_FALSE(a.certificate.empty());
    EXPECT_TRUE(a.certificate == b.certificate) << "certificates differ";
  }
}

TEST(Determinism, CertifiedRunOfTheSamplePathIsByteIdentical) {
  expect_identical_runs("determinism-certified", inputs("path.txt") + " --tolerance 0.5", true);
}

TEST(Determinism, ThesisModeRunOfTheSamplePathIsByteIdentical) {
  expect_identical_runs("determinism-thesis",
                        inputs("path.txt") + " --tolerance 0.5 --mode thesis", false);
}

TEST(Determinism, ReportsDifferOnlyInTheTimeStampField) {
  // The comparison above is only meaningful if the two reports are the whole documents minus
  // generated_at: check that the field is a UTC time stamp, the only varying key.
  const std::string directory = grpvss::test::make_temporary_directory("determinism-stamp");
  ASSERT_EQ(run_cli_exit_code("verify " + inputs("path.txt") + " --tolerance 0.5 --mode thesis --json " +
                    directory + "/r.json"),
            run_cli_exit_code("verify " + inputs("path.txt") + " --tolerance 0.5 --mode thesis --json " +
                    directory + "/s.json"));
  const auto r = nlohmann::json::parse(grpvss::test::read_text_file(directory + "/r.json"));
  const auto s = nlohmann::json::parse(grpvss::test::read_text_file(directory + "/s.json"));
  ASSERT_TRUE(r["generated_at"].is_string());
  EXPECT_EQ(r["generated_at"].get<std::string>().size(), std::string("2026-01-01T00:00:00Z").size());
  EXPECT_LE(nlohmann::json::diff(r, s).size(), 1u) << nlohmann::json::diff(r, s).dump();
  for (const auto& operation : nlohmann::json::diff(r, s)) {
    EXPECT_EQ(operation["path"], "/generated_at");
  }
}

}  // namespace
