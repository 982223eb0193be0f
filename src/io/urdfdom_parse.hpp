#pragma once
// urdfdom's parser, with its console_bridge messages captured (errors become InputError,
// warnings are returned) instead of printed. Private to src/io.

#include <memory>
#include <string>
#include <string_view>
#include <vector>

#include <urdf_model/model.h>

#include "grpvss/io/input_warning.hpp"

namespace grpvss::io {

struct UrdfdomModel {
  /// The model; its links' child lists are cleared when the last owner lets go, so that a
  /// cyclic file cannot leak it.
  std::shared_ptr<const urdf::ModelInterface> model;
  std::vector<InputWarning> warnings;
};

/// \brief urdf::parseURDF on `text`. \throws InputError(file, 0, "a URDF urdfdom accepts",
/// urdfdom's first error message) when it rejects the text.
UrdfdomModel parse_with_urdfdom(std::string_view text, const std::string& file);

}  // namespace grpvss::io
