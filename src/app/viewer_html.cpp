#include "viewer_html.hpp"

#include <nlohmann/json.hpp>

#include "grpvss/common/input_error.hpp"
#include "grpvss/report/markup_escape.hpp"
#include "viewer_assets.hpp"

namespace grpvss::app {
namespace {

void replace_once(std::string& text, const std::string& placeholder, const std::string& value) {
  const auto at = text.find(placeholder);
  if (at == std::string::npos) throw std::logic_error("viewer template lacks " + placeholder);
  text.replace(at, placeholder.size(), value);
}

/// JSON inside <script>: "<" only occurs inside JSON strings, where \u003c means the same, so
/// no "</script>" or "<!--" in a file name can end the script element early.
std::string script_safe_json(const nlohmann::json& report) {
  const std::string text = report.dump(-1, ' ', false, nlohmann::json::error_handler_t::replace);
  std::string out;
  out.reserve(text.size());
  for (char c : text) {
    if (c == '<') out += "\\u003c"; else out += c;
  }
  return out;
}

}  // namespace

std::string render_viewer_html(const nlohmann::json& report, const std::string& report_file) {
  if (viewer_bundle().empty()) {
    throw InputError(report_file, 0,
                     "a grpvss build with the viewer (run `npm ci` in src/viewer, then rebuild)");
  }
  if (!report.is_object() || !report.contains("scene") || !report["scene"].is_object() ||
      !report.contains("steps") || !report["steps"].is_array()) {
    throw InputError(report_file, 0, "a GRPVSS JSON report with a `scene` object",
                     "a report without one");
  }
  std::string page = viewer_template();
  std::string title = "GRPVSS report";
  if (report.contains("robot") && report["robot"].contains("name") && report["robot"]["name"].is_string()) {
    title += " - " + report["robot"]["name"].get<std::string>();
  }
  // The bundle goes in last: nothing inside it is ever scanned for placeholders.
  replace_once(page, "@GRPVSS_TITLE@", report::markup_escape(title));
  replace_once(page, "@GRPVSS_REPORT@", script_safe_json(report));
  replace_once(page, "@GRPVSS_BUNDLE@", viewer_bundle());
  return page;
}

}  // namespace grpvss::app
