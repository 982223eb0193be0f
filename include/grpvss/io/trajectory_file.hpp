#pragma once
/// \file
/// \brief Readers of planner trajectories: CSV (`time,<joint>...[,<joint>.vel...]`) and JSON
/// shaped like ROS `trajectory_msgs/JointTrajectory`; and matching the trajectory's joint
/// names against the robot's. Formats and every message: docs/trajectories.md, section 9.
///
/// Every defect throws grpvss::InputError naming the file, the line (JSON: the line of the
/// element's key or opening bracket; a syntax error names the line where it was found; line 0
/// only when the file cannot be read) and what was expected; JSON messages also name the
/// element, e.g. `points[3].positions`. A reader never returns a partial trajectory.

#include <string>
#include <string_view>
#include <vector>

#include "grpvss/model/joint_trajectory.hpp"

namespace grpvss::io {

/// \brief Reads a trajectory file: `.csv` as CSV, `.json` as JSON (extension compared
/// case-insensitively); any other name is read as JSON when its first non-blank character
/// is `{`, as CSV otherwise.
/// \throws InputError (file, line, expected, found) on any defect, line 0 when the file cannot
/// be read.
JointTrajectory read_trajectory_file(const std::string& path);

/// \brief Parses CSV text. Header: `time` then one column per joint, optionally one
/// `<joint>.vel` column per joint (for every joint or for none), in any order after `time`.
/// Rows: one number per column; seconds, rad or length, rad/s or length/s.
JointTrajectory parse_trajectory_csv(std::string_view text, const std::string& file_name);

/// \brief Parses JSON text: an object with `joint_names` (strings) and `points` (objects with
/// `positions`, optional `velocities`, `time_from_start` as seconds or `{sec, nanosec}` /
/// `{secs, nsecs}`; `accelerations` must be absent or empty, `effort` is ignored); an optional
/// `header` is ignored.
JointTrajectory parse_trajectory_json(std::string_view text, const std::string& file_name);

/// \brief The trajectory with its joints reordered into the robot's order
/// (`robot_joint_names[i]` becomes joint i).
/// \throws InputError(file, joint_names_line, ...) naming every missing joint (the robot has
/// it, the trajectory does not), every extra joint (the other way round) and every joint the
/// trajectory names twice.
JointTrajectory match_joints(const JointTrajectory& trajectory,
                             const std::vector<std::string>& robot_joint_names);

}  // namespace grpvss::io
