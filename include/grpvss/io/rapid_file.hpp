#pragma once
/// \file
/// \brief Reader of ABB RAPID programs (.mod, .prg, .sys). The subset read, the warnings and
/// every conversion: docs/robot-programs.md#abb-rapid.

#include <string>
#include <string_view>

#include "grpvss/model/robot_program.hpp"

namespace grpvss::io {

/// \brief Reads a RAPID file: its modules' data and the motions (MoveAbsJ, MoveJ, MoveL,
/// MoveC) of PROC main (or, without one, of the first PROC, with a warning), with tool, work
/// object, speed and zone data, and a warning for every statement not read.
/// \throws InputError(file, line, expected, found) on malformed input, on a motion whose data
/// the reader cannot compute, and on motion instructions it does not read (MoveLDO,
/// TriggL, SearchL, ...).
RobotProgram read_rapid_file(const std::string& path);

/// \brief As read_rapid_file() on text in memory; `file_name` is used in messages.
RobotProgram parse_rapid(std::string_view text, const std::string& file_name);

}  // namespace grpvss::io
