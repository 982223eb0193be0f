#include "start_option.hpp"

#include <cmath>
#include <cstddef>

#include <fmt/core.h>

#include "grpvss/cell/start_configuration.hpp"
#include "grpvss/common/input_error.hpp"

namespace grpvss::app {

void add_start_option(CLI::App& command, std::string& start) {
  command.add_option("--start", start,
                     "Start configuration q1,q2,... (default: the cell's home, else the robot "
                     "file's): radians (metres for prismatic joints) with a cell, degrees with "
                     "thesis files; a trajectory starts at its first point");
}

std::optional<Eigen::VectorXd> start_of(const std::string& start, const ModelInputs& model) {
  if (start.empty()) return std::nullopt;
  return cell::start_configuration(cell::parse_start_list(start), model.robot, model.from_cell);
}

void check_trajectory_start(const std::string& start, const ModelInputs& model,
                            const motion::JointTrajectoryMotion& motion) {
  const std::optional<Eigen::VectorXd> given = start_of(start, model);
  if (!given) return;
  const Eigen::VectorXd first = motion.q_at(motion.start_time());
  for (Eigen::Index j = 0; j < first.size(); ++j) {
    if (std::abs((*given)[j] - first[j]) <= kTrajectoryStartTolerance) continue;
    const Joint& joint = model.robot.joints[static_cast<std::size_t>(j)];
    throw InputError("--start", 0,
                     fmt::format("the trajectory's first point (it starts there): {} at {} "
                                 "(within {})",
                                 joint.name.empty() ? "joint " + std::to_string(j + 1) : joint.name,
                                 first[j], kTrajectoryStartTolerance),
                     fmt::format("{}", (*given)[j]));
  }
}

}  // namespace grpvss::app
