#include "grpvss/io/program_orientation.hpp"

#include <cmath>

#include "grpvss/io/units.hpp"

namespace grpvss::io {

Eigen::Quaterniond krl_abc_rotation(double a, double b, double c) {
  return Eigen::Quaterniond(Eigen::AngleAxisd(a, Eigen::Vector3d::UnitZ()) *
                            Eigen::AngleAxisd(b, Eigen::Vector3d::UnitY()) *
                            Eigen::AngleAxisd(c, Eigen::Vector3d::UnitX()));
}

Eigen::Isometry3d krl_frame_pose(double x_mm, double y_mm, double z_mm, double a_degrees,
                                 double b_degrees, double c_degrees) {
  Eigen::Isometry3d pose = Eigen::Isometry3d::Identity();
  pose.linear() = krl_abc_rotation(degrees_to_radians(a_degrees), degrees_to_radians(b_degrees),
                                   degrees_to_radians(c_degrees))
                      .toRotationMatrix();
  pose.translation() = Eigen::Vector3d(millimetres_to_metres(x_mm), millimetres_to_metres(y_mm),
                                       millimetres_to_metres(z_mm));
  return pose;
}

Eigen::Quaterniond rotation_vector_rotation(const Eigen::Vector3d& rotation_vector) {
  const double angle = rotation_vector.norm();
  if (angle == 0.0) return Eigen::Quaterniond::Identity();
  return Eigen::Quaterniond(Eigen::AngleAxisd(angle, rotation_vector / angle));
}

Eigen::Isometry3d urscript_pose(const Eigen::Matrix<double, 6, 1>& p) {
  Eigen::Isometry3d pose = Eigen::Isometry3d::Identity();
  pose.linear() = rotation_vector_rotation(p.tail<3>()).toRotationMatrix();
  pose.translation() = p.head<3>();
  return pose;
}

Eigen::Matrix<double, 6, 1> urscript_pose_vector(const Eigen::Isometry3d& pose) {
  const Eigen::AngleAxisd axis_angle(pose.linear());
  Eigen::Matrix<double, 6, 1> p;
  p.head<3>() = pose.translation();
  p.tail<3>() = axis_angle.axis() * axis_angle.angle();
  return p;
}

std::optional<Eigen::Quaterniond> rapid_quaternion(double q1, double q2, double q3, double q4) {
  const Eigen::Quaterniond q(q1, q2, q3, q4);  // Eigen's constructor takes w first, as RAPID
  const double norm = q.norm();
  if (!std::isfinite(norm) || std::fabs(norm - 1.0) > kRapidQuaternionNormTolerance) {
    return std::nullopt;
  }
  return q.normalized();
}

Eigen::Isometry3d rapid_pose(const Eigen::Vector3d& position_mm, const Eigen::Quaterniond& q) {
  Eigen::Isometry3d pose = Eigen::Isometry3d::Identity();
  pose.linear() = q.toRotationMatrix();
  pose.translation() = position_mm / 1000.0;
  return pose;
}

}  // namespace grpvss::io
