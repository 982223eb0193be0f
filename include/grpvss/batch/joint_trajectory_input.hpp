#pragma once
/// \file
/// \brief A planner's joint trajectory made into the motion a verification certifies: the one
/// loader `grpvss verify|trajectory|check-certificate --trajectory`, batch manifests'
/// `trajectory` jobs and the Python module share (docs/trajectories.md#verifying-a-trajectory).

#include <memory>
#include <string>

#include "grpvss/model/joint_trajectory.hpp"
#include "grpvss/model/robot_model.hpp"
#include "grpvss/motion/joint_trajectory_motion.hpp"

namespace grpvss::batch {

/// \brief `trajectory` (as read, joints named) matched to the robot's joints by name, and
/// the robot's position limits checked along the whole interpolation.
/// \throws InputError(trajectory.source_file, line, ...) for a robot without joint names (a
/// thesis robot file: trajectories need a URDF robot, i.e. a cell), a name mismatch or a
/// limit violation.
std::shared_ptr<const motion::JointTrajectoryMotion> joint_motion_of(
    const JointTrajectory& trajectory, const RobotModel& robot);

/// \brief Reads `file` (CSV or ROS JSON, io::read_trajectory_file) and returns
/// joint_motion_of() it. \throws InputError(file, line, ...) for any defect.
std::shared_ptr<const motion::JointTrajectoryMotion> load_joint_trajectory(
    const std::string& file, const RobotModel& robot);

}  // namespace grpvss::batch
