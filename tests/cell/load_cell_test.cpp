// The cell stage (src/cell): a cell file made into the model. The six-axis demo cell of data/
// and small cells written by the tests: names, pieces, base pose, allowed contacts, units and
// the errors of what the loader refuses.
#include <algorithm>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <limits>
#include <string>
#include <vector>

#include <unistd.h>

#include <gtest/gtest.h>

#include "grpvss/cell/load_cell.hpp"
#include "grpvss/io/cell_file.hpp"
#include "grpvss/common/input_error.hpp"
#include "grpvss/kinematics/forward_kinematics.hpp"
#include "grpvss/kinematics/kinematic_chain.hpp"
#include "cell/cell_pose.hpp"

namespace {

const std::string kSixAxisDir = std::string(GRPVSS_SOURCE_DIR) + "/data/sixaxis/";

// A cell around the six-axis robot, written beside its URDF (relative mesh paths keep working).
class LoadCell : public ::testing::Test {
 protected:
  std::string write(const std::string& obstacles_and_rest, const std::string& robot_extra = "") {
    file_ = std::filesystem::temp_directory_path() /
            ("grpvss-load-cell-" + std::to_string(::getpid()) + ".yaml");
    std::ofstream(file_) << "units: m\nrobot:\n  urdf: " << kSixAxisDir << "sixaxis.urdf\n"
                         << robot_extra << obstacles_and_rest;
    return file_.string();
  }
  void TearDown() override { std::filesystem::remove(file_); }
  std::filesystem::path file_;
};

TEST_F(LoadCell, TheDemoCellHasNamedLinksNamedPiecesAndItsAllowedContact) {
  const grpvss::cell::LoadedCell cell = grpvss::cell::load_cell(kSixAxisDir + "cell.yaml");
  ASSERT_EQ(cell.robot.joint_count(), 6);
  EXPECT_EQ(cell.robot.links[0].name, "base_link");
  EXPECT_EQ(cell.robot.links[4].name, "link_4");
  EXPECT_EQ(cell.robot.links[6].name, "tool0");  // frame 6 is the tip
  EXPECT_EQ(cell.robot.joints[0].name, "joint_1");
  // pedestal, table, the fixture's exact pieces, post: the U needs at least 2 convex pieces.
  const auto& names = cell.environment.names;
  ASSERT_GE(names.size(), 5u);
  EXPECT_EQ(names.front(), "pedestal");
  EXPECT_EQ(names.back(), "post");
  const auto pieces = std::count(names.begin(), names.end(), "fixture");
  EXPECT_GE(pieces, 2);
  EXPECT_EQ(grpvss::obstacle_label(cell.environment, 2), "fixture piece 0");
  ASSERT_EQ(cell.environment.allowed_contacts.size(), 1u);
  EXPECT_EQ(cell.environment.allowed_contacts[0], (grpvss::AllowedContactPair{0, 0, 0}));
  EXPECT_DOUBLE_EQ(cell.tolerance, 0.005);
  EXPECT_EQ(cell.model_unit, grpvss::LengthUnit::kMetre);
}

TEST_F(LoadCell, TheBasePoseMovesFrameZeroAndLinkZerosHullsIntoTheWorld) {
  const std::string file = write("obstacles:\n  - {name: far, box: [0.1, 0.1, 0.1], pose: {xyz: [9, 9, 9]}}\n",
                                 "  base: {xyz: [1, 2, 0.5], rpy: [0, 0, 1.5707963267948966]}\n");
  const grpvss::cell::LoadedCell cell = grpvss::cell::load_cell(file);
  // base_link's box spans x, y in [-0.15, 0.15], z in [0, 0.2] (float32 in the STL: within
  // 1e-8 of those decimals): in the world, around (1, 2, 0.5).
  Eigen::Vector3d lo = Eigen::Vector3d::Constant(1e9), hi = -lo;
  for (const Eigen::Vector3d& p : cell.robot.links[0].hulls[0].points) {
    lo = lo.cwiseMin(p);
    hi = hi.cwiseMax(p);
  }
  EXPECT_NEAR(lo.x(), 0.85, 1e-8);
  EXPECT_NEAR(hi.y(), 2.15, 1e-8);
  EXPECT_NEAR(lo.z(), 0.5, 1e-12);  // z = 0 is exact in float32
  EXPECT_NEAR(hi.z(), 0.7, 1e-8);
  // Joint 1 sits 0.2 m above the base, its frame turned by the base's 90 degrees.
  const grpvss::kinematics::KinematicChain chain = grpvss::kinematics::make_chain(cell.robot);
  grpvss::kinematics::Workspace workspace(cell.robot);
  grpvss::kinematics::forward_kinematics(chain, Eigen::VectorXd::Zero(6), workspace);
  EXPECT_TRUE(workspace.X_WL[1].translation().isApprox(Eigen::Vector3d(1, 2, 0.7), 1e-12));
  // The tool: x of the flange at home points along world +y (the base turned by 90 degrees).
  const Eigen::Vector3d tool_W = workspace.X_WL[6].translation();
  EXPECT_NEAR(tool_W.x(), 1.0, 1e-12);
  EXPECT_NEAR(tool_W.y(), 2.0 + 0.025 + 0.42 + 0.08 + 0.02, 1e-12);
  EXPECT_NEAR(tool_W.z(), 0.5 + 0.2 + 0.2 + 0.455 + 0.035, 1e-12);
  EXPECT_GT(cell.robot.hull_point_error, 0.0);
}

TEST_F(LoadCell, AnUnknownAllowedContactNameIsAnErrorNamingTheLine) {
  const std::string file =
      write("obstacles:\n  - {name: table, box: [1, 1, 0.1], pose: {xyz: [1, 0, 0]}}\n"
            "allowed_contacts:\n  - [link_9, table]\n");
  try {
    (void)grpvss::cell::load_cell(file);
    FAIL() << "loaded";
  } catch (const grpvss::InputError& error) {
    EXPECT_EQ(error.file(), file);
    EXPECT_EQ(error.line(), 7);
    EXPECT_NE(std::string(error.what()).find("a link or obstacle name of the cell"),
              std::string::npos)
        << error.what();
    EXPECT_NE(std::string(error.what()).find("'link_9'"), std::string::npos) << error.what();
  }
}

TEST_F(LoadCell, AQuaternionPosePlacesAnObstacleAsItsRpyTwin) {
  // A half-turn of 0.6 rad about z: quaternion (cos 0.3, 0, 0, sin 0.3) and rpy (0, 0, 0.6).
  const std::string file = write(
      "obstacles:\n"
      "  - {name: q, box: [0.3, 0.2, 0.1], pose: {xyz: [1, 0.5, 0], quaternion: {w: "
      "0.955336489125606, x: 0, y: 0, z: 0.29552020666133955}}}\n"
      "  - {name: r, box: [0.3, 0.2, 0.1], pose: {xyz: [1, 0.5, 0], rpy: [0, 0, 0.6]}}\n");
  const grpvss::cell::LoadedCell cell = grpvss::cell::load_cell(file);
  ASSERT_EQ(cell.environment.obstacles.size(), 2u);
  const auto& by_quaternion = cell.environment.obstacles[0].points;
  const auto& by_rpy = cell.environment.obstacles[1].points;
  ASSERT_EQ(by_quaternion.size(), by_rpy.size());
  for (std::size_t i = 0; i < by_rpy.size(); ++i) {
    EXPECT_LE((by_quaternion[i] - by_rpy[i]).norm(), 1e-15) << "corner " << i;
  }
  EXPECT_GT(cell.environment.point_error, 0.0);
  EXPECT_LT(cell.environment.point_error, 1e-14);
}

// A shape placed several times is built once per cell (cell_environment.cpp): each placement
// has exactly the pieces a cell with that obstacle alone gives, and its own named warnings.
TEST_F(LoadCell, ARepeatedShapeGivesEachPlacementItsOwnPiecesAndWarnings) {
  const std::string fixture = "mesh: " + kSixAxisDir + "meshes/u_fixture.stl, decompose: hull";
  const std::string second = "  - {name: b, " + fixture + ", pose: {xyz: [0.5, 0, 0.2], rpy: [0, 0, 1]}}\n";
  const std::string post = "  - {name: p2, cylinder: {radius: 0.04, length: 1.2}, pose: {xyz: [1, 1, 0]}}\n";
  const grpvss::cell::LoadedCell both = grpvss::cell::load_cell(write(
      "obstacles:\n  - {name: a, " + fixture + ", pose: {xyz: [1, 0, 0]}}\n" + second +
      "  - {name: p1, cylinder: {radius: 0.04, length: 1.2}}\n" + post));
  const grpvss::cell::LoadedCell alone = grpvss::cell::load_cell(write("obstacles:\n" + second + post));
  ASSERT_EQ(both.environment.names, (std::vector<std::string>{"a", "b", "p1", "p2"}));
  ASSERT_EQ(alone.environment.names, (std::vector<std::string>{"b", "p2"}));
  EXPECT_EQ(both.environment.obstacles[1].points, alone.environment.obstacles[0].points);
  EXPECT_EQ(both.environment.obstacles[3].points, alone.environment.obstacles[1].points);
  EXPECT_NE(both.environment.obstacles[0].points, both.environment.obstacles[1].points);
  // The U's hull covers more than the U: each placement warns under its own name.
  std::vector<std::string> warned;
  for (const grpvss::io::InputWarning& warning : both.warnings) {
    if (warning.text.find(": decompose: hull covers") != std::string::npos) {
      warned.push_back(warning.text.substr(0, warning.text.find(':')));
    }
  }
  EXPECT_EQ(warned, (std::vector<std::string>{"a", "b"}));
}

// A description built without the reader (the API overload) may hold a size that is not
// finite: it must still be refused, not matched to a kept shape of the same kind.
TEST_F(LoadCell, ANonFiniteSizeIsRefusedEvenAfterAKeptShapeOfItsKind) {
  grpvss::io::CellReadResult read = grpvss::io::read_cell_file(write(
      "obstacles:\n  - {name: a, box: [0.3, 0.2, 0.1]}\n  - {name: b, box: [0.3, 0.2, 0.1]}\n"));
  read.cell.obstacles[1].box_size.x() = std::numeric_limits<double>::quiet_NaN();
  try {
    grpvss::cell::load_cell(read.cell, read.warnings);
    ADD_FAILURE() << "a NaN box size was accepted";
  } catch (const grpvss::InputError& error) {
    EXPECT_NE(std::string(error.what()).find("b: "), std::string::npos) << error.what();
  }
}

TEST(QuaternionRotation, ItsBoundIsTheDecimalsFourUlpsPlusAFewUlps) {
  // Not normalised as written: (1, 2, 3, 4) / sqrt(30).
  const grpvss::kinematics::BoundedFactor factor =
      grpvss::cell::quaternion_rotation(Eigen::Vector4d(1, 2, 3, 4));
  const Eigen::Matrix3d expected =
      Eigen::Quaterniond(1 / std::sqrt(30.0), 2 / std::sqrt(30.0), 3 / std::sqrt(30.0),
                         4 / std::sqrt(30.0))
          .toRotationMatrix();
  EXPECT_LE((factor.X.linear() - expected).norm(), 1e-15);
  // 4u for the decimals plus the stored matrix's own (tiny, nonzero) distance.
  EXPECT_GT(factor.delta, 4 * std::numeric_limits<double>::epsilon() / 2);
  EXPECT_LT(factor.delta, 64 * std::numeric_limits<double>::epsilon());
}

TEST_F(LoadCell, AMillimetreCellAroundAUrdfRobotIsConvertedToMetres) {
  const std::string file =
      write("obstacles:\n  - {name: block, box: [100, 200, 300], pose: {xyz: [1000, 0, 0]}}\n"
            "tolerance: 5\n");
  std::string text;
  {
    std::ifstream in(file);
    text.assign(std::istreambuf_iterator<char>(in), {});
  }
  std::ofstream(file) << "units: mm\n" << text.substr(text.find('\n') + 1);
  const grpvss::cell::LoadedCell cell = grpvss::cell::load_cell(file);
  EXPECT_EQ(cell.model_unit, grpvss::LengthUnit::kMetre);
  EXPECT_DOUBLE_EQ(cell.model_units_per_cell_unit, 0.001);
  EXPECT_GE(cell.tolerance, 0.005);  // rounded up
  EXPECT_LE(cell.tolerance, 0.005 * (1 + 1e-15));
  Eigen::Vector3d hi = Eigen::Vector3d::Constant(-1e9);
  for (const Eigen::Vector3d& p : cell.environment.obstacles[0].points) hi = hi.cwiseMax(p);
  EXPECT_NEAR(hi.x(), 1.05, 1e-12);
  EXPECT_NEAR(hi.z(), 0.15, 1e-12);
  EXPECT_GT(cell.environment.point_error, 0.0);  // the conversion rounds
}

}  // namespace

