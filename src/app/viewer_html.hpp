#pragma once
// One self-contained HTML file (viewer + report, no network) for a JSON report with a scene.
#include <string>

#include <nlohmann/json_fwd.hpp>

namespace grpvss::app {

/// \brief The viewer page for `report` (docs/viewer.md).
/// \throws InputError (file = `report_file`) when the report has no `scene` object or this
///         build has no viewer bundle.
std::string render_viewer_html(const nlohmann::json& report, const std::string& report_file);

}  // namespace grpvss::app
