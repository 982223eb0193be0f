// `--start q1,q2,...` on verify, trajectory and check-certificate (issue #20 point 2): the path
// starts where it says (radians with a cell, degrees with thesis files), the certificate records
// it, check-certificate re-derives it from the same option and rejects or refuses another; a
// trajectory starts at its first point; a wrong count or a value beyond a joint's limits is
// refused naming the joint.
#include <unistd.h>

#include <cmath>
#include <filesystem>
#include <string>
#include <vector>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "app/exit_codes.hpp"
#include "support/cli_run.hpp"
#include "support/data_paths.hpp"
#include "support/text_files.hpp"

namespace {

using grpvss::test::kTestCells;
using grpvss::test::kUr5ePostNoSelfCell;
const std::string kPath = kTestCells + "ur5e-clear.txt";  // one PTP to (-30,-90,90,0,0,0) deg
using grpvss::test::kTestTrajectories;
using grpvss::test::kIbm7545Data;
// Pan turned by 0.2 rad from the cell's home (0, -1.5708, 1.5708, 0, 0, 0).
const std::string kStart = "0.2,-1.5708,1.5708,0,0,0";

using grpvss::test::CliRun;
using grpvss::test::run_cli;

class StartCli : public ::testing::Test {
 protected:
  void SetUp() override {
    directory_ = std::filesystem::temp_directory_path() /
                 ("grpvss-start-cli-" + std::to_string(::getpid()));
    std::filesystem::create_directories(directory_);
  }
  void TearDown() override { std::filesystem::remove_all(directory_); }
  std::string dir() const { return directory_.string(); }
  static std::string cell_path() { return "--cell " + kUr5ePostNoSelfCell + " --path " + kPath; }
  nlohmann::json read_json(const std::string& name) const {
    return nlohmann::json::parse(grpvss::test::read_text_file(dir() + "/" + name));
  }
  std::filesystem::path directory_;
};

TEST_F(StartCli, TheFirstStepIsTheStartAndTheCertificateRecordsIt) {
  const CliRun verify = run_cli(dir(), "verify " + cell_path() + " --start " + kStart +
                                           " --json r.json --certificate c.json");
  ASSERT_EQ(verify.exit_code, grpvss::app::kExitOk) << verify.out << verify.err;
  // Step 0 of the certificate is the start, bit for bit; so is the recorded start.
  const nlohmann::json certificate = read_json("c.json");
  const std::vector<double> start{0.2, -1.5708, 1.5708, 0, 0, 0};
  EXPECT_EQ(certificate["start"].get<std::vector<double>>(), start);
  EXPECT_EQ(certificate["segments"][0]["steps"][0]["q"].get<std::vector<double>>(), start);
  // The report's first segment starts there (degrees): the pan at 0.2 rad = 11.459155902616464.
  const nlohmann::json report = read_json("r.json");
  EXPECT_DOUBLE_EQ(report["segments"][0]["start_joint_values"][0].get<double>(), 0.2 * 180.0 / M_PI);
  // The move ends at the path's target whatever the start: pan -30 deg.
  EXPECT_DOUBLE_EQ(report["steps"].back()["joint_values"][0].get<double>(), -30.0);
}

TEST_F(StartCli, CheckCertificateAcceptsTheSameStartAndRejectsOrRefusesAnother) {
  ASSERT_EQ(run_cli(dir(), "verify " + cell_path() + " --start " + kStart +
                               " --certificate c.json --quiet")
                .exit_code,
            grpvss::app::kExitOk);
  const CliRun same = run_cli(dir(), "check-certificate " + cell_path() + " --start " + kStart + " c.json");
  EXPECT_EQ(same.exit_code, grpvss::app::kExitOk) << same.out << same.err;
  EXPECT_EQ(same.out.rfind("ACCEPTED: claim CLEAR", 0), 0u) << same.out;
  EXPECT_NE(same.out.find("  motion model checked: synchronized PTP timing, CP speed 1 per s, IK "
                          "UR closed form, start 0.2,-1.5708,1.5708,0,0,0\n"),
            std::string::npos)
      << same.out;
  // Without --start the check replays the path from the cell's home: rejected, saying why.
  const CliRun home = run_cli(dir(), "check-certificate " + cell_path() + " c.json");
  EXPECT_EQ(home.exit_code, grpvss::app::kExitFinding) << home.out << home.err;
  EXPECT_NE(home.out.find("  - the certificate was made for a path from start "
                          "0.2,-1.5708,1.5708,0,0,0, the check is given a path from the "
                          "robot's home\n"),
            std::string::npos)
      << home.out;
  // Another --start contradicts the certificate: refused before anything is checked.
  const CliRun other = run_cli(dir(), "check-certificate " + cell_path() +
                                          " --start 0.3,-1.5708,1.5708,0,0,0 c.json");
  EXPECT_EQ(other.exit_code, grpvss::app::kExitInputError) << other.out;
  EXPECT_EQ(other.err, "grpvss: error: --start:0: expected the start the certificate was made "
                       "for (0.2,-1.5708,1.5708,0,0,0, library units), found another start\n");
}

TEST_F(StartCli, ACertificateFromTheHomeIsRefusedWithAStart) {
  ASSERT_EQ(run_cli(dir(), "verify " + cell_path() + " --certificate c.json --quiet").exit_code,
            grpvss::app::kExitOk);
  EXPECT_FALSE(read_json("c.json").contains("start"));  // unchanged certificates without --start
  const CliRun check = run_cli(dir(), "check-certificate " + cell_path() + " --start " + kStart + " c.json");
  EXPECT_EQ(check.exit_code, grpvss::app::kExitInputError) << check.out;
  EXPECT_EQ(check.err, "grpvss: error: --start:0: expected the start the certificate was made "
                       "for (the robot's home, library units), found another start\n");
}

TEST_F(StartCli, AWrongCountOrAValueBeyondItsLimitIsRefusedNamingTheJoint) {
  const CliRun count = run_cli(dir(), "verify " + cell_path() + " --start 0,0");
  EXPECT_EQ(count.exit_code, grpvss::app::kExitInputError);
  EXPECT_EQ(count.err, "grpvss: error: --start:0: expected one value per joint (6 joints), "
                       "found 2 values\n");
  const CliRun limit = run_cli(dir(), "verify " + cell_path() + " --start 0,-1.5708,3.2,0,0,0");
  EXPECT_EQ(limit.exit_code, grpvss::app::kExitInputError);
  EXPECT_EQ(limit.err, "grpvss: error: --start:0: expected elbow_joint within its limits "
                       "[-3.14159, 3.14159] rad, found 3.2\n");
  const CliRun word = run_cli(dir(), "trajectory " + cell_path() + " --start 0,x,0,0,0,0");
  EXPECT_EQ(word.exit_code, grpvss::app::kExitInputError);
  EXPECT_EQ(word.err, "grpvss: error: --start:0: expected a comma-separated list of numbers "
                      "(entry 2), found 'x'\n");
}

TEST_F(StartCli, ThesisFilesTakeTheStartInDegrees) {
  const std::string robot = "--robot " + kIbm7545Data + "robot.txt --path " + kIbm7545Data + "path.txt";
  const CliRun planned = run_cli(dir(), "trajectory " + robot + " --start 10,20,1,30 --json");
  ASSERT_EQ(planned.exit_code, grpvss::app::kExitOk) << planned.err;
  const nlohmann::json document = nlohmann::json::parse(planned.out);
  // Degrees -> radians -> degrees: within an ulp of what was given (30 comes back 29.999999999999996).
  const std::vector<double> home = document["home"].get<std::vector<double>>();
  ASSERT_EQ(home.size(), 4u);
  EXPECT_DOUBLE_EQ(home[0], 10.0);
  EXPECT_DOUBLE_EQ(home[1], 20.0);
  EXPECT_EQ(home[2], 1.0);  // prismatic: length units, unchanged
  EXPECT_DOUBLE_EQ(home[3], 30.0);
  // Joint 1 of the IBM 7545 turns within [0, 200] degrees.
  const CliRun limit = run_cli(dir(), "trajectory " + robot + " --start 201,20,1,30");
  EXPECT_EQ(limit.exit_code, grpvss::app::kExitInputError);
  EXPECT_EQ(limit.err, "grpvss: error: --start:0: expected joint 1 within its limits [0, 200] "
                       "deg, found 201\n");
}

TEST_F(StartCli, ATrajectoryStartsAtItsFirstPointAndAnotherStartIsRefused) {
  const std::string trajectory = "--cell " + kUr5ePostNoSelfCell + " --trajectory " + kTestTrajectories + "ur5e-clear.json";
  // ur5e-clear.json starts at (lift -1.5708, pan 0, elbow 1.5708, 0, 0, 0): the robot's order.
  EXPECT_EQ(run_cli(dir(), "verify " + trajectory + " --start 0,-1.5708,1.5708,0,0,0 --quiet")
                .exit_code,
            grpvss::app::kExitOk);
  const CliRun other = run_cli(dir(), "verify " + trajectory + " --start 0,-1.5708,1.5708,0,0,1e-8");
  EXPECT_EQ(other.exit_code, grpvss::app::kExitInputError);
  EXPECT_EQ(other.err, "grpvss: error: --start:0: expected the trajectory's first point (it "
                       "starts there): wrist_3_joint at 0 (within 1e-09), found 1e-08\n");
  EXPECT_EQ(run_cli(dir(), "trajectory " + trajectory + " --start 0.1,-1.5708,1.5708,0,0,0")
                .exit_code,
            grpvss::app::kExitInputError);
}

TEST_F(StartCli, TheTrajectoryCommandStartsAtTheStart) {
  const CliRun planned = run_cli(dir(), "trajectory " + cell_path() + " --start " + kStart + " --at 0 --json");
  ASSERT_EQ(planned.exit_code, grpvss::app::kExitOk) << planned.err;
  const nlohmann::json document = nlohmann::json::parse(planned.out);
  EXPECT_DOUBLE_EQ(document["home"][0].get<double>(), 0.2 * 180.0 / M_PI);
  EXPECT_DOUBLE_EQ(document["samples"][0]["joints"][0].get<double>(), 0.2 * 180.0 / M_PI);
}

}  // namespace
