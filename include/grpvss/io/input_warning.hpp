#pragma once
/// \file
/// \brief A warning about an input file, returned as data (the library never prints).

#include <string>

namespace grpvss::io {

/// \brief Something in an input file that was read but ignored or adjusted.
struct InputWarning {
  std::string file;
  int line = 0;  ///< 1-based; 0 = the file as a whole
  std::string text;
};

}  // namespace grpvss::io
