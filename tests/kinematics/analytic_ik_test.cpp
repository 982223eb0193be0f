// AnalyticIk on real arms: FK -> IK round trips (the original among all solutions, every
// solution reaching the pose within the limits), singular and unreachable poses, the nearest
// solution, and the 2 pi turns.
#include "grpvss/kinematics/analytic_ik.hpp"

#include <cmath>
#include <random>

#include <gtest/gtest.h>

#include "support/angles.hpp"
#include "support/industrial_robots.hpp"
#include "support/pose_error.hpp"
#include "support/sample_robots.hpp"

namespace grpvss::kinematics {
namespace {

using grpvss::test::kPi;

AnalyticIk opw_ik(const KinematicChain& chain) {
  const Recognition<OpwChainModel> r = recognise_opw(chain);
  if (!r.model) throw std::runtime_error(r.reason);
  return AnalyticIk(chain, *r.model);
}

AnalyticIk ur_ik(const KinematicChain& chain) {
  const Recognition<UrChainModel> r = recognise_ur(chain);
  if (!r.model) throw std::runtime_error(r.reason);
  return AnalyticIk(chain, *r.model);
}

void expect_reaches(const AnalyticIk& ik, const ConfiguredSolution& s, const Eigen::Isometry3d& X) {
  for (int i = 0; i < 6; ++i) ASSERT_TRUE(std::isfinite(s.q[i]));
  const Eigen::Isometry3d X_s = test::chain_tool_pose(ik.chain(), s.q);
  EXPECT_LE(test::position_error(X_s, X), 1e-9);
  EXPECT_LE(test::rotation_error(X_s, X), 1e-9);
  EXPECT_TRUE(ik.chain().within_limits(s.q));
  EXPECT_EQ(s.configuration, ik.configuration_of(s.q));
}

// >= 1000 random configurations within the limits: the original q is among the solutions,
// each solution reaches the pose, solve(X, q) returns q itself.
void expect_round_trips(const AnalyticIk& ik, std::uint64_t seed) {
  std::mt19937_64 generator(seed);
  std::size_t most = 0;
  for (int trial = 0; trial < 1000; ++trial) {
    const Eigen::VectorXd q = test::random_chain_configuration(ik.chain(), generator);
    const Eigen::Isometry3d X = test::chain_tool_pose(ik.chain(), q);
    const std::vector<ConfiguredSolution> all = ik.solutions(X);
    int originals = 0;
    for (const ConfiguredSolution& s : all) {
      expect_reaches(ik, s, X);
      originals += (s.q - q).cwiseAbs().maxCoeff() <= 1e-9;
    }
    EXPECT_EQ(originals, 1) << "trial " << trial << " q = " << q.transpose();
    const IkSolution nearest = ik.solve(X, q);
    ASSERT_EQ(nearest.status, IkStatus::kSolved);
    EXPECT_LE((nearest.q - q).cwiseAbs().maxCoeff(), 1e-9);
    most = std::max(most, all.size());
  }
  EXPECT_GE(most, 8u);
}

TEST(AnalyticIk, RoundTripsKukaKr6R700) { expect_round_trips(opw_ik(test::kr6_r700_chain()), 1); }
TEST(AnalyticIk, RoundTripsAbbIrb2400) { expect_round_trips(opw_ik(test::irb2400_chain()), 2); }
TEST(AnalyticIk, RoundTripsPuma560FromDh) {
  expect_round_trips(opw_ik(make_chain(test::make_puma560_model())), 3);
}
TEST(AnalyticIk, RoundTripsUr5eFromUrdf) { expect_round_trips(ur_ik(test::ur5e_chain_from_urdf()), 4); }
TEST(AnalyticIk, RoundTripsUr5eFromDh) { expect_round_trips(ur_ik(make_chain(test::ur5e_dh_model())), 5); }

TEST(AnalyticIk, NamesTheFamily) {
  EXPECT_EQ(opw_ik(test::irb2400_chain()).name(), "OPW closed form");
  EXPECT_EQ(ur_ik(test::ur5e_chain_from_urdf()).name(), "UR closed form");
}

TEST(AnalyticIk, AllTurnsWithinTheLimitsAreListed) {
  // IRB 2400 axis 6 turns +-400 deg: q6 = 30 deg also reaches as -330 and 390 deg; axis 4
  // (+-200 deg) at 170 deg also as -190 deg.
  const AnalyticIk ik = opw_ik(test::irb2400_chain());
  Eigen::VectorXd q(6);
  q << 0.3, 0.2, 0.1, 170 * kPi / 180, 0.5, 30 * kPi / 180;
  const Eigen::Isometry3d X = test::chain_tool_pose(ik.chain(), q);
  int variants_of_q = 0;
  for (const ConfiguredSolution& s : ik.solutions(X)) {
    const Eigen::VectorXd turns = (s.q - q) / (2 * kPi);
    bool whole_turns = true;
    for (int i = 0; i < 6; ++i) whole_turns = whole_turns && std::abs(turns[i] - std::round(turns[i])) <= 1e-9;
    variants_of_q += whole_turns;
  }
  EXPECT_EQ(variants_of_q, 2 * 3);
}

TEST(AnalyticIk, SolveReturnsTheNearestSolution) {
  const AnalyticIk ik = opw_ik(test::kr6_r700_chain());
  std::mt19937_64 generator(6);
  for (int trial = 0; trial < 200; ++trial) {
    const Eigen::Isometry3d X =
        test::chain_tool_pose(ik.chain(), test::random_chain_configuration(ik.chain(), generator));
    const Eigen::VectorXd q_near = test::random_chain_configuration(ik.chain(), generator);
    double nearest = INFINITY;
    for (const ConfiguredSolution& s : ik.solutions(X, q_near)) nearest = std::min(nearest, (s.q - q_near).norm());
    const IkSolution solved = ik.solve(X, q_near);
    ASSERT_EQ(solved.status, IkStatus::kSolved);
    EXPECT_NEAR((solved.q - q_near).norm(), nearest, 1e-12);
  }
}

TEST(AnalyticIk, WristSingularPosesKeepTheCurrentAxis4) {
  // q5 = 0: axes 4 and 6 line up (UR: axis 6 parallel to 2-4); the free angle comes from q.
  for (const AnalyticIk& ik : {opw_ik(test::kr6_r700_chain()), ur_ik(make_chain(test::ur5e_dh_model()))}) {
    Eigen::VectorXd q(6);
    q << 0.3, -1.2, 0.8, 0.5, 0.0, -0.4;
    const Eigen::Isometry3d X = test::chain_tool_pose(ik.chain(), q);
    const std::vector<ConfiguredSolution> all = ik.solutions(X, q);
    ASSERT_FALSE(all.empty());
    int originals = 0;
    for (const ConfiguredSolution& s : all) {
      expect_reaches(ik, s, X);
      originals += (s.q - q).cwiseAbs().maxCoeff() <= 1e-12;
    }
    EXPECT_EQ(originals, 1) << ik.name();
    EXPECT_LE((ik.solve(X, q).q - q).cwiseAbs().maxCoeff(), 1e-12) << ik.name();
  }
}

TEST(AnalyticIk, WristSingularPoseOfTheUrdfChainIsReached) {
  // The URDF's rounded angles leave axis 6 some 1e-10 rad off parallel to axes 2-4 at q5 = 0:
  // q2, q3, q4, q6 are then barely determined (a near one-parameter family), q1 and q5 are,
  // and every solution reaches the pose.
  const AnalyticIk ik = ur_ik(test::ur5e_chain_from_urdf());
  Eigen::VectorXd q(6);
  q << 0.3, -1.2, 0.8, 0.5, 0.0, -0.4;
  const Eigen::Isometry3d X = test::chain_tool_pose(ik.chain(), q);
  const std::vector<ConfiguredSolution> all = ik.solutions(X, q);
  ASSERT_FALSE(all.empty());
  for (const ConfiguredSolution& s : all) expect_reaches(ik, s, X);
  const IkSolution nearest = ik.solve(X, q);
  ASSERT_EQ(nearest.status, IkStatus::kSolved);
  EXPECT_NEAR(nearest.q[0], q[0], 1e-9);
  EXPECT_NEAR(nearest.q[4], q[4], 1e-9);
}

TEST(AnalyticIk, ShoulderSingularPoseHasNoNan) {
  // KR6 flange straight up with the wrist centre on axis 1: theta_1 is free.
  const AnalyticIk ik = opw_ik(test::kr6_r700_chain());
  const OpwChainModel& m = *ik.opw();
  Eigen::Isometry3d X_BF = Eigen::Isometry3d::Identity();
  X_BF.translation() = Eigen::Vector3d(0, 0, 0.9 + m.parameters.c4);
  const Eigen::Isometry3d X = m.placement.X_WB * X_BF * m.placement.X_FT;
  const std::vector<ConfiguredSolution> all = ik.solutions(X);
  ASSERT_FALSE(all.empty());
  for (const ConfiguredSolution& s : all) expect_reaches(ik, s, X);
}

TEST(AnalyticIk, UnreachablePosesHaveNoSolution) {
  const AnalyticIk kr6 = opw_ik(test::kr6_r700_chain());
  const AnalyticIk ur5e = ur_ik(test::ur5e_chain_from_urdf());
  Eigen::Isometry3d far = Eigen::Isometry3d::Identity();
  far.translation() = Eigen::Vector3d(2.5, 0.3, 0.4);
  for (const AnalyticIk* ik : {&kr6, &ur5e}) {
    EXPECT_TRUE(ik->solutions(far).empty());
    EXPECT_EQ(ik->solve(far, Eigen::VectorXd::Zero(6)).status, IkStatus::kOutOfWorkspace);
  }
}

TEST(AnalyticIk, PosesReachableOnlyOutsideTheLimitsHaveNoSolution) {
  // A1 restricted to +-10 deg: a pose reached with A1 = 90 deg needs A1 = 90 deg (front
  // shoulder) or -90 deg (back shoulder), and no turn of either fits.
  KinematicChain chain = test::kr6_r700_chain();
  chain.joints[0].minimum = -10 * kPi / 180;
  chain.joints[0].maximum = 10 * kPi / 180;
  const AnalyticIk ik = opw_ik(chain);
  Eigen::VectorXd q(6);
  q << kPi / 2, -1.2, 0.8, 0.5, 0.6, -0.4;
  const Eigen::Isometry3d X = test::chain_tool_pose(chain, q);
  EXPECT_TRUE(ik.solutions(X).empty());
  EXPECT_EQ(ik.solve(X, q).status, IkStatus::kOutOfWorkspace);
}

}  // namespace
}  // namespace grpvss::kinematics

namespace grpvss::kinematics {
namespace {

TEST(AnalyticIk, TypicalUrPoseIsLeftElbowUpWristDownWithTheToolDown) {
  const AnalyticIk ik = ur_ik(test::ur5e_chain_from_urdf());
  Eigen::VectorXd q(6);
  q << 0, -kPi / 2, kPi / 2, -kPi / 2, -kPi / 2, 0;
  const ArmConfiguration c = ik.configuration_of(q);
  EXPECT_EQ(c.shoulder, Shoulder::kLeft);
  EXPECT_EQ(c.elbow, Elbow::kUp);
  EXPECT_EQ(c.wrist, Wrist::kDown);
  // base_link's z is up: tool0's z axis points down.
  EXPECT_NEAR(test::chain_tool_pose(ik.chain(), q).linear()(2, 2), -1.0, 1e-9);
}

}  // namespace
}  // namespace grpvss::kinematics
