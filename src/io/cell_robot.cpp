#include <string>

#include <fmt/core.h>

#include "cell_sections.hpp"

namespace grpvss::io {
namespace {

void read_robot_file(const CellYaml& yaml, const YAML::Node& node, CellRobot& robot) {
  const YAML::Node urdf = node["urdf"];
  const YAML::Node thesis = node["thesis"];
  if (urdf && thesis) yaml.fail(key_node(node, "thesis"), "robot", "either urdf or thesis, not both");
  if (!urdf && !thesis) {
    yaml.fail_at(yaml_line(node), "robot: the key 'urdf' or 'thesis' (the robot file)",
                 "a mapping without either");
  }
  if (thesis) {
    for (const char* key : {"package_paths", "srdf", "tip"}) {
      if (node[key]) {
        yaml.fail(key_node(node, key), "robot",
                  fmt::format("'{}' only with a urdf robot (a thesis robot file has none)", key));
      }
    }
    robot.source = CellRobot::Source::kThesis;
    robot.file = yaml.file(thesis, "robot.thesis");
    return;
  }
  robot.source = CellRobot::Source::kUrdf;
  if (const YAML::Node paths = node["package_paths"]) {
    if (!paths.IsSequence() || paths.size() == 0 || paths.size() > kMaxCellJoints) {
      yaml.fail(paths, "robot.package_paths", fmt::format("a list of 1 to {} directories", kMaxCellJoints));
    }
    for (std::size_t i = 0; i < paths.size(); ++i) {
      robot.package_paths.push_back(yaml.directory(paths[i], fmt::format("robot.package_paths[{}]", i)));
    }
  }
  robot.file = yaml.file(urdf, "robot.urdf", robot.package_paths);
  if (const YAML::Node srdf = node["srdf"]) robot.srdf = yaml.file(srdf, "robot.srdf", robot.package_paths);
  if (const YAML::Node tip = node["tip"]) robot.tip = yaml.name(tip, "robot.tip");
}

// `acceleration: {default: A, JOINT: A, ...}`: every value > 0, every joint once.
void read_accelerations(const CellYaml& yaml, const YAML::Node& node, CellRobot& robot) {
  const char* what = "robot.acceleration";
  if (!node.IsMap() || node.size() == 0 || node.size() > kMaxCellJoints + 1) {
    yaml.fail(node, what, "a mapping {default: A, JOINT_NAME: A, ...} (rad/s^2 or units/s^2)");
  }
  for (auto entry = node.begin(); entry != node.end(); ++entry) {
    const std::string joint = yaml.name(entry->first, what);
    const double value = yaml.positive(entry->second, fmt::format("{}.{}", what, joint));
    if (joint == "default") {
      if (robot.default_acceleration) yaml.fail(entry->first, what, "'default' once");
      robot.default_acceleration = value;
      continue;
    }
    for (const NamedJointValue& seen : robot.accelerations) {
      if (seen.joint == joint) {
        yaml.fail(entry->first, what, fmt::format("each joint once ('{}' is also on line {})", joint, seen.line));
      }
    }
    robot.accelerations.push_back({joint, value, yaml_line(entry->first)});
  }
}

}  // namespace

YAML::Node key_node(const YAML::Node& map, const char* key) {
  if (!map.IsMap()) return YAML::Node(YAML::NodeType::Undefined);
  for (auto entry = map.begin(); entry != map.end(); ++entry) {
    if (entry->first.IsScalar() && entry->first.Scalar() == key) return entry->first;
  }
  return YAML::Node(YAML::NodeType::Undefined);
}

CellRobot read_cell_robot(const CellYaml& yaml, const YAML::Node& node) {
  yaml.require_keys(node, "robot",
                    {"urdf", "thesis", "package_paths", "srdf", "tip", "base", "tool", "home",
                     "acceleration"});
  CellRobot robot;
  robot.line = yaml_line(node);
  read_robot_file(yaml, node, robot);
  if (const YAML::Node base = node["base"]) robot.base = yaml.pose(base, "robot.base");
  if (const YAML::Node tool = node["tool"]) robot.tool = yaml.pose(tool, "robot.tool");
  if (const YAML::Node home = node["home"]) {
    robot.home = yaml.numbers(home, "robot.home", kMaxCellJoints);
    robot.home_line = yaml_line(home);
  }
  if (const YAML::Node acceleration = node["acceleration"]) read_accelerations(yaml, acceleration, robot);
  return robot;
}

}  // namespace grpvss::io
