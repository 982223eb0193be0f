#pragma once
/// \file
/// \brief Reader of Universal Robots URScript programs (.script). The subset read, the
/// warnings and every conversion: docs/robot-programs.md#urscript.

#include <string>
#include <string_view>

#include "grpvss/model/robot_program.hpp"

namespace grpvss::io {

/// \brief Reads a URScript file: the motions (movej, movel, movec) of its program with the
/// TCP (set_tcp), speeds, blend radii and a warning for every statement not read.
/// \throws InputError(file, line, expected, found) on malformed input, on a motion whose
/// target the reader cannot compute, and on motions it does not read (movep, servoj, ...).
RobotProgram read_urscript_file(const std::string& path);

/// \brief As read_urscript_file() on text in memory; `file_name` is used in messages.
RobotProgram parse_urscript(std::string_view text, const std::string& file_name);

}  // namespace grpvss::io
