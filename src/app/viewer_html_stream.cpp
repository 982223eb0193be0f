#include "viewer_html_stream.hpp"

#include <stdexcept>

#include "grpvss/common/input_error.hpp"
#include "grpvss/report/markup_escape.hpp"
#include "viewer_assets.hpp"

namespace grpvss::app {
namespace {

std::size_t placeholder_at(const std::string& page, const std::string& placeholder) {
  const auto at = page.find(placeholder);
  if (at == std::string::npos) throw std::logic_error("viewer template lacks " + placeholder);
  return at;
}

}  // namespace

void require_viewer_bundle(const std::string& html_path) {
  if (viewer_bundle().empty()) {
    throw InputError(html_path, 0,
                     "a grpvss build with the viewer (run `npm ci` in src/viewer, then rebuild)");
  }
}

void write_viewer_html(const std::string& html_path, bool force, const std::string& robot_name,
                       const std::function<void(report::AtomicOutputFile&)>& write_report) {
  require_viewer_bundle(html_path);
  const std::string& page = viewer_template();
  const std::string title_placeholder = "@GRPVSS_TITLE@";
  const std::string report_placeholder = "@GRPVSS_REPORT@";
  const std::string bundle_placeholder = "@GRPVSS_BUNDLE@";
  const std::size_t title = placeholder_at(page, title_placeholder);
  const std::size_t report = placeholder_at(page, report_placeholder);
  const std::size_t bundle = placeholder_at(page, bundle_placeholder);
  if (!(title < report && report < bundle)) {
    throw std::logic_error("viewer template: placeholders out of order");
  }
  report::AtomicOutputFile output(html_path, force);
  output.write(page.substr(0, title));
  output.write(report::markup_escape("GRPVSS report - " + robot_name));
  const std::size_t after_title = title + title_placeholder.size();
  output.write(page.substr(after_title, report - after_title));
  write_report(output);
  const std::size_t after_report = report + report_placeholder.size();
  output.write(page.substr(after_report, bundle - after_report));
  output.write(viewer_bundle());
  output.write(page.substr(bundle + bundle_placeholder.size()));
  output.commit();
}

}  // namespace grpvss::app
