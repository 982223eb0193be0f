#include "grpvss/batch/joint_trajectory_input.hpp"

#include <vector>

#include "grpvss/common/input_error.hpp"
#include "grpvss/io/trajectory_file.hpp"
#include "grpvss/motion/joint_trajectory_source.hpp"

namespace grpvss::batch {

std::shared_ptr<const motion::JointTrajectoryMotion> joint_motion_of(
    const JointTrajectory& trajectory, const RobotModel& robot) {
  std::vector<std::string> names;
  for (const Joint& joint : robot.joints) {
    if (joint.name.empty()) {
      throw InputError(trajectory.source_file, trajectory.joint_names_line,
                       "a robot with named joints (a URDF robot in a cell, --cell): a "
                       "trajectory's joints are matched by name",
                       "a robot file without joint names");
    }
    names.push_back(joint.name);
  }
  return motion::certified_joint_motion(robot, io::match_joints(trajectory, names));
}

std::shared_ptr<const motion::JointTrajectoryMotion> load_joint_trajectory(
    const std::string& file, const RobotModel& robot) {
  return joint_motion_of(io::read_trajectory_file(file), robot);
}

}  // namespace grpvss::batch
