#pragma once
/// \file
/// \brief A timed joint trajectory as a planner writes it (CSV or ROS
/// `trajectory_msgs/JointTrajectory` JSON): named joints and waypoints, each with a time, the
/// joint positions and optionally the joint velocities. Plain data: the readers
/// (io/trajectory_file.hpp) fill and validate it, the motion stage
/// (motion/joint_trajectory_motion.hpp) interpolates it. Format: docs/trajectories.md.

#include <string>
#include <vector>

#include <Eigen/Core>

namespace grpvss {

/// \brief The file format a trajectory was read from (it decides how a waypoint is named in
/// messages).
enum class TrajectoryFormat { kCsv, kRosJson };

/// \brief Waypoints in time order. Invariants the readers guarantee (and
/// motion::JointTrajectoryMotion checks again):
/// - at least one waypoint; `times` strictly increasing, `times[0] >= 0` (it may be > 0);
/// - every `positions[k]` has one entry per joint name, in the order of `joint_names`;
/// - `velocities` is empty (no waypoint has velocities) or has one vector per waypoint;
/// - every number is finite with magnitude at most 1e9.
struct JointTrajectory {
  std::vector<std::string> joint_names;
  std::vector<double> times;                  ///< seconds from the trajectory's start
  std::vector<Eigen::VectorXd> positions;     ///< per waypoint: rad (revolute), length (prismatic)
  std::vector<Eigen::VectorXd> velocities;    ///< per waypoint: rad/s, length/s; or empty

  std::string source_file;                    ///< the file read, for messages
  TrajectoryFormat format = TrajectoryFormat::kCsv;
  int joint_names_line = 0;                   ///< CSV header line / JSON `joint_names` line
  std::vector<int> source_lines;              ///< per waypoint: CSV row line / JSON `points[k]` line

  int waypoint_count() const { return static_cast<int>(times.size()); }
  int joint_count() const { return static_cast<int>(joint_names.size()); }
  bool has_velocities() const { return !velocities.empty(); }
};

/// \brief How messages name waypoint `k` (0-based): `line 7` for CSV, `points[3] (line 12)`
/// for JSON (line omitted when unknown, i.e. 0).
inline std::string describe_waypoint(const JointTrajectory& trajectory, int k) {
  const int line = k < static_cast<int>(trajectory.source_lines.size())
                       ? trajectory.source_lines[static_cast<std::size_t>(k)]
                       : 0;
  if (trajectory.format == TrajectoryFormat::kCsv) return "line " + std::to_string(line);
  std::string text = "points[" + std::to_string(k) + "]";
  if (line > 0) text += " (line " + std::to_string(line) + ")";
  return text;
}

}  // namespace grpvss
