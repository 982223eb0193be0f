// The UR model's FK against UR's DH product written out here, its eight inverse branches
// against its FK, and the branch order against the configuration the angles are in.
#include "grpvss/kinematics/ur_kinematics.hpp"

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

UrParameters ur5e_parameters() { return {0.1625, -0.425, -0.3922, 0.1333, 0.0997, 0.0996}; }
UrParameters ur10e() { return {0.1807, -0.6127, -0.57155, 0.17415, 0.11985, 0.11655}; }

// Standard DH through Eigen's elementary transforms (independent of ur_kinematics.cpp).
Eigen::Isometry3d dh(double theta, double d, double a, double alpha) {
  return Eigen::Isometry3d(Eigen::AngleAxisd(theta, Eigen::Vector3d::UnitZ())) *
         Eigen::Translation3d(0, 0, d) * Eigen::Translation3d(a, 0, 0) *
         Eigen::AngleAxisd(alpha, Eigen::Vector3d::UnitX());
}

Eigen::Isometry3d reference_forward(const UrParameters& p, const ModelAngles& t) {
  return dh(t[0], p.d1, 0, kPi / 2) * dh(t[1], 0, p.a2, 0) * dh(t[2], 0, p.a3, 0) *
         dh(t[3], p.d4, 0, kPi / 2) * dh(t[4], p.d5, 0, -kPi / 2) * dh(t[5], p.d6, 0, 0);
}

TEST(UrKinematics, ForwardIsUrsDhProduct) {
  std::mt19937_64 generator(3);
  for (int trial = 0; trial < 200; ++trial) {
    const ModelAngles t = random_angles(generator);
    EXPECT_LE(test::position_error(ur_forward(ur5e_parameters(), t), reference_forward(ur5e_parameters(), t)), 1e-15);
    EXPECT_LE(test::rotation_error(ur_forward(ur5e_parameters(), t), reference_forward(ur5e_parameters(), t)), 1e-15);
  }
}

TEST(UrKinematics, ForwardAtZeroIsTheStretchedArm) {
  // Flange at (a2 + a3, -d4 - d6, d1 - d5), tool z along -y.
  const Eigen::Isometry3d X = ur_forward(ur5e_parameters(), {0, 0, 0, 0, 0, 0});
  EXPECT_NEAR((X.translation() - Eigen::Vector3d(-0.8172, -0.2329, 0.0628)).norm(), 0.0, 1e-15);
  EXPECT_NEAR((X.linear().col(2) - Eigen::Vector3d(0, -1, 0)).norm(), 0.0, 1e-15);
}

TEST(UrKinematics, ArmSidesAreTheWristPointAndElbowHeights) {
  const UrParameters p = ur5e_parameters();
  std::mt19937_64 generator(4);
  for (int trial = 0; trial < 100; ++trial) {
    ModelAngles t = random_angles(generator);
    const UrArmSides sides = ur_arm_sides(p, t);
    t[0] = 0;  // the axis-1 frame is B's
    const Eigen::Isometry3d X = ur_forward(p, t);
    const Eigen::Vector3d p5 = X.translation() - p.d6 * X.linear().col(2);
    EXPECT_NEAR(sides.wrist_ahead_of_axis1, p5.x(), 1e-14);
    // Arm plane coordinates (x, z - d1): elbow E and axis-4 point P4, cross P4 x E.
    const Eigen::Vector2d E(p.a2 * std::cos(t[1]), p.a2 * std::sin(t[1]));
    const Eigen::Vector2d P4 = E + p.a3 * Eigen::Vector2d(std::cos(t[1] + t[2]), std::sin(t[1] + t[2]));
    EXPECT_NEAR(sides.elbow_over_chord, P4.x() * E.y() - P4.y() * E.x(), 1e-14);
  }
}

