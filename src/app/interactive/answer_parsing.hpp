#pragma once
/// \file
/// \brief Parsing one typed answer of the interactive session (thesis A.2.2 conventions:
/// "USE A COMMA AFTER EACH DATA INCLUDING THE LAST ONE", "ENTER Y/N (DEFAULT = N)").
/// Pure functions: no I/O, so every rule is unit-testable.

#include <optional>
#include <string>
#include <vector>

namespace grpvss::app::interactive {

/// The answer without leading/trailing blanks and without a trailing '\r' (DOS line ends).
std::string trim_answer(const std::string& answer);

/// \brief Numbers separated by commas and/or blanks; a trailing comma is allowed (the thesis
/// asks for one) and empty fields between commas are not. Every number must be finite.
/// \returns std::nullopt and sets `why` when the answer is not such a list.
std::optional<std::vector<double>> parse_number_list(const std::string& answer, std::string& why);

/// "Y", "YES", "N", "NO" in any case; the empty answer means `default_yes`.
std::optional<bool> parse_yes_no(const std::string& answer, bool default_yes);

/// An integer 1..count written alone (a trailing comma or period is tolerated: "1." or "1,").
std::optional<int> parse_option(const std::string& answer, int count);

}  // namespace grpvss::app::interactive
