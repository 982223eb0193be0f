#pragma once
/// \file
/// \brief "Did you mean ...?" for misspelt keys and names in input files.

#include <string>
#include <string_view>
#include <vector>

namespace grpvss::io {

/// The Levenshtein distance (insertions, deletions, substitutions) between two texts.
std::size_t edit_distance(std::string_view a, std::string_view b);

/// \brief The candidate closest to `text` when it is close enough to be a misspelling: at
/// distance <= 2 and below half of `text`'s length (ties: the first). Empty when none is.
std::string closest_candidate(std::string_view text, const std::vector<std::string_view>& candidates);

/// " (did you mean 'X'?)" for closest_candidate(), or "" when there is none.
std::string did_you_mean(std::string_view text, const std::vector<std::string_view>& candidates);

}  // namespace grpvss::io
