#pragma once
/// \file
/// \brief Position and velocity limits along the interpolation of a joint trajectory,
/// decided exactly. A cubic Hermite piece can overshoot its waypoints, so waypoints within
/// the limits do not make the motion stay within them; the motion bound's axis radii hold only
/// within the limits (proofs/motion-bound.md#lemma-axis-radius), which makes this check a
/// premise of proofs/joint-variation.md#theorem-variation-motion-bound.
/// proof: proofs/joint-variation.md#lemma-position-limits, #lemma-velocity-limits

#include <optional>
#include <string>

#include <Eigen/Core>

#include "grpvss/model/robot_model.hpp"
#include "grpvss/motion/joint_trajectory_motion.hpp"

namespace grpvss::motion {

/// \brief Per joint (in the motion's joint order): lower <= q <= upper, |dq/dt| <= max_speed
/// (+infinity: no speed limit).
struct JointLimits {
  Eigen::VectorXd lower, upper;  ///< rad (revolute), length (prismatic)
  Eigen::VectorXd max_speed;     ///< rad/s, length/s; >= 0 or +infinity
};

/// The robot's position limits (Joint::minimum, Joint::maximum) and no speed limits.
JointLimits position_limits_of(const RobotModel& robot);

/// The robot's position limits and its speed limits (Joint::max_velocity: a URDF's
/// `<limit velocity>`, +infinity where it gives none): what a joint trajectory is held to.
JointLimits joint_limits_of(const RobotModel& robot);

enum class LimitKind {
  kBelowLower,  ///< q_j < lower_j
  kAboveUpper,  ///< q_j > upper_j
  kOverSpeed,   ///< |dq_j/dt| > max_speed_j
};

/// \brief Where the motion leaves a limit: the worst point of the first offending piece.
struct LimitViolation {
  int joint = 0;           ///< 0-based, in the motion's joint order
  std::string joint_name;
  LimitKind kind = LimitKind::kAboveUpper;
  int piece = 0;           ///< 0-based piece, -1 for a trajectory of one waypoint
  double time = 0.0;       ///< s; the nearest double when the worst point is irrational
  double value = 0.0;      ///< position or velocity there (rounded for messages)
  double limit = 0.0;      ///< the limit it exceeds (the speed limit for kOverSpeed)
};

/// \brief The first violation along the motion: the earliest piece on which some joint
/// leaves a limit; within that piece the violation whose worst point (largest excursion of
/// that joint and kind) comes first. Decided exactly in rational arithmetic (and in
/// Q(sqrt(D)) at an irrational extremum): std::nullopt means every q_j(t) and dq_j/dt of the
/// interpolation of the stored doubles is within the limits on [start_time(), end_time()];
/// touching a limit is within it.
/// \throws std::invalid_argument if the limits do not have one entry per joint, lower > upper,
/// or a speed limit is negative or NaN.
std::optional<LimitViolation> first_limit_violation(const JointTrajectoryMotion& motion,
                                                    const JointLimits& limits);

/// "joint 'elbow' (3) is above its upper limit 2.5 at t = 1.25 s: 2.61 (piece 2, between
/// line 4 and line 5)" for messages; joint numbers are 1-based here.
std::string describe(const LimitViolation& violation, const JointTrajectory& trajectory);

}  // namespace grpvss::motion
