#pragma once
// Private helpers of the closed-form solvers: elementary rotations and angle wrapping.

#include <cmath>

#include <Eigen/Geometry>

namespace grpvss::kinematics::detail {

constexpr double kPi = 3.14159265358979323846;

inline Eigen::Matrix3d rot_x(double angle) {
  return Eigen::AngleAxisd(angle, Eigen::Vector3d::UnitX()).toRotationMatrix();
}
inline Eigen::Matrix3d rot_y(double angle) {
  return Eigen::AngleAxisd(angle, Eigen::Vector3d::UnitY()).toRotationMatrix();
}
inline Eigen::Matrix3d rot_z(double angle) {
  return Eigen::AngleAxisd(angle, Eigen::Vector3d::UnitZ()).toRotationMatrix();
}

/// angle + 2 pi k in (-pi, pi].
inline double wrap_angle(double angle) {
  const double wrapped = std::remainder(angle, 2 * kPi);
  return wrapped <= -kPi ? wrapped + 2 * kPi : wrapped;
}

/// Rotation angle (rad) of R_a^T R_b: how far apart two orientations are. Via the quaternion,
/// so small angles keep full relative precision.
inline double rotation_distance(const Eigen::Matrix3d& R_a, const Eigen::Matrix3d& R_b) {
  Eigen::Quaterniond dq(R_a.transpose() * R_b);
  dq.normalize();
  return 2 * std::atan2(dq.vec().norm(), std::abs(dq.w()));
}

}  // namespace grpvss::kinematics::detail
