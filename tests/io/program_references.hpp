#pragma once
// Independent references for the robot-program reader tests: rotation matrices written out by
// hand (not through the code under test) and comparisons of poses and targets.

#include <cmath>
#include <string>
#include <variant>

#include <Eigen/Geometry>
#include <gtest/gtest.h>

#include "grpvss/model/robot_program.hpp"
#include "support/angles.hpp"

namespace grpvss::testing {

using grpvss::test::kPi;
inline constexpr double kDegree = kPi / 180.0;

/// KUKA's A, B, C written out: R = Rz(A) Ry(B) Rx(C), multiplied by hand.
inline Eigen::Matrix3d krl_reference(double a, double b, double c) {
  const double ca = std::cos(a), sa = std::sin(a), cb = std::cos(b), sb = std::sin(b);
  const double cc = std::cos(c), sc = std::sin(c);
  Eigen::Matrix3d R;
  R << ca * cb, ca * sb * sc - sa * cc, ca * sb * cc + sa * sc,
       sa * cb, sa * sb * sc + ca * cc, sa * sb * cc - ca * sc,
       -sb, cb * sc, cb * cc;
  return R;
}

/// Rodrigues' formula for a rotation vector r = angle * axis.
inline Eigen::Matrix3d rodrigues_reference(const Eigen::Vector3d& r) {
  const double angle = r.norm();
  if (angle == 0) return Eigen::Matrix3d::Identity();
  const Eigen::Vector3d k = r / angle;
  Eigen::Matrix3d K;
  K << 0, -k.z(), k.y(), k.z(), 0, -k.x(), -k.y(), k.x(), 0;
  return Eigen::Matrix3d::Identity() + std::sin(angle) * K + (1 - std::cos(angle)) * K * K;
}

/// The rotation matrix of a quaternion (w, x, y, z), normalised first, written out.
inline Eigen::Matrix3d quaternion_reference(double w, double x, double y, double z) {
  const double n = std::sqrt(w * w + x * x + y * y + z * z);
  w /= n, x /= n, y /= n, z /= n;
  Eigen::Matrix3d R;
  R << 1 - 2 * (y * y + z * z), 2 * (x * y - w * z), 2 * (x * z + w * y),
       2 * (x * y + w * z), 1 - 2 * (x * x + z * z), 2 * (y * z - w * x),
       2 * (x * z - w * y), 2 * (y * z + w * x), 1 - 2 * (x * x + y * y);
  return R;
}

/// A rotation about a coordinate axis (0 = x, 1 = y, 2 = z), written out.
inline Eigen::Matrix3d axis_rotation(int axis, double angle) {
  const double c = std::cos(angle), s = std::sin(angle);
  Eigen::Matrix3d R;
  if (axis == 0) R << 1, 0, 0, 0, c, -s, 0, s, c;
  if (axis == 1) R << c, 0, s, 0, 1, 0, -s, 0, c;
  if (axis == 2) R << c, -s, 0, s, c, 0, 0, 0, 1;
  return R;
}

inline void expect_matrix_near(const Eigen::Matrix3d& actual, const Eigen::Matrix3d& expected,
                               double tolerance) {
  EXPECT_LE((actual - expected).cwiseAbs().maxCoeff(), tolerance)
      << actual << "\nexpected\n" << expected;
}

inline void expect_vector_near(const Eigen::Vector3d& actual, const Eigen::Vector3d& expected,
                               double tolerance) {
  EXPECT_LE((actual - expected).cwiseAbs().maxCoeff(), tolerance)
      << actual.transpose() << "\nexpected " << expected.transpose();
}

/// The Cartesian target (fails the test if the target holds joints).
inline const CartesianTarget& cartesian(const ProgramTarget& target) {
  static const CartesianTarget kNone;
  const auto* cartesian = std::get_if<CartesianTarget>(&target);
  EXPECT_NE(cartesian, nullptr) << "a joint target where a Cartesian one was expected";
  return cartesian ? *cartesian : kNone;
}

/// The joint values (fails the test if the target is Cartesian).
inline Eigen::VectorXd joints(const ProgramTarget& target) {
  const auto* joint = std::get_if<JointTarget>(&target);
  EXPECT_NE(joint, nullptr) << "a Cartesian target where a joint one was expected";
  return joint ? joint->q : Eigen::VectorXd();
}

inline Eigen::VectorXd vector6(double a, double b, double c, double d, double e, double f) {
  Eigen::VectorXd q(6);
  q << a, b, c, d, e, f;
  return q;
}

inline void expect_warning(const ProgramWarning& warning, const std::string& file, int line,
                           const std::string& text) {
  EXPECT_EQ(warning.file, file);
  EXPECT_EQ(warning.line, line);
  EXPECT_EQ(warning.text, text);
}

}  // namespace grpvss::testing
