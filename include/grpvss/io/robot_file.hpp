#pragma once
/// \file
/// \brief Reader of the robot-modelling file (thesis Appendix A.1.1.1). Format and every
/// message: docs/input-formats.md.

#include <string>
#include <string_view>

#include "grpvss/model/robot_model.hpp"

namespace grpvss::io {

/// Largest accepted number of joints N.
inline constexpr long long kMaxJoints = 64;

/// \brief Reads and validates a robot file. Angles in the file are degrees, stored radians.
/// \throws InputError (file, line, expected) on any defect; never returns a partial model.
RobotModel read_robot_file(const std::string& path);

/// \brief As read_robot_file() on text already in memory; `file_name` is used in messages
/// and becomes RobotModel::name.
RobotModel parse_robot_file(std::string_view text, const std::string& file_name);

}  // namespace grpvss::io
