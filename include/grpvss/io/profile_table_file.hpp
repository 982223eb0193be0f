#pragma once
/// \file
/// \brief Reads a user motion-time table file (format: docs/trajectories.md#motion-time-tables).

#include <string>
#include <string_view>

#include "grpvss/model/profile_table_data.hpp"

namespace grpvss::io {

/// Parses the table text; `file_name` is used in messages.
/// \throws grpvss::InputError naming the line and what was expected.
ProfileTableData parse_profile_table(std::string_view text, std::string file_name);

/// Reads and parses a file. \throws grpvss::InputError (line 0 when it cannot be read).
ProfileTableData read_profile_table_file(const std::string& path);

}  // namespace grpvss::io
