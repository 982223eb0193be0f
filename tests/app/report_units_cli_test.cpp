// The JSON report's `units.length` (issue 19, point 5): the model's length unit when a cell is
// used ("m" for a URDF robot, whatever the cell's units, since its lengths are converted to
// metres; the cell's unit for a thesis robot), "unit of the input files" for thesis files; the
// report validates against docs/report.schema.json either way.
#include <filesystem>
#include <fstream>
#include <string>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "support/cli_run.hpp"
#include "support/data_paths.hpp"
#include "support/json_structure_check.hpp"
#include "support/text_files.hpp"

namespace {

using grpvss::test::CliRun;
using grpvss::test::run_cli;
using nlohmann::json;

using grpvss::test::kSourceDir;
using grpvss::test::kTestCells;
using grpvss::test::kIbm7545Data;

class ReportUnits : public ::testing::Test {
 protected:
  void SetUp() override { directory_ = grpvss::test::make_temporary_directory("report-units"); }
  void TearDown() override { std::filesystem::remove_all(directory_); }
  // units.length of `grpvss verify <inputs> --json r.json`, after validating the report.
  std::string length_unit(const std::string& inputs) const {
    const CliRun verify = run_cli(directory_, "verify " + inputs + " --json r.json --force --quiet");
    EXPECT_NE(verify.exit_code, 2) << verify.out << verify.err;
    const json report = json::parse(grpvss::test::read_text_file(directory_ + "/r.json"));
    const json schema = json::parse(grpvss::test::read_text_file(kSourceDir + "/docs/report.schema.json"));
    EXPECT_EQ(grpvss::test::check_json_structure(report, schema), std::vector<std::string>{});
    return report.at("units").at("length").get<std::string>();
  }
  std::string directory_;
};

TEST_F(ReportUnits, AUrdfCellInMetresSaysMetres) {
  EXPECT_EQ(length_unit("--cell " + kTestCells + "ur5e-post.yaml --path " + kTestCells + "ur5e-clear.txt"), "m");
}

TEST_F(ReportUnits, AUrdfRobotInACellInMillimetresIsStillReportedInMetres) {
  const std::string robots = kSourceDir + "/../shared/robots/ur5e";
  std::ofstream(directory_ + "/mm.yaml")
      << "units: mm\nrobot:\n  urdf: " << robots << "/ur5e.urdf\n  package_paths: [" << robots
      << "]\n  tip: tool0\n  base: {xyz: [0, 0, 800]}\n  home: [0, -1.5708, 1.5708, 0, 0, 0]\n"
      << "obstacles:\n  - {name: post, box: [100, 100, 100], pose: {xyz: [2000, 0, 0]}}\ntolerance: 5\n";
  EXPECT_EQ(length_unit("--cell mm.yaml --path " + kTestCells + "ur5e-clear.txt"), "m");
}

TEST_F(ReportUnits, AThesisRobotInACellTakesTheCellsUnit) {
  std::ofstream(directory_ + "/p.txt") << "1\n1\n10.,30.\n10.,30.\n1.,1.\n10.,30.\n";
  for (const std::string unit : {"in", "mm"}) {
    std::ofstream(directory_ + "/" + unit + ".yaml")
        << "units: " << unit << "\nrobot:\n  thesis: " << kIbm7545Data << "robot.txt\n"
        << "obstacles:\n  - {name: far, box: [1, 1, 1], pose: {xyz: [900, 900, 900]}}\ntolerance: 0.5\n";
    EXPECT_EQ(length_unit("--cell " + unit + ".yaml --path p.txt"), unit);
  }
}

TEST_F(ReportUnits, ThesisFilesKeepTheirWording) {
  EXPECT_EQ(length_unit("--robot " + kIbm7545Data + "robot.txt --env " + kIbm7545Data + "environment.txt --path " + kIbm7545Data +
                        "path.txt --tolerance 0.5"),
            "unit of the input files");
}

}  // namespace
