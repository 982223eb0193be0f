#include "grpvss/kinematics/jacobian.hpp"

#include <random>

#include <gtest/gtest.h>

#include "grpvss/kinematics/kinematic_chain.hpp"
#include "support/random_configurations.hpp"
#include "support/sample_robots.hpp"

namespace grpvss::kinematics {
namespace {

Eigen::Vector3d place(const KinematicChain& chain, Workspace& ws, const Eigen::VectorXd& q,
                      int link, const Eigen::Vector3d& p_L) {
  forward_kinematics(chain, q, ws);
  return ws.X_WL[static_cast<std::size_t>(link)] * p_L;
}

// Central differences, step h: truncation error O(h^2) ~ 1e-12, rounding O(u / h) ~ 1e-10.
TEST(PointJacobian, MatchesCentralDifferencesOnBothRobots) {
  for (const RobotModel& model : {test::make_ibm7545_model(), test::make_puma560_model()}) {
    const KinematicChain chain = make_chain(model);
    Workspace ws(model);
    std::mt19937_64 generator(11);
    std::uniform_real_distribution<double> coordinate(-20.0, 20.0);
    const double h = 1e-6;
    for (int trial = 0; trial < 100; ++trial) {
      const Eigen::VectorXd q = test::random_configuration(model, generator);
      for (int link = 0; link <= model.joint_count(); ++link) {
        const Eigen::Vector3d p_L(coordinate(generator), coordinate(generator),
                                  coordinate(generator));
        forward_kinematics(chain, q, ws);
        const Eigen::Matrix<double, 3, Eigen::Dynamic> J = point_jacobian(chain, ws, link, p_L);
        ASSERT_EQ(J.cols(), model.joint_count());
        for (int j = 0; j < model.joint_count(); ++j) {
          Eigen::VectorXd q_plus = q, q_minus = q;
          q_plus[j] += h;
          q_minus[j] -= h;
          const Eigen::Vector3d numeric =
              (place(chain, ws, q_plus, link, p_L) - place(chain, ws, q_minus, link, p_L)) / (2 * h);
          EXPECT_LT((J.col(j) - numeric).norm(), 1e-6)
              << model.name << " link " << link << " joint " << j + 1;
          if (j >= link) EXPECT_EQ(J.col(j).norm(), 0.0);
        }
      }
    }
  }
}

TEST(EndEffectorJacobian, AngularRowsMatchRotationDifferences) {
  const RobotModel model = test::make_puma560_model();
  const KinematicChain chain = make_chain(model);
  Workspace ws(model);
  std::mt19937_64 generator(12);
  const double h = 1e-6;
  for (int trial = 0; trial < 50; ++trial) {
    const Eigen::VectorXd q = test::random_configuration(model, generator);
    forward_kinematics(chain, q, ws);
    const Eigen::Matrix<double, 6, Eigen::Dynamic> J = end_effector_jacobian(chain, ws);
    const Eigen::Matrix3d R = ws.X_WL.back().linear();
    for (int j = 0; j < model.joint_count(); ++j) {
      Eigen::VectorXd q_plus = q, q_minus = q;
      q_plus[j] += h;
      q_minus[j] -= h;
      forward_kinematics(chain, q_plus, ws);
      const Eigen::Matrix3d R_plus = ws.X_WL.back().linear();
      const Eigen::Vector3d p_plus = ws.X_WL.back().translation();
      forward_kinematics(chain, q_minus, ws);
      const Eigen::Matrix3d R_minus = ws.X_WL.back().linear();
      const Eigen::Vector3d p_minus = ws.X_WL.back().translation();
      // dR/dq R^T = [omega]x
      const Eigen::Matrix3d W = (R_plus - R_minus) / (2 * h) * R.transpose();
      const Eigen::Vector3d omega(W(2, 1), W(0, 2), W(1, 0));
      EXPECT_LT((J.col(j).tail<3>() - omega).norm(), 1e-6);
      EXPECT_LT((J.col(j).head<3>() - (p_plus - p_minus) / (2 * h)).norm(), 1e-6);
    }
  }
}

TEST(PointJacobian, RejectsBadLink) {
  const RobotModel model = test::make_ibm7545_model();
  const KinematicChain chain = make_chain(model);
  Workspace ws(model);
  forward_kinematics(chain, Eigen::VectorXd::Zero(4), ws);
  EXPECT_THROW(point_jacobian(chain, ws, 5, Eigen::Vector3d::Zero()), std::logic_error);
  EXPECT_THROW(point_jacobian(chain, ws, -1, Eigen::Vector3d::Zero()), std::logic_error);
}

}  // namespace
}  // namespace grpvss::kinematics
