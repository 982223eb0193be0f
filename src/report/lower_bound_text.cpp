#include "grpvss/report/lower_bound_text.hpp"

#include <cmath>
#include <cstdlib>
#include <stdexcept>

#include <fmt/format.h>

namespace grpvss::report {

std::string format_lower_bound(double value, int decimals) {
  if (decimals < 0 || decimals > 9) throw std::invalid_argument("format_lower_bound: decimals 0..9");
  std::string text = fmt::format("{:.{}f}", value, decimals);
  if (!std::isfinite(value)) return text;
  // Rounded to nearest: if that went up, the next lower printable number is one unit in the
  // last decimal below, far (half a unit) from any rounding boundary, so its text is exact.
  const double printed = std::strtod(text.c_str(), nullptr);
  if (printed > value) {
    text = fmt::format("{:.{}f}", printed - std::pow(10.0, -decimals), decimals);
    // Beyond ~1e11 the unit is below the spacing of doubles: print the value itself.
    if (std::strtod(text.c_str(), nullptr) > value) text = fmt::format("{}", value);
  }
  return text;
}

}  // namespace grpvss::report
