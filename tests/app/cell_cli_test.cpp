// `grpvss verify --cell` and `check-certificate --cell` on a real robot: the UR5e of
// ../shared/robots on a table beside a post (tests/data/cells/ur5e-post.yaml). A clear path is
// CLEAR and its certificate ACCEPTED; a path through the post is COLLISION naming the link and
// the obstacle; a cell and thesis files together are refused.
#include <sys/wait.h>
#include <unistd.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <string>

#include <gtest/gtest.h>

#include "app/exit_codes.hpp"
#include "support/cli_run.hpp"
#include "support/data_paths.hpp"
#include "support/text_files.hpp"

namespace {

using grpvss::test::kIbm7545Data;
using grpvss::test::kTestCells;

using grpvss::test::CliRun;
using grpvss::test::run_cli;

class CellCli : public ::testing::Test {
 protected:
  void SetUp() override {
    directory_ = std::filesystem::temp_directory_path() /
                 ("grpvss-cell-cli-" + std::to_string(::getpid()));
    std::filesystem::create_directories(directory_);
  }
  void TearDown() override { std::filesystem::remove_all(directory_); }
  std::string dir() const { return directory_.string(); }
  std::filesystem::path directory_;
};

TEST_F(CellCli, AClearUr5ePathIsClearAndItsCertificateIsAccepted) {
  const std::string inputs = "--cell " + kTestCells + "ur5e-post.yaml --path " + kTestCells + "ur5e-clear.txt";
  const CliRun verify = run_cli(dir(), "verify " + inputs + " --certificate c.json");
  ASSERT_EQ(verify.exit_code, grpvss::app::kExitOk) << verify.out << verify.err;
  EXPECT_NE(verify.out.find("verdict: CLEAR"), std::string::npos) << verify.out;
  // Link names from the URDF, obstacle names from the cell; the cell's tolerance (5 mm).
  EXPECT_NE(verify.out.find("tolerance: 0.005 "), std::string::npos) << verify.out;
  EXPECT_NE(verify.out.find("forearm_link: smallest certified clearance"), std::string::npos)
      << verify.out;
  const CliRun check = run_cli(dir(), "check-certificate " + inputs + " c.json");
  EXPECT_EQ(check.exit_code, 0) << check.out << check.err;
  EXPECT_NE(check.out.find("ACCEPTED: claim CLEAR"), std::string::npos) << check.out;
  EXPECT_NE(check.out.find("synchronized PTP timing"), std::string::npos) << check.out;
}

TEST_F(CellCli, AUr5ePathThroughThePostIsACollisionOfTheForearmWithThePost) {
  const CliRun verify = run_cli(dir(), "verify --cell " + kTestCells + "ur5e-post.yaml --path " +
                                           kTestCells + "ur5e-through-post.txt");
  ASSERT_EQ(verify.exit_code, grpvss::app::kExitFinding) << verify.out << verify.err;
  EXPECT_NE(verify.out.find("verdict: COLLISION"), std::string::npos) << verify.out;
  EXPECT_NE(verify.out.find("interference: forearm_link hull 0 / post, "), std::string::npos)
      << verify.out;
}

TEST_F(CellCli, ACellWithThesisRobotFilesIsRefusedBeforeAnyWork) {
  const CliRun verify = run_cli(dir(), "verify --cell " + kTestCells + "ur5e-post.yaml --robot " +
                                           kIbm7545Data + "robot.txt --path " +
                                           kTestCells + "ur5e-clear.txt");
  EXPECT_EQ(verify.exit_code, grpvss::app::kExitInputError) << verify.out << verify.err;
  EXPECT_NE(verify.err.find("either --cell or --robot with --env, not both"), std::string::npos)
      << verify.err;
}

TEST_F(CellCli, WithoutACellOrAToleranceTheRunIsRefused) {
  const std::string& data = kIbm7545Data;
  const CliRun verify = run_cli(dir(), "verify --robot " + data + "robot.txt --env " + data +
                                           "environment.txt --path " + data + "path.txt");
  EXPECT_EQ(verify.exit_code, grpvss::app::kExitInputError) << verify.out << verify.err;
  EXPECT_NE(verify.err.find("--tolerance DELTA"), std::string::npos) << verify.err;
}

}  // namespace

