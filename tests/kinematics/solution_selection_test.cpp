// The configuration of a configuration selects exactly it: KUKA Status/Turn on the KR 6, ABB
// confdata on the IRB 2400, the arm configuration on every arm (then nearest among turns).
#include "grpvss/kinematics/solution_selection.hpp"

#include <cmath>
#include <random>

#include <gtest/gtest.h>

#include "support/angles.hpp"
#include "support/industrial_robots.hpp"

namespace grpvss::kinematics {
namespace {

using grpvss::test::kPi;

AnalyticIk opw_solver(const KinematicChain& chain) { return AnalyticIk(chain, *recognise_opw(chain).model); }
AnalyticIk ur_solver(const KinematicChain& chain) { return AnalyticIk(chain, *recognise_ur(chain).model); }

bool equal(const Eigen::VectorXd& a, const Eigen::VectorXd& b) {
  return (a - b).cwiseAbs().maxCoeff() <= 1e-9;
}

bool whole_turns_apart(const Eigen::VectorXd& a, const Eigen::VectorXd& b) {
  for (int i = 0; i < a.size(); ++i) {
    const double turns = (a[i] - b[i]) / (2 * kPi);
    if (std::abs(turns - std::round(turns)) > 1e-9) return false;
  }
  return true;
}

TEST(SolutionSelection, KukaStatusAndTurnSelectExactlyTheOriginal) {
  const AnalyticIk ik = opw_solver(test::kr6_r700_chain());
  std::mt19937_64 generator(41);
  const Eigen::VectorXd elsewhere = Eigen::VectorXd::Zero(6);
  for (int trial = 0; trial < 1000; ++trial) {
    const Eigen::VectorXd q = test::random_chain_configuration(ik.chain(), generator);
    const Eigen::Isometry3d X = test::chain_tool_pose(ik.chain(), q);
    const KukaStatusTurn bits = kuka_status_turn(*ik.opw(), q);
    int with_bits = 0;
    for (const ConfiguredSolution& s : ik.solutions(X)) with_bits += kuka_status_turn(*ik.opw(), s.q) == bits;
    EXPECT_EQ(with_bits, 1) << "trial " << trial;
    const std::optional<Eigen::VectorXd> chosen =
        solution_with_status_turn(ik, X, bits.status, bits.turn, elsewhere);
    ASSERT_TRUE(chosen);
    EXPECT_TRUE(equal(*chosen, q)) << "trial " << trial;
  }
}

TEST(SolutionSelection, AbbConfdataSelectsExactlyTheOriginal) {
  const AnalyticIk ik = opw_solver(test::irb2400_chain());
  std::mt19937_64 generator(42);
  for (int trial = 0; trial < 1000; ++trial) {
    const Eigen::VectorXd q = test::random_chain_configuration(ik.chain(), generator);
    const Eigen::Isometry3d X = test::chain_tool_pose(ik.chain(), q);
    const AbbConfdata conf = abb_confdata(*ik.opw(), q);
    int with_conf = 0;
    for (const ConfiguredSolution& s : ik.solutions(X)) with_conf += abb_confdata(*ik.opw(), s.q) == conf;
    EXPECT_EQ(with_conf, 1) << "trial " << trial;
    const std::optional<Eigen::VectorXd> chosen = solution_with_confdata(ik, X, conf, Eigen::VectorXd::Zero(6));
    ASSERT_TRUE(chosen);
    EXPECT_TRUE(equal(*chosen, q)) << "trial " << trial;
  }
}

// The arm configuration selects the branch; the turns of that branch are told apart by
// nearness to q_near.
void expect_configuration_selects(const AnalyticIk& ik, std::uint64_t seed) {
  std::mt19937_64 generator(seed);
  for (int trial = 0; trial < 1000; ++trial) {
    const Eigen::VectorXd q = test::random_chain_configuration(ik.chain(), generator);
    const Eigen::Isometry3d X = test::chain_tool_pose(ik.chain(), q);
    const ArmConfiguration c = ik.configuration_of(q);
    for (const ConfiguredSolution& s : ik.solutions(X)) {
      if (s.configuration == c) {
        EXPECT_TRUE(whole_turns_apart(s.q, q)) << "trial " << trial;
      }
    }
    const std::optional<Eigen::VectorXd> chosen = solution_with_configuration(ik, X, c, q);
    ASSERT_TRUE(chosen);
    EXPECT_TRUE(equal(*chosen, q)) << "trial " << trial;
  }
}

TEST(SolutionSelection, ArmConfigurationSelectsTheBranch) {
  expect_configuration_selects(opw_solver(test::kr6_r700_chain()), 43);
  expect_configuration_selects(opw_solver(test::irb2400_chain()), 44);
  expect_configuration_selects(ur_solver(test::ur5e_chain_from_urdf()), 45);
}

TEST(SolutionSelection, AConfigurationNoSolutionHasGivesNone) {
  // Within its axis-3 stops the IRB 2400 never has the wrist centre behind the lower arm.
  const AnalyticIk ik = opw_solver(test::irb2400_chain());
  std::mt19937_64 generator(46);
  for (int trial = 0; trial < 100; ++trial) {
    const Eigen::VectorXd q = test::random_chain_configuration(ik.chain(), generator);
    AbbConfdata conf = abb_confdata(*ik.opw(), q);
    conf.cfx |= 2;
    EXPECT_FALSE(solution_with_confdata(ik, test::chain_tool_pose(ik.chain(), q), conf, q));
  }
}

TEST(SolutionSelection, NearestSolutionIsTheClosestInJointSpace) {
  EXPECT_FALSE(nearest_solution({}, Eigen::VectorXd::Zero(6)));
  std::vector<ConfiguredSolution> solutions(3);
  solutions[0].q = Eigen::VectorXd::Constant(6, 1.0);
  solutions[1].q = Eigen::VectorXd::Constant(6, 0.2);
  solutions[2].q = Eigen::VectorXd::Constant(6, -0.3);
  EXPECT_EQ(*nearest_solution(solutions, Eigen::VectorXd::Constant(6, 0.5)), solutions[1].q);
  EXPECT_EQ(*nearest_solution(solutions, Eigen::VectorXd::Constant(6, -1.0)), solutions[2].q);
}

TEST(SolutionSelection, VendorBitsNeedAnOpwArm) {
  const AnalyticIk ik = ur_solver(test::ur5e_chain_from_urdf());
  EXPECT_THROW(solution_with_status_turn(ik, Eigen::Isometry3d::Identity(), 2, std::nullopt,
                                         Eigen::VectorXd::Zero(6)),
               std::invalid_argument);
  EXPECT_THROW(solution_with_confdata(ik, Eigen::Isometry3d::Identity(), {}, Eigen::VectorXd::Zero(6)),
               std::invalid_argument);
}

}  // namespace
}  // namespace grpvss::kinematics
