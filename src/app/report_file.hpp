#pragma once
// Reading a JSON report written by `grpvss verify --json` (animate and render read only it).
#include <string>

#include <nlohmann/json.hpp>

namespace grpvss::app {

/// \brief The parsed report.
/// \throws InputError when the file cannot be read, is not JSON, or is not a GRPVSS report
///         with a `scene` object (schema grpvss-report/1, docs/report-schema.md).
nlohmann::json read_report_file(const std::string& path);

}  // namespace grpvss::app
