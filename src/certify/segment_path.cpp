#include "segment_path.hpp"

#include "grpvss/motion/cp_line.hpp"

namespace grpvss::certify {

double SegmentPath::time_at(double s) const {
  if (!is_cp()) return segment_->start_time + s;
  const double end = parameter_end();
  return segment_->start_time + (end > 0.0 ? segment_->duration * (s / end) : 0.0);
}

std::optional<Eigen::VectorXd> SegmentPath::q_at(double s, const Eigen::VectorXd& q_previous) const {
  if (!is_cp()) return segment_->ptp->joints_at(s);
  if (s <= 0.0) return segment_->q_start;
  if (s >= parameter_end()) return segment_->q_end;
  return motion::solve_within_limits(*robot_, *kinematics_, segment_->cp->pose_at(s), q_previous);
}

Eigen::VectorXd SegmentPath::joint_velocity_at(double s) const {
  if (is_cp()) return Eigen::VectorXd::Zero(robot_->joint_count());
  return segment_->ptp->velocities_at(s);
}

}  // namespace grpvss::certify
