#include "grpvss/motion/joint_trajectory_source.hpp"

#include <algorithm>
#include <stdexcept>
#include <utility>

#include <fmt/core.h>

#include "grpvss/common/input_error.hpp"
#include "grpvss/motion/joint_limit_check.hpp"

namespace grpvss::motion {

const char* to_string(JointInterpolation interpolation) {
  return interpolation == JointInterpolation::kLinear ? "linear" : "cubic-hermite";
}

std::shared_ptr<const JointTrajectoryMotion> certified_joint_motion(const RobotModel& robot,
                                                                    JointTrajectory trajectory) {
  if (trajectory.joint_count() != robot.joint_count()) {
    throw std::invalid_argument("certified_joint_motion: joints not matched to the robot's");
  }
  auto motion = std::make_shared<const JointTrajectoryMotion>(std::move(trajectory));
  const JointTrajectory& stored = motion->trajectory();
  // proof: proofs/joint-variation.md#lemma-position-limits, #lemma-velocity-limits
  if (const auto violation = first_limit_violation(*motion, joint_limits_of(robot))) {
    const int waypoint = violation->piece < 0 ? 0 : violation->piece;
    const int line = waypoint < static_cast<int>(stored.source_lines.size())
                         ? stored.source_lines[static_cast<std::size_t>(waypoint)]
                         : 0;
    throw InputError(stored.source_file, line,
                     "joint positions and speeds within the robot's limits along the interpolated motion",
                     describe(*violation, stored));
  }
  return motion;
}

Eigen::VectorXd step_configuration(const JointTrajectoryMotion& motion, const RobotModel& robot,
                                   double t) {
  Eigen::VectorXd q = motion.q_at(t);
  for (int j = 0; j < robot.joint_count(); ++j) {
    q[j] = std::clamp(q[j], robot.joints[j].minimum, robot.joints[j].maximum);
  }
  return q;
}

std::string describe_motion_model(const JointTrajectoryMotion& motion,
                                  const std::string& file_label) {
  return fmt::format("joint trajectory {}, {} interpolation, {} waypoints, {}..{} s", file_label,
                     motion.interpolation() == JointInterpolation::kLinear ? "linear"
                                                                           : "cubic Hermite",
                     motion.trajectory().waypoint_count(), motion.start_time(), motion.end_time());
}

}  // namespace grpvss::motion
