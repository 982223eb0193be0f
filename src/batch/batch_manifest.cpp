#include "grpvss/batch/batch_manifest.hpp"

#include <cmath>
#include <filesystem>
#include <functional>
#include <map>
#include <optional>
#include <sstream>

#include <fmt/core.h>
#include <nlohmann/json.hpp>
#include <yaml-cpp/yaml.h>

#include "grpvss/common/input_error.hpp"
#include "grpvss/io/text_file.hpp"

namespace grpvss::batch {
namespace {

/// One `key: value` of a job, whatever the manifest's format: the text of a string (or of a
/// YAML scalar) and, when the value is a number, its value.
struct RawValue {
  std::optional<std::string> text;  ///< empty: not a string, scalar or integer
  std::optional<double> number;     ///< empty: not a number
  std::string kind;                 ///< "a string", "an array", ... for messages
  bool integer_only = false;        ///< `text` is a JSON integer's: good for `id` alone
};

struct RawJob {
  int line = 0;
  std::vector<std::pair<std::string, RawValue>> fields;  ///< in the manifest's order
};

/// Where the job's words go: strings (file names resolved against the manifest's folder) and
/// numbers.
struct KeyRule {
  enum class Kind { kText, kFile, kNumber } kind;
  std::function<void(BatchJob&, const std::string&)> set_text;
  std::function<void(BatchJob&, double)> set_number;
};

KeyRule text_key(std::function<void(BatchJob&, const std::string&)> set) {
  return {KeyRule::Kind::kText, std::move(set), {}};
}
KeyRule file_key(std::function<void(BatchJob&, const std::string&)> set) {
  return {KeyRule::Kind::kFile, std::move(set), {}};
}
KeyRule number_key(std::function<void(BatchJob&, double)> set) {
  return {KeyRule::Kind::kNumber, {}, std::move(set)};
}

const std::map<std::string, KeyRule>& key_rules() {
  static const std::map<std::string, KeyRule> rules{
      {"id", text_key([](BatchJob& j, const std::string& v) { j.id = v; })},
      {"robot", file_key([](BatchJob& j, const std::string& v) { j.options.robot_file = v; })},
      {"env", file_key([](BatchJob& j, const std::string& v) { j.options.environment_file = v; })},
      {"cell", file_key([](BatchJob& j, const std::string& v) { j.options.cell_file = v; })},
      {"path", file_key([](BatchJob& j, const std::string& v) { j.options.path_file = v; })},
      {"trajectory",
       file_key([](BatchJob& j, const std::string& v) { j.options.trajectory_file = v; })},
      {"program",
       file_key([](BatchJob& j, const std::string& v) { j.options.program_file = v; })},
      {"tolerance", number_key([](BatchJob& j, double v) { j.options.tolerance = v; })},
      {"mode", text_key([](BatchJob& j, const std::string& v) { j.options.mode = v; })},
      {"offset", text_key([](BatchJob& j, const std::string& v) { j.options.offset = v; })},
      {"claim", text_key([](BatchJob& j, const std::string& v) { j.options.claim = v; })},
      {"timing", text_key([](BatchJob& j, const std::string& v) { j.options.timing = v; })},
      {"profile_table",
       file_key([](BatchJob& j, const std::string& v) { j.options.profile_table = v; })},
      {"ik", text_key([](BatchJob& j, const std::string& v) { j.options.ik = v; })},
      {"start", text_key([](BatchJob& j, const std::string& v) { j.options.start = v; })},
      {"cp_speed", number_key([](BatchJob& j, double v) { j.options.cp_speed = v; })},
      {"output", file_key([](BatchJob& j, const std::string& v) { j.outputs.thesis_output = v; })},
      {"json", file_key([](BatchJob& j, const std::string& v) { j.outputs.json = v; })},
      {"html", file_key([](BatchJob& j, const std::string& v) { j.outputs.html = v; })},
      {"certificate", file_key([](BatchJob& j, const std::string& v) { j.outputs.certificate = v; })},
  };
  return rules;
}

std::string key_list() {
  std::string text;
  for (const std::string& key : job_keys()) text += (text.empty() ? "" : ", ") + key;
  return text;
}

// A relative file name is relative to the manifest's folder; "plugin:X.so" likewise.
std::string resolved(const std::string& name, const std::filesystem::path& base) {
  const std::filesystem::path path(name);
  if (name.empty() || path.is_absolute() || base.empty()) return name;
  return (base / path).lexically_normal().string();
}

void apply_field(BatchJob& job, const std::string& key, const RawValue& value,
                 const std::string& file, const std::filesystem::path& base) {
  const auto rule = key_rules().find(key);
  if (rule == key_rules().end()) {
    throw InputError(file, job.line, "one of the job keys " + key_list(), "`" + key + "`");
  }
  if (rule->second.kind == KeyRule::Kind::kNumber) {
    if (!value.number) throw InputError(file, job.line, "`" + key + "`: a number", value.kind);
    rule->second.set_number(job, *value.number);
    return;
  }
  if (!value.text || (value.integer_only && key != "id")) {
    throw InputError(file, job.line, "`" + key + "`: a string", value.kind);
  }
  const bool is_file = rule->second.kind == KeyRule::Kind::kFile;
  rule->second.set_text(job, is_file ? resolved(*value.text, base) : *value.text);
}

bool has_key(const RawJob& raw, const std::string& key) {
  for (const auto& field : raw.fields) {
    if (field.first == key) return true;
  }
  return false;
}

/// Exactly one motion: a `path` program, a planner's `trajectory` or a robot `program`.
void require_one_motion(const RawJob& raw, const std::string& file) {
  const int given = (has_key(raw, "path") ? 1 : 0) + (has_key(raw, "trajectory") ? 1 : 0) +
                    (has_key(raw, "program") ? 1 : 0);
  if (given != 1) {
    throw InputError(file, raw.line, "exactly one of `path`, `trajectory` and `program`",
                     given == 0 ? "neither" : "several");
  }
}

/// A robot program is verified as its controller runs it (docs/robot-programs.md): the keys
/// `grpvss verify --program` refuses (--timing other than synchronized, --profile-table) are
/// refused.
void refuse_program_conflicts(const BatchJob& job, const RawJob& raw, const std::string& file) {
  if (job.options.program_file.empty()) return;
  const std::string why = "a program is verified as the controller runs it: synchronized PTP, exact stops";
  const bool other_timing = has_key(raw, "timing") && job.options.timing != "synchronized";
  for (const auto& [key, refused] :
       {std::pair<const char*, bool>{"timing", other_timing},
        std::pair<const char*, bool>{"profile_table", has_key(raw, "profile_table")}}) {
    if (refused) {
      throw InputError(file, raw.line, std::string("no `") + key + "` with `program` (" + why + ")",
                       std::string("`") + key + "`");
    }
  }
}

/// A trajectory is the motion (docs/trajectories.md#verifying-a-trajectory): the keys that
/// would choose another, the thesis output file and the thesis step rule are refused, as
/// `grpvss verify --trajectory` refuses their options.
void refuse_trajectory_conflicts(const BatchJob& job, const RawJob& raw, const std::string& file) {
  if (job.options.trajectory_file.empty()) return;
  const std::string motion = "the trajectory's waypoint times and interpolation are the motion";
  const std::vector<std::pair<const char*, std::string>> refused{
      {"timing", motion}, {"profile_table", motion}, {"cp_speed", motion},
      {"start", "a trajectory starts at its first waypoint"},
      {"output", "the thesis output file describes path programs; use `json`"}};
  for (const auto& [key, why] : refused) {
    if (has_key(raw, key)) {
      throw InputError(file, raw.line, std::string("no `") + key + "` with `trajectory` (" + why + ")",
                       std::string("`") + key + "`");
    }
  }
  if (job.options.mode == "thesis") {
    throw InputError(file, raw.line,
                     "no `mode: thesis` with `trajectory` (the thesis step rule is defined for "
                     "PTP and CP segments)",
                     "mode 'thesis'");
  }
}

/// A job names its model by `cell`, or by `robot` and `env` (thesis files, which need
/// `tolerance`: only a cell can supply it); and its motion.
void require_keys(const RawJob& raw, const std::string& file) {
  const bool cell = has_key(raw, "cell");
  if (cell && (has_key(raw, "robot") || has_key(raw, "env"))) {
    throw InputError(file, raw.line, "either `cell`, or `robot` with `env`, not both");
  }
  const std::vector<const char*> required =
      cell ? std::vector<const char*>{} : std::vector<const char*>{"robot", "env", "tolerance"};
  for (const char* key : required) {
    if (!has_key(raw, key)) {
      throw InputError(file, raw.line, std::string("a job with the key `") + key + "` (or a `cell`)");
    }
  }
  require_one_motion(raw, file);
  // Present numbers must be numbers > 0 (an absent one is supplied by the cell or a default).
  for (const char* key : {"tolerance", "cp_speed"}) {
    for (const auto& field : raw.fields) {
      const std::optional<double>& number = field.second.number;
      if (field.first == key && number && !(std::isfinite(*number) && *number > 0.0)) {
        throw InputError(file, raw.line, std::string("`") + key + "`: a finite number > 0",
                         fmt::format("{}", *number));
      }
    }
  }
}

BatchJob job_from(const RawJob& raw, std::size_t index, const std::string& file,
                  const std::filesystem::path& base) {
  BatchJob job;
  job.index = index;
  job.line = raw.line;
  for (const auto& [key, value] : raw.fields) apply_field(job, key, value, file, base);
  require_keys(raw, file);
  check_verify_options(job.options, file, job.line);
  refuse_trajectory_conflicts(job, raw, file);
  refuse_program_conflicts(job, raw, file);
  const std::string plugin = "plugin:";
  if (job.options.ik.rfind(plugin, 0) == 0) {
    job.options.ik = plugin + resolved(job.options.ik.substr(plugin.size()), base);
  }
  if (!job.outputs.certificate.empty() && job.options.mode != "certified") {
    throw InputError(file, job.line, "`certificate` only with `mode: certified`",
                     "mode '" + job.options.mode + "'");
  }
  return job;
}

// ---- JSON Lines ----

std::string json_kind(const nlohmann::json& value) {
  if (value.is_string()) return "a string";
  if (value.is_number()) return "a number";
  if (value.is_boolean()) return "a boolean";
  if (value.is_null()) return "null";
  if (value.is_array()) return "an array";
  return "an object";
}

RawValue json_value(const nlohmann::json& value) {
  RawValue raw{{}, {}, json_kind(value)};
  if (value.is_string()) raw.text = value.get<std::string>();
  if (value.is_number()) raw.number = value.get<double>();
  if (value.is_number_integer()) {  // an `id` may be a number
    raw.text = value.dump();
    raw.integer_only = true;
  }
  return raw;
}

std::vector<RawJob> json_lines_jobs(const std::string& text, const std::string& file) {
  std::vector<RawJob> jobs;
  std::istringstream lines(text);
  std::string line_text;
  for (int line = 1; std::getline(lines, line_text); ++line) {
    if (line_text.find_first_not_of(" \t\r") == std::string::npos) continue;
    nlohmann::json object;
    try {
      object = nlohmann::json::parse(line_text);
    } catch (const nlohmann::json::parse_error& error) {
      throw InputError(file, line, "a JSON object (one job per line)", error.what());
    }
    if (!object.is_object()) {
      throw InputError(file, line, "a JSON object (one job per line)", json_kind(object));
    }
    RawJob job{line, {}};
    for (const auto& [key, value] : object.items()) job.fields.emplace_back(key, json_value(value));
    jobs.push_back(std::move(job));
  }
  return jobs;
}

// ---- YAML ----

std::string yaml_kind(const YAML::Node& node) {
  if (node.IsSequence()) return "a sequence";
  if (node.IsMap()) return "a mapping";
  if (node.IsNull()) return "nothing";
  return "a scalar";
}

RawValue yaml_value(const YAML::Node& node) {
  RawValue raw{{}, {}, yaml_kind(node)};
  if (!node.IsScalar()) return raw;
  raw.text = node.Scalar();
  double number = 0.0;
  if (YAML::convert<double>::decode(node, number)) raw.number = number;
  return raw;
}

int line_of(const YAML::Node& node) { return node.Mark().line + 1; }

YAML::Node yaml_document(const std::string& text, const std::string& file) {
  try {
    return YAML::Load(text);
  } catch (const YAML::Exception& error) {
    throw InputError(file, error.mark.line + 1, "a YAML document", error.msg);
  }
}

std::vector<RawJob> yaml_jobs(const std::string& text, const std::string& file) {
  const YAML::Node document = yaml_document(text, file);
  if (!document.IsMap()) throw InputError(file, 1, "a mapping with the key `jobs`", yaml_kind(document));
  for (const auto& entry : document) {
    const std::string key = entry.first.Scalar();
    if (key != "jobs") throw InputError(file, line_of(entry.first), "the top-level key `jobs`", "`" + key + "`");
  }
  const YAML::Node sequence = document["jobs"];
  if (!sequence || !sequence.IsSequence()) {
    throw InputError(file, 1, "`jobs`: a sequence of jobs", sequence ? yaml_kind(sequence) : "none");
  }
  std::vector<RawJob> jobs;
  for (const YAML::Node& item : sequence) {
    if (!item.IsMap()) throw InputError(file, line_of(item), "a job (a mapping)", yaml_kind(item));
    RawJob job{line_of(item), {}};
    for (const auto& field : item) job.fields.emplace_back(field.first.Scalar(), yaml_value(field.second));
    jobs.push_back(std::move(job));
  }
  return jobs;
}

std::vector<RawJob> raw_jobs(const std::string& text, const std::string& file) {
  const std::string extension = std::filesystem::path(file).extension().string();
  if (extension == ".jsonl" || extension == ".json") return json_lines_jobs(text, file);
  if (extension == ".yaml" || extension == ".yml") return yaml_jobs(text, file);
  throw InputError(file, 0, "a manifest named *.jsonl, *.json, *.yaml or *.yml",
                   "'" + extension + "'");
}

}  // namespace

const std::vector<std::string>& job_keys() {
  static const std::vector<std::string> keys{
      "id", "robot", "env", "cell", "path", "trajectory", "program", "tolerance", "mode", "offset", "claim", "timing",
      "profile_table", "ik", "cp_speed", "start", "output", "json", "html", "certificate"};
  return keys;
}

BatchManifest parse_batch_manifest(const std::string& text, const std::string& file_name) {
  const std::filesystem::path base = std::filesystem::path(file_name).parent_path();
  BatchManifest manifest{file_name, {}};
  const std::vector<RawJob> raw = raw_jobs(text, file_name);
  if (raw.empty()) throw InputError(file_name, 0, "at least one job", "none");
  manifest.jobs.reserve(raw.size());
  for (std::size_t i = 0; i < raw.size(); ++i) {
    manifest.jobs.push_back(job_from(raw[i], i, file_name, base));
  }
  return manifest;
}

BatchManifest read_batch_manifest(const std::string& path) {
  return parse_batch_manifest(io::read_text_file(path), path);
}

}  // namespace grpvss::batch
