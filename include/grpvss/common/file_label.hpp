// How messages name an input file: the file's name without its folder.
#pragma once

#include <string>

namespace grpvss {

inline std::string file_label(const std::string& path) {
  const auto slash = path.find_last_of('/');
  return slash == std::string::npos ? path : path.substr(slash + 1);
}

}  // namespace grpvss
