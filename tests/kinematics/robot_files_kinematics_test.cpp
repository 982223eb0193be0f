// Kinematics on the robots as read from data/ (io reader), compared with the in-code models.
#include <cmath>
#include <random>
#include <string>

#include <gtest/gtest.h>

#include "grpvss/io/robot_file.hpp"
#include "grpvss/kinematics/fk_error_bound.hpp"
#include "grpvss/kinematics/forward_kinematics.hpp"
#include "grpvss/kinematics/ibm7545_ik.hpp"
#include "grpvss/kinematics/inverse_kinematics.hpp"
#include "grpvss/kinematics/kinematic_chain.hpp"
#include "support/angles.hpp"
#include "support/pose_error.hpp"
#include "support/random_configurations.hpp"
#include "support/sample_robots.hpp"

namespace grpvss::kinematics {
namespace {

using grpvss::test::kPi;
using grpvss::test::deg;

RobotModel read_robot_fixture(const std::string& relative) {
  return io::read_robot_file(std::string(GRPVSS_SOURCE_DIR) + "/" + relative);
}

void expect_same_kinematics(const RobotModel& a, const RobotModel& b) {
  ASSERT_EQ(a.joint_count(), b.joint_count());
  for (std::size_t i = 0; i < a.joints.size(); ++i) {
    EXPECT_EQ(a.joints[i].type, b.joints[i].type) << i;
    EXPECT_NEAR(a.joints[i].dh.theta, b.joints[i].dh.theta, 1e-12) << i;
    EXPECT_NEAR(a.joints[i].dh.d, b.joints[i].dh.d, 1e-12) << i;
    EXPECT_NEAR(a.joints[i].dh.a, b.joints[i].dh.a, 1e-12) << i;
    EXPECT_NEAR(a.joints[i].dh.alpha, b.joints[i].dh.alpha, 1e-12) << i;
    EXPECT_NEAR(a.joints[i].minimum, b.joints[i].minimum, 1e-12) << i;
    EXPECT_NEAR(a.joints[i].maximum, b.joints[i].maximum, 1e-12) << i;
  }
}

TEST(RobotFilesKinematics, Ibm7545FileMatchesInCodeModelAndThesisHome) {
  const RobotModel model = read_robot_fixture("data/ibm7545/robot.txt");
  expect_same_kinematics(model, test::make_ibm7545_model());
  EXPECT_TRUE(is_ibm7545_structure(model));
  const Eigen::Isometry3d X_WE = end_effector_pose(make_chain(model), Eigen::VectorXd::Zero(4));
  EXPECT_LT((X_WE.translation() - Eigen::Vector3d(25.6, 0, 10.45)).norm(), 1e-12);
}

TEST(RobotFilesKinematics, Ibm7545FileThesisIkNumbers) {
  const RobotModel model = read_robot_fixture("data/ibm7545/robot.txt");
  const auto ik = make_default_ik(model);
  EXPECT_EQ(ik->name(), "IBM 7545 closed form");
  const IkSolution s1 = ik->solve(test::scara_target(0, 20, 8, deg(-30)), Eigen::VectorXd::Zero(4));
  ASSERT_EQ(s1.status, IkStatus::kSolved);
  EXPECT_NEAR(s1.q[0], deg(61.16), deg(0.01));
  EXPECT_NEAR(s1.q[1], deg(79.90), deg(0.01));
  EXPECT_NEAR(s1.q[2], 2.45, 0.01);
  EXPECT_NEAR(s1.q[3], deg(171.06), deg(0.01));
  const IkSolution s2 = ik->solve(test::scara_target(-20, -5, 2, deg(-60)), s1.q);
  ASSERT_EQ(s2.status, IkStatus::kSolved);
  EXPECT_NEAR(s2.q[0], deg(166.68), deg(0.01));
  EXPECT_NEAR(s2.q[1], deg(75.16), deg(0.01));
  EXPECT_NEAR(s2.q[2], 8.45, 0.01);
  EXPECT_NEAR(s2.q[3], deg(-58.16), deg(0.01));
  EXPECT_EQ(ik->solve(test::scara_target(15, 2, 8, deg(-90)), s2.q).status,
            IkStatus::kOutOfWorkspace);
}

TEST(RobotFilesKinematics, Puma560FileReadsAndRoundTrips) {
  const RobotModel model = read_robot_fixture("data/puma560/robot.txt");
  expect_same_kinematics(model, test::make_puma560_model());
  ASSERT_EQ(model.links.size(), 7u);
  for (const Link& link : model.links) {
    ASSERT_EQ(link.hulls.size(), 1u);
    EXPECT_EQ(link.hulls[0].points.size(), 16u);
  }
  const KinematicChain chain = make_chain(model);
  const auto ik = make_default_ik(model);
  EXPECT_EQ(ik->name(), "damped least squares");
  std::mt19937_64 generator(61);
  for (int trial = 0; trial < 50; ++trial) {
    const Eigen::VectorXd q = test::random_configuration(model, generator);
    const Eigen::Isometry3d X_target = end_effector_pose(chain, q);
    const IkSolution solution = ik->solve(X_target, chain.home());
    ASSERT_EQ(solution.status, IkStatus::kSolved) << trial;
    EXPECT_TRUE(chain.within_limits(solution.q));
    const Eigen::Isometry3d X_solved = end_effector_pose(chain, solution.q);
    EXPECT_LT(test::position_error(X_solved, X_target), 1e-8);
    EXPECT_LT(test::rotation_error(X_solved, X_target), 1e-8);
  }
}

// Home: arm stretched along x0 at shoulder height, forearm (z3) pointing up to the wrist.
TEST(RobotFilesKinematics, Puma560HomePose) {
  const RobotModel model = read_robot_fixture("data/puma560/robot.txt");
  Workspace ws(model);
  forward_kinematics(make_chain(model), Eigen::VectorXd::Zero(6), ws);
  // Wrist centre = origin of frame 4: (a2 + a3, -d3, d1 + d4)  (z1 = -y0 turns d3 toward -y).
  EXPECT_LT((ws.X_WL[4].translation() - Eigen::Vector3d(17.8, -5.9, 26.45 + 17.0)).norm(), 1e-12);
  EXPECT_LT((ws.X_WL[6].translation() - Eigen::Vector3d(17.8, -5.9, 26.45 + 17.0 + 2.2)).norm(),
            1e-12);
}

}  // namespace
}  // namespace grpvss::kinematics
