#include "trajectory_inputs.hpp"

#include "grpvss/common/input_error.hpp"

namespace grpvss::app {

void refuse_with_trajectory(bool given, const std::string& option, const std::string& why) {
  if (!given) return;
  throw InputError(option, 0, "no " + option + " with --trajectory (" + why + ")", option);
}

void require_path_or_trajectory(const std::string& path_file, const std::string& trajectory_file) {
  if (path_file.empty() == trajectory_file.empty()) {
    throw InputError("--path", 0, "exactly one of --path and --trajectory",
                     path_file.empty() ? "neither" : "both");
  }
}

}  // namespace grpvss::app
