#include "grpvss/kinematics/ik_plugin_loader.hpp"

#include <random>
#include <string>

#include <gtest/gtest.h>

#include "grpvss/common/input_error.hpp"
#include "grpvss/kinematics/forward_kinematics.hpp"
#include "grpvss/kinematics/ibm7545_ik.hpp"
#include "grpvss/kinematics/kinematic_chain.hpp"
#include "support/angles.hpp"
#include "support/pose_error.hpp"
#include "support/random_configurations.hpp"
#include "support/sample_robots.hpp"

namespace grpvss::kinematics {
namespace {

using grpvss::test::kPi;
using grpvss::test::deg;

TEST(IkPluginLoader, SolvesThesisTargetsLikeTheClosedForm) {
  const RobotModel model = test::make_ibm7545_model();
  const auto plugin = load_ik_plugin(GRPVSS_IK_PLUGIN_GOOD, model);
  EXPECT_EQ(plugin->name(), "IBM 7545 example plug-in");
  const IkSolution solution =
      plugin->solve(test::scara_target(0, 20, 8, deg(-30)), Eigen::VectorXd::Zero(4));
  ASSERT_EQ(solution.status, IkStatus::kSolved);
  EXPECT_NEAR(solution.q[0] * 180 / kPi, 61.16, 0.01);
  EXPECT_NEAR(solution.q[1] * 180 / kPi, 79.90, 0.01);
  EXPECT_NEAR(solution.q[2], 2.45, 0.01);
  EXPECT_NEAR(solution.q[3] * 180 / kPi, 171.06, 0.01);
  EXPECT_EQ(plugin->solve(test::scara_target(15, 2, 8, deg(-90)), Eigen::VectorXd::Zero(4)).status,
            IkStatus::kOutOfWorkspace);
}

// The row-major hand-over is right: random poses round-trip and agree with the built-in solver.
TEST(IkPluginLoader, AgreesWithBuiltInClosedFormOnRandomPoses) {
  const RobotModel model = test::make_ibm7545_model();
  const KinematicChain chain = make_chain(model);
  const auto plugin = load_ik_plugin(GRPVSS_IK_PLUGIN_GOOD, model);
  const auto built_in = make_ibm7545_ik(model);
  std::mt19937_64 generator(51);
  for (int trial = 0; trial < 200; ++trial) {
    const Eigen::VectorXd q_true = test::random_configuration(model, generator);
    const Eigen::Isometry3d X_target = end_effector_pose(chain, q_true);
    const IkSolution a = plugin->solve(X_target, q_true);
    const IkSolution b = built_in->solve(X_target, q_true);
    ASSERT_EQ(a.status, IkStatus::kSolved);
    ASSERT_EQ(b.status, IkStatus::kSolved);
    EXPECT_LT((a.q - b.q).norm(), 1e-9);
    EXPECT_LT(test::position_error(end_effector_pose(chain, a.q), X_target), 1e-9);
  }
}

void expect_input_error(const std::string& path, const std::string& expected_fragment) {
  try {
    load_ik_plugin(path, test::make_ibm7545_model());
    FAIL() << "no InputError for " << path;
  } catch (const InputError& error) {
    EXPECT_EQ(error.file(), path);
    EXPECT_EQ(error.line(), 0);
    EXPECT_NE(error.expected().find(expected_fragment), std::string::npos) << error.what();
  }
}

TEST(IkPluginLoader, MissingFileIsInputError) {
  expect_input_error("/nonexistent/libnothing.so", "loadable IK plug-in");
}

TEST(IkPluginLoader, NonLibraryFileIsInputError) {
  expect_input_error(std::string(GRPVSS_SOURCE_DIR) + "/data/ibm7545/robot.txt",
                     "loadable IK plug-in");
}

TEST(IkPluginLoader, MissingSymbolIsInputError) {
  expect_input_error(GRPVSS_IK_PLUGIN_OMIT_SOLVE, "grpvss_ik_solve");
}

TEST(IkPluginLoader, WrongAbiVersionIsInputError) {
  try {
    load_ik_plugin(GRPVSS_IK_PLUGIN_WRONG_ABI, test::make_ibm7545_model());
    FAIL();
  } catch (const InputError& error) {
    EXPECT_EQ(error.expected(), "IK plug-in ABI version 1");
    EXPECT_EQ(error.found(), "99");
  }
}

TEST(IkPluginLoader, BadReturnCodeIsInputErrorAtSolve) {
  const auto plugin = load_ik_plugin(GRPVSS_IK_PLUGIN_BAD_RETURN_CODE, test::make_ibm7545_model());
  try {
    plugin->solve(test::scara_target(0, 20, 8, 0), Eigen::VectorXd::Zero(4));
    FAIL();
  } catch (const InputError& error) {
    EXPECT_EQ(error.file(), GRPVSS_IK_PLUGIN_BAD_RETURN_CODE);
    EXPECT_EQ(error.found(), "7");
  }
}

}  // namespace
}  // namespace grpvss::kinematics
