#include "output_paths.hpp"

#include <filesystem>
#include <system_error>

#include "grpvss/common/input_error.hpp"
#include "grpvss/report/atomic_output.hpp"

namespace grpvss::app {
namespace {

// The file a path names, for comparison: symlinks and `..` resolved as far as the path exists
// (an output usually does not exist yet; its folder does).
std::filesystem::path file_identity(const std::string& path) {
  // Absolute first: weakly_canonical leaves a relative path whose first part does not exist
  // ("x.json") relative, and "./x.json" would not compare equal to it.
  const std::filesystem::path absolute = std::filesystem::absolute(path).lexically_normal();
  std::error_code error;
  std::filesystem::path resolved = std::filesystem::weakly_canonical(absolute, error);
  if (error) resolved = absolute;
  return resolved;
}

bool same_file(const std::string& a, const std::string& b) {
  if (a == report::kStandardOutput || b == report::kStandardOutput) return a == b;
  return file_identity(a) == file_identity(b);
}

}  // namespace

void check_requested_outputs(const std::vector<RequestedOutput>& outputs,
                             const std::vector<std::string>& inputs, bool force) {
  for (std::size_t i = 0; i < outputs.size(); ++i) {
    const RequestedOutput& output = outputs[i];
    if (output.path.empty()) continue;
    for (std::size_t j = 0; j < i; ++j) {
      if (!outputs[j].path.empty() && same_file(outputs[j].path, output.path)) {
        throw InputError(output.option, 0, "an output different from " + outputs[j].option,
                         output.path);
      }
    }
    for (const std::string& input : inputs) {
      if (!input.empty() && same_file(input, output.path)) {
        throw InputError(output.option, 0, "an output that is not one of the input files",
                         output.path);
      }
    }
    if (!force && output.path != report::kStandardOutput &&
        std::filesystem::exists(output.path)) {
      throw report::OutputExistsError(output.path);
    }
  }
}

bool writes_to_standard_output(const std::vector<RequestedOutput>& outputs) {
  for (const RequestedOutput& output : outputs) {
    if (output.path == report::kStandardOutput) return true;
  }
  return false;
}

}  // namespace grpvss::app
