// `grpvss verify|trajectory|check-certificate --trajectory T` on the UR5e cell of
// tests/data/cells/ur5e-post.yaml (the robot of ../shared/robots, tests only) with planner
// trajectories from tests/data/trajectories: a linear CSV through the post is a COLLISION of
// the forearm with the post at a stated time; a cubic ROS JSON trajectory that stays clear is
// CLEAR and its certificate ACCEPTED, REJECTED when tampered with or used with another file; a
// cubic piece whose waypoints are clear but whose overshoot swings the forearm into the post is
// a COLLISION while the linear interpolation of the same waypoints is CLEAR; name mismatches,
// limit violations and contradicting options are refused with their exact messages.
#include <unistd.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <string>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "app/exit_codes.hpp"
#include "support/cli_run.hpp"
#include "support/data_paths.hpp"
#include "support/text_files.hpp"

namespace {

using grpvss::test::kUr5ePostNoSelfCell;
using grpvss::test::kTestTrajectories;

using grpvss::test::CliRun;
using grpvss::test::run_cli;

class JointTrajectoryCli : public ::testing::Test {
 protected:
  void SetUp() override {
    directory_ = std::filesystem::temp_directory_path() /
                 ("grpvss-joint-trajectory-cli-" + std::to_string(::getpid()));
    std::filesystem::create_directories(directory_);
  }
  void TearDown() override { std::filesystem::remove_all(directory_); }
  std::string dir() const { return directory_.string(); }
  static std::string inputs(const std::string& trajectory) {
    return "--cell " + kUr5ePostNoSelfCell + " --trajectory " + kTestTrajectories + trajectory;
  }
  std::filesystem::path directory_;
};

bool contains(const std::string& text, const std::string& part) {
  return text.find(part) != std::string::npos;
}

}  // namespace