namespace {

// A copy of ur5e-bolted.yaml in `directory` without its allowed_contacts (its relative paths
// made absolute).
std::string cell_without_allowed_contacts(const std::string& directory) {
  std::string text = grpvss::test::read_text_file(kTestCells + "ur5e-bolted.yaml");
  text = text.substr(0, text.find("allowed_contacts:")) + "tolerance: 0.005\n";
  for (std::size_t at = text.find("../../../../"); at != std::string::npos;
       at = text.find("../../../../")) {
    text.replace(at, 12, std::string(GRPVSS_SOURCE_DIR) + "/../");
  }
  const std::string file = directory + "/unbolted.yaml";
  std::ofstream(file) << text;
  return file;
}

TEST_F(CellCli, ARobotBoltedToItsTableIsClearWithTheAllowedContactAndItsCertificateSaysSo) {
  const std::string inputs =
      "--cell " + kTestCells + "ur5e-bolted.yaml --path " + kTestCells + "ur5e-clear.txt";
  const CliRun verify = run_cli(dir(), "verify " + inputs + " --certificate c.json");
  ASSERT_EQ(verify.exit_code, grpvss::app::kExitOk) << verify.out << verify.err;
  EXPECT_NE(verify.out.find("allowed contacts (not verified): base_link hull 0 (base_link_inertia) / table\n"),
            std::string::npos)
      << verify.out;
  const CliRun check = run_cli(dir(), "check-certificate " + inputs + " c.json");
  EXPECT_EQ(check.exit_code, 0) << check.out << check.err;
  // The certificate lists the pair; without it the checker refuses the certificate.
  const std::string certificate = grpvss::test::read_text_file(dir() + "/c.json");
  const std::size_t at = certificate.find("\"allowed_contacts\"");
  ASSERT_NE(at, std::string::npos);
  std::string tampered = certificate;
  tampered.replace(at, std::string("\"allowed_contacts\"").size(), "\"allowed_contacts_x\"");
  std::ofstream(dir() + "/tampered.json") << tampered;
  const CliRun rejected = run_cli(dir(), "check-certificate " + inputs + " tampered.json");
  EXPECT_EQ(rejected.exit_code, 1) << rejected.out << rejected.err;
  EXPECT_NE(rejected.out.find("the certificate's allowed contacts differ from the inputs'"),
            std::string::npos)
      << rejected.out;
}

TEST_F(CellCli, WithoutTheAllowedContactTheBaseOnTheTableIsACollision) {
  const std::string cell = cell_without_allowed_contacts(dir());
  const CliRun verify =
      run_cli(dir(), "verify --cell " + cell + " --path " + kTestCells + "ur5e-clear.txt");
  EXPECT_EQ(verify.exit_code, grpvss::app::kExitFinding) << verify.out << verify.err;
  EXPECT_NE(verify.out.find("interference: base_link hull 0 (base_link_inertia) / table, "), std::string::npos)
      << verify.out;
}

TEST_F(CellCli, AUr5eFoldingItsWristIntoItsUpperArmIsASelfCollisionNamingBothLinks) {
  const std::string inputs =
      "--cell " + kTestCells + "ur5e-self.yaml --path " + kTestCells + "ur5e-fold.txt";
  const CliRun verify =
      run_cli(dir(), "verify " + inputs + " --certificate c.json --json r.json");
  ASSERT_EQ(verify.exit_code, grpvss::app::kExitFinding) << verify.out << verify.err;
  EXPECT_NE(verify.out.find("verdict: COLLISION"), std::string::npos) << verify.out;
  EXPECT_NE(verify.out.find("self-collision not verified: base_link_inertia / shoulder_link "
                            "(adjacent); shoulder_link / upper_arm_link (adjacent);"),
            std::string::npos)
      << verify.out;
  EXPECT_NE(verify.out.find("self-collision: wrist_2_link / upper_arm_link, step"),
            std::string::npos)
      << verify.out;
  const std::string report = grpvss::test::read_text_file(dir() + "/r.json");
  EXPECT_NE(report.find("\"name\": \"wrist_2_link / upper_arm_link\""), std::string::npos);
  EXPECT_NE(report.find("\"self_contacts\""), std::string::npos);
  const CliRun check = run_cli(dir(), "check-certificate " + inputs + " c.json");
  EXPECT_EQ(check.exit_code, 0) << check.out << check.err;
  EXPECT_NE(check.out.find("ACCEPTED: claim COLLISION"), std::string::npos) << check.out;
}

}  // namespace

namespace {

const std::string kSixAxis = std::string(GRPVSS_SOURCE_DIR) + "/data/sixaxis/";

TEST_F(CellCli, TheSixAxisDemoCellIsClearOnItsClearPathAndItsCertificateIsAccepted) {
  const std::string inputs =
      "--cell " + kSixAxis + "cell.yaml --path " + kSixAxis + "path-clear.txt";
  const CliRun verify = run_cli(dir(), "verify " + inputs + " --certificate c.json");
  ASSERT_EQ(verify.exit_code, grpvss::app::kExitOk) << verify.out << verify.err;
  EXPECT_NE(verify.out.find("allowed contacts (not verified): base_link hull 0 / pedestal\n"),
            std::string::npos)
      << verify.out;
  const CliRun check = run_cli(dir(), "check-certificate " + inputs + " c.json");
  EXPECT_EQ(check.exit_code, 0) << check.out << check.err;
}

TEST_F(CellCli, TheSixAxisDemoCellCollisionPathHitsThePostWithTheForearm) {
  const CliRun verify = run_cli(dir(), "verify --cell " + kSixAxis + "cell.yaml --path " +
                                           kSixAxis + "path-collision.txt");
  EXPECT_EQ(verify.exit_code, grpvss::app::kExitFinding) << verify.out << verify.err;
  EXPECT_NE(verify.out.find("interference: link_4 hull 0 / post, "), std::string::npos)
      << verify.out;
}

}  // namespace
