#pragma once
// ABB RAPID data as model pieces in SI: robtarget, jointtarget, tooldata, wobjdata,
// speeddata, zonedata; and the predefined data of the RAPID BASE module.

#include <map>
#include <string>
#include <vector>

#include <Eigen/Geometry>

#include "grpvss/io/program_lexer.hpp"
#include "grpvss/model/robot_program.hpp"
#include "rapid_value.hpp"

namespace grpvss::io::rapid {

/// tool0, wobj0, load0, v5 ... v7000, vmax, fine, z0 ... z200 (keys upper case).
const std::map<std::string, Value>& predefined_data();

/// Where a conversion happens, for its messages: "the target of MoveL" at `line`.
struct Context {
  const TokenCursor& cursor;
  int line;
  std::string what;
};

/// A robtarget as a Cartesian target (mm -> m, quaternion w first, confdata); extax values
/// below 9E9 (= axis in use) are listed in `external_axes` ("eax_a = 300").
CartesianTarget robtarget_target(const Value& value, const Context& context,
                                 std::vector<std::string>& external_axes);
/// A jointtarget as joint values (degrees -> radians).
JointTarget jointtarget_target(const Value& value, const Context& context,
                               std::vector<std::string>& external_axes);
/// tooldata's tframe: X_FT. A stationary tool (robhold FALSE) is rejected.
Eigen::Isometry3d tool_pose(const Value& value, const Context& context);
/// wobjdata's uframe * oframe: X_RB. A robot-held work object (robhold TRUE) and a moving
/// user frame (ufprog FALSE) are rejected.
Eigen::Isometry3d work_object_pose(const Value& value, const Context& context);
/// speeddata in SI (vmax: the TCP and orientation speeds stay unset: the robot's maximum).
MotionSpeed speed_data(const Value& value, const Context& context);
/// zonedata: fine is an exact stop, others a radius (pzone_tcp), pzone_ori and zone_ori.
MotionBlend zone_data(const Value& value, const Context& context);

}  // namespace grpvss::io::rapid
