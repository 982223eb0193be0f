#pragma once
/// \file
/// \brief Distance between two poses for IK tests: position distance and rotation angle.

#include <algorithm>
#include <cmath>

#include <Eigen/Geometry>

namespace grpvss::test {

inline double position_error(const Eigen::Isometry3d& a, const Eigen::Isometry3d& b) {
  return (a.translation() - b.translation()).norm();
}

/// Angle of a^T b, computed from the quaternion so that small angles are accurate.
inline double rotation_error(const Eigen::Isometry3d& a, const Eigen::Isometry3d& b) {
  Eigen::Quaterniond dq(Eigen::Matrix3d(a.linear().transpose() * b.linear()));
  dq.normalize();
  return 2 * std::atan2(dq.vec().norm(), std::abs(dq.w()));
}

/// World target of the thesis's SCARA sample: position and yaw, tool z pointing down.
inline Eigen::Isometry3d scara_target(double x, double y, double z, double yaw) {
  Eigen::Isometry3d X = Eigen::Isometry3d::Identity();
  X.linear() = (Eigen::AngleAxisd(yaw, Eigen::Vector3d::UnitZ()) *
                Eigen::AngleAxisd(3.14159265358979323846, Eigen::Vector3d::UnitX()))
                   .toRotationMatrix();
  X.translation() = Eigen::Vector3d(x, y, z);
  return X;
}

}  // namespace grpvss::test
