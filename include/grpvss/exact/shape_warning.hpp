#pragma once
/// \file
/// \brief A warning about an input shape, returned as data (the library prints nothing).

#include <string>

namespace grpvss::geometry {

/// \brief `file:line: text`; line 0 means the file as a whole (meshes: the text names the
/// triangle or vertex index).
struct ShapeWarning {
  std::string file;
  int line = 0;
  std::string text;
};

}  // namespace grpvss::geometry
