// JSON trajectories shaped like ROS trajectory_msgs/JointTrajectory (docs/trajectories.md,
// section 9.2).
#include <charconv>
#include <cmath>
#include <cstdint>
#include <set>
#include <string>

#include <fmt/format.h>

#include "grpvss/common/input_error.hpp"
#include "number_reader.hpp"
#include "grpvss/io/trajectory_file.hpp"
#include "trajectory_json_lines.hpp"
#include "trajectory_text.hpp"

namespace grpvss::io {
namespace {

using nlohmann::json;

constexpr std::int64_t kMaxSeconds = 1000000000;  // NumberReader::kMaxMagnitude
constexpr std::int64_t kNanosecondsPerSecond = 1000000000;

/// "an array of 3", "a string", ... for messages.
std::string describe(const json& value) {
  if (value.is_array()) return "an array of " + std::to_string(value.size());
  if (value.is_object()) return "an object";
  if (value.is_null()) return "null";
  if (value.is_boolean()) return value.get<bool>() ? "true" : "false";
  if (value.is_string()) return "the string " + quoted_text(value.get<std::string>());
  return "the number " + value.dump();
}

/// Where a value sits, for messages: the file, the line and the element's path.
struct Element {
  const std::string& file;
  int line;
  std::string path;  ///< e.g. "points[3].positions"

