#pragma once
/// \file
/// \brief A planner's joint trajectory as the motion the verifier and the checker certify
/// (docs/trajectories.md#verifying-a-trajectory): the interpolation, its limits checked along
/// the motion, and the one-line statement of the motion model every output carries.

#include <memory>
#include <string>

#include <Eigen/Core>

#include "grpvss/model/joint_trajectory.hpp"
#include "grpvss/model/robot_model.hpp"
#include "grpvss/motion/joint_trajectory_motion.hpp"

namespace grpvss::motion {

/// "linear" or "cubic-hermite" (the certificate's and the JSON report's spelling).
const char* to_string(JointInterpolation interpolation);

/// \brief The motion of `trajectory` (joints already in the robot's order: io::match_joints),
/// after checking the robot's position limits along the whole interpolation (exactly,
/// first_limit_violation): the axis radii of the motion bound hold only within them
/// (proofs/joint-variation.md#lemma-position-limits).
/// \throws InputError(file, line of the piece's first waypoint, "joint values within the
/// robot's limits along the motion", describe(violation)) on a violation.
std::shared_ptr<const JointTrajectoryMotion> certified_joint_motion(const RobotModel& robot,
                                                                    JointTrajectory trajectory);

/// \brief A step configuration of a joint trajectory: q_at(t) clamped into the robot's position
/// limits (a rounded value next to a limit the exact motion touches could lie an ulp outside).
/// Clamping only brings it closer to the exact q(t), which lies within the limits, so the
/// variation bound of the unclamped samples still holds.
/// proof: proofs/joint-variation.md#remark-clamped-samples
Eigen::VectorXd step_configuration(const JointTrajectoryMotion& motion, const RobotModel& robot,
                                   double t);

/// "joint trajectory T, cubic Hermite interpolation, 4 waypoints, 0..3 s" (`file_label`: T).
std::string describe_motion_model(const JointTrajectoryMotion& motion,
                                  const std::string& file_label);

}  // namespace grpvss::motion
