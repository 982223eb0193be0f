#include "cp_model_check.hpp"

#include <algorithm>
#include <cmath>
#include <optional>

#include <Eigen/Eigenvalues>

#include "grpvss/kinematics/jacobian.hpp"
#include "grpvss/motion/cp_line.hpp"

namespace grpvss::certify {

CpModelCheck::CpModelCheck(const RobotCell& cell, const CpModelSettings& settings)
    : cell_(&cell),
      settings_(settings),
      workspace_(kinematics::Workspace::frames_only(cell.chain().joints.size())) {
  for (const HullPoints& hull : cell.robot().links.back().hulls) {
    for (const auto& p_L : hull.points) end_link_reach_ = std::max(end_link_reach_, p_L.norm());
  }
}

double CpModelCheck::deviation(const SegmentPath& path, double s0, const Eigen::VectorXd& q0,
                               double s1, const Eigen::VectorXd& q1) const {
  // Position: the tolerance (times a fraction). Orientation: the angle that moves the farthest
  // point of the last link's hulls by that much (a joint-4 wrap of 360 degrees moves no
  // origin but sweeps the whole tool).
  const double limit = settings_.deviation_fraction * cell_->tolerance();
  const double angle_limit = limit / end_link_reach_;
  double deviation = 0.0;
  for (const double fraction : {0.25, 0.5, 0.75}) {
    q_mid_ = q0 + fraction * (q1 - q0);
    const Eigen::Isometry3d X_WE_joint_linear = kinematics::end_effector_pose(cell_->chain(), q_mid_);
    const Eigen::Isometry3d X_WE_line = path.line().pose_at(s0 + fraction * (s1 - s0));
    const Eigen::AngleAxisd rotation_error(X_WE_line.linear().transpose() *
                                           X_WE_joint_linear.linear());
    deviation = std::max({deviation,
                          (X_WE_joint_linear.translation() - X_WE_line.translation()).norm() / limit,
                          std::abs(rotation_error.angle()) / angle_limit});
    if (!(deviation <= 1.0)) return deviation;  // NaN too: the model fails
  }
  return deviation;
}

double CpModelCheck::reach(const SegmentPath& path, double s, const Eigen::VectorXd& q,
                           double s_failing, double resolution) const {
  // Invariant: the model holds from s to s + low (trivially at 0) and fails to s_failing.
  double low = 0.0;
  double high = s_failing - s;
  while (high - low > resolution) {
    const double middle = 0.5 * (low + high);
    const std::optional<Eigen::VectorXd> q_middle = path.q_at(s + middle, q);
    (q_middle && holds(path, s, q, s + middle, *q_middle) ? low : high) = middle;
  }
  return low;
}

bool CpModelCheck::near_singularity(const Eigen::VectorXd& q) {
  kinematics::forward_kinematics(cell_->chain(), q, workspace_);
  const Eigen::Matrix<double, 3, Eigen::Dynamic> jacobian = kinematics::point_jacobian(
      cell_->chain(), workspace_, cell_->robot().joint_count(), Eigen::Vector3d::Zero());
  if (jacobian.cols() < 3) return false;
  // The smallest singular value of the 3 x n Jacobian is the square root of the smallest
  // eigenvalue of J J^T (3 x 3, closed form): a tenth of an SVD's cost. Its rounding, about
  // eps |J|^2 in the eigenvalue, is ~1e-11 in sigma at the 1e-3 threshold.
  const Eigen::Matrix3d gram = jacobian * jacobian.transpose();
  Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> eigen;
  eigen.computeDirect(gram, Eigen::EigenvaluesOnly);
  const double threshold = settings_.singular_value_threshold;
  return eigen.eigenvalues()(0) < threshold * threshold;
}

bool CpModelCheck::unreachable_next_to_a_limit(const SegmentPath& path, double s,
                                               const Eigen::VectorXd& q) const {
  // Joint values are clamped to their limits by PTP targets, so a CP segment may start with a
  // joint exactly at one; elsewhere a step landing on a limit is rare. Only then the line is
  // probed, at distances far below a step (IK only, no probe).
  constexpr double kLimitBand = 1e-6;
  const RobotModel& robot = cell_->robot();
  bool at_limit = false;
  for (int j = 0; j < robot.joint_count(); ++j) {
    const Joint& joint = robot.joints[static_cast<std::size_t>(j)];
    at_limit |= std::abs(q[j] - joint.minimum) <= kLimitBand ||
                std::abs(q[j] - joint.maximum) <= kLimitBand;
  }
  if (!at_limit) return false;
  const double left = path.parameter_end() - s;
  for (const double ahead : {cell_->tolerance() / 64.0, cell_->tolerance() / 8.0}) {
    if (!(ahead < left)) break;
    if (!path.q_at(s + ahead, q)) return true;
  }
  return false;
}

}  // namespace grpvss::certify