  [[noreturn]] void fail(const std::string& expected, const std::string& found) const {
    throw InputError(file, line, expected + " in " + path, found);
  }
};

double finite_number(const json& value, const Element& element, const std::string& what) {
  if (!value.is_number()) element.fail(what, describe(value));
  const double number = value.get<double>();
  if (!(std::fabs(number) <= NumberReader::kMaxMagnitude)) {
    element.fail(what + " of magnitude at most 1e9", describe(value));
  }
  return number;
}

/// An array of exactly `count` numbers (joint values, one per joint name).
Eigen::VectorXd joint_vector(const json& value, std::size_t count, const Element& element) {
  const std::string expected = std::to_string(count) + " numbers (one per joint name)";
  if (!value.is_array() || value.size() != count) element.fail("an array of " + expected, describe(value));
  Eigen::VectorXd vector(static_cast<Eigen::Index>(count));
  for (std::size_t j = 0; j < count; ++j) {
    const Element item{element.file, element.line, element.path + "[" + std::to_string(j) + "]"};
    vector[static_cast<Eigen::Index>(j)] = finite_number(value[j], item, "a number");
  }
  return vector;
}

/// A non-negative integer within [0, maximum] (ROS Duration fields).
std::int64_t duration_field(const json& object, const char* key, std::int64_t maximum,
                            const Element& element) {
  const Element field{element.file, element.line, element.path + "." + key};
  if (!object.contains(key)) field.fail("an integer", "nothing");
  const json& value = object.at(key);
  const bool in_range =
      (value.is_number_unsigned() && value.get<std::uint64_t>() <= static_cast<std::uint64_t>(maximum)) ||
      (value.is_number_integer() && value.get<std::int64_t>() >= 0 && value.get<std::int64_t>() <= maximum);
  if (!in_range) field.fail("an integer in [0, " + std::to_string(maximum) + "]", describe(value));
  return value.get<std::int64_t>();
}

/// The nearest double to sec + nanosec 10^-9 (decimal text read back correctly rounded).
double seconds_from_parts(std::int64_t seconds, std::int64_t nanoseconds) {
  const std::string text = fmt::format("{}.{:09}", seconds, nanoseconds);
  double value = 0.0;
  std::from_chars(text.data(), text.data() + text.size(), value);
  return value;
}

/// `time_from_start`: seconds, `{sec, nanosec}` (ROS 2) or `{secs, nsecs}` (ROS 1).
double time_from_start(const json& value, const Element& element) {
  if (value.is_number()) {
    return finite_number(value, element, "a time in seconds");
  }
  const bool ros2 = value.is_object() && value.contains("sec");
  const bool ros1 = value.is_object() && value.contains("secs");
  if (!value.is_object() || value.size() != 2 || ros1 == ros2) {
    element.fail("seconds or an object {\"sec\": ..., \"nanosec\": ...}", describe(value));
  }
  const std::int64_t seconds = duration_field(value, ros2 ? "sec" : "secs", kMaxSeconds, element);
  const std::int64_t nanoseconds =
      duration_field(value, ros2 ? "nanosec" : "nsecs", kNanosecondsPerSecond - 1, element);
  return seconds_from_parts(seconds, nanoseconds);
}

std::vector<std::string> joint_names(const LocatedJson& located, const std::string& file) {
  const Element element{file, located.top_members.at("joint_names"), "joint_names"};
  const json& names = located.document.at("joint_names");
  if (!names.is_array() || names.empty()) {
    element.fail("a non-empty array of joint names", describe(names));
  }
  std::vector<std::string> result;
  std::set<std::string> seen;
  for (std::size_t j = 0; j < names.size(); ++j) {
    const Element item{file, element.line, "joint_names[" + std::to_string(j) + "]"};
    if (!names[j].is_string() || names[j].get<std::string>().empty()) {
      item.fail("a non-empty string", describe(names[j]));
    }
    const std::string& name = names[j].get_ref<const std::string&>();
    if (!seen.insert(name).second) item.fail("each joint named once", quoted_text(name) + " again");
    result.push_back(name);
  }
  return result;
}

/// The velocities of point k, or an empty vector when it has none (absent or []).
Eigen::VectorXd point_velocities(const json& point, std::size_t joints, const Element& element) {
  if (!point.contains("velocities")) return {};
  const json& value = point.at("velocities");
  if (value.is_array() && value.empty()) return {};
  return joint_vector(value, joints, element);
}

/// Velocities in every point or in none (the controller interpolates cubically only when
/// both ends of a piece have them; GRPVSS asks for one rule for the whole trajectory).
void check_velocities_everywhere(const JointTrajectory& trajectory, bool has_velocities,
                                 const Element& element) {
  const int k = trajectory.waypoint_count();
  if (k == 0 || trajectory.has_velocities() == has_velocities) return;
  element.fail(std::string("velocities in every point or in none (points[0] ") +
                   (trajectory.has_velocities() ? "has them)" : "has none)"),
               has_velocities ? "velocities" : "none");
}

void append_point(JointTrajectory& trajectory, const json& point, const JsonPointLines& lines,
                  std::size_t k) {
  const std::string& file = trajectory.source_file;
  const std::string path = "points[" + std::to_string(k) + "]";
  const Element element{file, lines.start, path};
  if (!point.is_object()) element.fail("an object", describe(point));
  if (lines.unknown_member_line != 0) {
    throw InputError(file, lines.unknown_member_line,
                     "only positions, velocities, accelerations, effort and time_from_start in " + path,
                     quoted_text(lines.unknown_member));
  }
  const auto member = [&](const char* key) {
    return Element{file, lines.line_of(key) != 0 ? lines.line_of(key) : lines.start,
                   path + "." + key};
  };
  if (!point.contains("positions")) element.fail("a member 'positions'", "none");
  if (!point.contains("time_from_start")) element.fail("a member 'time_from_start'", "none");
  if (point.contains("accelerations") &&
      !(point.at("accelerations").is_array() && point.at("accelerations").empty())) {
    member("accelerations")
        .fail("no accelerations (quintic interpolation is not supported)",
              describe(point.at("accelerations")));
  }
  const std::size_t joints = trajectory.joint_names.size();
  const Eigen::VectorXd positions = joint_vector(point.at("positions"), joints, member("positions"));
  const Eigen::VectorXd velocities = point_velocities(point, joints, member("velocities"));
  const Element time_element = member("time_from_start");
  const double time = time_from_start(point.at("time_from_start"), time_element);
  check_velocities_everywhere(trajectory, velocities.size() > 0, member("velocities"));
  check_waypoint_time(trajectory, time, time_element.line, time_element.path);
  trajectory.times.push_back(time);
  trajectory.positions.push_back(positions);
  if (velocities.size() > 0) trajectory.velocities.push_back(velocities);
  trajectory.source_lines.push_back(lines.start);
}

void check_top_level(const LocatedJson& located, const std::string& file) {
  const json& root = located.document;
  if (!root.is_object()) {
    throw InputError(file, located.root_line,
                     "a JSON object with 'joint_names' and 'points' (trajectory_msgs/JointTrajectory)",
                     describe(root));
  }
  for (const auto& [key, line] : located.top_members) {
    if (key != "joint_names" && key != "points" && key != "header") {
      throw InputError(file, line, "only joint_names, points and header at the top level",
                       quoted_text(key));
    }
  }
  for (const char* key : {"joint_names", "points"}) {
    if (!root.contains(key)) {
      throw InputError(file, located.root_line, std::string("a member '") + key + "' in the top-level object",
                       "none");
    }
  }
}

}  // namespace

JointTrajectory parse_trajectory_json(std::string_view text, const std::string& file_name) {
  const LocatedJson located = parse_located_json(text, file_name);
  check_top_level(located, file_name);
  JointTrajectory trajectory;
  trajectory.source_file = file_name;
  trajectory.format = TrajectoryFormat::kRosJson;
  trajectory.joint_names = joint_names(located, file_name);
  trajectory.joint_names_line = located.top_members.at("joint_names");
  const json& points = located.document.at("points");
  if (!points.is_array() || points.empty()) {
    Element{file_name, located.top_members.at("points"), "points"}.fail(
        "a non-empty array of points", describe(points));
  }
  for (std::size_t k = 0; k < points.size(); ++k) {
    append_point(trajectory, points[k], located.points.at(k), k);
  }
  return trajectory;
}

}  // namespace grpvss::io
