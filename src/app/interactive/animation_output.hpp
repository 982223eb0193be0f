#pragma once
/// \file
/// \brief The "graphics animation" of the thesis's session, as files: after each processed
/// motion the session writes, under one free base name,
/// - `BASE.json`: the JSON report with its `scene` (docs/report-schema.md, docs/viewer.md);
/// - `BASE.svg`: the thesis's wireframe picture (report::render_step_svg) of the first
///   colliding step, else the last step, in the session's view (ANGLEX/Y/Z, SCALE, SHIFT);
/// - `BASE.html`: the 3-D animation, when an HTML renderer is given (the viewer is linked into
///   the executable, not into this library, so the command passes it in).

#include <functional>
#include <string>

#include <nlohmann/json_fwd.hpp>

#include "grpvss/certify/robot_cell.hpp"
#include "grpvss/evidence/verification_result.hpp"
#include "grpvss/report/input_digests.hpp"
#include "interactive/view_settings.hpp"

namespace grpvss::app::interactive {

/// Renders the HTML page of a report with a scene; may throw InputError (e.g. a build without
/// the viewer bundle).
using HtmlRenderer = std::function<std::string(const nlohmann::json& report,
                                               const std::string& report_file)>;

struct AnimationRequest {
  const certify::VerificationResult& result;
  const certify::RobotCell& cell;  ///< the cell the run used
  const report::InputDigests& digests;
  const ViewSettings& view;
};

struct AnimationFiles {
  std::string json;        ///< always written
  std::string svg;         ///< empty when the run has no step to draw
  int svg_step = 0;        ///< the step drawn
  std::string html;        ///< empty without a renderer or when it failed
  std::string html_error;  ///< why there is no HTML (empty when written or not asked for)
};

/// \brief Writes the animation files under `base` or, when any of its names exists,
/// `base`-2, -3, ... (never overwriting a file).
/// \throws InputError when the directory is not writable (or 1000 names are taken).
AnimationFiles write_animation(const AnimationRequest& request, const std::string& base,
                               const HtmlRenderer& render_html);

}  // namespace grpvss::app::interactive