// A URDF's `<limit velocity>` is the joint's speed limit; 0 means none (the URDF convention).
TEST(LoadCellVelocity, UrdfVelocityLimitsBecomeTheJointsMaxVelocityAndZeroMeansUnlimited) {
  const grpvss::cell::LoadedCell demo = grpvss::cell::load_cell(kSixAxisDir + "cell.yaml");
  for (const grpvss::Joint& joint : demo.robot.joints) EXPECT_EQ(joint.max_velocity, 6.28);
  // The same robot with joint_2's velocity 0, beside a link to the demo's meshes.
  const std::filesystem::path folder = std::filesystem::temp_directory_path() /
                                       ("grpvss-velocity-" + std::to_string(::getpid()));
  std::filesystem::create_directories(folder);
  std::filesystem::create_directory_symlink(kSixAxisDir + "meshes", folder / "meshes");
  std::ifstream in(kSixAxisDir + "sixaxis.urdf");
  std::string urdf((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  const std::string joint_2 = "upper=\"0.785\" effort=\"100\" velocity=\"6.28\"";
  ASSERT_NE(urdf.find(joint_2), std::string::npos);
  urdf.replace(urdf.find(joint_2), joint_2.size(), "upper=\"0.785\" effort=\"100\" velocity=\"0\"");
  std::ofstream(folder / "robot.urdf") << urdf;
  std::ofstream(folder / "cell.yaml")
      << "units: m\nrobot:\n  urdf: robot.urdf\nobstacles:\n"
         "  - {name: far, box: [0.1, 0.1, 0.1], pose: {xyz: [9, 9, 9]}}\n";
  const grpvss::cell::LoadedCell cell = grpvss::cell::load_cell((folder / "cell.yaml").string());
  std::filesystem::remove_all(folder);
  EXPECT_EQ(cell.robot.joints[0].max_velocity, 6.28);
  EXPECT_EQ(cell.robot.joints[1].max_velocity, std::numeric_limits<double>::infinity());
}
