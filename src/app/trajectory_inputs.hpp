#pragma once
// A planner's joint trajectory (`--trajectory T`) as `verify`, `trajectory` and
// `check-certificate` read it (docs/trajectories.md#verifying-a-trajectory).
#include <memory>
#include <string>

#include "grpvss/model/robot_model.hpp"
#include "grpvss/motion/joint_trajectory_motion.hpp"

namespace grpvss::app {

/// \brief Reads T (CSV or ROS JSON), matches its joints to the robot's by name and checks the
/// robot's position limits along the interpolation. A URDF robot's joint values are in rad and
/// metres, as the trajectory's.
/// \throws InputError(T, line, ...) for a defect of the file, a name mismatch, a limit
/// violation, or a robot without joint names (a thesis robot file: trajectories need a URDF
/// robot, i.e. a cell).
std::shared_ptr<const motion::JointTrajectoryMotion> load_joint_trajectory(
    const std::string& file, const RobotModel& robot);

/// Why a motion option is refused with --trajectory.
inline constexpr const char* kTrajectoryIsTheMotion =
    "the trajectory's waypoint times and interpolation are the motion";

/// \brief `option` (e.g. "--timing") given with --trajectory is refused, saying `why`.
/// \throws InputError(option, 0, ...) when `given`.
void refuse_with_trajectory(bool given, const std::string& option,
                            const std::string& why = kTrajectoryIsTheMotion);

/// \brief Exactly one of --path and --trajectory. \throws InputError otherwise.
void require_path_or_trajectory(const std::string& path_file, const std::string& trajectory_file);

}  // namespace grpvss::app
