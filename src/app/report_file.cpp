#include "report_file.hpp"

#include "grpvss/common/input_error.hpp"
#include "grpvss/io/text_file.hpp"
#include "grpvss/report/json_report.hpp"

namespace grpvss::app {

nlohmann::json read_report_file(const std::string& path) {
  const std::string text = io::read_text_file(path);
  nlohmann::json report;
  try {
    report = nlohmann::json::parse(text);
  } catch (const nlohmann::json::parse_error& error) {
    throw InputError(path, 0, "a JSON document", error.what());
  }
  if (!report.is_object() || report.value("schema", std::string()) != report::kReportSchemaId) {
    throw InputError(path, 0, std::string("a GRPVSS report (schema ") + report::kReportSchemaId + ")");
  }
  if (!report.contains("scene") || !report["scene"].is_object()) {
    throw InputError(path, 0, "a report with a `scene` object (grpvss verify --json of this version)");
  }
  return report;
}

}  // namespace grpvss::app