void expect_ur_round_trip(const UrParameters& p, std::uint64_t seed) {
  std::mt19937_64 generator(seed);
  for (int trial = 0; trial < 1000; ++trial) {
    const ModelAngles t = random_angles(generator);
    const Eigen::Isometry3d X = ur_forward(p, t);
    const std::array<ModelBranch, 8> branches = ur_inverse(p, X);
    int matches = 0;
    for (std::size_t i = 0; i < 8; ++i) {
      if (!branches[i].valid) continue;  // the planar arm may not reach on the other shoulder
      const Eigen::Isometry3d X_i = ur_forward(p, branches[i].theta);
      EXPECT_LE(test::position_error(X_i, X), 1e-12);
      EXPECT_LE(test::rotation_error(X_i, X), 1e-12);
      const ArmConfiguration c = ur_configuration(p, branches[i].theta);
      const bool negative_x = i & 4, second_elbow = i & 2, negative_sin5 = i & 1;
      EXPECT_EQ(c.shoulder, negative_x ? Shoulder::kLeft : Shoulder::kRight);  // d4 > 0
      // a2 a3 > 0: the second elbow (sin t3 < 0) is above the chord on the right shoulder.
      EXPECT_EQ(c.elbow, negative_x != second_elbow ? Elbow::kUp : Elbow::kDown);
      EXPECT_EQ(c.wrist, negative_sin5 ? Wrist::kDown : Wrist::kUp);
      bool same = true;
      for (std::size_t j = 0; j < 6; ++j) same = same && angle_difference(branches[i].theta[j], t[j]) <= 1e-9;
      matches += same;
    }
    EXPECT_EQ(matches, 1) << "trial " << trial;
  }
}

TEST(UrKinematics, EveryBranchReachesThePoseAndOneIsTheOriginal) {
  expect_ur_round_trip(ur5e_parameters(), 21);
  expect_ur_round_trip(ur10e(), 22);
}

TEST(UrKinematics, WristSingularPoseTakesTheGivenTheta6) {
  const UrParameters p = ur5e_parameters();
  const ModelAngles t = {0.2, -1.0, 1.1, 0.4, 0.0, 0.7};
  const Eigen::Isometry3d X = ur_forward(p, t);
  bool found = false;
  for (const ModelBranch& branch : ur_inverse(p, X, 0.7)) {
    if (!branch.valid) continue;
    for (double value : branch.theta) ASSERT_TRUE(std::isfinite(value));
    EXPECT_LE(test::position_error(ur_forward(p, branch.theta), X), 1e-12);
    EXPECT_LE(test::rotation_error(ur_forward(p, branch.theta), X), 1e-12);
    bool same = true;
    for (std::size_t j = 0; j < 6; ++j) same = same && angle_difference(branch.theta[j], t[j]) <= 1e-12;
    found = found || same;
  }
  EXPECT_TRUE(found);
}

TEST(UrKinematics, ShoulderSingularPoseHasBothShouldersEqual) {
  // P5 exactly d4 from axis 1 (P5 . x1 = 0): the two theta_1 coincide.
  const UrParameters p = ur5e_parameters();
  Eigen::Isometry3d X = Eigen::Isometry3d::Identity();
  X.linear() = Eigen::AngleAxisd(kPi / 2, Eigen::Vector3d::UnitY()).toRotationMatrix();
  X.translation() = Eigen::Vector3d(0.0, -p.d4, 0.45) + p.d6 * X.linear().col(2);
  const std::array<ModelBranch, 8> branches = ur_inverse(p, X);
  int valid = 0;
  for (std::size_t i = 0; i < 8; ++i) {
    if (!branches[i].valid) continue;
    ++valid;
    for (double value : branches[i].theta) ASSERT_TRUE(std::isfinite(value));
    EXPECT_LE(test::position_error(ur_forward(p, branches[i].theta), X), 1e-12);
    EXPECT_LE(test::rotation_error(ur_forward(p, branches[i].theta), X), 1e-12);
    if (i < 4) {
      EXPECT_NEAR(angle_difference(branches[i].theta[0], branches[i + 4].theta[0]), 0.0, 1e-15);
    }
  }
  EXPECT_EQ(valid, 8);
}

TEST(UrKinematics, UnreachablePosesHaveNoBranch) {
  Eigen::Isometry3d far = Eigen::Isometry3d::Identity();
  far.translation() = Eigen::Vector3d(2.0, 0.0, 0.5);
  for (const ModelBranch& branch : ur_inverse(ur5e_parameters(), far)) EXPECT_FALSE(branch.valid);
  // P5 nearer axis 1 than d4: no theta_1 at all.
  Eigen::Isometry3d inside = Eigen::Isometry3d::Identity();
  inside.translation() = Eigen::Vector3d(0.05, 0.0, 0.5 + ur5e_parameters().d6);
  for (const ModelBranch& branch : ur_inverse(ur5e_parameters(), inside)) EXPECT_FALSE(branch.valid);
}

}  // namespace
}  // namespace grpvss::kinematics
