// `grpvss verify|trajectory|check-certificate --program FILE` (docs/robot-programs.md#verifying-
// a-program) on the UR5e cell of tests/data/cells/ur5e-post-no-self.yaml (the robot of
// ../shared/robots, tests only) and the six-axis demo cell (data/sixaxis/cell.yaml), with the
// programs of tests/data/programs: a URScript movej program with joint lists and a pose solved
// by IK is CLEAR and its certificate ACCEPTED, REJECTED once the program is edited; a program
// through the post is a COLLISION of the forearm with the post, with the verdict, the first
// colliding segment and the colliding configuration of its equivalent joint trajectory (CSV); a
// KRL E6POS with Status/Turn through a tool and a base resolves to the joints it was computed
// from; straight TCP lines (movel, LIN, MoveL) are certified CP lines, CLEAR and ACCEPTED, and a
// movel through the post collides as its equivalent IND 3 path does; a turning line under
// another tool than the cell's, circular and blended motions are refused with their file:line.
#include <unistd.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "app/exit_codes.hpp"
#include "support/cli_run.hpp"
#include "support/data_paths.hpp"
#include "support/text_files.hpp"

namespace {

using grpvss::test::kSourceDir;
using grpvss::test::kUr5ePostNoSelfCell;
const std::string kSixAxisCell = kSourceDir + "/data/sixaxis/cell.yaml";
using grpvss::test::kTestPrograms;

using grpvss::test::CliRun;
using grpvss::test::run_cli;

class ProgramCli : public ::testing::Test {
 protected:
  void SetUp() override {
    directory_ = std::filesystem::temp_directory_path() /
                 ("grpvss-program-cli-" + std::to_string(::getpid()));
    std::filesystem::create_directories(directory_);
  }
  void TearDown() override { std::filesystem::remove_all(directory_); }
  std::string dir() const { return directory_.string(); }
  std::filesystem::path directory_;
};

bool text_contains(const std::string& text, const std::string& part) {
  return text.find(part) != std::string::npos;
}

// The summary's first lines: the motion model, then the verdict.
void expect_summary_starts_with(const CliRun& run, const std::string& lines) {
  EXPECT_EQ(run.out.rfind(lines, 0), 0u) << run.out;
}

std::string ur5e(const std::string& program) {
  return "--cell " + kUr5ePostNoSelfCell + " --program " + kTestPrograms + program;
}

// "file:line q1 ... q6" entries of the certificate's program_targets, as numbers.
std::vector<std::vector<double>> recorded_targets(const nlohmann::json& certificate) {
  std::vector<std::vector<double>> targets;
  std::stringstream entries(certificate["inputs"]["program_targets"].get<std::string>());
  std::string entry;
  while (std::getline(entries, entry, ';')) {
    std::stringstream fields(entry);
    std::string location;
    fields >> location;
    std::vector<double> q;
    double value = 0.0;
    while (fields >> value) q.push_back(value);
    targets.push_back(q);
  }
  return targets;
}

TEST_F(ProgramCli, AUrScriptMovejProgramIsClearAndItsCertificateAccepted) {
  const CliRun verify = run_cli(dir(), "verify " + ur5e("ur5e-clear.script") + " --certificate c.json");
  ASSERT_EQ(verify.exit_code, grpvss::app::kExitOk) << verify.out << verify.err;
  expect_summary_starts_with(verify, "motion: program ur5e-clear.script (URScript), synchronized PTP, 3 "
                                     "motions (2 joint targets, 1 pose by IK), exact stops\nverdict: CLEAR\n");
  EXPECT_TRUE(text_contains(verify.out, "steps: 12  cycle time: 4.119 s")) << verify.out;
  // Every reader warning reaches the user, one per ignored line.
  EXPECT_TRUE(text_contains(verify.err, "ur5e-clear.script:9: not read: popup(\"placed\")\n")) << verify.err;

  const nlohmann::json certificate =
      nlohmann::json::parse(grpvss::test::read_text_file(dir() + "/c.json"));
  EXPECT_EQ(certificate["inputs"]["program_language"], "URScript");
  EXPECT_EQ(certificate["inputs"]["program"].get<std::string>().size(), 64u);
  EXPECT_FALSE(certificate["inputs"].contains("path"));
  // The pose p[...] was computed from q = (-0.6, -1.4, 1.5, -1.2, -1.57, 0.2) with the UR5e's
  // published DH parameters in the controller's base frame (6 decimals written): the IK in the
  // cell (base turned by 0.25 rad, ur_description's base_link = base turned by pi) finds it back.
  const std::vector<std::vector<double>> targets = recorded_targets(certificate);
  ASSERT_EQ(targets.size(), 3u);
  const std::vector<double> expected{-0.6, -1.4, 1.5, -1.2, -1.57, 0.2};
  ASSERT_EQ(targets[1].size(), 6u);
  for (std::size_t j = 0; j < 6; ++j) EXPECT_NEAR(targets[1][j], expected[j], 5e-6) << j;
  EXPECT_DOUBLE_EQ(targets[0][0], -0.5235987755982988);

  const CliRun check = run_cli(dir(), "check-certificate " + ur5e("ur5e-clear.script") + " c.json");
  EXPECT_EQ(check.exit_code, grpvss::app::kExitOk) << check.out << check.err;
  EXPECT_EQ(check.out.rfind("ACCEPTED: claim CLEAR (749 inequalities decided exactly)\n  claim "
                            "checked: motion (CLEAR = robot + tolerance clear along the whole "
                            "motion)\n  motion model checked: program ur5e-clear.script (URScript), synchronized "
                            "PTP, 3 motions (2 joint targets, 1 pose by IK), exact stops, IK UR "
                            "closed form\n",
                            0),
            0u)
      << check.out;
}

TEST_F(ProgramCli, AnEditedProgramIsRejectedByTheCheck) {
  std::filesystem::copy_file(kTestPrograms + "ur5e-clear.script", dir() + "/p.script");
  const std::string inputs = "--cell " + kUr5ePostNoSelfCell + " --program p.script";
  ASSERT_EQ(run_cli(dir(), "verify " + inputs + " --certificate c.json").exit_code,
            grpvss::app::kExitOk);
  std::string text = grpvss::test::read_text_file(dir() + "/p.script");
  const std::string approach = "-0.5235987755982988";
  text.replace(text.find(approach), approach.size(), "-0.6");
  std::ofstream(dir() + "/p.script") << text;
  const CliRun check = run_cli(dir(), "check-certificate " + inputs + " c.json");
  EXPECT_EQ(check.exit_code, grpvss::app::kExitFinding) << check.out << check.err;
  EXPECT_TRUE(text_contains(check.out, "REJECTED: claim CLEAR")) << check.out;
  EXPECT_TRUE(text_contains(check.out, "  - the program file differs from the one certified\n")) << check.out;
  // A program's certificate checked as a path program is rejected too.
  const CliRun as_path = run_cli(dir(), "check-certificate --cell " + kUr5ePostNoSelfCell + " --path " + kSourceDir +
                                            "/tests/data/cells/ur5e-clear.txt c.json");
  EXPECT_EQ(as_path.exit_code, grpvss::app::kExitFinding) << as_path.out << as_path.err;
}

TEST_F(ProgramCli, AProgramAndItsEquivalentTrajectoryGiveTheSameCollision) {
  const CliRun program =
      run_cli(dir(), "verify " + ur5e("ur5e-through-post.script") + " --json p.json");
  ASSERT_EQ(program.exit_code, grpvss::app::kExitFinding) << program.out << program.err;
  expect_summary_starts_with(program, "motion: program ur5e-through-post.script (URScript), synchronized "
                                      "PTP, 2 motions (2 joint targets, 0 poses by IK), exact stops\n"
                                      "verdict: COLLISION\n");
  EXPECT_TRUE(text_contains(program.out, "interference: forearm_link hull 0 / post, steps 16-37 "
                                    "(1.359-2.082 s), unexpanded collides at steps 23-37"))
      << program.out;
  const CliRun trajectory = run_cli(dir(), "verify --cell " + kUr5ePostNoSelfCell + " --trajectory " + kSourceDir +
                                               "/tests/data/trajectories/ur5e-through-post.csv "
                                               "--json t.json");
  ASSERT_EQ(trajectory.exit_code, grpvss::app::kExitFinding) << trajectory.out;
  const auto p = nlohmann::json::parse(grpvss::test::read_text_file(dir() + "/p.json"));
  const auto t = nlohmann::json::parse(grpvss::test::read_text_file(dir() + "/t.json"));
  EXPECT_EQ(p["verdict"], t["verdict"]);
  EXPECT_EQ(p["collision_step"], 23);
  EXPECT_EQ(t["collision_step"], 21);
  const nlohmann::json& p_step = p["steps"][22];
  const nlohmann::json& t_step = t["steps"][20];
  EXPECT_EQ(p_step["segment"], 2);  // the same first colliding motion: the second movej / piece
  EXPECT_EQ(t_step["segment"], 2);
  EXPECT_EQ(p["segments"][1]["source_line"], 6);  // the movej's line
  // Steps fall at other times (trapezoids against linear interpolation) on the same joint-space
  // line: the first colliding configurations differ only along it, by 0.28 deg of the pan joint
  // (the other joints stand still, equal up to the last bit of their degree conversion).
  EXPECT_NEAR(p_step["joint_values"][0].get<double>(), 64.2542248016121, 1e-9);
  EXPECT_NEAR(t_step["joint_values"][0].get<double>(), 63.97820610955593, 1e-9);
  for (int j = 1; j < 6; ++j) {
    EXPECT_NEAR(p_step["joint_values"][j].get<double>(), t_step["joint_values"][j].get<double>(), 1e-12) << j;
  }
}

TEST_F(ProgramCli, AKrlE6posWithStatusAndTurnResolvesToTheJointsItWasComputedFrom) {
  const CliRun verify = run_cli(dir(), "verify --cell " + kSixAxisCell + " --program " + kTestPrograms +
                                           "sixaxis_ptp.src --certificate c.json");
  ASSERT_EQ(verify.exit_code, grpvss::app::kExitOk) << verify.out << verify.err;
  expect_summary_starts_with(verify, "motion: program sixaxis_ptp.src (KUKA KRL), synchronized PTP, 3 "
                                     "motions (2 joint targets, 1 pose by IK), exact stops\nverdict: CLEAR\n");
  // XPICK was computed from q = (0.3, -0.4, 0.5, 0.6, -0.7, 0.2) by the URDF's own FK, through
  // the 100 mm tool and the base at (200 mm, 0, 0) turned by 90 deg (4 decimals of mm and deg).
  const auto certificate = nlohmann::json::parse(grpvss::test::read_text_file(dir() + "/c.json"));
  EXPECT_EQ(certificate["inputs"]["program_language"], "KUKA KRL");
  const std::vector<std::vector<double>> targets = recorded_targets(certificate);
  ASSERT_EQ(targets.size(), 3u);
  const std::vector<double> expected{0.3, -0.4, 0.5, 0.6, -0.7, 0.2};
  for (std::size_t j = 0; j < 6; ++j) EXPECT_NEAR(targets[1][j], expected[j], 5e-6) << j;
  EXPECT_NEAR(targets[0][0], 20.0 * M_PI / 180.0, 1e-12);
  const CliRun check = run_cli(dir(), "check-certificate --cell " + kSixAxisCell + " --program " +
                                          kTestPrograms + "sixaxis_ptp.src c.json");
  EXPECT_EQ(check.exit_code, grpvss::app::kExitOk) << check.out << check.err;
}

TEST_F(ProgramCli, AnotherStatusNamesAConfigurationTheTargetDoesNotHave) {
  std::filesystem::copy_file(kTestPrograms + "sixaxis_ptp.src", dir() + "/s.src");
  std::filesystem::copy_file(kTestPrograms + "$config.dat", dir() + "/$config.dat");
  std::string data = grpvss::test::read_text_file(kTestPrograms + "sixaxis_ptp.dat");
  data.replace(data.find("S 6,T 18"), 8, "S 2,T 18");
  std::ofstream(dir() + "/s.dat") << data;
  const CliRun verify = run_cli(dir(), "verify --cell " + kSixAxisCell + " --program s.src");
  EXPECT_EQ(verify.exit_code, grpvss::app::kExitInputError) << verify.out;
  EXPECT_TRUE(text_contains(verify.err, "s.src:11: expected a pose the robot reaches within its joint "
                                   "limits in S 2 T 18 (OPW closed form), found no solution for "
                                   "the flange at p_WF = (0.3457, 0.0689, 1.3572) m"))
      << verify.err;
}

TEST_F(ProgramCli, UrScriptMovelLinesAreClearAndTheirCertificateAccepted) {
  const CliRun verify =
      run_cli(dir(), "verify " + ur5e("ur5e-movel-clear.script") + " --certificate c.json --json r.json");
  ASSERT_EQ(verify.exit_code, grpvss::app::kExitOk) << verify.out << verify.err;
  expect_summary_starts_with(verify, "motion: program ur5e-movel-clear.script (URScript), synchronized PTP "
                                     "and CP lines, 4 motions (1 joint target, 0 poses by IK, 3 straight "
                                     "TCP lines), exact stops\nverdict: CLEAR\n");
  const auto report = nlohmann::json::parse(grpvss::test::read_text_file(dir() + "/r.json"));
  ASSERT_EQ(report["segments"].size(), 4u);
  EXPECT_EQ(report["segments"][1]["source_line"], 11);
  EXPECT_TRUE(text_contains(verify.out, "steps: 24  cycle time: 3.914 s")) << verify.out;
  const auto certificate = nlohmann::json::parse(grpvss::test::read_text_file(dir() + "/c.json"));
  const std::vector<std::vector<double>> targets = recorded_targets(certificate);
  ASSERT_EQ(targets.size(), 4u);
  // The last movel names the approach joints: the line back ends in them.
  const std::vector<double> approach{-0.52359877559829882, -1.5707963267948966, 1.5707963267948966,
                                     -1.5707963267948966, -1.5707963267948966, 0};
  for (std::size_t j = 0; j < 6; ++j) EXPECT_NEAR(targets[3][j], approach[j], 1e-9) << j;
  const CliRun check = run_cli(dir(), "check-certificate " + ur5e("ur5e-movel-clear.script") + " c.json");
  EXPECT_EQ(check.exit_code, grpvss::app::kExitOk) << check.out << check.err;
  EXPECT_EQ(check.out.rfind("ACCEPTED: claim CLEAR", 0), 0u) << check.out;
}

TEST_F(ProgramCli, AMovelAndItsEquivalentCpLinePathGiveTheSameCollision) {
  const CliRun program =
      run_cli(dir(), "verify " + ur5e("ur5e-movel-post.script") + " --json p.json --certificate c.json");
  ASSERT_EQ(program.exit_code, grpvss::app::kExitFinding) << program.out << program.err;
  EXPECT_TRUE(text_contains(program.out, "verdict: COLLISION\n")) << program.out;
  const CliRun path = run_cli(dir(), "verify --cell " + kUr5ePostNoSelfCell + " --path " + kSourceDir +
                                         "/tests/data/cells/ur5e-movel-post.txt --cp-speed 0.25 "
                                         "--json t.json");
  ASSERT_EQ(path.exit_code, grpvss::app::kExitFinding) << path.out << path.err;
  const auto p = nlohmann::json::parse(grpvss::test::read_text_file(dir() + "/p.json"));
  const auto t = nlohmann::json::parse(grpvss::test::read_text_file(dir() + "/t.json"));
  EXPECT_EQ(p["verdict"], "COLLISION");
  EXPECT_EQ(t["verdict"], "COLLISION");
  EXPECT_EQ(p["collision_step"], 8);
  EXPECT_EQ(t["collision_step"], p["collision_step"]);
  const int first = p["collision_step"].get<int>() - 1;
  EXPECT_EQ(p["steps"][first]["segment"], 2);  // the movel, the IND 3 line
  EXPECT_EQ(t["steps"][first]["segment"], 2);
  EXPECT_EQ(p["segments"][1]["source_line"], 8);
  for (int j = 0; j < 6; ++j) {
    EXPECT_NEAR(p["steps"][first]["joint_values"][j].get<double>(),
                t["steps"][first]["joint_values"][j].get<double>(), 1e-6)  // deg: 17-digit file values
        << j;
  }
  EXPECT_TRUE(text_contains(program.out, "interference: wrist_1_link hull 0 / post, steps 8-15")) << program.out;
  const CliRun check = run_cli(dir(), "check-certificate " + ur5e("ur5e-movel-post.script") + " c.json");
  EXPECT_EQ(check.exit_code, grpvss::app::kExitOk) << check.out << check.err;
  EXPECT_EQ(check.out.rfind("ACCEPTED: claim COLLISION", 0), 0u) << check.out;
}

TEST_F(ProgramCli, AKrlLinAndARapidMoveLAreVerifiedAndTheirCertificatesAccepted) {
  for (const std::string program : {"sixaxis_lin.src", "sixaxis_movel.mod"}) {
    const std::string inputs = "--cell " + kSixAxisCell + " --program " + kTestPrograms + program;
    const std::string certificate_file = program + ".cert";
    const CliRun verify = run_cli(dir(), "verify " + inputs + " --certificate " + certificate_file);
    ASSERT_EQ(verify.exit_code, grpvss::app::kExitOk) << verify.out << verify.err;
    EXPECT_TRUE(text_contains(verify.out, "5 motions (2 joint targets, 1 pose by IK, 2 straight TCP "
                                     "lines), exact stops\nverdict: CLEAR\n"))
        << verify.out;
    const auto certificate =
        nlohmann::json::parse(grpvss::test::read_text_file(dir() + "/" + certificate_file));
    const std::vector<std::vector<double>> targets = recorded_targets(certificate);
    ASSERT_EQ(targets.size(), 5u);
    // Up and back down the line: the joints at its end are the pick's, (0.3, -0.4, 0.5, 0.6, -0.7, 0.2).
    const std::vector<double> pick{0.3, -0.4, 0.5, 0.6, -0.7, 0.2};
    for (std::size_t j = 0; j < 6; ++j) EXPECT_NEAR(targets[3][j], pick[j], 5e-6) << program << j;
    const CliRun check = run_cli(dir(), "check-certificate " + inputs + " " + certificate_file);
    EXPECT_EQ(check.exit_code, grpvss::app::kExitOk) << check.out << check.err;
  }
}

TEST_F(ProgramCli, ALinWhoseStatusTheLineDoesNotReachIsAnError) {
  std::filesystem::copy_file(kTestPrograms + "sixaxis_lin.src", dir() + "/s.src");
  std::filesystem::copy_file(kTestPrograms + "$config.dat", dir() + "/$config.dat");
  std::string data = grpvss::test::read_text_file(kTestPrograms + "sixaxis_lin.dat");
  data.replace(data.rfind("S 6,T 18"), 8, "S 2,T 18");  // XBACK only
  std::ofstream(dir() + "/s.dat") << data;
  const CliRun verify = run_cli(dir(), "verify --cell " + kSixAxisCell + " --program s.src");
  EXPECT_EQ(verify.exit_code, grpvss::app::kExitInputError) << verify.out;
  EXPECT_TRUE(text_contains(verify.err, "s.src:15: expected the configuration the line's target names "
                                   "(S 2 T 18) reached along the line from the previous target, "
                                   "found the line ends at joints (17.19, -22.92, 28.65, 34.38, "
                                   "-40.11, 11.46) deg, and the named configuration has no solution there"))
      << verify.err;
}

struct Refusal {
  std::string cell;
  std::string program;
  std::string message;
};

TEST_F(ProgramCli, TurningLinesUnderAnotherToolCircularAndBlendedMotionsAreRefused) {
  const std::string joint = "expected a joint motion (movej) ending in an exact stop: the verifier "
                            "models a program as synchronized PTP motions, found ";
  const std::string blended = ": the blended corner leaves the joint-space line and no bound on "
                              "it is proven; use an exact stop (UR r=0, KUKA without "
                              "C_PTP/C_DIS/C_VEL/C_ORI, ABB fine)";
  const std::vector<Refusal> refusals{
      {kUr5ePostNoSelfCell, "ur5e-movel.script",
       "ur5e-movel.script:5: expected a movel whose TCP is the cell's end effector E, or one that "
       "keeps the tool's orientation: a straight TCP line that turns is no straight line of E "
       "under another tool; set the cell's `tool` to the program's tool, found tool "
       "set_tcp(p[0, 0, 0.1, 0, 0, 0]) with its TCP at (0, 0, 100) mm in the flange, the cell's E at (0, 0, 0) mm, and the orientation "
       "turning by "},
      {kUr5ePostNoSelfCell, "ur5e-movec.script",
       "ur5e-movec.script:5: " + joint + "movec: circular moves are not modelled"},
      {kUr5ePostNoSelfCell, "ur5e-blend.script", "ur5e-blend.script:4: " + joint + "blend radius r = 0.05 m" + blended},
      {kUr5ePostNoSelfCell, "ur5e-zone.mod",
       "ur5e-zone.mod:6: expected a joint motion (MoveJ or MoveAbsJ) ending in an exact stop: the "
       "verifier models a program as synchronized PTP motions, found zone z10" + blended},
      {kSixAxisCell, "sixaxis_cptp.src",
       "sixaxis_cptp.src:8: expected a joint motion (PTP) ending in an exact stop: the verifier "
       "models a program as synchronized PTP motions, found zone C_PTP" + blended},
  };
  for (const Refusal& refusal : refusals) {
    for (const std::string command : {"verify", "trajectory"}) {
      const CliRun run = run_cli(dir(), command + " --cell " + refusal.cell + " --program " +
                                            kTestPrograms + refusal.program);
      EXPECT_EQ(run.exit_code, grpvss::app::kExitInputError) << refusal.program << run.out;
      EXPECT_TRUE(text_contains(run.err, refusal.message)) << run.err;
    }
  }
}

TEST_F(ProgramCli, TrajectoryPrintsTheProgramsMotion) {
  const CliRun run = run_cli(dir(), "trajectory " + ur5e("ur5e-through-post.script"));
  ASSERT_EQ(run.exit_code, grpvss::app::kExitOk) << run.out << run.err;
  expect_summary_starts_with(run, "motion: program ur5e-through-post.script (URScript), synchronized PTP, "
                                  "2 motions (2 joint targets, 0 poses by IK), exact stops\n");
  EXPECT_TRUE(text_contains(run.out, "PTP TIMING: SYNCHRONIZED")) << run.out;
  EXPECT_TRUE(text_contains(run.out, "ENDING JOINT VALUES    100.00   -90.00    90.00     0.00     0.00     0.00"))
      << run.out;
}

TEST_F(ProgramCli, OptionsThatContradictTheProgramAreRefused) {
  const CliRun timing = run_cli(dir(), "verify " + ur5e("ur5e-clear.script") + " --timing independent");
  EXPECT_EQ(timing.exit_code, grpvss::app::kExitInputError);
  EXPECT_TRUE(text_contains(timing.err, "--timing:0: expected no --timing with --program (a program "
                                   "is verified as the controller runs it: synchronized PTP, "
                                   "exact stops), found --timing"))
      << timing.err;
  const CliRun both = run_cli(dir(), "verify " + ur5e("ur5e-clear.script") + " --path " + kSourceDir +
                                         "/tests/data/cells/ur5e-clear.txt");
  EXPECT_EQ(both.exit_code, grpvss::app::kExitInputError) << both.err;
  const CliRun thesis = run_cli(dir(), "verify --robot " + kSourceDir + "/data/ibm7545/robot.txt --env " +
                                           kSourceDir + "/data/ibm7545/environment.txt --program " +
                                           kTestPrograms + "ur5e-clear.script");
  EXPECT_EQ(thesis.exit_code, grpvss::app::kExitInputError);
  EXPECT_TRUE(text_contains(thesis.err, "a URDF robot in a cell (--cell)")) << thesis.err;
}

}  // namespace
