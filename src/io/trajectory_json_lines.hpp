#pragma once
// Parsing a trajectory JSON document while remembering on which line each element starts, so
// that messages can say `file:12: expected ... in points[3].positions` (nlohmann-json 3.11
// keeps no positions in its values). Not a public header.
#include <array>
#include <cstddef>
#include <map>
#include <string>
#include <string_view>
#include <vector>

#include <nlohmann/json.hpp>

namespace grpvss::io {

/// The members a point object may have (ROS `trajectory_msgs/JointTrajectoryPoint`).
inline constexpr std::array<std::string_view, 5> kPointMembers = {
    "positions", "velocities", "accelerations", "effort", "time_from_start"};

/// Lines (1-based) of the elements of one point object `points[k]`; 0 = absent.
struct JsonPointLines {
  int start = 0;                                  ///< the point's opening bracket (or value)
  std::array<int, kPointMembers.size()> members{};  ///< line of each known member's key
  std::string unknown_member;                     ///< the first other key, if any
  int unknown_member_line = 0;

  /// Line of member `key` (one of kPointMembers); 0 when absent.
  int line_of(std::string_view key) const;
};

/// The parsed document and the lines of its top-level members and of the `points` elements.
struct LocatedJson {
  nlohmann::json document;
  int root_line = 1;
  std::map<std::string, int> top_members;  ///< line of each top-level key
  std::vector<JsonPointLines> points;      ///< one per element of the top-level `points` array
};

/// Parses `text`. Duplicate keys at the top level or in a point are rejected (a JSON object
/// with two `positions` is ambiguous).
/// \throws InputError(file_name, line, ...) on a syntax error, a number out of double range,
/// or a duplicate key.
LocatedJson parse_located_json(std::string_view text, const std::string& file_name);

}  // namespace grpvss::io
