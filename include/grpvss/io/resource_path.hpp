#pragma once
/// \file
/// \brief Resolving the file references of robot descriptions: `package://NAME/PATH`,
/// `file://PATH` and plain paths (relative ones against the referring file's folder).

#include <string>
#include <vector>

namespace grpvss::io {

/// \brief Where a reference led.
struct ResolvedResource {
  std::string path;                ///< the existing file found; empty when none was
  std::vector<std::string> tried;  ///< every candidate looked at, in order (for messages)
};

/// \brief Resolves `reference`.
///
/// - `package://NAME/PATH`: for each directory D of `package_directories` in order, the first
///   existing file among D/NAME/PATH and (when D's last component is NAME) D/PATH.
/// - `file://PATH`: PATH (a relative PATH is taken against `base_directory`).
/// - anything else without a `scheme://`: a path, relative ones against `base_directory`.
/// Other schemes (`http://`, ...) and a `package://` without NAME or PATH resolve to nothing.
ResolvedResource resolve_resource(const std::string& reference, const std::string& base_directory,
                                  const std::vector<std::string>& package_directories);

/// \brief The directories of the `ROS_PACKAGE_PATH` environment variable (`:`-separated,
/// empty entries dropped); empty when it is unset.
std::vector<std::string> ros_package_path_directories();

}  // namespace grpvss::io
