#pragma once
// One segment's configurations as a function of its parameter s: time for PTP, path length
// for CP (docs/verification.md#segment-parameter).

#include <optional>

#include <Eigen/Core>

#include "grpvss/model/robot_model.hpp"
#include "grpvss/motion/kinematics_access.hpp"
#include "grpvss/motion/trajectory.hpp"

namespace grpvss::certify {

class SegmentPath {
 public:
  SegmentPath(const RobotModel& robot, const motion::KinematicsAccess& kinematics,
              const motion::SegmentTrajectory& segment)
      : robot_(&robot), kinematics_(&kinematics), segment_(&segment) {}

  bool is_cp() const { return segment_->kind == motion::SegmentKind::kCpLine; }
  /// A piece of a planner's joint trajectory (parameter: time since the piece's waypoint).
  bool is_trajectory_piece() const { return segment_->joint_motion != nullptr; }
  double parameter_end() const { return is_cp() ? segment_->cp->length() : segment_->duration; }
  /// Path time at parameter s.
  double time_at(double s) const;

  /// PTP: the profile. Trajectory piece: the interpolation at time_at(s). CP: IK of the line's pose nearest the previous step's joints; the end
  /// of the line is the motion stage's own end configuration (the next segment starts there).
  std::optional<Eigen::VectorXd> q_at(double s, const Eigen::VectorXd& q_previous) const;

  /// PTP: the joint velocities at s; CP: zero (the thesis rule's PTP branch only).
  Eigen::VectorXd joint_velocity_at(double s) const;

  /// Trajectory pieces: per joint, V_j >= the total variation of the joint path between the
  /// configurations q_at(s0) and q_at(s1) (the motion between may be non-monotone); the
  /// motion bound multiplies it by the axis radii. Empty for PTP and CP segments (monotone
  /// joints: the increments are the variation).
  /// proof: proofs/joint-variation.md#corollary-sampled-ends
  Eigen::VectorXd joint_variation(double s0, double s1) const;

  const motion::SegmentTrajectory& segment() const { return *segment_; }
  const motion::CpLine& line() const { return *segment_->cp; }

 private:
  const RobotModel* robot_;
  const motion::KinematicsAccess* kinematics_;
  const motion::SegmentTrajectory* segment_;
};

}  // namespace grpvss::certify
