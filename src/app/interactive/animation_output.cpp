#include "interactive/animation_output.hpp"

#include <array>

#include <filesystem>
#include <system_error>

#include <fmt/core.h>
#include <nlohmann/json.hpp>

#include "grpvss/common/input_error.hpp"
#include "grpvss/report/atomic_output.hpp"
#include "grpvss/report/json_report.hpp"
#include "grpvss/report/scene_json.hpp"
#include "grpvss/report/svg_render.hpp"

#include "interactive/svg_window.hpp"

namespace grpvss::app::interactive {
namespace {

bool exists(const std::string& path) {
  std::error_code error;
  return std::filesystem::exists(std::filesystem::symlink_status(path, error));
}

std::string free_base(const std::string& base) {
  constexpr int kMaxAttempts = 1000;
  for (int attempt = 1; attempt <= kMaxAttempts; ++attempt) {
    const std::string candidate = attempt == 1 ? base : fmt::format("{}-{}", base, attempt);
    if (!exists(candidate + ".json") && !exists(candidate + ".svg") && !exists(candidate + ".html")) {
      return candidate;
    }
  }
  throw InputError(base + ".json", 0,
                   fmt::format("a free name among {} numbered variants", kMaxAttempts));
}

/// The step worth a picture: the first collision, else the last step (0: none).
int picture_step(const certify::VerificationResult& result) {
  if (result.collision_step) return *result.collision_step;
  return result.steps.empty() ? 0 : result.steps.back().index;
}

report::SvgView svg_view(const ViewSettings& view) {
  report::SvgView svg;
  svg.angle_x_deg = view.angles_deg[0];
  svg.angle_y_deg = view.angles_deg[1];
  svg.angle_z_deg = view.angles_deg[2];
  svg.scale = view.scale;
  svg.shift = view.shift;
  return svg;
}

}  // namespace

AnimationFiles write_animation(const AnimationRequest& request, const std::string& base,
                               const HtmlRenderer& render_html) {
  nlohmann::json report =
      report::report_to_json(request.result, request.cell.robot(), request.digests);
  report["scene"] = report::scene_to_json(request.result, request.cell);
  const std::string name = free_base(base);
  AnimationFiles files;
  files.json = name + ".json";
  // Everything is rendered before anything is published.
  std::string svg;
  files.svg_step = picture_step(request.result);
  if (files.svg_step > 0) {
    report::SvgView view = svg_view(request.view);
    const std::array<double, 2> window = default_svg_window(report);  // the scene's size
    view.window_min = window[0];
    view.window_max = window[1];
    svg = report::render_step_svg(report, files.svg_step, view, files.json);
  }
  std::string html;
  if (render_html) {
    try {
      html = render_html(report, files.json);
    } catch (const InputError& error) {
      files.html_error = error.what();
    }
  }
  report::write_file_atomically(files.json, report::render_json_report(report), false);
  if (!svg.empty()) {
    files.svg = name + ".svg";
    report::write_file_atomically(files.svg, svg, false);
  }
  if (!html.empty()) {
    files.html = name + ".html";
    report::write_file_atomically(files.html, html, false);
  }
  return files;
}

}  // namespace grpvss::app::interactive
