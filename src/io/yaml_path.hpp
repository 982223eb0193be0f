#pragma once
/// \file
/// \brief The YAML path: joint targets and ABSOLUTE end-effector poses (position and
/// orientation as rpy, quaternion or axis-angle, in the world or the robot's base frame) with
/// declared units. Format and messages: docs/input-formats.md#yaml-path.

#include <string>
#include <string_view>

#include "grpvss/io/path_file.hpp"

namespace grpvss::io {

/// \brief Reads a YAML path for `robot`, converting lengths to `placement.model_unit` and
/// `frame: base` poses to the world through `placement.X_WR`.
/// \throws InputError naming the file, the line and what was expected.
PathProgram parse_yaml_path(std::string_view text, const std::string& file_name,
                            const RobotModel& robot, const PathPlacement& placement);

}  // namespace grpvss::io
