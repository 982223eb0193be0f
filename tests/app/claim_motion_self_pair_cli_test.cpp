// `grpvss verify` on the Panda's grazing fold (tests/data/cells/panda-self.yaml,
// panda-grazing-fold.txt; tests/certify/claim_motion_self_pair_test.cpp for the verifier): the
// summary names both links of the self pair that keeps less than the tolerance along the
// motion, and the JSON report's tolerance_shortfall carries other_link, validating against
// docs/report.schema.json. docs/verification.md#claim
#include <unistd.h>

#include <filesystem>
#include <string>
#include <vector>

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
using grpvss::test::kTestCells;

class ClaimMotionSelfPairCli : public ::testing::Test {
 protected:
  void SetUp() override {
    directory_ = (std::filesystem::temp_directory_path() /
                  ("grpvss-claim-self-" + std::to_string(::getpid())))
                     .string();
    std::filesystem::create_directories(directory_);
  }
  void TearDown() override { std::filesystem::remove_all(directory_); }
  std::string directory_;
};

TEST_F(ClaimMotionSelfPairCli, TheSummaryAndTheJsonNameBothLinksOfThePair) {
  const CliRun verify = run_cli(directory_, "verify --cell " + kTestCells + "panda-self.yaml --path " +
                                                kTestCells + "panda-grazing-fold.txt --json r.json");
  ASSERT_EQ(verify.exit_code, grpvss::app::kExitWithinTolerance) << verify.out << verify.err;
  EXPECT_NE(verify.out.find("verdict: WITHIN_TOLERANCE\n"), std::string::npos) << verify.out;
  EXPECT_NE(verify.out.find("claim motion not met: panda_link2 / panda_hand_tcp keeps only 0.0049 "
                            "along steps 29-30 (tolerance 0.005)"),
            std::string::npos)
      << verify.out;
  const json report = json::parse(grpvss::test::read_text_file(directory_ + "/r.json"));
  const json schema = json::parse(grpvss::test::read_text_file(kSourceDir + "/docs/report.schema.json"));
  EXPECT_EQ(grpvss::test::check_json_structure(report, schema), std::vector<std::string>{});
  const json& shortfall = report.at("tolerance_shortfall");
  EXPECT_EQ(shortfall.at("step"), 30);
  EXPECT_EQ(shortfall.at("link"), 2);
  EXPECT_EQ(shortfall.at("other_link"), 7);
  EXPECT_TRUE(shortfall.at("obstacle").is_null());
  EXPECT_LT(shortfall.at("motion_clearance").get<double>(), 0.005);

  const CliRun steps = run_cli(directory_, "verify --cell " + kTestCells + "panda-self.yaml --path " +
                                               kTestCells + "panda-grazing-fold.txt --claim steps");
  EXPECT_EQ(steps.exit_code, grpvss::app::kExitOk) << steps.out << steps.err;
  EXPECT_NE(steps.out.find("verdict: CLEAR\n"), std::string::npos) << steps.out;
}

}  // namespace
