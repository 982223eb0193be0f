#pragma once
/// \file
/// \brief Reader of cell files (YAML, through Debian's yaml-cpp): the robot, its frames, the
/// named obstacles and the allowed contacts of a robot cell. Every key, unit and message:
/// docs/cell-format.md.
///
/// The reader checks the file's structure, types, ranges and referenced files; what needs the
/// robot (the number of joints, joint and link names) is checked when the cell is loaded
/// (cell/load_cell.hpp).

#include <cstddef>
#include <string>
#include <string_view>
#include <vector>

#include "grpvss/io/input_warning.hpp"
#include "grpvss/model/cell_description.hpp"

namespace grpvss::io {

/// Largest accepted cell file (bytes).
inline constexpr std::size_t kMaxCellFileBytes = std::size_t{16} * 1024 * 1024;
/// Largest accepted number of obstacle entries and of allowed-contact pairs.
inline constexpr std::size_t kMaxCellEntries = 100000;

/// A length (converted to metres) above this warns: no robot cell is 100 m across, but a
/// cell in mm read as m is (docs/cell-format.md#unit-warnings).
inline constexpr double kLargestPlausibleLengthMetres = 100.0;
/// A cell whose largest length (sizes and positions, in metres) is below this warns: no
/// robot fits in 5 cm, but a cell in m read as mm does.
inline constexpr double kSmallestPlausibleCellMetres = 0.05;

/// \brief The description and what the reader noted on the way.
struct CellReadResult {
  CellDescription cell;
  std::vector<InputWarning> warnings;
};

/// \brief Reads and validates a cell file; relative paths resolve against its folder.
/// \throws InputError(path, line, expected, found) naming the YAML line (1-based) of the
/// offending key or value; never returns a partial description.
CellReadResult read_cell_file(const std::string& path);

/// \brief As read_cell_file() on text in memory. `file_name` is used in messages and its
/// folder for relative paths. With `check_files` false, referenced files are resolved but
/// not required to exist (for the fuzzer and for tests of the structure alone).
CellReadResult parse_cell(std::string_view text, const std::string& file_name,
                          bool check_files = true);

}  // namespace grpvss::io
