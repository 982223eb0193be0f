#include "did_you_mean.hpp"

#include <algorithm>
#include <numeric>

namespace grpvss::io {
namespace {

// Longer texts are never misspellings of a key or a name worth suggesting (and the distance
// costs |a| x |b|).
constexpr std::size_t kLongestCompared = 64;
constexpr std::size_t kLargestSuggestedDistance = 2;

}  // namespace

std::size_t edit_distance(std::string_view a, std::string_view b) {
  std::vector<std::size_t> row(b.size() + 1);
  std::iota(row.begin(), row.end(), std::size_t{0});
  for (std::size_t i = 1; i <= a.size(); ++i) {
    std::size_t diagonal = row[0];
    row[0] = i;
    for (std::size_t j = 1; j <= b.size(); ++j) {
      const std::size_t substitution = diagonal + (a[i - 1] == b[j - 1] ? 0 : 1);
      diagonal = row[j];
      row[j] = std::min({row[j] + 1, row[j - 1] + 1, substitution});
    }
  }
  return row[b.size()];
}

std::string closest_candidate(std::string_view text, const std::vector<std::string_view>& candidates) {
  if (text.size() > kLongestCompared) return {};
  std::string best;
  std::size_t best_distance = kLargestSuggestedDistance + 1;
  for (const std::string_view candidate : candidates) {
    if (candidate.size() > kLongestCompared) continue;
    const std::size_t distance = edit_distance(text, candidate);
    if (distance < best_distance && 2 * distance < text.size()) {
      best = std::string(candidate);
      best_distance = distance;
    }
  }
  return best;
}

std::string did_you_mean(std::string_view text, const std::vector<std::string_view>& candidates) {
  const std::string best = closest_candidate(text, candidates);
  return best.empty() ? std::string() : " (did you mean '" + best + "'?)";
}

}  // namespace grpvss::io
