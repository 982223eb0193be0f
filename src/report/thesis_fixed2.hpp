// Numbers as the thesis's FORTRAN printed them.
#pragma once

#include <string>

#include <fmt/format.h>

namespace grpvss::report {

/// `%.2f` as FORTRAN's F format printed it, without the "-0.00" a tiny negative would give.
inline std::string fixed2(double value) {
  std::string text = fmt::format("{:.2f}", value);
  if (text == "-0.00") text = "0.00";
  return text;
}

}  // namespace grpvss::report
