#pragma once
/// \file
/// \brief Reader of the environment-modelling file (thesis Appendix A.1.1.2). Format and every
/// message: docs/input-formats.md.

#include <string>
#include <string_view>

#include "grpvss/model/environment.hpp"

namespace grpvss::io {

/// \brief Reads and validates an environment file (smallest angle in degrees, stored radians).
/// \throws InputError (file, line, expected) on any defect; never returns a partial model.
Environment read_environment_file(const std::string& path);

/// \brief As read_environment_file() on text already in memory.
Environment parse_environment_file(std::string_view text, const std::string& file_name);

}  // namespace grpvss::io
