// A double as text that reads back to the same double (17 significant digits), for messages
// that quote a value from an input file.
#pragma once

#include <cstdio>
#include <string>

namespace grpvss::io {

inline std::string round_trip_text(double x) {
  char buffer[64];
  std::snprintf(buffer, sizeof buffer, "%.17g", x);
  return buffer;
}

}  // namespace grpvss::io
