#pragma once
/// \file
/// \brief Reader of KUKA KRL programs: a .src with its .dat (and a $config.dat) beside it.
/// The subset read, the warnings and every conversion: docs/robot-programs.md#kuka-krl.

#include <string>
#include <string_view>
#include <vector>

#include "grpvss/model/robot_program.hpp"

namespace grpvss::io {

/// \brief A KRL data file's text and the name used in messages.
struct KrlDataText {
  std::string file_name;
  std::string text;
};

/// \brief Reads `src_path` and, when they exist beside it, `$config.dat` (system-wide data:
/// TOOL_DATA, BASE_DATA, HOME) and the .dat of the same name (names matched ignoring
/// case). A missing .dat is fine until the program needs one of its points.
/// \throws InputError(file, line, expected, found) on malformed input, on a point, tool or
/// base the program uses but nobody declares (the message names it), and on motions the
/// reader does not read (PTP_REL, SPLINE, ...).
RobotProgram read_krl_file(const std::string& src_path);

/// \brief The data files read_krl_file() reads beside `src_path`, in its order: `$config.dat`
/// and the .dat of the same name, each only when it exists (names matched ignoring case).
std::vector<std::string> krl_data_files_beside(const std::string& src_path);

/// \brief As read_krl_file() on texts in memory: `data_files` are read in order (later
/// declarations replace earlier ones), before the program runs.
RobotProgram parse_krl(std::string_view src_text, const std::string& src_name,
                       const std::vector<KrlDataText>& data_files);

}  // namespace grpvss::io
