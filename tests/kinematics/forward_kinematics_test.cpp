#include "grpvss/kinematics/forward_kinematics.hpp"

#include <cmath>
#include <random>
#include <stdexcept>

#include <boost/multiprecision/cpp_bin_float.hpp>
#include <gtest/gtest.h>

#include "grpvss/kinematics/kinematic_chain.hpp"
#include "support/angles.hpp"
#include "support/kinematics_reference.hpp"
#include "support/random_configurations.hpp"
#include "support/sample_robots.hpp"

namespace grpvss::kinematics {
namespace {

using grpvss::test::kPi;

TEST(ForwardKinematics, Ibm7545HomeMatchesThesis) {
  const RobotModel model = test::make_ibm7545_model();
  const KinematicChain chain = make_chain(model);
  const Eigen::Isometry3d X_WE = end_effector_pose(chain, Eigen::VectorXd::Zero(4));
  EXPECT_NEAR(X_WE.translation().x(), 25.6, 1e-12);
  EXPECT_NEAR(X_WE.translation().y(), 0.0, 1e-12);
  EXPECT_NEAR(X_WE.translation().z(), 10.45, 1e-12);
  // Tool z points down, tool x along world x (yaw 0).
  EXPECT_NEAR((X_WE.linear().col(2) - Eigen::Vector3d(0, 0, -1)).norm(), 0.0, 1e-12);
  EXPECT_NEAR((X_WE.linear().col(0) - Eigen::Vector3d(1, 0, 0)).norm(), 0.0, 1e-12);
}

TEST(ForwardKinematics, Ibm7545YawIsTheta1PlusTheta2MinusTheta4) {
  const RobotModel model = test::make_ibm7545_model();
  const KinematicChain chain = make_chain(model);
  std::mt19937_64 generator(1);
  for (int trial = 0; trial < 100; ++trial) {
    const Eigen::VectorXd q = test::random_configuration(model, generator);
    const Eigen::Isometry3d X_WE = end_effector_pose(chain, q);
    const double yaw = std::atan2(X_WE.linear()(1, 0), X_WE.linear()(0, 0));
    EXPECT_NEAR(std::remainder(yaw - (q[0] + q[1] - q[3]), 2 * kPi), 0.0, 1e-12);
    EXPECT_NEAR(X_WE.translation().z(), 25.5 - q[2] - 15.05, 1e-12);
  }
}

// The chain (fixed transform + z motion + fixed transform) against the closed-form DH matrix.
TEST(ForwardKinematics, MatchesClosedFormDhOnBothRobots) {
  for (const RobotModel& model : {test::make_ibm7545_model(), test::make_puma560_model()}) {
    const KinematicChain chain = make_chain(model);
    Workspace ws(model);
    std::mt19937_64 generator(2);
    for (int trial = 0; trial < 200; ++trial) {
      const Eigen::VectorXd q = test::random_configuration(model, generator);
      forward_kinematics(chain, q, ws);
      for (int link = 0; link <= model.joint_count(); ++link) {
        const Eigen::Matrix4d expected = test::reference_link_pose<double>(model, q, link);
        EXPECT_LT((ws.X_WL[static_cast<std::size_t>(link)].matrix() - expected).cwiseAbs().maxCoeff(),
                  1e-12)
            << model.name << " link " << link;
      }
      EXPECT_LT((end_effector_pose(chain, q).matrix() - ws.X_WL.back().matrix()).cwiseAbs().maxCoeff(),
                1e-15);
    }
  }
}

TEST(ForwardKinematics, JointFrameZIsTheJointAxis) {
  const RobotModel model = test::make_puma560_model();
  const KinematicChain chain = make_chain(model);
  Workspace ws(model);
  std::mt19937_64 generator(3);
  const Eigen::VectorXd q = test::random_configuration(model, generator);
  forward_kinematics(chain, q, ws);
  // Standard DH: joint i turns about z_{i-1}, through the origin of frame i-1.
  for (int i = 0; i < model.joint_count(); ++i) {
    const auto k = static_cast<std::size_t>(i);
    EXPECT_LT((ws.X_WJ[k].linear().col(2) - ws.X_WL[k].linear().col(2)).norm(), 1e-14);
    EXPECT_LT((ws.X_WJ[k].translation() - ws.X_WL[k].translation()).norm(), 1e-14);
  }
}

TEST(ForwardKinematics, PlacesEveryHullPoint) {
  const RobotModel model = test::make_puma560_model();
  const KinematicChain chain = make_chain(model);
  Workspace ws(model);
  std::mt19937_64 generator(4);
  const Eigen::VectorXd q = test::random_configuration(model, generator);
  forward_kinematics(chain, q, ws);
  place_hull_points(model, ws);
  for (std::size_t link = 0; link < model.links.size(); ++link) {
    const Eigen::Matrix4d X_WL = test::reference_link_pose<double>(model, q, static_cast<int>(link));
    for (std::size_t h = 0; h < model.links[link].hulls.size(); ++h) {
      const auto& points_L = model.links[link].hulls[h].points;
      ASSERT_EQ(ws.hull_points_W[link][h].size(), points_L.size());
      for (std::size_t k = 0; k < points_L.size(); ++k) {
        const Eigen::Vector3d expected = (X_WL * points_L[k].homogeneous()).head<3>();
        EXPECT_LT((ws.hull_points_W[link][h][k] - expected).norm(), 1e-12);
      }
    }
  }
}

TEST(ForwardKinematics, RejectsMismatchedSizes) {
  const RobotModel model = test::make_ibm7545_model();
  const KinematicChain chain = make_chain(model);
  Workspace ws(model);
  EXPECT_THROW(forward_kinematics(chain, Eigen::VectorXd::Zero(3), ws), std::logic_error);
  Workspace other(test::make_puma560_model());
  EXPECT_THROW(forward_kinematics(chain, Eigen::VectorXd::Zero(4), other), std::logic_error);
  EXPECT_THROW(end_effector_pose(chain, Eigen::VectorXd::Zero(5)), std::logic_error);
}

TEST(KinematicChain, LimitsAndHomeComeFromTheModel) {
  const RobotModel model = test::make_ibm7545_model();
  const KinematicChain chain = make_chain(model);
  ASSERT_EQ(chain.joint_count(), 4);
  EXPECT_EQ(chain.joints[2].type, JointType::kPrismatic);
  EXPECT_DOUBLE_EQ(chain.joints[0].maximum, 200.0 * kPi / 180.0);
  EXPECT_TRUE(chain.within_limits(chain.home()));
  Eigen::VectorXd q = chain.home();
  q[2] = 9.81;
  EXPECT_FALSE(chain.within_limits(q));
  EXPECT_TRUE(chain.within_limits(q, 0.02));
}

// proofs/fk-rounding.md#trig-rounding: a constant DH angle that is a quarter-turn multiple in
// degrees (within one turn) is stored with exact 0 and +-1 entries, each still within the
// lemma's 4u of the exact cosine and sine of the double angle (50 digits), up to two turns.
TEST(KinematicChain, QuarterTurnAnglesAreStoredWithoutTrigResidueWithinTheLemmasBound) {
  using Float50 = boost::multiprecision::cpp_bin_float_50;
  constexpr double u = 0x1p-53;
  for (int quarter = -8; quarter <= 8; ++quarter) {
    RobotModel model = test::make_puma560_model();
    const double alpha = quarter * 90.0 * kPi / 180.0;  // as the robot file reader converts
    model.joints[0].dh.alpha = alpha;
    const Eigen::Matrix3d R = make_chain(model).joints[0].X_JC.linear();
    const Float50 c = cos(Float50(alpha));
    const Float50 s = sin(Float50(alpha));
    const Eigen::Matrix<Float50, 3, 3> exact =
        (Eigen::Matrix<Float50, 3, 3>() << 1, 0, 0, 0, c, -s, 0, s, c).finished();
    for (int i = 0; i < 3; ++i) {
      for (int j = 0; j < 3; ++j) {
        // Within one turn the residue is below 3u; at 720 deg (4.9e-16) it must be kept.
        if (std::abs(quarter) <= 4) {
          EXPECT_TRUE(R(i, j) == 0.0 || std::abs(R(i, j)) == 1.0) << quarter << " " << i << j;
        }
        EXPECT_LE(abs(Float50(R(i, j)) - exact(i, j)), Float50(4 * u)) << quarter << " " << i << j;
      }
    }
  }
}

// So the IBM 7545's 180 deg twist keeps every link frame's z axis exactly vertical: a placed
// horizontal face stays exactly planar (docs/verification.md#interference-points).
TEST(KinematicChain, Ibm7545LinkFramesKeepAnExactlyVerticalAxis) {
  const RobotModel model = test::make_ibm7545_model();
  const KinematicChain chain = make_chain(model);
  Workspace ws(model);
  std::mt19937_64 generator(7545);
  for (int trial = 0; trial < 200; ++trial) {
    forward_kinematics(chain, test::random_configuration(model, generator), ws);
    for (const Eigen::Isometry3d& X_WL : ws.X_WL) {
      EXPECT_EQ(X_WL.linear()(2, 0), 0.0);
      EXPECT_EQ(X_WL.linear()(2, 1), 0.0);
      EXPECT_EQ(X_WL.linear()(0, 2), 0.0);
      EXPECT_EQ(X_WL.linear()(1, 2), 0.0);
      EXPECT_EQ(std::abs(X_WL.linear()(2, 2)), 1.0);
    }
  }
}

}  // namespace
}  // namespace grpvss::kinematics
