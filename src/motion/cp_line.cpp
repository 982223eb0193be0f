#include "grpvss/motion/cp_line.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <utility>

#include <fmt/core.h>

namespace grpvss::motion {

Eigen::Matrix3d rotation_about(const Eigen::Vector3d& axis, double angle) {
  const double norm = axis.norm();
  if (angle == 0.0 || norm == 0.0) return Eigen::Matrix3d::Identity();
  return Eigen::AngleAxisd(angle, axis / norm).toRotationMatrix();
}

Eigen::Isometry3d world_target_pose(const Eigen::Isometry3d& X_WE_start,
                                    const WorldTarget& target) {
  Eigen::Isometry3d X_WE = Eigen::Isometry3d::Identity();
  const Eigen::Matrix3d rotation = rotation_about(target.axis_W, target.angle);
  X_WE.linear() = target.orientation_is_absolute ? rotation : rotation * X_WE_start.linear();
  X_WE.translation() = target.position_W;
  return X_WE;
}

Eigen::AngleAxisd orientation_change_W(const Eigen::Isometry3d& X_WE_start, const WorldTarget& target) {
  if (!target.orientation_is_absolute) {
    if (target.angle == 0.0 || target.axis_W.norm() == 0.0) return Eigen::AngleAxisd(0.0, Eigen::Vector3d::Zero());
    return Eigen::AngleAxisd(target.angle, target.axis_W.normalized());
  }
  // The shortest turn from the start orientation to R_WE (angle in [0, pi]).
  const Eigen::AngleAxisd change(rotation_about(target.axis_W, target.angle) *
                                 X_WE_start.linear().transpose());
  return change.angle() == 0.0 ? Eigen::AngleAxisd(0.0, Eigen::Vector3d::Zero()) : change;
}

CpLine::CpLine(const Eigen::Isometry3d& X_WE_start, const WorldTarget& target)
    : X_WE_start_(X_WE_start),
      p_W_end_(target.position_W),
      axis_W_(orientation_change_W(X_WE_start, target).axis()),
      angle_(orientation_change_W(X_WE_start, target).angle()),
      length_((target.position_W - X_WE_start.translation()).norm()) {}

Eigen::Isometry3d CpLine::pose_at(double l) const {
  if (is_zero_length()) throw std::logic_error("CpLine::pose_at on a zero-length line");
  const double fraction = std::clamp(l, 0.0, length_) / length_;
  Eigen::Isometry3d X_WE = Eigen::Isometry3d::Identity();
  const Eigen::Vector3d p_W_start = X_WE_start_.translation();
  X_WE.translation() = fraction == 1.0 ? p_W_end_ : p_W_start + (p_W_end_ - p_W_start) * fraction;
  X_WE.linear() = rotation_about(axis_W_, angle_ * fraction) * X_WE_start_.linear();
  return X_WE;
}

std::optional<Eigen::VectorXd> solve_within_limits(const RobotModel& robot,
                                                   const KinematicsAccess& kinematics,
                                                   const Eigen::Isometry3d& X_WE,
                                                   const Eigen::VectorXd& q_near) {
  std::optional<Eigen::VectorXd> q = kinematics.inverse(X_WE, q_near);
  if (!q || q->size() != robot.joint_count() || !q->allFinite()) return std::nullopt;
  if (first_joint_outside_limits(robot, *q) >= 0) return std::nullopt;
  return q;
}

CpSampling sample_cp_line(const RobotModel& robot, const KinematicsAccess& kinematics,
                          const CpLine& line, const Eigen::VectorXd& q_start, double spacing,
                          int segment) {
  if (!(spacing > 0.0) || !std::isfinite(spacing))
    throw std::invalid_argument("sample_cp_line: spacing must be positive and finite");
  const bool in_path = segment > 0;
  CpSampling result;
  if (line.is_zero_length()) {
    result.error = make_thesis_error(in_path ? 4 : 1, segment,
                                     fmt::format("line length {:.3g}", line.length()));
    return result;
  }
  // The thesis refuses a segment whose final position is out of workspace before moving.
  if (!solve_within_limits(robot, kinematics, line.end_pose(), q_start)) {
    const Eigen::Vector3d p = line.end_pose().translation();
    result.error = make_thesis_error(
        in_path ? 3 : 2, segment,
        fmt::format("no IK solution within the joint limits at ({:.2f}, {:.2f}, {:.2f})", p.x(),
                    p.y(), p.z()));
    return result;
  }
  const int pieces = std::max(1, static_cast<int>(std::ceil(line.length() / spacing)));
  result.samples.reserve(static_cast<std::size_t>(pieces) + 1);
  result.samples.push_back({0.0, q_start});
  for (int k = 1; k <= pieces; ++k) {
    const double l = k == pieces ? line.length() : line.length() * k / pieces;
    auto q = solve_within_limits(robot, kinematics, line.pose_at(l), result.samples.back().q);
    if (!q) {
      const Eigen::Vector3d p = line.pose_at(l).translation();
      result.error = make_thesis_error(
          in_path ? 5 : 2, segment,
          fmt::format("no IK solution within the joint limits at l = {:.3f} of {:.3f}, point "
                      "({:.2f}, {:.2f}, {:.2f})",
                      l, line.length(), p.x(), p.y(), p.z()));
      return result;
    }
    result.samples.push_back({l, std::move(*q)});
  }
  return result;
}

}  // namespace grpvss::motion
