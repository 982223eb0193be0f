// Names in every output of a cell's run (the six-axis demo's collision path, data/sixaxis):
// the certificate lists the links' and obstacles' names and the checker rejects a certificate
// whose names differ from the inputs'; the thesis output file names each interference point's
// pair (golden file); the JSON report validates against docs/report.schema.json; the SVG
// picture titles links and obstacles. Thesis files get none of it.
#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <string>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "app/exit_codes.hpp"
#include "support/cli_run.hpp"
#include "support/data_paths.hpp"
#include "support/json_structure_check.hpp"
#include "support/text_files.hpp"

namespace {

using grpvss::test::CliRun;
using grpvss::test::run_cli;
using nlohmann::json;

using grpvss::test::kSourceDir;
const std::string kSixAxisDataDir = kSourceDir + "/data/sixaxis/";

class CellNamesCli : public ::testing::Test {
 protected:
  void SetUp() override {
    directory_ = std::filesystem::temp_directory_path() /
                 ("grpvss-cell-names-" + std::to_string(::getpid()));
    std::filesystem::create_directories(directory_);
    // The path file copied beside the outputs, so that the thesis file's label is its name.
    std::filesystem::copy_file(kSixAxisDataDir + "path-collision.txt", directory_ / "path-collision.txt");
  }
  void TearDown() override { std::filesystem::remove_all(directory_); }
  std::string dir() const { return directory_.string(); }
  std::string read(const std::string& name) const {
    return grpvss::test::read_text_file(dir() + "/" + name);
  }
  std::filesystem::path directory_;
};

const std::string kCellInputs = "--cell " + kSixAxisDataDir + "cell.yaml --path path-collision.txt";

TEST_F(CellNamesCli, TheCertificateNamesTheCellsLinksAndObstaclesAndTheCheckerComparesThem) {
  const CliRun verify = run_cli(dir(), "verify " + kCellInputs + " --certificate c.json --quiet");
  ASSERT_EQ(verify.exit_code, grpvss::app::kExitFinding) << verify.out << verify.err;
  const json certificate = json::parse(read("c.json"));
  ASSERT_TRUE(certificate.contains("names"));
  // Link i is the URDF's i-th link of the chain (the last, tool0, carries link_6's hull).
  EXPECT_EQ(certificate["names"]["links"],
            json::parse(R"(["base_link", "link_1", "link_2", "link_3", "link_4", "link_5", "tool0"])"))
      << certificate["names"].dump();
  // One label per obstacle hull: the U-shaped fixture is three convex pieces.
  EXPECT_EQ(certificate["names"]["obstacles"],
            json::parse(R"(["pedestal", "table", "fixture piece 0", "fixture piece 1",
                            "fixture piece 2", "post"])"));
  const CliRun check = run_cli(dir(), "check-certificate " + kCellInputs + " c.json");
  EXPECT_EQ(check.exit_code, 0) << check.out << check.err;

  // The names are not trusted: a renamed obstacle is rejected, as is a certificate without them.
  json renamed = certificate;
  renamed["names"]["obstacles"].back() = "pole";
  std::ofstream(dir() + "/renamed.json") << renamed.dump(1);
  const CliRun rejected = run_cli(dir(), "check-certificate " + kCellInputs + " renamed.json");
  EXPECT_EQ(rejected.exit_code, 1) << rejected.out << rejected.err;
  EXPECT_NE(rejected.out.find("the certificate's link or obstacle names differ from the inputs'"),
            std::string::npos)
      << rejected.out;
  json unnamed = certificate;
  unnamed.erase("names");
  std::ofstream(dir() + "/unnamed.json") << unnamed.dump(1);
  EXPECT_EQ(run_cli(dir(), "check-certificate " + kCellInputs + " unnamed.json").exit_code, 1);
}

TEST_F(CellNamesCli, ThesisFilesCertificatesHaveNoNames) {
  const std::string ibm = kSourceDir + "/data/ibm7545/";
  const CliRun verify =
      run_cli(dir(), "verify --robot " + ibm + "robot.txt --env " + ibm + "environment.txt --path " +
                         ibm + "path.txt --tolerance 0.5 --certificate c.json --quiet");
  ASSERT_EQ(verify.exit_code, grpvss::app::kExitFinding) << verify.out << verify.err;
  EXPECT_FALSE(json::parse(read("c.json")).contains("names"));
}

TEST_F(CellNamesCli, TheThesisOutputFileNamesEachInterferencePointsPair) {
  const CliRun verify = run_cli(dir(), "verify " + kCellInputs + " --out out.txt --quiet");
  ASSERT_EQ(verify.exit_code, grpvss::app::kExitFinding) << verify.out << verify.err;
  EXPECT_EQ(read("out.txt"),
            grpvss::test::read_text_file(kSourceDir + "/tests/app/golden/sixaxis-path-collision.out"));
}

TEST_F(CellNamesCli, TheJsonReportValidatesAndTheSvgTitlesLinksAndObstacles) {
  const CliRun verify = run_cli(dir(), "verify " + kCellInputs + " --json r.json --quiet");
  ASSERT_EQ(verify.exit_code, grpvss::app::kExitFinding) << verify.out << verify.err;
  const json report = json::parse(read("r.json"));
  const json schema = json::parse(grpvss::test::read_text_file(kSourceDir + "/docs/report.schema.json"));
  EXPECT_EQ(grpvss::test::check_json_structure(report, schema), std::vector<std::string>{});
  ASSERT_TRUE(report["collision_step"].is_number_integer());
  const int step = report["collision_step"].get<int>();
  const CliRun render = run_cli(
      dir(), "render r.json --step " + std::to_string(step) + " --svg s.svg");
  ASSERT_EQ(render.exit_code, 0) << render.out << render.err;
  const std::string svg = read("s.svg");
  EXPECT_NE(svg.find("<title>link_4 (link 4), hull 0</title></path>"), std::string::npos);
  EXPECT_NE(svg.find("<title>base_link (link 0), hull 0</title></path>"), std::string::npos);
  EXPECT_NE(svg.find("<title>post (obstacle 5)</title></path>"), std::string::npos);
  EXPECT_NE(svg.find("<title>fixture piece 2 (obstacle 4)</title></path>"), std::string::npos);
  // The last link is tool0; its hull is link_6's collision geometry.
  EXPECT_NE(svg.find("<title>tool0 (link 6), hull 0 (link_6)</title></path>"), std::string::npos);
  EXPECT_NE(svg.find("<title>link_4 hull 0 / post</title></polygon>"), std::string::npos) << svg;
  // Step 0, the start configuration, is drawn too.
  EXPECT_EQ(run_cli(dir(), "render r.json --step 0 --svg s0.svg").exit_code, 0);
  EXPECT_NE(read("s0.svg").find("step 0 - t = 0.000 s"), std::string::npos);
}

}  // namespace
