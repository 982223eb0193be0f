#pragma once
// Small text helpers shared by the CSV and JSON trajectory readers (not a public header).
#include <string>
#include <string_view>
#include <vector>

#include "grpvss/model/joint_trajectory.hpp"

namespace grpvss::io {

/// `text` without a leading UTF-8 byte-order mark.
std::string_view without_byte_order_mark(std::string_view text);

/// `text` without leading and trailing blanks (space, tab, CR, VT, FF).
std::string_view trim_blanks(std::string_view text);

/// `'text'` for messages: cut after 40 characters, control and non-ASCII bytes as \xNN.
std::string quoted_text(std::string_view text);

/// The items separated by `separator`.
std::string join(const std::vector<std::string>& items, const std::string& separator);

/// A number as messages print it: the shortest text that reads back to the same double.
std::string format_number(double value);

/// Throws InputError(trajectory.source_file, line, ...) unless `time` >= 0 and, when the
/// trajectory already has waypoints, `time` > the last waypoint's time. `what` names the
/// value in the message ("time", "points[3].time_from_start").
void check_waypoint_time(const JointTrajectory& trajectory, double time, int line,
                         const std::string& what);

}  // namespace grpvss::io
