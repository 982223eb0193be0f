#include "grpvss/evidence/certificate.hpp"

#include <cmath>
#include <cstdint>
#include <type_traits>
#include <limits>

#include <nlohmann/json.hpp>

#include "grpvss/common/input_error.hpp"

namespace grpvss::certify {
namespace {

using nlohmann::json;

// JSON has no infinity: an absent broadphase margin is written as null.
json number_or_null(double value) { return std::isfinite(value) ? json(value) : json(nullptr); }

json vector_to_json(const Eigen::VectorXd& v) {
  json array = json::array();
  for (Eigen::Index i = 0; i < v.size(); ++i) array.push_back(v[i]);
  return array;
}

GoverningTerm governing_from_string(const std::string& name, const std::string& file) {
  for (GoverningTerm term : {GoverningTerm::kTolerance, GoverningTerm::kClearance,
                             GoverningTerm::kThesisRule, GoverningTerm::kSegmentEnd,
                             GoverningTerm::kRawClearance, GoverningTerm::kUncertified}) {
    if (name == to_string(term)) return term;
  }
  throw InputError(file, 0, "a governing term name", name);
}

// Reads a required field with a clear message naming the JSON path.
template <typename T>
T field(const json& object, const char* key, const std::string& where, const std::string& file) {
  if (!object.is_object() || !object.contains(key)) {
    throw InputError(file, 0, "field '" + std::string(key) + "' in " + where);
  }
  const json& value = object.at(key);
  if constexpr (std::is_same_v<T, int>) {
    // get<int>() of a float outside int's range is undefined behaviour (found reviewing for the
    // certificate fuzz target, docs/reliability.md): only integers within int's range pass.
    const bool in_range =
        value.is_number_unsigned()
            ? value.get<std::uint64_t>() <= static_cast<std::uint64_t>(std::numeric_limits<int>::max())
            : value.is_number_integer() &&
                  value.get<std::int64_t>() >= std::numeric_limits<int>::min() &&
                  value.get<std::int64_t>() <= std::numeric_limits<int>::max();
    if (!in_range) {
      throw InputError(file, 0, "an integer in int range for field '" + std::string(key) + "' in " + where);
    }
  }
  try {
    return value.get<T>();
  } catch (const json::exception&) {
    throw InputError(file, 0, "field '" + std::string(key) + "' in " + where + " of the right type");
  }
}

// A field whose text names an enumerator: `parse` returns nullopt for an unknown name.
template <typename Parse>
auto named_field(const json& object, const char* key, Parse parse, const char* expected,
                 const std::string& file) {
  const auto text = field<std::string>(object, key, "the certificate", file);
  const auto value = parse(text);
  if (!value) throw InputError(file, 0, std::string(key) + " " + expected, "'" + text + "'");
  return *value;
}

// The "inputs" object: name -> text. A value that is not a string is kept as "" (it then
// matches no digest, and the checker names the file that differs).
std::map<std::string, std::string> input_names(const json& document, const std::string& file) {
  std::map<std::string, std::string> inputs;
  if (!document.contains("inputs")) return inputs;
  const json& object = document.at("inputs");
  if (!object.is_object()) throw InputError(file, 0, "an object for 'inputs'");
  for (const auto& [name, value] : object.items()) {
    inputs[name] = value.is_string() ? value.get<std::string>() : std::string();
  }
  return inputs;
}

double margin_field(const json& object, const std::string& where, const std::string& file) {
  if (!object.contains("broadphase_margin")) {
    throw InputError(file, 0, "field 'broadphase_margin' in " + where);
  }
  const json& value = object.at("broadphase_margin");
  if (value.is_null()) return std::numeric_limits<double>::infinity();
  if (!value.is_number()) throw InputError(file, 0, "a number or null for broadphase_margin in " + where);
  return value.get<double>();
}

Eigen::VectorXd vector_field(const json& object, const char* key, const std::string& where,
                             const std::string& file) {
  const auto values = field<std::vector<double>>(object, key, where, file);
  return Eigen::Map<const Eigen::VectorXd>(values.data(), static_cast<Eigen::Index>(values.size()));
}

/// A separated record's witness plane and its certified distance lower bound, the same
/// fields for hull–obstacle evidence and self-collision pairs.
void add_separation(json& item, const geometry::SeparationWitness& witness, double lower_bound) {
  item["normal"] = {witness.normal.x(), witness.normal.y(), witness.normal.z()};
  item["offset_a"] = witness.offset_a;
  item["offset_b"] = witness.offset_b;
  item["lower_bound"] = lower_bound;
}

/// Reads what add_separation wrote.
void read_separation(const json& item, const std::string& where, const std::string& file,
                     geometry::SeparationWitness& witness, double& lower_bound) {
  const auto normal = field<std::vector<double>>(item, "normal", where, file);
  if (normal.size() != 3) throw InputError(file, 0, "a 3-vector normal in " + where);
  witness.normal = {normal[0], normal[1], normal[2]};
  witness.offset_a = field<double>(item, "offset_a", where, file);
  witness.offset_b = field<double>(item, "offset_b", where, file);
  lower_bound = field<double>(item, "lower_bound", where, file);
}

json self_pair_to_json(const SelfPairRecord& record) {
  json item = {{"separated", record.separated}};
  if (record.separated) add_separation(item, record.witness, record.lower_bound);
  if (record.revolution_lower_bound > 0.0) item["revolution_lower_bound"] = record.revolution_lower_bound;
  return item;
}

SelfPairRecord self_pair_from_json(const json& item, const std::string& where,
                                   const std::string& file) {
  SelfPairRecord record;
  record.separated = field<bool>(item, "separated", where, file);
  if (record.separated) read_separation(item, where, file, record.witness, record.lower_bound);
  if (item.contains("revolution_lower_bound")) {
    record.revolution_lower_bound = field<double>(item, "revolution_lower_bound", where, file);
  }
  return record;
}

}  // namespace

json certificate_step_to_json(const StepCertificate& step) {
  json hulls = json::array();
  for (const HullRecord& hull : step.hulls) {
    json evidence = json::array();
    for (const EvidenceRecord& record : hull.evidence) {
      json item = {{"obstacle", record.obstacle},
                   {"expanded", record.expanded},
                   {"separated", record.separated}};
      if (record.separated) add_separation(item, record.witness, record.lower_bound);
      evidence.push_back(item);
    }
    hulls.push_back({{"link", hull.link},
                     {"hull", hull.hull},
                     {"radius", hull.radius},
                     {"broadphase_margin", number_or_null(hull.broadphase_margin)},
                     {"evidence", evidence}});
  }
  json item = {{"step", step.step},
               {"parameter", step.parameter},
               {"q", vector_to_json(step.q)},
               {"hulls", hulls}};
  if (!step.self_pairs.empty()) {
    json pairs = json::array();
    for (const SelfPairRecord& record : step.self_pairs) pairs.push_back(self_pair_to_json(record));
    item["self_pairs"] = pairs;
  }
  if (!step.to_next.hull_motion_bounds.empty()) {
    json governing = json::array();
    for (GoverningTerm term : step.to_next.governing) governing.push_back(to_string(term));
    item["to_next"] = {{"certified", step.to_next.certified},
                       {"hull_motion_bounds", step.to_next.hull_motion_bounds},
                       {"hull_allowances", step.to_next.hull_allowances},
                       {"governing", governing}};
    if (!step.to_next.self_pair_motion_bounds.empty()) {
      item["to_next"]["self_pair_motion_bounds"] = step.to_next.self_pair_motion_bounds;
      item["to_next"]["self_pair_allowances"] = step.to_next.self_pair_allowances;
    }
    if (!step.to_next.self_pair_by_revolution.empty()) {
      item["to_next"]["self_pair_by_revolution"] = step.to_next.self_pair_by_revolution;
    }
  }
  return item;
}

json certificate_segment_to_json(const SegmentCertificate& segment) {
  json steps = json::array();
  for (const StepCertificate& step : segment.steps) steps.push_back(certificate_step_to_json(step));
  return {{"number", segment.number},
          {"kind", motion::to_string(segment.kind)},
          {"parameter_end", segment.parameter_end},
          {"steps", steps}};
}

json certificate_to_json(const Certificate& certificate) {
  json document;
  document["format"] = "grpvss-certificate";
  document["version"] = 1;
  document["mode"] = to_string(certificate.mode);
  document["tolerance"] = certificate.tolerance;
  document["offset_shape"] = geometry::to_string(certificate.offset_shape);
  document["timing"] = motion::to_string(certificate.timing);
  document["cp_speed"] = certificate.cp_speed;
  document["cp_deviation_fraction"] = certificate.cp_deviation_fraction;
  document["placement_error"] = certificate.placement_error;
  document["expansion_radius"] = certificate.expansion_radius;
  document["claim"] = to_string(certificate.claim);
  document["clear_claim"] = to_string(certificate.clear_claim);
  document["collision_step"] = certificate.collision_step;
  if (!certificate.allowed_contacts.empty()) {
    json allowed = json::array();
    for (const AllowedContactPair& pair : certificate.allowed_contacts) {
      allowed.push_back({{"link", pair.link}, {"hull", pair.hull}, {"obstacle", pair.obstacle}});
    }
    document["allowed_contacts"] = allowed;
  }
  if (!certificate.names.empty()) document["names"] = certificate_names_to_json(certificate.names);
  if (!certificate.self_collision_pairs.empty()) {
    json pairs = json::array();
    for (const SelfCollisionPair& pair : certificate.self_collision_pairs) {
      pairs.push_back({{"link_a", pair.link_a}, {"hull_a", pair.hull_a},
                       {"link_b", pair.link_b}, {"hull_b", pair.hull_b}});
    }
    document["self_collision_pairs"] = pairs;
  }
  if (!certificate.trajectory_interpolation.empty()) {
    document["trajectory_interpolation"] = certificate.trajectory_interpolation;
  }
  if (certificate.start) document["start"] = vector_to_json(*certificate.start);
  json errors = json::array();
  for (const PathError& error : certificate.errors) {
    errors.push_back({{"code", error.code}, {"segment", error.segment}, {"step", error.step},
                      {"message", error.message}});
  }
  document["errors"] = errors;
  json segments = json::array();
  for (const SegmentCertificate& segment : certificate.segments) {
    segments.push_back(certificate_segment_to_json(segment));
  }
  document["segments"] = segments;
  return document;
}

Certificate certificate_header_from_json(const json& document, const std::string& file) {
  // Compared as JSON values, not with value(): a "format" or "version" of another JSON type
  // made value() throw json::type_error past the InputError contract (found reviewing for the
  // certificate fuzz target).
  if (!document.is_object() || !document.contains("format") ||
      document.at("format") != json("grpvss-certificate")) {
    throw InputError(file, 0, "a GRPVSS certificate (\"format\": \"grpvss-certificate\")");
  }
  if (!document.contains("version") || document.at("version") != json(1)) {
    throw InputError(file, 0, "certificate version 1");
  }
  Certificate certificate;
  const std::string top = "the certificate";
  certificate.mode = named_field(document, "mode", resolution_mode_from_string,
                                 "certified or thesis", file);
  certificate.tolerance = field<double>(document, "tolerance", top, file);
  certificate.offset_shape = named_field(document, "offset_shape", geometry::offset_shape_from_string,
                                         "cube or rhombicuboctahedron", file);
  certificate.timing = named_field(document, "timing", motion::ptp_timing_from_string,
                                   "independent or synchronized", file);
  certificate.cp_speed = field<double>(document, "cp_speed", top, file);
  // The checker replays the trajectory with it: found by fuzzing (a zero speed threw).
  if (!(certificate.cp_speed > 0.0) || !std::isfinite(certificate.cp_speed)) {
    throw InputError(file, 0, "a finite cp_speed > 0");
  }
  certificate.cp_deviation_fraction = field<double>(document, "cp_deviation_fraction", top, file);
  certificate.placement_error = field<double>(document, "placement_error", top, file);
  certificate.expansion_radius = field<double>(document, "expansion_radius", top, file);
  certificate.claim = named_field(document, "claim", verdict_from_string,
                                  "CLEAR, COLLISION, WITHIN_TOLERANCE, UNDECIDED or ERROR", file);
  // Absent: a certificate made before the claim existed, i.e. with `steps`.
  certificate.clear_claim =
      document.contains("clear_claim")
          ? named_field(document, "clear_claim", clear_claim_from_string, "motion or steps", file)
          : ClearClaim::kSteps;
  certificate.collision_step = field<int>(document, "collision_step", top, file);
  for (const json& error : field<json>(document, "errors", top, file)) {
    certificate.errors.push_back({field<int>(error, "code", "an error", file),
                                  field<int>(error, "segment", "an error", file),
                                  field<int>(error, "step", "an error", file),
                                  field<std::string>(error, "message", "an error", file)});
  }
  if (document.contains("allowed_contacts")) {
    for (const json& pair : field<json>(document, "allowed_contacts", top, file)) {
      const std::string where = "an allowed contact";
      certificate.allowed_contacts.push_back({field<int>(pair, "link", where, file),
                                              field<int>(pair, "hull", where, file),
                                              field<int>(pair, "obstacle", where, file)});
    }
  }
  if (document.contains("names")) {
    certificate.names = certificate_names_from_json(document.at("names"), file);
  }
  if (document.contains("self_collision_pairs")) {
    for (const json& pair : field<json>(document, "self_collision_pairs", top, file)) {
      const std::string where = "a self-collision pair";
      certificate.self_collision_pairs.push_back(
          {field<int>(pair, "link_a", where, file), field<int>(pair, "hull_a", where, file),
           field<int>(pair, "link_b", where, file), field<int>(pair, "hull_b", where, file)});
    }
  }
  if (document.contains("trajectory_interpolation")) {
    certificate.trajectory_interpolation =
        field<std::string>(document, "trajectory_interpolation", top, file);
    if (certificate.trajectory_interpolation != "linear" &&
        certificate.trajectory_interpolation != "cubic-hermite") {
      throw InputError(file, 0, "trajectory_interpolation linear or cubic-hermite",
                       certificate.trajectory_interpolation);
    }
  }
  if (document.contains("start")) {
    certificate.start = vector_field(document, "start", top, file);
  }
  certificate.inputs = input_names(document, file);
  // Present; its elements are read one by one (segment_certificate_from_json).
  if (!document.contains("segments")) throw InputError(file, 0, "field 'segments' in " + top);
  return certificate;
}

SegmentCertificate segment_certificate_from_json(const json& segment_json, const std::string& file) {
  SegmentCertificate segment;
  const std::string where = "a segment";
  segment.number = field<int>(segment_json, "number", where, file);
  segment.kind = named_field(segment_json, "kind", motion::segment_kind_from_string,
                             "ptp-joint, ptp-world or cp-line", file);
  segment.parameter_end = field<double>(segment_json, "parameter_end", where, file);
  for (const json& step_json : field<json>(segment_json, "steps", where, file)) {
    StepCertificate step;
    const std::string step_where = "step of segment " + std::to_string(segment.number);
    step.step = field<int>(step_json, "step", step_where, file);
    step.parameter = field<double>(step_json, "parameter", step_where, file);
    step.q = vector_field(step_json, "q", step_where, file);
    for (const json& hull_json : field<json>(step_json, "hulls", step_where, file)) {
      HullRecord hull;
      hull.link = field<int>(hull_json, "link", step_where, file);
      hull.hull = field<int>(hull_json, "hull", step_where, file);
      hull.radius = field<double>(hull_json, "radius", step_where, file);
      hull.broadphase_margin = margin_field(hull_json, step_where, file);
      for (const json& evidence_json : field<json>(hull_json, "evidence", step_where, file)) {
        EvidenceRecord record;
        record.obstacle = field<int>(evidence_json, "obstacle", step_where, file);
        record.expanded = field<bool>(evidence_json, "expanded", step_where, file);
        record.separated = field<bool>(evidence_json, "separated", step_where, file);
        if (record.separated) {
          read_separation(evidence_json, step_where, file, record.witness, record.lower_bound);
        }
        hull.evidence.push_back(record);
      }
      step.hulls.push_back(std::move(hull));
    }
    if (step_json.contains("self_pairs")) {
      for (const json& pair_json : field<json>(step_json, "self_pairs", step_where, file)) {
        step.self_pairs.push_back(self_pair_from_json(pair_json, step_where, file));
      }
    }
    if (step_json.contains("to_next")) {
      const json& next = step_json.at("to_next");
      step.to_next.certified = field<bool>(next, "certified", step_where, file);
      step.to_next.hull_motion_bounds =
          field<std::vector<double>>(next, "hull_motion_bounds", step_where, file);
      step.to_next.hull_allowances =
          field<std::vector<double>>(next, "hull_allowances", step_where, file);
      for (const auto& name : field<std::vector<std::string>>(next, "governing", step_where, file)) {
        step.to_next.governing.push_back(governing_from_string(name, file));
      }
      if (next.contains("self_pair_motion_bounds")) {
        step.to_next.self_pair_motion_bounds =
            field<std::vector<double>>(next, "self_pair_motion_bounds", step_where, file);
        step.to_next.self_pair_allowances =
            field<std::vector<double>>(next, "self_pair_allowances", step_where, file);
      }
      if (next.contains("self_pair_by_revolution")) {
        step.to_next.self_pair_by_revolution =
            field<std::vector<int>>(next, "self_pair_by_revolution", step_where, file);
      }
    }
    segment.steps.push_back(std::move(step));
  }
  return segment;
}

Certificate certificate_from_json(const json& document, const std::string& file) {
  Certificate certificate = certificate_header_from_json(document, file);
  for (const json& segment_json : document.at("segments")) {
    certificate.segments.push_back(segment_certificate_from_json(segment_json, file));
  }
  return certificate;
}

}  // namespace grpvss::certify
