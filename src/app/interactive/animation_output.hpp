#pragma once
/// \file
/// \brief The "graphics animation" of the thesis's session, as a file: after each processed
/// motion the session writes one document the user opens in a browser.
///
/// Until the viewer's HTML writer is in this build, the document is the JSON report
/// (docs/report-schema.md) and the view settings stay with the session; write_animation() is
/// the one place that changes when the HTML writer arrives.

#include <string>

#include "grpvss/certify/verification_result.hpp"
#include "grpvss/model/environment.hpp"
#include "grpvss/model/robot_model.hpp"
#include "grpvss/report/input_digests.hpp"
#include "interactive/view_settings.hpp"

namespace grpvss::app::interactive {

struct AnimationRequest {
  const certify::VerificationResult& result;
  const RobotModel& robot;
  const Environment& environment;
  const report::InputDigests& digests;
  const ViewSettings& view;
};

/// What kind of document write_animation() produces.
struct AnimationFormat {
  const char* extension;    ///< ".json" (later ".html")
  const char* description;  ///< said to the user
  bool is_html;
};

AnimationFormat animation_format();

/// \brief Writes the animation document to `base` + extension, or, when that name exists,
/// `base`-2 + extension, -3, ... (never overwriting a file). Returns the path written.
/// \throws InputError when the directory is not writable (or 1000 names are taken).
std::string write_animation(const AnimationRequest& request, const std::string& base);

}  // namespace grpvss::app::interactive
