#include "grpvss/batch/batch_result_json.hpp"

#include <nlohmann/json.hpp>

namespace grpvss::batch {

std::string job_result_json(const JobResult& result) {
  using Json = nlohmann::ordered_json;
  Json line;
  line["index"] = result.index;
  line["line"] = result.line;
  line["id"] = result.id.empty() ? Json(nullptr) : Json(result.id);
  line["verdict"] = result.verdict ? Json(certify::to_string(*result.verdict)) : Json(nullptr);
  line["exit_code"] = result.exit_code;
  line["steps"] = result.steps;
  line["smallest_clearance"] = nullptr;
  if (const auto& smallest = result.smallest_clearance) {
    line["smallest_clearance"] = {{"clearance", smallest->clearance},
                                  {"link", smallest->link},
                                  {"obstacle", smallest->obstacle < 0 ? Json(nullptr) : Json(smallest->obstacle)},
                                  {"step", smallest->step}};
    // Names only for named models, so thesis jobs' lines stay as they were.
    if (!smallest->link_name.empty()) line["smallest_clearance"]["link_name"] = smallest->link_name;
    if (!smallest->obstacle_name.empty()) {
      line["smallest_clearance"]["obstacle_name"] = smallest->obstacle_name;
    }
  }
  Json outputs = Json::object();
  for (const WrittenOutput& output : result.outputs) outputs[output.key] = output.path;
  line["outputs"] = std::move(outputs);
  line["error"] = nullptr;
  if (const auto& error = result.error) {
    line["error"] = {{"file", error->file}, {"line", error->line}, {"message", error->message}};
  }
  if (!result.warnings.empty()) {
    Json warnings = Json::array();
    for (const io::InputWarning& warning : result.warnings) {
      warnings.push_back({{"file", warning.file}, {"line", warning.line}, {"text", warning.text}});
    }
    line["warnings"] = std::move(warnings);
  }
  return line.dump(-1, ' ', false, Json::error_handler_t::replace);
}

}  // namespace grpvss::batch
