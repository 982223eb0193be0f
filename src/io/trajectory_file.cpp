#include "grpvss/io/trajectory_file.hpp"

#include <algorithm>
#include <cctype>
#include <map>
#include <stdexcept>

#include "grpvss/common/input_error.hpp"
#include "grpvss/io/text_file.hpp"
#include "trajectory_text.hpp"

namespace grpvss::io {
namespace {

bool has_extension(const std::string& path, const std::string& extension) {
  if (path.size() < extension.size()) return false;
  return std::equal(extension.rbegin(), extension.rend(), path.rbegin(), [](char a, char b) {
    return std::tolower(static_cast<unsigned char>(a)) == std::tolower(static_cast<unsigned char>(b));
  });
}

bool looks_like_json(std::string_view text) {
  text = without_byte_order_mark(text);
  const std::size_t first = text.find_first_not_of(" \t\r\n");
  return first != std::string_view::npos && text[first] == '{';
}

/// Index of every trajectory joint name; names given twice are collected in `twice`.
std::map<std::string, int> index_names(const std::vector<std::string>& names,
                                       std::vector<std::string>& twice) {
  std::map<std::string, int> index;
  for (std::size_t j = 0; j < names.size(); ++j) {
    if (!index.emplace(names[j], static_cast<int>(j)).second &&
        std::find(twice.begin(), twice.end(), names[j]) == twice.end()) {
      twice.push_back(names[j]);
    }
  }
  return index;
}

std::string mismatch_text(const std::vector<std::string>& missing,
                          const std::vector<std::string>& extra,
                          const std::vector<std::string>& twice) {
  std::vector<std::string> parts;
  if (!missing.empty()) parts.push_back("missing " + join(missing, ", "));
  if (!extra.empty()) parts.push_back("extra " + join(extra, ", "));
  if (!twice.empty()) parts.push_back("named twice " + join(twice, ", "));
  return join(parts, "; ");
}

Eigen::VectorXd reordered(const Eigen::VectorXd& values, const std::vector<int>& source_index) {
  Eigen::VectorXd result(static_cast<Eigen::Index>(source_index.size()));
  for (std::size_t i = 0; i < source_index.size(); ++i) {
    result[static_cast<Eigen::Index>(i)] = values[source_index[i]];
  }
  return result;
}

}  // namespace

JointTrajectory read_trajectory_file(const std::string& path) {
  const std::string text = read_text_file(path);
  if (has_extension(path, ".csv")) return parse_trajectory_csv(text, path);
  if (has_extension(path, ".json") || looks_like_json(text)) return parse_trajectory_json(text, path);
  return parse_trajectory_csv(text, path);
}

JointTrajectory match_joints(const JointTrajectory& trajectory,
                             const std::vector<std::string>& robot_joint_names) {
  std::vector<std::string> robot_twice;
  const std::map<std::string, int> robot_index = index_names(robot_joint_names, robot_twice);
  if (!robot_twice.empty()) {
    throw std::invalid_argument("match_joints: the robot names a joint twice: " + join(robot_twice, ", "));
  }
  std::vector<std::string> missing, extra, twice;
  const std::map<std::string, int> index = index_names(trajectory.joint_names, twice);
  std::vector<int> source_index;
  for (const std::string& name : robot_joint_names) {
    const auto it = index.find(name);
    if (it == index.end()) missing.push_back(name);
    else source_index.push_back(it->second);
  }
  for (const std::string& name : trajectory.joint_names) {
    if (robot_index.count(name) == 0 && std::find(extra.begin(), extra.end(), name) == extra.end()) {
      extra.push_back(name);
    }
  }
  if (!missing.empty() || !extra.empty() || !twice.empty()) {
    throw InputError(trajectory.source_file, trajectory.joint_names_line,
                     "the robot's joints, each once: " + join(robot_joint_names, ", "),
                     mismatch_text(missing, extra, twice));
  }
  JointTrajectory matched = trajectory;
  matched.joint_names = robot_joint_names;
  for (Eigen::VectorXd& q : matched.positions) q = reordered(q, source_index);
  for (Eigen::VectorXd& v : matched.velocities) v = reordered(v, source_index);
  return matched;
}

}  // namespace grpvss::io
