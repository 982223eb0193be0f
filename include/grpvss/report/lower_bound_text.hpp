#pragma once
/// \file
/// \brief Printing a proven lower bound with a fixed number of decimals without overstating
/// it: "{:.4f}" rounds to nearest, so 0.04356 would print as 0.0436, a claim not proven.

#include <string>

namespace grpvss::report {

/// \brief `value` with `decimals` decimals (0..9), rounded down: the printed number is never
/// above `value` and less than 10^-decimals (plus rounding) below it.
std::string format_lower_bound(double value, int decimals);

}  // namespace grpvss::report
