// `grpvss trajectory --cp-spacing` defaults (issue 19, point 5): the cell's motion.cp_spacing,
// else 0.5 in converted to the model's length unit (0.5 for thesis files, 0.0127 m for a URDF
// robot, 12.7 for a thesis robot in a cell in mm); the text prints it with the digits it needs
// and --help names the unit.
#include <filesystem>
#include <fstream>
#include <string>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "support/cli_run.hpp"
#include "support/data_paths.hpp"
#include "support/text_files.hpp"

namespace {

using grpvss::test::CliRun;
using grpvss::test::run_cli;

using grpvss::test::kSourceDir;
using grpvss::test::kTestCells;
using grpvss::test::kIbm7545Data;

class TrajectoryCpSpacing : public ::testing::Test {
 protected:
  void SetUp() override { directory_ = grpvss::test::make_temporary_directory("cp-spacing"); }
  void TearDown() override { std::filesystem::remove_all(directory_); }
  CliRun trajectory(const std::string& arguments) const {
    return run_cli(directory_, "trajectory " + arguments);
  }
  double json_spacing(const std::string& arguments) const {
    const CliRun run = trajectory(arguments + " --json");
    EXPECT_EQ(run.exit_code, 0) << run.out << run.err;
    return nlohmann::json::parse(run.out).at("cp_spacing").get<double>();
  }
  std::string directory_;
};

TEST_F(TrajectoryCpSpacing, AUrdfRobotWithoutACellSpacingGetsHalfAnInchInMetres) {
  const std::string inputs = "--cell " + kTestCells + "ur5e-post.yaml --path " + kTestCells + "ur5e-clear.txt";
  EXPECT_EQ(json_spacing(inputs), 0.5 * 0.0254);
  const CliRun text = trajectory(inputs);
  ASSERT_EQ(text.exit_code, 0) << text.out << text.err;
  EXPECT_NE(text.out.find("CP SEGMENTS: NOMINAL SPEED 1.00 PER S, SAMPLE SPACING 0.0127\n"), std::string::npos)
      << text.out;
}

TEST_F(TrajectoryCpSpacing, TheCellsMotionCpSpacingIsTheDefault) {
  // ur5e-fixture.yaml: motion: {cp_speed: 0.25, cp_spacing: 0.01}, units m.
  const std::string inputs = "--cell " + kTestCells + "ur5e-fixture.yaml --path " + kTestCells + "ur5e-clear.txt";
  EXPECT_EQ(json_spacing(inputs), 0.01);
  // A thesis robot in a cell in inches with its own spacing.
  std::ofstream(directory_ + "/in.yaml") << "units: in\nrobot:\n  thesis: " << kIbm7545Data
                                          << "robot.txt\nmotion: {cp_spacing: 0.25}\n";
  std::ofstream(directory_ + "/p.txt") << "1\n1\n10.,30.\n10.,30.\n1.,1.\n10.,30.\n";
  EXPECT_EQ(json_spacing("--cell in.yaml --path p.txt"), 0.25);
}

TEST_F(TrajectoryCpSpacing, TheCommandLineOverridesTheDefault) {
  const std::string inputs = "--cell " + kTestCells + "ur5e-fixture.yaml --path " + kTestCells + "ur5e-clear.txt";
  EXPECT_EQ(json_spacing(inputs + " --cp-spacing 0.002"), 0.002);
}

TEST_F(TrajectoryCpSpacing, AThesisRobotInACellInMillimetresGetsHalfAnInchInMillimetres) {
  std::ofstream(directory_ + "/mm.yaml") << "units: mm\nrobot:\n  thesis: " << kIbm7545Data << "robot.txt\n";
  std::ofstream(directory_ + "/p.txt") << "1\n1\n10.,30.\n10.,30.\n1.,1.\n10.,30.\n";
  EXPECT_EQ(json_spacing("--cell mm.yaml --path p.txt"), 0.5 * 25.4);
  const CliRun text = trajectory("--cell mm.yaml --path p.txt");
  EXPECT_NE(text.out.find("SAMPLE SPACING 12.70\n"), std::string::npos) << text.out;
}

TEST_F(TrajectoryCpSpacing, ThesisFilesKeepHalfAUnitAndTheirText) {
  const std::string inputs = "--robot " + kIbm7545Data + "robot.txt --path " + kIbm7545Data + "path.txt";
  EXPECT_EQ(json_spacing(inputs), 0.5);
  const CliRun text = trajectory(inputs);
  EXPECT_NE(text.out.find("CP SEGMENTS: NOMINAL SPEED 1.00 PER S, SAMPLE SPACING 0.50\n"), std::string::npos)
      << text.out;
}

TEST_F(TrajectoryCpSpacing, HelpNamesTheUnitAndTheDefaults) {
  const CliRun help = trajectory("--help");
  ASSERT_EQ(help.exit_code, 0) << help.err;
  EXPECT_NE(help.out.find("in the model's length unit"), std::string::npos) << help.out;
  EXPECT_NE(help.out.find("0.0127 m for a URDF robot"), std::string::npos) << help.out;
}

}  // namespace
