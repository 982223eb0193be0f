/// The orientation conventions of the three languages, checked against references written
/// out here by hand (closed-form rotation matrices), not against the code under test.

#include "grpvss/io/program_orientation.hpp"

#include <cmath>
#include <tuple>

#include <gtest/gtest.h>

#include "io/program_references.hpp"

namespace grpvss::io {
namespace {

using grpvss::testing::krl_reference;
using grpvss::testing::kPi;
using grpvss::testing::quaternion_reference;
using grpvss::testing::rodrigues_reference;

constexpr double kTolerance = 1e-15;

void expect_near(const Eigen::Matrix3d& actual, const Eigen::Matrix3d& expected, double tolerance) {
  grpvss::testing::expect_matrix_near(actual, expected, tolerance);
}

TEST(ProgramOrientation, KrlA90MapsXToY) {
  const Eigen::Matrix3d R = krl_abc_rotation(kPi / 2, 0, 0).toRotationMatrix();
  expect_near(R, (Eigen::Matrix3d() << 0, -1, 0, 1, 0, 0, 0, 0, 1).finished(), kTolerance);
  EXPECT_LE((R * Eigen::Vector3d::UnitX() - Eigen::Vector3d::UnitY()).norm(), kTolerance);
}

TEST(ProgramOrientation, KrlB90TurnsZTowardsX) {
  // B is about the new Y: z goes to x, x goes to -z.
  const Eigen::Matrix3d R = krl_abc_rotation(0, kPi / 2, 0).toRotationMatrix();
  EXPECT_LE((R * Eigen::Vector3d::UnitZ() - Eigen::Vector3d::UnitX()).norm(), kTolerance);
  EXPECT_LE((R * Eigen::Vector3d::UnitX() + Eigen::Vector3d::UnitZ()).norm(), kTolerance);
}

TEST(ProgramOrientation, KrlAbcIsZThenNewYThenNewX) {
  for (const auto& [a, b, c] : {std::tuple{30.0, 20.0, 10.0}, std::tuple{-120.0, 45.0, 170.0},
                                std::tuple{90.0, 0.0, 180.0}, std::tuple{10.0, -89.0, -35.0}}) {
    const double ar = a * kPi / 180, br = b * kPi / 180, cr = c * kPi / 180;
    expect_near(krl_abc_rotation(ar, br, cr).toRotationMatrix(), krl_reference(ar, br, cr), 1e-15);
  }
}

TEST(ProgramOrientation, KrlFramePoseIsMetresAndDegrees) {
  const Eigen::Isometry3d pose = krl_frame_pose(1200, -50, 100, 90, 0, 0);
  EXPECT_EQ(pose.translation(), Eigen::Vector3d(1.2, -0.05, 0.1));
  expect_near(pose.linear(), krl_reference(kPi / 2, 0, 0), kTolerance);
}

TEST(ProgramOrientation, UrRotationVectorQuarterTurnAboutZMapsXToY) {
  const Eigen::Matrix3d R = rotation_vector_rotation({0, 0, kPi / 2}).toRotationMatrix();
  EXPECT_LE((R * Eigen::Vector3d::UnitX() - Eigen::Vector3d::UnitY()).norm(), kTolerance);
  expect_near(R, rodrigues_reference({0, 0, kPi / 2}), kTolerance);
}

TEST(ProgramOrientation, UrRotationVectorsMatchRodrigues) {
  for (const Eigen::Vector3d& r : {Eigen::Vector3d(0, kPi, 0), Eigen::Vector3d(0.1, -0.2, 0.3),
                                   Eigen::Vector3d(2.0, 1.0, -1.5), Eigen::Vector3d(0, 0, 0)}) {
    expect_near(rotation_vector_rotation(r).toRotationMatrix(), rodrigues_reference(r), 1e-15);
  }
}

TEST(ProgramOrientation, UrPoseVectorRoundTrips) {
  Eigen::Matrix<double, 6, 1> p;
  p << 0.4, -0.2, 0.3, 0.1, -0.7, 1.2;
  const Eigen::Matrix<double, 6, 1> back = urscript_pose_vector(urscript_pose(p));
  EXPECT_LE((back - p).cwiseAbs().maxCoeff(), 1e-15);
}

TEST(ProgramOrientation, RapidQuaternionIsWFirst) {
  // [q1, q2, q3, q4] = [cos 45, 0, 0, sin 45]: a quarter turn about z, x to y.
  const auto q = rapid_quaternion(std::sqrt(0.5), 0, 0, std::sqrt(0.5));
  ASSERT_TRUE(q.has_value());
  const Eigen::Matrix3d R = q->toRotationMatrix();
  EXPECT_LE((R * Eigen::Vector3d::UnitX() - Eigen::Vector3d::UnitY()).norm(), 1e-15);
  expect_near(R, quaternion_reference(std::sqrt(0.5), 0, 0, std::sqrt(0.5)), 1e-15);
  // [0, 0, 1, 0]: half a turn about y (the usual "tool pointing down").
  expect_near(rapid_quaternion(0, 0, 1, 0)->toRotationMatrix(),
              (Eigen::Matrix3d() << -1, 0, 0, 0, 1, 0, 0, 0, -1).finished(), 0.0);
}

TEST(ProgramOrientation, RapidQuaternionNormalisesWithinToleranceAndRejectsBeyond) {
  const auto rounded = rapid_quaternion(0.707106781, 0, 0.707106781, 0);  // 9 digits, as written
  ASSERT_TRUE(rounded.has_value());
  EXPECT_NEAR(rounded->norm(), 1.0, 1e-15);
  EXPECT_FALSE(rapid_quaternion(1, 0, 0, 0.1).has_value());       // norm 1.005
  EXPECT_FALSE(rapid_quaternion(0, 0, 0, 0).has_value());
  EXPECT_TRUE(rapid_quaternion(1.0009, 0, 0, 0).has_value());     // within 1e-3
  EXPECT_FALSE(rapid_quaternion(1.0011, 0, 0, 0).has_value());
}

TEST(ProgramOrientation, RapidPoseIsMillimetresToMetres) {
  const Eigen::Isometry3d pose = rapid_pose({600, -300, 200}, Eigen::Quaterniond::Identity());
  EXPECT_EQ(pose.translation(), Eigen::Vector3d(0.6, -0.3, 0.2));
}

}  // namespace
}  // namespace grpvss::io
