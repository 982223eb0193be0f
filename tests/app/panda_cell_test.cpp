// A Franka Panda (../shared/robots: 7 joints, STL links, `_sc` capsules as circumscribing
// polytopes, a hand with box fingers on side branches) in a cell with a table and a shelf
// (tests/data/cells/panda-shelf.yaml): a clear path is CLEAR with its certificate ACCEPTED, a
// path into the shelf is a COLLISION of the hand, and a ceiling panel 3 mm above the arm's
// highest point while joint 1 turns is WITHIN_TOLERANCE at 5 mm and CLEAR at 1 mm, with a
// certified clearance within a millimetre below the true 3 mm.
#include <algorithm>
#include <filesystem>
#include <fstream>
#include <limits>
#include <string>

#include <fmt/core.h>
#include <gtest/gtest.h>

#include "app/exit_codes.hpp"
#include "grpvss/cell/load_cell.hpp"
#include "grpvss/kinematics/forward_kinematics.hpp"
#include "grpvss/kinematics/kinematic_chain.hpp"
#include "support/cli_run.hpp"
#include "support/data_paths.hpp"
#include "support/text_files.hpp"

namespace {

using grpvss::test::CliRun;
using grpvss::test::run_cli;

using grpvss::test::kTestCells;

class PandaCell : public ::testing::Test {
 protected:
  void SetUp() override { directory_ = grpvss::test::make_temporary_directory("panda-cell"); }
  void TearDown() override { std::filesystem::remove_all(directory_); }
  std::string directory_;
};

TEST_F(PandaCell, AClearPathIsClearAndItsCertificateIsAccepted) {
  const std::string inputs =
      "--cell " + kTestCells + "panda-shelf.yaml --path " + kTestCells + "panda-clear.txt";
  const CliRun verify = run_cli(directory_, "verify " + inputs + " --certificate c.json");
  ASSERT_EQ(verify.exit_code, grpvss::app::kExitOk) << verify.out << verify.err;
  EXPECT_NE(verify.out.find("verdict: CLEAR\nmode: certified  tolerance: 0.005  steps: 2 "),
            std::string::npos)
      << verify.out;
  // Link 0 is in the clearance list; hulls merged from `_sc` links name the link they came from.
  EXPECT_NE(verify.out.find("\npanda_link0: smallest certified clearance "), std::string::npos)
      << verify.out;
  EXPECT_NE(verify.out.find("panda_link1 hull 1 (panda_link1_sc) / table"), std::string::npos)
      << verify.out;
  const CliRun check = run_cli(directory_, "check-certificate " + inputs + " c.json");
  EXPECT_EQ(check.exit_code, 0) << check.out << check.err;
  EXPECT_NE(check.out.find("ACCEPTED: claim CLEAR"), std::string::npos) << check.out;
}

TEST_F(PandaCell, APathIntoTheShelfIsACollisionOfTheHandWithTheShelf) {
  const std::string inputs =
      "--cell " + kTestCells + "panda-shelf.yaml --path " + kTestCells + "panda-into-shelf.txt";
  const CliRun verify = run_cli(directory_, "verify " + inputs + " --certificate c.json");
  ASSERT_EQ(verify.exit_code, grpvss::app::kExitFinding) << verify.out << verify.err;
  // Step 29 (86 before the step's axis distances, proofs/motion-bound.md#lemma-axis-distance-along-step).
  EXPECT_NE(verify.out.find("first collision at step 29\n"
                            "interference: panda_hand_tcp hull 12 (panda_hand_sc) / shelf, "),
            std::string::npos)
      << verify.out;
  EXPECT_NE(verify.out.find("(panda_leftfinger) / shelf"), std::string::npos) << verify.out;
  EXPECT_EQ(verify.out.find("interference: panda_link"), std::string::npos) << verify.out;
  const CliRun check = run_cli(directory_, "check-certificate " + inputs + " c.json");
  EXPECT_EQ(check.exit_code, 0) << check.out << check.err;
  EXPECT_NE(check.out.find("ACCEPTED: claim COLLISION"), std::string::npos) << check.out;
}

/// The highest z of every robot hull vertex at q, from the model's own placement.
double highest_point_z(const grpvss::RobotModel& robot, const Eigen::VectorXd& q) {
  namespace kin = grpvss::kinematics;
  kin::Workspace workspace(robot);
  kin::forward_kinematics(kin::make_chain(robot), q, workspace);
  kin::place_hull_points(robot, workspace);
  double highest = -std::numeric_limits<double>::infinity();
  for (const auto& link : workspace.hull_points_W) {
    for (const auto& hull : link) {
      for (const Eigen::Vector3d& p : hull) highest = std::max(highest, p.z());
    }
  }
  return highest;
}

// Turning joint 1 about the vertical keeps every height: the panel's gap to the arm's highest
// vertex is the true clearance throughout, 3 mm.
TEST_F(PandaCell, APanelThreeMillimetresAboveTheArmGrazesIt) {
  const grpvss::cell::LoadedCell loaded = grpvss::cell::load_cell(kTestCells + "panda-shelf.yaml");
  Eigen::VectorXd home(7);
  home << 0, -0.785, 0, -2.356, 0, 1.571, 0.785;
  const double panel_bottom = highest_point_z(loaded.robot, home) + 0.003;
  std::string cell = grpvss::test::read_text_file(kTestCells + "panda-shelf.yaml");
  const std::string shared = std::string(GRPVSS_SOURCE_DIR) + "/../shared/robots/franka_panda";
  for (const std::string relative : {"../../../../shared/robots/franka_panda"}) {
    for (std::size_t at = cell.find(relative); at != std::string::npos; at = cell.find(relative)) {
      cell.replace(at, relative.size(), shared);
    }
  }
  // The panel joins the obstacles, right after the shelf.
  const std::size_t after_shelf = cell.find('\n', cell.find("  - {name: shelf")) + 1;
  cell.insert(after_shelf,
              fmt::format("  - {{name: panel, box: [2, 2, 0.02], pose: {{xyz: [0, 0, {:.17g}]}}}}\n",
                          panel_bottom + 0.01));
  std::ofstream(directory_ + "/panel.yaml") << cell;
  std::ofstream(directory_ + "/turn.txt") << "1\n1\n60.,30.\n-45.,30.\n0.,30.\n-135.,30.\n0.,30.\n90.,30.\n45.,30.\n";
  const CliRun five = run_cli(directory_, "verify --cell panel.yaml --path turn.txt --tolerance 0.005");
  EXPECT_EQ(five.exit_code, grpvss::app::kExitWithinTolerance) << five.out << five.err;
  EXPECT_NE(five.out.find("verdict: WITHIN_TOLERANCE"), std::string::npos) << five.out;
  const CliRun one = run_cli(directory_, "verify --cell panel.yaml --path turn.txt --tolerance 0.001");
  ASSERT_EQ(one.exit_code, grpvss::app::kExitOk) << one.out << one.err;
  // The hand (the top) has the smallest certified clearance to the panel: a lower bound of the
  // true 3 mm, and not more than a millimetre below it.
  const std::string hand = "panda_hand_tcp: smallest certified clearance ";
  const std::size_t value = one.out.find(hand);
  ASSERT_NE(value, std::string::npos) << one.out;
  const std::size_t start = value + hand.size();
  const double clearance = std::stod(one.out.substr(start, one.out.find(' ', start) - start));
  EXPECT_NE(one.out.find(" (panel)", start), std::string::npos) << one.out;
  EXPECT_LE(clearance, 0.003) << one.out;
  EXPECT_GE(clearance, 0.002) << one.out;
}

}  // namespace
