#pragma once
/// \file
/// \brief Reader of the path-input file (thesis Appendix A.1.3). Format and every message:
/// docs/input-formats.md.

#include <string>
#include <string_view>

#include "grpvss/model/path_program.hpp"
#include "grpvss/model/robot_model.hpp"

namespace grpvss::io {

/// \brief Reads and validates a path file for `robot` (which fixes N and the joint types:
/// revolute targets and speeds are degrees and deg/s in the file, radians inside).
/// Joint targets outside the joint limits are NOT rejected here (thesis error 3 belongs to
/// the motion stage).
/// \throws InputError (file, line, expected) on any defect; never returns a partial program.
PathProgram read_path_file(const std::string& path, const RobotModel& robot);

/// \brief As read_path_file() on text already in memory.
PathProgram parse_path_file(std::string_view text, const std::string& file_name,
                            const RobotModel& robot);

}  // namespace grpvss::io
