#pragma once
/// \file
/// \brief One entry point for industrial robot programs: picks the reader by the file's
/// extension (docs/robot-programs.md).

#include <string>
#include <vector>

#include "grpvss/model/robot_program.hpp"

namespace grpvss::io {

/// \brief Reads a robot program, choosing the language by extension (ignoring case):
/// `.script` (URScript, io/urscript_file.hpp), `.src` (KUKA KRL with its .dat and a
/// $config.dat beside it, io/krl_file.hpp), `.mod`, `.modx`, `.prg`, `.sys`, `.sysx` (ABB
/// RAPID, io/rapid_file.hpp).
/// \throws InputError(path, 0, ...) for another extension (a PolyScope `.urp` and a KRL
/// `.dat` alone are named as such), and whatever the chosen reader throws.
RobotProgram read_robot_program(const std::string& path);

/// \brief Every file read_robot_program(path) reads: the program itself and, for a KRL .src,
/// the .dat files beside it that exist. A batch refuses outputs that name any of them.
std::vector<std::string> robot_program_files(const std::string& path);

}  // namespace grpvss::io
