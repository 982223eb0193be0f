#include "grpvss/kinematics/numeric_ik.hpp"

#include <cmath>
#include <random>

#include <gtest/gtest.h>

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

// FK(IK(FK(q))) = FK(q) for random q within limits; q_near alternates between home and a
// perturbed copy of the true configuration.
void numeric_round_trip(const RobotModel& model, std::uint64_t seed, int poses) {
  const KinematicChain chain = make_chain(model);
  const auto ik = make_numeric_ik(model);
  std::mt19937_64 generator(seed);
  std::normal_distribution<double> noise(0.0, 0.2);
  int solved = 0;
  for (int trial = 0; trial < poses; ++trial) {
    const Eigen::VectorXd q_true = test::random_configuration(model, generator);
    Eigen::VectorXd q_near = chain.home();
    if (trial % 2 == 1) {
      q_near = q_true;
      for (int i = 0; i < q_near.size(); ++i) q_near[i] += noise(generator);
    }
    const Eigen::Isometry3d X_target = end_effector_pose(chain, q_true);
    const IkSolution solution = ik->solve(X_target, q_near);
    ASSERT_EQ(solution.status, IkStatus::kSolved) << model.name << " pose " << trial;
    ++solved;
    EXPECT_TRUE(chain.within_limits(solution.q)) << trial;
    const Eigen::Isometry3d X_solved = end_effector_pose(chain, solution.q);
    EXPECT_LT(test::position_error(X_solved, X_target), 1e-8) << trial;
    EXPECT_LT(test::rotation_error(X_solved, X_target), 1e-8) << trial;
    // The nearest converged solution is never farther from q_near than the configuration
    // the pose came from would be, unless the solver missed that one; it must at least be
    // a true solution (checked above).
  }
  EXPECT_EQ(solved, poses);
}

TEST(NumericIk, RoundTripPuma560) { numeric_round_trip(test::make_puma560_model(), 31, 300); }

TEST(NumericIk, RoundTripIbm7545) { numeric_round_trip(test::make_ibm7545_model(), 32, 300); }

TEST(NumericIk, AgreesWithClosedFormOnThesisTargets) {
  const RobotModel model = test::make_ibm7545_model();
  const auto numeric = make_numeric_ik(model);
  const auto closed = make_ibm7545_ik(model);
  const Eigen::Isometry3d target = test::scara_target(0, 20, 8, deg(-30));
  const IkSolution a = numeric->solve(target, Eigen::VectorXd::Zero(4));
  const IkSolution b = closed->solve(target, Eigen::VectorXd::Zero(4));
  ASSERT_EQ(a.status, IkStatus::kSolved);
  ASSERT_EQ(b.status, IkStatus::kSolved);
  EXPECT_LT((a.q - b.q).norm(), 1e-7);
  EXPECT_EQ(numeric->solve(test::scara_target(15, 2, 8, deg(-90)), Eigen::VectorXd::Zero(4)).status,
            IkStatus::kOutOfWorkspace);
}

TEST(NumericIk, UnreachablePosesAreOutOfWorkspace) {
  const RobotModel scara = test::make_ibm7545_model();
  const auto scara_ik = make_numeric_ik(scara);
  // A 4-joint SCARA cannot tilt its tool.
  Eigen::Isometry3d tilted = test::scara_target(0, 20, 8, 0);
  tilted.linear() = Eigen::AngleAxisd(0.1, Eigen::Vector3d::UnitX()) * tilted.linear();
  EXPECT_EQ(scara_ik->solve(tilted, Eigen::VectorXd::Zero(4)).status, IkStatus::kOutOfWorkspace);
  const RobotModel puma = test::make_puma560_model();
  const auto puma_ik = make_numeric_ik(puma);
  Eigen::Isometry3d far = Eigen::Isometry3d::Identity();
  far.translation() = Eigen::Vector3d(100, 0, 20);
  const IkSolution solution = puma_ik->solve(far, Eigen::VectorXd::Zero(6));
  EXPECT_EQ(solution.status, IkStatus::kOutOfWorkspace);
  EXPECT_EQ(solution.q.size(), 0);
}

TEST(NumericIk, PrefersTheSolutionNearQNear) {
  // Elbow-up and elbow-down both reach this pose; q_near picks one.
  const RobotModel model = test::make_puma560_model();
  const KinematicChain chain = make_chain(model);
  const auto ik = make_numeric_ik(model);
  Eigen::VectorXd q(6);
  q << 0.3, 0.4, -0.5, 0.2, 0.6, -0.3;
  const Eigen::Isometry3d target = end_effector_pose(chain, q);
  const IkSolution solution = ik->solve(target, q);
  ASSERT_EQ(solution.status, IkStatus::kSolved);
  EXPECT_LT((solution.q - q).norm(), 1e-7);
}

}  // namespace
}  // namespace grpvss::kinematics
