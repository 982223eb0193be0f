#include "interactive/animation_output.hpp"

#include <fmt/core.h>
#include <nlohmann/json.hpp>

#include "grpvss/common/input_error.hpp"
#include "grpvss/report/atomic_output.hpp"
#include "grpvss/report/json_report.hpp"

namespace grpvss::app::interactive {

AnimationFormat animation_format() {
  return {".json", "A JSON REPORT: THE HTML ANIMATION WRITER IS NOT IN THIS BUILD YET", false};
}

namespace {

std::string render_animation(const AnimationRequest& request) {
  // The HTML writer (viewer branch) replaces this line; it takes request.view and
  // request.environment as well.
  return report::render_json_report(
      report::report_to_json(request.result, request.robot, request.digests));
}

}  // namespace

std::string write_animation(const AnimationRequest& request, const std::string& base) {
  const std::string content = render_animation(request);
  const std::string extension = animation_format().extension;
  constexpr int kMaxAttempts = 1000;
  for (int attempt = 1; attempt <= kMaxAttempts; ++attempt) {
    const std::string path =
        attempt == 1 ? base + extension : fmt::format("{}-{}{}", base, attempt, extension);
    try {
      report::write_file_atomically(path, content, /*force=*/false);
      return path;
    } catch (const report::OutputExistsError&) {
      // Taken: try the next number.
    }
  }
  throw InputError(base + extension, 0,
                   fmt::format("a free name among {} numbered variants", kMaxAttempts));
}

}  // namespace grpvss::app::interactive