namespace {

TEST_F(JointTrajectoryCli, ALinearCsvThroughThePostIsACollisionOfTheForearmAtAStatedTime) {
  const CliRun verify = run_cli(dir(), "verify " + inputs("ur5e-through-post.csv") + " --json r.json");
  ASSERT_EQ(verify.exit_code, grpvss::app::kExitFinding) << verify.out << verify.err;
  // The summary's first line states the motion model.
  EXPECT_EQ(verify.out.rfind("motion: joint trajectory ur5e-through-post.csv, linear "
                             "interpolation, 3 waypoints, 0..2 s\nverdict: COLLISION\n", 0),
            0u)
      << verify.out;
  EXPECT_TRUE(contains(verify.out, "interference: forearm_link hull 0 / post, steps 15-34 "
                                   "(1.313-2.000 s), unexpanded collides at steps 21-34"))
      << verify.out;
  const nlohmann::json report =
      nlohmann::json::parse(grpvss::test::read_text_file(dir() + "/r.json"));
  EXPECT_EQ(report["motion_model"],
            "joint trajectory ur5e-through-post.csv, linear interpolation, 3 waypoints, 0..2 s");
  ASSERT_EQ(report["segments"].size(), 2u);
  EXPECT_EQ(report["segments"][0]["kind"], "trajectory-piece");
  EXPECT_EQ(report["segments"][1]["source_line"], 4);  // the piece's end waypoint
  EXPECT_EQ(report["segments"][0]["cycle_time"], 1.0);
  EXPECT_EQ(report["collision_step"], 21);
  // The first colliding step: its time, and its pan joint where the linear interpolation
  // (0.8 rad at 1 s to 1.74533 rad at 2 s) has it (the report's joints are in degrees).
  const nlohmann::json& step = report["steps"][20];
  ASSERT_EQ(step["index"], 21);
  EXPECT_EQ(step["segment"], 2);
  const double t = step["path_time"].get<double>();
  // The march's proposals follow the certified clearances, which move in their last bits when
  // a bound is formed differently (the placed templates moved t by ~1e-14 s): to 1 ns.
  EXPECT_NEAR(t, 1.33494160360012, 1e-9);
  EXPECT_DOUBLE_EQ(step["segment_parameter"].get<double>(), t - 1.0);
  const double pan_rad = 0.8 + (t - 1.0) * (1.74533 - 0.8);
  EXPECT_NEAR(step["joint_values"][0].get<double>(), pan_rad * 180.0 / M_PI, 1e-9);
}

TEST_F(JointTrajectoryCli, AClearCubicRosJsonTrajectoryIsClearAndItsCertificateAccepted) {
  const CliRun verify =
      run_cli(dir(), "verify " + inputs("ur5e-clear.json") + " --certificate c.json");
  ASSERT_EQ(verify.exit_code, grpvss::app::kExitOk) << verify.out << verify.err;
  EXPECT_EQ(verify.out.rfind("motion: joint trajectory ur5e-clear.json, cubic Hermite "
                             "interpolation, 3 waypoints, 0..3 s\nverdict: CLEAR\n",
                             0),
            0u)
      << verify.out;
  EXPECT_TRUE(contains(verify.out, "steps: 6  cycle time: 3.000 s")) << verify.out;
  const nlohmann::json certificate =
      nlohmann::json::parse(grpvss::test::read_text_file(dir() + "/c.json"));
  EXPECT_EQ(certificate["trajectory_interpolation"], "cubic-hermite");
  EXPECT_TRUE(certificate["inputs"].contains("trajectory"));
  EXPECT_FALSE(certificate["inputs"].contains("path"));
  ASSERT_EQ(certificate["segments"].size(), 2u);
  EXPECT_EQ(certificate["segments"][1]["kind"], "trajectory-piece");
  EXPECT_EQ(certificate["segments"][1]["parameter_end"], 1.5);
  const CliRun check = run_cli(dir(), "check-certificate " + inputs("ur5e-clear.json") + " c.json");
  EXPECT_EQ(check.exit_code, 0) << check.out << check.err;
  EXPECT_EQ(check.out.rfind("ACCEPTED: claim CLEAR (392 inequalities decided exactly)\n", 0), 0u)
      << check.out;
  EXPECT_TRUE(contains(check.out, "motion model checked: joint trajectory ur5e-clear.json, cubic "
                                  "Hermite interpolation, 3 waypoints, 0..3 s, IK UR closed form"))
      << check.out;
}

TEST_F(JointTrajectoryCli, ACubicOvershootBetweenClearWaypointsHitsThePostTheLinearOneIsClear) {
  // Both waypoints (pan 0 and -0.2 rad) are clear and the linear motion between them turns
  // away from the post; the cubic with slopes +2.6 and -2.6 rad/s swings the pan to 1.2 rad at
  // t = 1 s (0 + 5.2 s(1-s) - 0.2 (3s^2 - 2s^3) at s = 1/2), into the post, and back.
  const CliRun linear = run_cli(dir(), "verify " + inputs("ur5e-overshoot-linear.csv"));
  EXPECT_EQ(linear.exit_code, grpvss::app::kExitOk) << linear.out << linear.err;
  EXPECT_TRUE(contains(linear.out, "verdict: CLEAR\n")) << linear.out;
  const CliRun cubic = run_cli(dir(), "verify " + inputs("ur5e-overshoot-cubic.csv"));
  ASSERT_EQ(cubic.exit_code, grpvss::app::kExitFinding) << cubic.out << cubic.err;
  EXPECT_TRUE(contains(cubic.out, "interference: forearm_link hull 0 / post, steps 15-25 "
                                  "(0.656-1.134 s, clear by 1.253 s), unexpanded collides at "
                                  "steps 22-25"))
      << cubic.out;
  const CliRun samples =
      run_cli(dir(), "trajectory " + inputs("ur5e-overshoot-cubic.csv") + " --at 1");
  EXPECT_EQ(samples.exit_code, 0) << samples.err;
  // 1.2 rad = 68.75 degrees at the top of the overshoot.
  EXPECT_TRUE(contains(samples.out, "T =     1.000 S  SEGMENT 1      68.75   -90.00    90.00"))
      << samples.out;
}

std::string certificate_of(const std::string& directory, const std::string& trajectory,
                           const std::string& name, int exit_code = grpvss::app::kExitOk) {
  const CliRun verify = run_cli(directory, "verify --cell " + kUr5ePostNoSelfCell + " --trajectory " +
                                               kTestTrajectories + trajectory + " --certificate " +
                                               name + " --quiet");
  EXPECT_EQ(verify.exit_code, exit_code) << verify.err;
  return directory + "/" + name;
}

TEST_F(JointTrajectoryCli, ACertificateCheckedWithAnotherTrajectoryOrTamperedIsRejected) {
  certificate_of(dir(), "ur5e-clear.json", "c.json");
  const CliRun other =
      run_cli(dir(), "check-certificate " + inputs("ur5e-overshoot-cubic.csv") + " c.json");
  EXPECT_EQ(other.exit_code, grpvss::app::kExitFinding) << other.out << other.err;
  EXPECT_TRUE(contains(other.out, "REJECTED: claim CLEAR")) << other.out;
  EXPECT_TRUE(contains(other.out, "  - the trajectory file differs from the one certified\n"))
      << other.out;
  // A certificate of a trajectory checked as a path program is rejected too.
  const CliRun as_path = run_cli(dir(), "check-certificate --cell " + kUr5ePostNoSelfCell + " --path " +
                                            GRPVSS_SOURCE_DIR "/tests/data/cells/ur5e-clear.txt c.json");
  EXPECT_EQ(as_path.exit_code, grpvss::app::kExitFinding) << as_path.out << as_path.err;
  EXPECT_TRUE(contains(as_path.out, "the certificate was made for a joint trajectory "
                                    "(cubic-hermite interpolation), the check is given a path "
                                    "program"))
      << as_path.out;
  // A recorded configuration moved by 1e-9 rad is not the trajectory's.
  nlohmann::json certificate = nlohmann::json::parse(grpvss::test::read_text_file(dir() + "/c.json"));
  nlohmann::json& q = certificate["segments"][0]["steps"][1]["q"];
  q[0] = q[0].get<double>() + 1e-9;
  std::ofstream(dir() + "/t.json") << certificate.dump(1);
  const CliRun tampered = run_cli(dir(), "check-certificate " + inputs("ur5e-clear.json") + " t.json");
  EXPECT_EQ(tampered.exit_code, grpvss::app::kExitFinding) << tampered.out << tampered.err;
  EXPECT_TRUE(contains(tampered.out, "the configuration is not the trajectory's at this parameter"))
      << tampered.out;
}

TEST_F(JointTrajectoryCli, ALinearCertificatePassedOffAsTheCubicOvershootIsRejected) {
  // The linear run's steps, relabelled as the cubic trajectory's (interpolation and digest):
  // the checker re-derives the cubic motion, whose configurations and joint variation (the
  // pan turns between the waypoints) the linear steps do not cover.
  certificate_of(dir(), "ur5e-overshoot-linear.csv", "l.json");
  certificate_of(dir(), "ur5e-overshoot-cubic.csv", "k.json", grpvss::app::kExitFinding);
  nlohmann::json linear = nlohmann::json::parse(grpvss::test::read_text_file(dir() + "/l.json"));
  const nlohmann::json cubic = nlohmann::json::parse(grpvss::test::read_text_file(dir() + "/k.json"));
  linear["trajectory_interpolation"] = "cubic-hermite";
  linear["inputs"]["trajectory"] = cubic["inputs"]["trajectory"];
  std::ofstream(dir() + "/m.json") << linear.dump(1);
  const CliRun check =
      run_cli(dir(), "check-certificate " + inputs("ur5e-overshoot-cubic.csv") + " m.json");
  EXPECT_EQ(check.exit_code, grpvss::app::kExitFinding) << check.out << check.err;
  EXPECT_TRUE(contains(check.out, "segment 1 step 1: the configuration is not the trajectory's "
                                  "at this parameter"))
      << check.out;
  EXPECT_TRUE(contains(check.out, ": the recorded motion bound is below the exact bound"))
      << check.out;
}

TEST_F(JointTrajectoryCli, JointNameMismatchesAndLimitViolationsAreRefusedWithTheirExactText) {
  const CliRun names = run_cli(dir(), "verify " + inputs("ur5e-names-mismatch.csv"));
  EXPECT_EQ(names.exit_code, grpvss::app::kExitInputError);
  EXPECT_EQ(names.err, "grpvss: error: " + kTestTrajectories +
                           "ur5e-names-mismatch.csv:1: expected the robot's joints, each once: "
                           "shoulder_pan_joint, shoulder_lift_joint, elbow_joint, wrist_1_joint, "
                           "wrist_2_joint, wrist_3_joint, found missing wrist_3_joint; extra "
                           "gripper_joint\n");
  const CliRun limit = run_cli(dir(), "verify " + inputs("ur5e-elbow-limit.csv"));
  EXPECT_EQ(limit.exit_code, grpvss::app::kExitInputError);
  EXPECT_EQ(limit.err, "grpvss: error: " + kTestTrajectories +
                           "ur5e-elbow-limit.csv:3: expected joint positions and speeds within the "
                           "robot's limits along the interpolated motion, found joint 'elbow_joint' (3) "
                           "is above its upper position limit 3.141592653589793 at t = 3 s: 3.3 "
                           "(piece 2, between line 3 and line 4)\n");
  // The same refusals from trajectory and check-certificate (before any certificate is read).
  EXPECT_EQ(run_cli(dir(), "trajectory " + inputs("ur5e-elbow-limit.csv")).exit_code,
            grpvss::app::kExitInputError);
  EXPECT_EQ(run_cli(dir(), "check-certificate " + inputs("ur5e-names-mismatch.csv") + " none.json")
                .exit_code,
            grpvss::app::kExitInputError);
}

TEST_F(JointTrajectoryCli, TheThesisOutputFileListsThePiecesWithTheMotionModel) {
  const CliRun verify = run_cli(dir(), "verify " + inputs("ur5e-clear.json") + " --out o.txt");
  ASSERT_EQ(verify.exit_code, grpvss::app::kExitOk) << verify.err;
  const std::string out = grpvss::test::read_text_file(dir() + "/o.txt");
  // Waypoints 0 and 1 in the robot's joint order, degrees: lift -1.5708 rad = -90.00, the pan
  // -0.3 rad = -17.19, lift and elbow -+1.4 rad = -+80.21.
  EXPECT_EQ(out.rfind("THE TOLERANCE VALUE = 0.005\n\nTHE RESOLUTION MODE = CERTIFIED\n\n"
                      "THE MOTION MODEL = joint trajectory ur5e-clear.json, cubic Hermite "
                      "interpolation, 3 waypoints, 0..3 s\n\n"
                      "THE 1TH SEGMENT OF THE PATH INPUT FROM FILE ur5e-clear.json\n\n"
                      "--- JOINT TRAJECTORY PIECE ---\n STARTING JOINT VALUE FINAL JOINT VALUE\n\n"
                      "JOINT 1\t0.00\t-17.19\nJOINT 2\t-90.00\t-80.21\nJOINT 3\t90.00\t80.21\n"
                      "JOINT 4\t0.00\t0.00\nJOINT 5\t0.00\t0.00\nJOINT 6\t0.00\t0.00\n\n"
                      "IN 1TH STEP, THE JOINT VALUES ARE\n",
                      0),
            0u)
      << out;
  EXPECT_NE(out.find("THE 2TH SEGMENT OF THE PATH INPUT FROM FILE ur5e-clear.json\n\n"
                     "--- JOINT TRAJECTORY PIECE ---\n"),
            std::string::npos);
  const std::string end = "\nTOTAL 6 STEPS IN THIS PATH\nNO COLLISION DETECTED IN THIS PATH\n";
  ASSERT_GE(out.size(), end.size());
  EXPECT_EQ(out.substr(out.size() - end.size()), end) << out;
}

// The UR5e's URDF limits every joint to 3.141592653589793 rad/s (`<limit velocity>`).
TEST_F(JointTrajectoryCli, SpeedsBeyondTheUrdfVelocityLimitAreRefusedNamingJointTimeAndLimit) {
  // Cubic, at rest at both waypoints: the pan's speed peaks mid-piece at 1.5 * 1.1 / 0.5 = 3.3.
  const CliRun cubic = run_cli(dir(), "verify " + inputs("ur5e-pan-too-fast.csv"));
  EXPECT_EQ(cubic.exit_code, grpvss::app::kExitInputError);
  EXPECT_EQ(cubic.err, "grpvss: error: " + kTestTrajectories + "ur5e-pan-too-fast.csv:2: expected joint positions and speeds within the robot's "
                        "limits along the interpolated motion, found joint 'shoulder_pan_joint' "
                        "(1) is faster than its speed limit 3.141592653589793 at t = 0.25 s: "
                        "3.3000000000000003 (piece 1, between line 2 and line 3)\n");
  // Linear: the second piece's slope (0.6 - 0.2) / 0.1 = 4 rad/s.
  const CliRun linear = run_cli(dir(), "trajectory " + inputs("ur5e-pan-too-fast-linear.csv"));
  EXPECT_EQ(linear.exit_code, grpvss::app::kExitInputError);
  EXPECT_EQ(linear.err, "grpvss: error: " + kTestTrajectories + "ur5e-pan-too-fast-linear.csv:3: expected joint positions and speeds within the "
                         "robot's limits along the interpolated motion, found joint "
                         "'shoulder_pan_joint' (1) is faster than its speed limit "
                         "3.141592653589793 at t = 1 s: 3.999999999999996 (piece 2, between "
                         "line 3 and line 4)\n");
  EXPECT_EQ(run_cli(dir(), "check-certificate " + inputs("ur5e-pan-too-fast.csv") + " none.json")
                .exit_code,
            grpvss::app::kExitInputError);
}

TEST_F(JointTrajectoryCli, OptionsThatContradictTheTrajectoryAreRefused) {
  const CliRun timing = run_cli(dir(), "verify " + inputs("ur5e-clear.json") + " --timing independent");
  EXPECT_EQ(timing.exit_code, grpvss::app::kExitInputError);
  EXPECT_EQ(timing.err, "grpvss: error: --timing:0: expected no --timing with --trajectory (the "
                        "trajectory's waypoint times and interpolation are the motion), found "
                        "--timing\n");
  const CliRun thesis = run_cli(dir(), "verify " + inputs("ur5e-clear.json") + " --mode thesis");
  EXPECT_EQ(thesis.exit_code, grpvss::app::kExitInputError);
  EXPECT_TRUE(contains(thesis.err, "expected no --mode thesis with --trajectory")) << thesis.err;
  const CliRun neither = run_cli(dir(), "verify --cell " + kUr5ePostNoSelfCell);
  EXPECT_EQ(neither.exit_code, grpvss::app::kExitInputError);
  EXPECT_EQ(neither.err, "grpvss: error: --path:0: expected exactly one of --path, "
                         "--trajectory and --program, found none\n");
  const CliRun thesis_robot = run_cli(
      dir(), "verify --robot " GRPVSS_SOURCE_DIR "/data/ibm7545/robot.txt --env " GRPVSS_SOURCE_DIR
             "/data/ibm7545/environment.txt --tolerance 0.5 --trajectory " + kTestTrajectories +
                 "ur5e-clear.json");
  EXPECT_EQ(thesis_robot.exit_code, grpvss::app::kExitInputError);
  EXPECT_TRUE(contains(thesis_robot.err, "ur5e-clear.json:3: expected a robot with named joints "
                                         "(a URDF robot in a cell, --cell)"))
      << thesis_robot.err;
  certificate_of(dir(), "ur5e-clear.json", "c.json");
  const CliRun check_timing = run_cli(
      dir(), "check-certificate " + inputs("ur5e-clear.json") + " --timing synchronized c.json");
  EXPECT_EQ(check_timing.exit_code, grpvss::app::kExitInputError) << check_timing.out;
}

}  // namespace
