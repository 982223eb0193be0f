#include "grpvss/cell/start_configuration.hpp"

#include <cmath>
#include <cstddef>
#include <stdexcept>
#include <string>

#include <fmt/core.h>

#include "grpvss/common/input_error.hpp"
#include "grpvss/io/units.hpp"

namespace grpvss::cell {
namespace {

std::string joint_label(const Joint& joint, int index) {
  return joint.name.empty() ? "joint " + std::to_string(index + 1) : joint.name;
}

// Thesis files state revolute joints in degrees; a cell (and every URDF value) in radians.
bool in_degrees(const Joint& joint, bool from_cell) {
  return !from_cell && joint.type == JointType::kRevolute;
}

double to_input_units(double value, const Joint& joint, bool from_cell) {
  return in_degrees(joint, from_cell) ? value / io::kRadiansPerDegree : value;
}

std::string unit_name(const Joint& joint, bool from_cell) {
  if (joint.type == JointType::kPrismatic) return "length units";
  return in_degrees(joint, from_cell) ? "deg" : "rad";
}

}  // namespace

Eigen::VectorXd start_configuration(const std::vector<double>& values, const RobotModel& robot,
                                    bool from_cell, const std::string& source) {
  if (static_cast<int>(values.size()) != robot.joint_count()) {
    throw InputError(source, 0,
                     fmt::format("one value per joint ({} joints)", robot.joint_count()),
                     fmt::format("{} values", values.size()));
  }
  Eigen::VectorXd start(robot.joint_count());
  for (int j = 0; j < robot.joint_count(); ++j) {
    const Joint& joint = robot.joints[static_cast<std::size_t>(j)];
    const double given = values[static_cast<std::size_t>(j)];
    // The same rounded product as the readers': a limit written in degrees stays reachable.
    const double value = in_degrees(joint, from_cell) ? io::degrees_to_radians(given) : given;
    if (!std::isfinite(given) || value < joint.minimum || value > joint.maximum) {
      throw InputError(source, 0,
                       fmt::format("{} within its limits [{:g}, {:g}] {}", joint_label(joint, j),
                                   to_input_units(joint.minimum, joint, from_cell),
                                   to_input_units(joint.maximum, joint, from_cell),
                                   unit_name(joint, from_cell)),
                       fmt::format("{}", given));
    }
    start[j] = value;
  }
  return start;
}

std::vector<double> parse_start_list(const std::string& text, const std::string& source) {
  std::vector<double> values;
  std::size_t begin = 0;
  while (true) {
    const std::size_t comma = text.find(',', begin);
    const std::string entry =
        text.substr(begin, comma == std::string::npos ? std::string::npos : comma - begin);
    std::size_t used = 0;
    double value = 0.0;
    try {
      value = std::stod(entry, &used);
    } catch (const std::exception&) {
      used = 0;
    }
    if (used == 0 || entry.find_first_not_of(" ", used) != std::string::npos) {
      throw InputError(source, 0,
                       fmt::format("a comma-separated list of numbers (entry {})", values.size() + 1),
                       "'" + entry + "'");
    }
    values.push_back(value);
    if (comma == std::string::npos) return values;
    begin = comma + 1;
  }
}

}  // namespace grpvss::cell
