#include "trajectory_inputs.hpp"

#include <vector>

#include "grpvss/common/input_error.hpp"
#include "grpvss/io/trajectory_file.hpp"
#include "grpvss/motion/joint_trajectory_source.hpp"

namespace grpvss::app {

std::shared_ptr<const motion::JointTrajectoryMotion> load_joint_trajectory(
    const std::string& file, const RobotModel& robot) {
  const JointTrajectory read = io::read_trajectory_file(file);
  std::vector<std::string> names;
  for (const Joint& joint : robot.joints) {
    if (joint.name.empty()) {
      throw InputError(file, read.joint_names_line,
                       "a robot with named joints (a URDF robot in a cell, --cell): a "
                       "trajectory's joints are matched by name",
                       "a robot file without joint names");
    }
    names.push_back(joint.name);
  }
  return motion::certified_joint_motion(robot, io::match_joints(read, names));
}

void refuse_with_trajectory(bool given, const std::string& option, const std::string& why) {
  if (!given) return;
  throw InputError(option, 0, "no " + option + " with --trajectory (" + why + ")", option);
}

void require_path_or_trajectory(const std::string& path_file, const std::string& trajectory_file) {
  if (path_file.empty() == trajectory_file.empty()) {
    throw InputError("--path", 0, "exactly one of --path and --trajectory",
                     path_file.empty() ? "neither" : "both");
  }
}

}  // namespace grpvss::app
