#include "segment_path.hpp"

#include "grpvss/motion/cp_line.hpp"
#include "grpvss/motion/joint_trajectory_source.hpp"

namespace grpvss::certify {

double SegmentPath::time_at(double s) const {
  // A piece ends exactly at its next waypoint's time (start + duration may round past it).
  if (is_trajectory_piece() && s >= parameter_end()) {
    return segment_->joint_motion->piece_breaks()[static_cast<std::size_t>(segment_->number)];
  }
  if (!is_cp()) return segment_->start_time + s;
  const double end = parameter_end();
  return segment_->start_time + (end > 0.0 ? segment_->duration * (s / end) : 0.0);
}

std::optional<Eigen::VectorXd> SegmentPath::q_at(double s, const Eigen::VectorXd& q_previous) const {
  if (is_trajectory_piece()) {
    return motion::step_configuration(*segment_->joint_motion, *robot_, time_at(s));
  }
  // A PTP segment ends at its target exactly (the checker's planned configuration there; the
  // profile at its duration may differ from it by a rounding).
  if (!is_cp()) return s >= parameter_end() ? segment_->q_end : segment_->ptp->joints_at(s);
  if (s <= 0.0) return segment_->q_start;
  if (s >= parameter_end()) return segment_->q_end;
  return motion::solve_within_limits(*robot_, *kinematics_, segment_->cp->pose_at(s), q_previous);
}

Eigen::VectorXd SegmentPath::joint_velocity_at(double s) const {
  if (is_cp()) return Eigen::VectorXd::Zero(robot_->joint_count());
  if (is_trajectory_piece()) return segment_->joint_motion->qdot_at(time_at(s));
  return segment_->ptp->velocities_at(s);
}

Eigen::VectorXd SegmentPath::joint_variation(double s0, double s1) const {
  if (!is_trajectory_piece()) return {};
  return segment_->joint_motion->variation_bound_from_samples(time_at(s0), time_at(s1));
}

}  // namespace grpvss::certify
