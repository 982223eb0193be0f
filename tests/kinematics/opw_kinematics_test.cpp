// The OPW model's FK against hand values, its eight inverse branches against its FK, and the
// branch order against the configuration the angles are in.
#include "grpvss/kinematics/opw_kinematics.hpp"

#include <cmath>
#include <random>

#include <gtest/gtest.h>

#include "grpvss/kinematics/arm_configuration.hpp"
#include "support/angles.hpp"
#include "support/model_angles.hpp"
#include "support/pose_error.hpp"

namespace grpvss::kinematics {
namespace {

using grpvss::test::angle_difference;
using grpvss::test::kPi;
using grpvss::test::random_angles;

// ABB IRB 2400/10, metres (Brandstoetter et al. 2014).
OpwParameters irb2400() { return {0.100, -0.135, 0.0, 0.615, 0.705, 0.755, 0.085}; }
// An arm with every length non-zero, the shoulder offset b included.
OpwParameters skewed() { return {0.15, -0.04, 0.09, 0.5, 0.6, 0.55, 0.1}; }

TEST(OpwKinematics, ForwardAtZeroPlacesTheFlangeAboveTheWristCentre) {
  const Eigen::Isometry3d X = opw_forward(irb2400(), {0, 0, 0, 0, 0, 0});
  // C = (a1 + a2, b, c1 + c2 + c3), flange c4 above, orientation of B.
  EXPECT_NEAR((X.translation() - Eigen::Vector3d(-0.035, 0.0, 2.16)).norm(), 0.0, 1e-15);
  EXPECT_NEAR((X.linear() - Eigen::Matrix3d::Identity()).norm(), 0.0, 1e-15);
}

TEST(OpwKinematics, ForwardWithForearmLevelMatchesTheIrb2400Drawing) {
  // theta_3 = 90 deg: the forearm points forward; wrist centre at x = a1 + c3, z = c1 + c2 - a2,
  // theta_5 = 90 deg then turns the flange down.
  const Eigen::Isometry3d X = opw_forward(irb2400(), {0, 0, kPi / 2, 0, kPi / 2, 0});
  EXPECT_NEAR((X.translation() - Eigen::Vector3d(0.855, 0.0, 1.455 - 0.085)).norm(), 0.0, 1e-15);
  EXPECT_NEAR((X.linear().col(2) - Eigen::Vector3d(0, 0, -1)).norm(), 0.0, 1e-15);
}

TEST(OpwKinematics, ArmSidesAreTheWristCentreCoordinates) {
  const OpwParameters p = skewed();
  std::mt19937_64 generator(1);
  for (int trial = 0; trial < 100; ++trial) {
    ModelAngles t = random_angles(generator);
    const OpwArmSides sides = opw_arm_sides(p, t);
    t[0] = 0;  // axis-1 frame = B
    const Eigen::Isometry3d X = opw_forward(p, t);
    const Eigen::Vector3d c = X.translation() - p.c4 * X.linear().col(2);
    EXPECT_NEAR(sides.wrist_ahead_of_axis1, c.x(), 1e-14);
    // In front of the lower arm: along the lower arm's normal Ry(t2 + 90 deg) z.
    const Eigen::Vector3d elbow(p.a1 + p.c2 * std::sin(t[1]), p.b, p.c1 + p.c2 * std::cos(t[1]));
    const Eigen::Vector3d normal(std::cos(t[1]), 0, -std::sin(t[1]));
    EXPECT_NEAR(sides.wrist_ahead_of_lower_arm, normal.dot(c - elbow), 1e-14);
  }
}

void expect_round_trip(const OpwParameters& p, std::uint64_t seed) {
  std::mt19937_64 generator(seed);
  for (int trial = 0; trial < 1000; ++trial) {
    const ModelAngles t = random_angles(generator);
    const Eigen::Isometry3d X = opw_forward(p, t);
    const std::array<ModelBranch, 8> branches = opw_inverse(p, X);
    int matches = 0;
    int valid = 0;
    for (std::size_t i = 0; i < 8; ++i) {
      // The other shoulder's arm may not reach (its distance from axis 2 differs by 2 a1).
      if (!branches[i].valid) continue;
      ++valid;
      const Eigen::Isometry3d X_i = opw_forward(p, branches[i].theta);
      EXPECT_LE(test::position_error(X_i, X), 1e-12);
      EXPECT_LE(test::rotation_error(X_i, X), 1e-12);
      // Index 4 s + 2 e + w against the configuration the branch's angles are in.
      const ArmConfiguration c = opw_configuration(p, branches[i].theta);
      const bool back = i & 4, second_elbow = i & 2, flip = i & 1;
      EXPECT_EQ(c.shoulder, back ? Shoulder::kBack : Shoulder::kFront);
      EXPECT_EQ(c.elbow, back == second_elbow ? Elbow::kUp : Elbow::kDown);
      EXPECT_EQ(c.wrist, flip ? Wrist::kFlip : Wrist::kNoFlip);
      bool same = true;
      for (std::size_t j = 0; j < 6; ++j) same = same && angle_difference(branches[i].theta[j], t[j]) <= 1e-9;
      matches += same;
    }
    EXPECT_EQ(matches, 1) << "the original angles are exactly one branch, trial " << trial;
    EXPECT_TRUE(valid == 4 || valid == 8) << "trial " << trial;
  }
}

TEST(OpwKinematics, EveryBranchReachesThePoseAndOneIsTheOriginal) {
  expect_round_trip(irb2400(), 11);
  expect_round_trip(skewed(), 12);
}

TEST(OpwKinematics, WristSingularPoseTakesTheGivenTheta4) {
  const OpwParameters p = skewed();
  const ModelAngles t = {0.3, -0.4, 1.1, 0.9, 0.0, -0.5};
  const Eigen::Isometry3d X = opw_forward(p, t);
  const std::array<ModelBranch, 8> branches = opw_inverse(p, X, {0.0, 0.9});
  bool found = false;
  for (const ModelBranch& branch : branches) {
    ASSERT_TRUE(branch.valid);
    for (double value : branch.theta) ASSERT_TRUE(std::isfinite(value));
    EXPECT_LE(test::position_error(opw_forward(p, branch.theta), X), 1e-12);
    EXPECT_LE(test::rotation_error(opw_forward(p, branch.theta), X), 1e-12);
    bool same = true;
    for (std::size_t j = 0; j < 6; ++j) same = same && angle_difference(branch.theta[j], t[j]) <= 1e-12;
    found = found || same;
  }
  EXPECT_TRUE(found);
}

TEST(OpwKinematics, WristCentreOnAxis1TakesTheGivenTheta1) {
  OpwParameters p = irb2400();
  // Flange straight up over axis 1: the wrist centre is on axis 1, theta_1 is free.
  Eigen::Isometry3d X = Eigen::Isometry3d::Identity();
  X.translation() = Eigen::Vector3d(0, 0, 1.6 + p.c4);
  const std::array<ModelBranch, 8> branches = opw_inverse(p, X, {0.7, 0.0});
  int valid = 0;
  for (const ModelBranch& branch : branches) {
    if (!branch.valid) continue;
    ++valid;
    for (double value : branch.theta) ASSERT_TRUE(std::isfinite(value));
    EXPECT_TRUE(angle_difference(branch.theta[0], 0.7) <= 1e-15 ||
                angle_difference(branch.theta[0], 0.7 + kPi) <= 1e-15);
    EXPECT_LE(test::position_error(opw_forward(p, branch.theta), X), 1e-12);
    EXPECT_LE(test::rotation_error(opw_forward(p, branch.theta), X), 1e-12);
  }
  EXPECT_EQ(valid, 8);
}

TEST(OpwKinematics, StretchedElbowGivesCoincidingElbowBranches) {
  const OpwParameters p = irb2400();
  const double stretched = -std::atan2(p.a2, p.c3);  // theta_3 + psi_3 = 0
  const ModelAngles t = {0.2, 0.3, stretched, 0.4, 0.5, 0.6};
  const Eigen::Isometry3d X = opw_forward(p, t);
  const std::array<ModelBranch, 8> branches = opw_inverse(p, X);
  for (const ModelBranch& branch : branches) {
    if (!branch.valid) continue;
    for (double value : branch.theta) ASSERT_TRUE(std::isfinite(value));
    EXPECT_LE(test::position_error(opw_forward(p, branch.theta), X), 1e-12);
    EXPECT_LE(test::rotation_error(opw_forward(p, branch.theta), X), 1e-9);
  }
  // The original's shoulder: both elbow branches exist and are the same arm angles.
  for (std::size_t w = 0; w < 2; ++w) {
    ASSERT_TRUE(branches[w].valid && branches[2 + w].valid);
    EXPECT_NEAR(angle_difference(branches[w].theta[2], branches[2 + w].theta[2]), 0.0, 1e-7);
    EXPECT_NEAR(angle_difference(branches[w].theta[2], stretched), 0.0, 1e-7);
  }
}

TEST(OpwKinematics, UnreachablePosesHaveNoBranch) {
  Eigen::Isometry3d far = Eigen::Isometry3d::Identity();
  far.translation() = Eigen::Vector3d(3.0, 0.0, 1.0);  // beyond c2 + k
  for (const ModelBranch& branch : opw_inverse(irb2400(), far)) EXPECT_FALSE(branch.valid);
  // With b != 0 the wrist centre cannot come nearer axis 1 than |b|.
  Eigen::Isometry3d inside = Eigen::Isometry3d::Identity();
  inside.translation() = Eigen::Vector3d(0.03, 0.0, 1.0 + skewed().c4);
  for (const ModelBranch& branch : opw_inverse(skewed(), inside)) EXPECT_FALSE(branch.valid);
}

}  // namespace
}  // namespace grpvss::kinematics
