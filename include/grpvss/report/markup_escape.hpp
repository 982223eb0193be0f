#pragma once
/// \file
/// \brief Escaping text for XML/HTML character data and attribute values (SVG, viewer page).

#include <string>

namespace grpvss::report {

/// \p text with `&`, `<`, `>` and `"` replaced by their entities.
std::string markup_escape(const std::string& text);

}  // namespace grpvss::report
