/// read_robot_program(): the reader is chosen by the file's extension, ignoring case.

#include "grpvss/io/robot_program_file.hpp"

#include <filesystem>
#include <fstream>
#include <string>

#include <gtest/gtest.h>

#include "support/input_error_expectations.hpp"
#include "support/text_files.hpp"

namespace grpvss::io {
namespace {

using grpvss::testing::expect_input_error;

const std::string kProgramsFolder = std::string(GRPVSS_SOURCE_DIR) + "/data/programs/";

TEST(RobotProgramFile, PicksTheReaderByExtension) {
  const RobotProgram ur = read_robot_program(kProgramsFolder + "ur5e_pick_and_place.script");
  EXPECT_EQ(ur.language, ProgramLanguage::kUrScript);
  EXPECT_EQ(ur.motions.size(), 8u);
  const RobotProgram krl = read_robot_program(kProgramsFolder + "kr_palletize.src");
  EXPECT_EQ(krl.language, ProgramLanguage::kKrl);
  EXPECT_EQ(krl.files.size(), 3u);  // the .src, $config.dat and the .dat beside it
  const RobotProgram rapid = read_robot_program(kProgramsFolder + "irb_glue.mod");
  EXPECT_EQ(rapid.language, ProgramLanguage::kRapid);
  EXPECT_EQ(rapid.motions.size(), 8u);
}

TEST(RobotProgramFile, ExtensionsAreMatchedIgnoringCase) {
  const std::string folder = test::make_temporary_directory("program-extension");
  std::ofstream(folder + "/MOVE.SCRIPT") << "movej([0, 0, 0, 0, 0, 0])\n";
  std::ofstream(folder + "/Main.Prg") << "MODULE m\nPROC main()\nENDPROC\nENDMODULE\n";
  EXPECT_EQ(read_robot_program(folder + "/MOVE.SCRIPT").language, ProgramLanguage::kUrScript);
  EXPECT_EQ(read_robot_program(folder + "/Main.Prg").language, ProgramLanguage::kRapid);
  std::filesystem::remove_all(folder);
}

TEST(RobotProgramFile, RejectsOtherFilesNamingWhatIsExpected) {
  expect_input_error([] { read_robot_program("cell.urp"); }, "cell.urp", 0,
                     "cell.urp:0: expected a URScript file (.script): a .urp is a compressed PolyScope program; "
                     "save it as a script on the robot, found a .urp file");
  expect_input_error([] { read_robot_program("pick.dat"); }, "pick.dat", 0,
                     "pick.dat:0: expected the .src of a KUKA program (its .dat is read with it), found a .dat file");
  expect_input_error([] { read_robot_program("path.txt"); }, "path.txt", 0,
                     "path.txt:0: expected a robot program: .script (URScript), .src (KUKA KRL), .mod, .modx, .prg, "
                     ".sys or .sysx (ABB RAPID), found '.txt'");
  expect_input_error([] { read_robot_program("program"); }, "program", 0,
                     "program:0: expected a robot program: .script (URScript), .src (KUKA KRL), .mod, .modx, .prg, "
                     ".sys or .sysx (ABB RAPID), found no extension");
}

TEST(RobotProgramFile, AMissingFileIsNamed) {
  try {
    read_robot_program("/nonexistent/pick.src");
    ADD_FAILURE() << "no InputError";
  } catch (const InputError& error) {
    EXPECT_EQ(error.file(), "/nonexistent/pick.src");
    EXPECT_EQ(error.line(), 0);
    EXPECT_EQ(error.expected(), "a readable file");
  }
}

}  // namespace
}  // namespace grpvss::io
