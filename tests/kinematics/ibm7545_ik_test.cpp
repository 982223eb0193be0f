#include "grpvss/kinematics/ibm7545_ik.hpp"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <limits>
#include <random>
#include <stdexcept>
#include <vector>

#include <gtest/gtest.h>

#include "grpvss/kinematics/forward_kinematics.hpp"
#include "grpvss/kinematics/kinematic_chain.hpp"
#include "support/angles.hpp"
#include "support/pose_error.hpp"
#include "support/random_configurations.hpp"
#include "support/sample_robots.hpp"

namespace grpvss::kinematics {
namespace {

using grpvss::test::kPi;
using grpvss::test::deg;
double to_deg(double radians) { return radians * 180.0 / kPi; }

void expect_joints_deg(const IkSolution& solution, double q1, double q2, double q3, double q4) {
  ASSERT_EQ(solution.status, IkStatus::kSolved);
  std::printf("IK -> %.4f deg %.4f deg %.4f %.4f deg\n", to_deg(solution.q[0]),
              to_deg(solution.q[1]), solution.q[2], to_deg(solution.q[3]));
  EXPECT_NEAR(to_deg(solution.q[0]), q1, 0.01);
  EXPECT_NEAR(to_deg(solution.q[1]), q2, 0.01);
  EXPECT_NEAR(solution.q[2], q3, 0.01);
  EXPECT_NEAR(to_deg(solution.q[3]), q4, 0.01);
}

// Thesis Appendix A.3, segment 1: (0,20,8), orientation change Rot((0,0,-1), 30 deg) from home.
TEST(Ibm7545Ik, ThesisSegment1Target) {
  const auto ik = make_ibm7545_ik(test::make_ibm7545_model());
  expect_joints_deg(ik->solve(test::scara_target(0, 20, 8, deg(-30)), Eigen::VectorXd::Zero(4)),
                    61.16, 79.90, 2.45, 171.06);
}

// Segment 2: CP to (-20,-5,2), another -30 deg of yaw.
TEST(Ibm7545Ik, ThesisSegment2Target) {
  const auto ik = make_ibm7545_ik(test::make_ibm7545_model());
  Eigen::VectorXd q_start(4);
  q_start << deg(61.16), deg(79.90), 2.45, deg(171.06);
  expect_joints_deg(ik->solve(test::scara_target(-20, -5, 2, deg(-60)), q_start), 166.68, 75.16,
                    8.45, -58.16);
}

// Segment 4: (15,2,8) needs theta1 = -29.3 deg (below 0) or a negative theta2.
TEST(Ibm7545Ik, ThesisSegment4TargetIsOutOfWorkspace) {
  const auto ik = make_ibm7545_ik(test::make_ibm7545_model());
  for (const double yaw_deg : {-90.0, 20.0, 0.0, 170.0}) {
    const IkSolution solution =
        ik->solve(test::scara_target(15, 2, 8, deg(yaw_deg)), Eigen::VectorXd::Zero(4));
    EXPECT_EQ(solution.status, IkStatus::kOutOfWorkspace) << yaw_deg;
    EXPECT_EQ(solution.q.size(), 0);
  }
}

TEST(Ibm7545Ik, TiltedToolOrFarTargetIsOutOfWorkspace) {
  const auto ik = make_ibm7545_ik(test::make_ibm7545_model());
  Eigen::Isometry3d tilted = test::scara_target(0, 20, 8, 0);
  tilted.linear() = Eigen::AngleAxisd(1e-7, Eigen::Vector3d::UnitX()) * tilted.linear();
  EXPECT_EQ(ik->solve(tilted, Eigen::VectorXd::Zero(4)).status, IkStatus::kOutOfWorkspace);
  EXPECT_EQ(ik->solve(test::scara_target(30, 0, 8, 0), Eigen::VectorXd::Zero(4)).status,
            IkStatus::kOutOfWorkspace);  // beyond a1 + a2 = 25.6
  EXPECT_EQ(ik->solve(test::scara_target(0, 20, 12, 0), Eigen::VectorXd::Zero(4)).status,
            IkStatus::kOutOfWorkspace);  // z above 10.45 needs q3 < 0
}

TEST(Ibm7545Ik, RecognisesTheStructure) {
  EXPECT_TRUE(is_ibm7545_structure(test::make_ibm7545_model()));
  EXPECT_FALSE(is_ibm7545_structure(test::make_puma560_model()));
  RobotModel model = test::make_ibm7545_model();
  model.joints[1].dh.alpha = deg(-180);  // the same rotation
  EXPECT_TRUE(is_ibm7545_structure(model));
  model.joints[1].dh.alpha = deg(90);
  EXPECT_FALSE(is_ibm7545_structure(model));
  EXPECT_THROW(make_ibm7545_ik(model), std::invalid_argument);
  model = test::make_ibm7545_model();
  model.joints[3].dh.a = 0.5;
  EXPECT_FALSE(is_ibm7545_structure(model));
  model = test::make_ibm7545_model();
  model.joints[2].type = JointType::kRevolute;
  EXPECT_FALSE(is_ibm7545_structure(model));
}

// At the stretched (theta2 = 0) and the folded (theta2 = 180 deg) elbow both branches meet:
// sin(elbow) is 0 there, or the square root of a rounding-sized 1 - c2^2.
// Each pose round-trips within 1e-8, and the straight elbow is found at joint 2's limit 0.
TEST(Ibm7545Ik, StretchedAndFoldedElbowsRoundTrip) {
  RobotModel model = test::make_ibm7545_model();
  model.joints[1].minimum = deg(-180);
  model.joints[1].maximum = deg(180);
  const KinematicChain chain = make_chain(model);
  const auto ik = make_ibm7545_ik(model);
  for (const double elbow_deg : {0.0, 180.0, -180.0}) {
    for (const double q1_deg : {10.0, 95.0, 170.0}) {
      Eigen::VectorXd q_true(4);
      q_true << deg(q1_deg), deg(elbow_deg), 3.0, deg(20.0);
      const Eigen::Isometry3d X_target = end_effector_pose(chain, q_true);
      const IkSolution solution = ik->solve(X_target, q_true);
      ASSERT_EQ(solution.status, IkStatus::kSolved) << q1_deg << " " << elbow_deg;
      const Eigen::Isometry3d X_solved = end_effector_pose(chain, solution.q);
      EXPECT_LT(test::position_error(X_solved, X_target), 1e-8) << q1_deg << " " << elbow_deg;
      EXPECT_LT(test::rotation_error(X_solved, X_target), 1e-8) << q1_deg << " " << elbow_deg;
      EXPECT_NEAR(std::abs(solution.q[1]), std::abs(q_true[1]), 1e-6) << q1_deg << " " << elbow_deg;
    }
  }
  // On the thesis's limits (joint 2 in [0, 135] deg) the stretched arm is at the limit.
  const RobotModel thesis = test::make_ibm7545_model();
  Eigen::VectorXd stretched(4);
  stretched << deg(40.0), 0.0, 2.0, deg(-30.0);
  const IkSolution solution = make_ibm7545_ik(thesis)->solve(
      end_effector_pose(make_chain(thesis), stretched), Eigen::VectorXd::Zero(4));
  ASSERT_EQ(solution.status, IkStatus::kSolved);
  EXPECT_GE(solution.q[1], 0.0);
  EXPECT_LT(solution.q[1], 1e-6);
  EXPECT_NEAR(solution.q[0], deg(40.0), 1e-6);
}

// Every solution of the SCARA for a reachable pose, derived independently of the solver:
// the mirror elbow reflects both links across the line from the base axis to the wrist
// (theta1' = 2 phi - theta1, theta2' = -theta2, yaw kept), and every revolute joint may move
// by 2 pi k. Returns those within the limits.
std::vector<Eigen::VectorXd> all_valid_solutions(const RobotModel& model, const Eigen::VectorXd& q) {
  const KinematicChain chain = make_chain(model);
  const Eigen::Vector3d p = end_effector_pose(chain, q).translation();
  const double phi = std::atan2(p.y(), p.x());
  Eigen::VectorXd mirror = q;
  mirror[0] = 2 * phi - q[0];
  mirror[1] = -q[1];
  mirror[3] = q[3] + (mirror[0] + mirror[1]) - (q[0] + q[1]);
  std::vector<Eigen::VectorXd> valid;
  for (const Eigen::VectorXd& base : {q, mirror}) {
    for (int k0 = -4; k0 <= 4; ++k0) {
      for (int k1 = -4; k1 <= 4; ++k1) {
        for (int k3 = -4; k3 <= 4; ++k3) {
          Eigen::VectorXd candidate = base;
          candidate[0] += 2 * kPi * k0;
          candidate[1] += 2 * kPi * k1;
          candidate[3] += 2 * kPi * k3;
          if (chain.within_limits(candidate, 1e-9)) valid.push_back(candidate);
        }
      }
    }
  }
  return valid;
}

void ibm7545_round_trip(const RobotModel& model, std::uint64_t seed, int poses, int& positive_elbows,
                int& negative_elbows, bool check_nearest = true) {
  const KinematicChain chain = make_chain(model);
  const auto ik = make_ibm7545_ik(model);
  std::mt19937_64 generator(seed);
  for (int trial = 0; trial < poses; ++trial) {
    const Eigen::VectorXd q_true = test::random_configuration(model, generator);
    const Eigen::VectorXd q_near = test::random_configuration(model, generator);
    const Eigen::Isometry3d X_target = end_effector_pose(chain, q_true);
    const IkSolution solution = ik->solve(X_target, q_near);
    ASSERT_EQ(solution.status, IkStatus::kSolved) << trial;
    EXPECT_TRUE(chain.within_limits(solution.q));
    const Eigen::Isometry3d X_solved = end_effector_pose(chain, solution.q);
    EXPECT_LT(test::position_error(X_solved, X_target), 1e-8);
    EXPECT_LT(test::rotation_error(X_solved, X_target), 1e-8);
    (solution.q[1] + model.joints[1].dh.theta > 0 ? positive_elbows : negative_elbows) += 1;
    if (!check_nearest) continue;
    // The returned solution is the valid one nearest to q_near.
    double nearest = std::numeric_limits<double>::infinity();
    for (const Eigen::VectorXd& candidate : all_valid_solutions(model, q_true)) {
      nearest = std::min(nearest, (candidate - q_near).norm());
    }
    EXPECT_NEAR((solution.q - q_near).norm(), nearest, 1e-7) << trial;
  }
}

TEST(Ibm7545Ik, RoundTripOnThesisLimits) {
  int positive = 0, negative = 0;
  ibm7545_round_trip(test::make_ibm7545_model(), 21, 400, positive, negative);
  EXPECT_EQ(positive, 400);  // joint 2 is limited to 0..135 deg: only one elbow is valid
}

// Wider limits make both elbows valid and joint values ambiguous by 2 pi, so nearest-to-q_near
// decides between up to a dozen solutions.
TEST(Ibm7545Ik, RoundTripBothElbowsOnWideLimits) {
  RobotModel model = test::make_ibm7545_model();
  model.joints[0].minimum = deg(-270);
  model.joints[0].maximum = deg(270);
  model.joints[1].minimum = deg(-150);
  model.joints[1].maximum = deg(150);
  model.joints[3].minimum = deg(-400);
  model.joints[3].maximum = deg(400);
  int positive = 0, negative = 0;
  ibm7545_round_trip(model, 22, 400, positive, negative);
  EXPECT_GT(positive, 50);
  EXPECT_GT(negative, 50);
}

// DH constant offsets (theta of every joint, d of joints 2 and 3) enter the closed form too.
TEST(Ibm7545Ik, RoundTripWithDhOffsets) {
  RobotModel model = test::make_ibm7545_model();
  model.joints[0].dh.theta = 0.1;
  model.joints[1].dh.theta = -0.2;
  model.joints[1].dh.d = 1.5;
  model.joints[2].dh.theta = 0.3;
  model.joints[2].dh.d = 0.5;
  model.joints[3].dh.theta = 0.05;
  model.joints[1].minimum = deg(-150);
  model.joints[1].maximum = deg(150);
  ASSERT_TRUE(is_ibm7545_structure(model));
  int positive = 0, negative = 0;
  ibm7545_round_trip(model, 23, 300, positive, negative, /*check_nearest=*/false);
  EXPECT_GT(positive, 30);
  EXPECT_GT(negative, 30);
}

}  // namespace
}  // namespace grpvss::kinematics
