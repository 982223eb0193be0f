#include "grpvss/io/trajectory_csv_text.hpp"

#include <fmt/core.h>

namespace grpvss::io {
namespace {

void append_row(std::string& text, double time, const Eigen::VectorXd& positions,
                const Eigen::VectorXd* velocities) {
  text += fmt::format("{}", time);
  for (Eigen::Index j = 0; j < positions.size(); ++j) text += fmt::format(",{}", positions[j]);
  if (velocities) {
    for (Eigen::Index j = 0; j < velocities->size(); ++j) text += fmt::format(",{}", (*velocities)[j]);
  }
  text += '\n';
}

}  // namespace

std::string render_trajectory_csv(const JointTrajectory& trajectory) {
  std::string text = "time";
  for (const std::string& name : trajectory.joint_names) text += "," + name;
  if (trajectory.has_velocities()) {
    for (const std::string& name : trajectory.joint_names) text += "," + name + ".vel";
  }
  text += '\n';
  for (std::size_t k = 0; k < trajectory.times.size(); ++k) {
    append_row(text, trajectory.times[k], trajectory.positions[k],
               trajectory.has_velocities() ? &trajectory.velocities[k] : nullptr);
  }
  return text;
}

}  // namespace grpvss::io
