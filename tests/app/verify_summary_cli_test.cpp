// What `grpvss verify` prints on the thesis's sample: the verdict block with one line per
// interference episode (where each collision begins and ends), checked line by line.
#include <sys/wait.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <string>

#include <gtest/gtest.h>

#include "support/data_paths.hpp"
#include "support/text_files.hpp"

namespace {

using grpvss::test::kIbm7545Data;

// Runs `grpvss verify` on robot.txt with `environment_file` and `path`, tolerance 0.5, and
// `extra` options; returns its exit code and its standard output (with standard error) in `text`.
int run_verify(const std::string& environment_file, const std::string& path,
               const std::string& directory, std::string& text, const std::string& extra = "") {
  const std::string out = directory + "/stdout.txt";
  const int status = std::system((std::string(GRPVSS_CLI) + " verify --robot " + kIbm7545Data +
                                  "robot.txt --env " + kIbm7545Data + environment_file + " --path " +
                                  path + " --tolerance 0.5 " + extra + " > " + out + " 2>&1")
                                     .c_str());
  text = grpvss::test::read_text_file(out);
  return WIFEXITED(status) ? WEXITSTATUS(status) : -1;
}

TEST(VerifySummaryCli, TheSamplesEpisodesArePrintedBetweenTheFirstCollisionAndTheClearances) {
  const std::string directory = grpvss::test::make_temporary_directory("verify-summary");
  std::string text;
  EXPECT_EQ(run_verify("environment.txt", kIbm7545Data + "path.txt", directory, text), 1);
  std::filesystem::remove_all(directory);
  const std::string expected =
      "first collision at step 4\n"
      "interference: link 3 hull 1 / obstacle 0, steps 3-12 (8.980-13.332 s, clear by "
      "13.751 s), unexpanded collides at steps 4-9\n"
      "interference: link 3 hull 0 / obstacle 0, steps 4-13 (9.309-13.751 s, clear by "
      "14.170 s), unexpanded collides at steps 5-13\n"
      "interference: link 4 hull 0 / obstacle 0, steps 4-5 (9.309-9.735 s, clear by "
      "10.162 s), expanded hull only\n"
      "error 7 (segment 3, step 23)";
  EXPECT_NE(text.find(expected), std::string::npos) << text;
}

// The Table 3 PTP with the post 0.62 in. below the quill: CLEAR, and the summary says how far
// from the obstacles the links are proven to stay along the motion. Under `--claim steps` that
// is for the quill less than the tolerance, which the note spells out; under the default claim
// (`motion`) it is at least the tolerance.
// `grpvss check-certificate` derives the same clearances along the motion from the certificate
// on its own and prints them after ACCEPTED.
TEST(VerifySummaryCli, AClearRunStatesTheClearanceProvenAlongTheMotion) {
  const std::string directory = grpvss::test::make_temporary_directory("verify-summary");
  const std::string path = directory + "/ptp.txt";
  std::ofstream(path) << "1\n1\n50.,3.\n50.,3.\n4.,0.3\n50.,3.\n";
  std::string text;
  EXPECT_EQ(run_verify("bench-environment-near-miss.txt", path, directory, text,
                       "--claim steps --certificate " + directory + "/c.json"),
            0);
  const std::string checked = directory + "/checked.txt";
  const std::string inputs = " --robot " + kIbm7545Data + "robot.txt --env " + kIbm7545Data +
                             "bench-environment-near-miss.txt --path " + path + " ";
  EXPECT_EQ(std::system((std::string(GRPVSS_CLI) + " check-certificate" + inputs + directory +
                         "/c.json > " + checked + " 2>&1")
                            .c_str()),
            0);
  const std::string check_text = grpvss::test::read_text_file(checked);
  std::filesystem::remove_all(directory);
  EXPECT_NE(check_text.find("\n  link 4: stays farther than 0.0435 from every obstacle along the "
                            "motion (smallest at steps 3-4)\n"),
            std::string::npos)
      << check_text;
  EXPECT_NE(text.find("link 4: smallest certified clearance 0.6906 at step 5 (obstacle 0); along "
                      "the motion > 0.0435 (steps 3-4)\n"),
            std::string::npos)
      << text;
  EXPECT_NE(text.find("note: along the motion link 4 is only proven to stay farther than 0.0435 "
                      "(steps 3-4), less than the tolerance 0.5: the nominal path is clear, a "
                      "robot deviating from it by the tolerance is not proven clear\n"),
            std::string::npos)
      << text;

  const std::string motion_directory = grpvss::test::make_temporary_directory("verify-summary");
  const std::string motion_path = motion_directory + "/ptp.txt";
  std::ofstream(motion_path) << "1\n1\n50.,3.\n50.,3.\n4.,0.3\n50.,3.\n";
  EXPECT_EQ(run_verify("bench-environment-near-miss.txt", motion_path, motion_directory, text), 0);
  std::filesystem::remove_all(motion_directory);
  EXPECT_NE(text.find("link 4: smallest certified clearance 0.6181 at step 10 (obstacle 0); along "
                      "the motion > 0.5083 (steps 8-9)\n"
                      "along the whole motion every link stays farther than 0.5083 (>= the "
                      "tolerance) from every obstacle\n"),
            std::string::npos)
      << text;
  EXPECT_EQ(text.find("note: along the motion"), std::string::npos) << text;
}

}  // namespace
