#include "grpvss/batch/verify_options.hpp"

#include <algorithm>
#include <cmath>
#include <memory>

#include <fmt/core.h>

#include "grpvss/batch/motion_statement.hpp"
#include "grpvss/cell/start_configuration.hpp"
#include "grpvss/common/input_error.hpp"
#include "grpvss/io/profile_table_file.hpp"
#include "grpvss/motion/profile_table.hpp"

namespace grpvss::batch {
namespace {

bool is_one_of(const std::string& word, const std::vector<std::string>& choices) {
  return std::find(choices.begin(), choices.end(), word) != choices.end();
}

std::string listed(const std::vector<std::string>& choices) {
  std::string text;
  for (std::size_t i = 0; i < choices.size(); ++i) {
    if (i > 0) text += i + 1 == choices.size() ? " or " : ", ";
    text += choices[i];
  }
  return text;
}

void check_word(const std::string& key, const std::string& word,
                const std::vector<std::string>& choices, const std::string& file, int line) {
  if (!is_one_of(word, choices)) {
    throw InputError(file, line, "`" + key + "`: " + listed(choices), "'" + word + "'");
  }
}

void check_positive(const std::string& key, double value, const std::string& file, int line) {
  if (!(std::isfinite(value) && value > 0.0)) {
    throw InputError(file, line, "`" + key + "`: a finite number > 0", fmt::format("{}", value));
  }
}

}  // namespace

const std::vector<std::string>& mode_choices() {
  static const std::vector<std::string> choices{"certified", "thesis"};
  return choices;
}

const std::vector<std::string>& offset_choices() {
  static const std::vector<std::string> choices{"auto", "cube", "rhombicuboctahedron"};
  return choices;
}

const std::vector<std::string>& timing_choices() {
  static const std::vector<std::string> choices{"independent", "synchronized"};
  return choices;
}

const std::vector<std::string>& claim_choices() {
  static const std::vector<std::string> choices{"motion", "steps"};
  return choices;
}

cell::ModelSources model_sources(const VerifyOptions& options) {
  return {options.robot_file, options.environment_file, options.cell_file, options.package_paths};
}

void check_verify_options(const VerifyOptions& options, const std::string& file, int line) {
  if (options.tolerance != 0.0) check_positive("tolerance", options.tolerance, file, line);
  if (options.cp_speed != 0.0) check_positive("cp_speed", options.cp_speed, file, line);
  check_word("mode", options.mode, mode_choices(), file, line);
  check_word("offset", options.offset, offset_choices(), file, line);
  check_word("claim", options.claim, claim_choices(), file, line);
  if (!options.timing.empty()) check_word("timing", options.timing, timing_choices(), file, line);
  try {
    (void)parse_ik_choice(options.ik);
  } catch (const InputError& error) {
    throw InputError(file, line, "`ik`: " + error.expected(), error.found());
  }
}

VerifyOptions resolve_model_defaults(const VerifyOptions& options, const cell::ModelInputs& model) {
  VerifyOptions resolved = options;
  if (options.tolerance > 0.0) {
    resolved.tolerance = cell::to_model_units(options.tolerance, model);
  } else if (model.tolerance) {
    resolved.tolerance = *model.tolerance;
  } else {
    throw InputError("--tolerance", 0,
                     model.from_cell ? "--tolerance, or `tolerance` in the cell file"
                                     : "--tolerance DELTA (> 0, length units)");
  }
  if (resolved.timing.empty()) resolved.timing = model.from_cell ? "synchronized" : "independent";
  resolved.cp_speed = options.cp_speed > 0.0
                          ? options.cp_speed * model.model_units_per_cell_unit
                          : model.cp_speed.value_or(1.0);
  return resolved;
}

certify::SetupRequest make_setup_request(const VerifyOptions& options) {
  certify::SetupRequest request;
  request.tolerance = options.tolerance;
  request.mode = options.mode == "thesis" ? certify::ResolutionMode::kThesis
                                          : certify::ResolutionMode::kCertified;
  request.offset_shape = geometry::offset_shape_from_string(options.offset);  // "auto": unset
  request.claim = certify::clear_claim_from_string(options.claim).value_or(certify::ClearClaim::kMotion);
  request.motion.timing =
      motion::ptp_timing_from_string(options.timing).value_or(motion::PtpTiming::kIndependent);
  request.motion.cp_speed = options.cp_speed;
  if (!options.profile_table.empty()) {
    request.motion.table = std::make_shared<const motion::ProfileTable>(
        io::read_profile_table_file(options.profile_table));
  }
  return request;
}

std::optional<Eigen::VectorXd> resolve_start(const VerifyOptions& options, const RobotModel& robot,
                                             bool from_cell, const std::string& source) {
  if (options.start.empty()) return std::nullopt;
  return cell::start_configuration(cell::parse_start_list(options.start, source), robot,
                                   from_cell, source);
}

kinematics::IkChoice parse_ik_choice(const std::string& text) {
  const std::string plugin_prefix = "plugin:";
  if (text == "auto") return {kinematics::IkMethod::kAuto, {}};
  if (text == "numeric") return {kinematics::IkMethod::kNumeric, {}};
  if (text == "ibm7545") return {kinematics::IkMethod::kIbm7545, {}};
  if (text == "opw") return {kinematics::IkMethod::kOpw, {}};
  if (text == "ur") return {kinematics::IkMethod::kUr, {}};
  if (text.rfind(plugin_prefix, 0) == 0 && text.size() > plugin_prefix.size()) {
    return {kinematics::IkMethod::kPlugin, text.substr(plugin_prefix.size())};
  }
  throw InputError("--ik", 0, "auto, ibm7545, opw, ur, numeric or plugin:PATH.so", "'" + text + "'");
}

// ---- The motion statement (grpvss/batch/motion_statement.hpp) ----
namespace {  // the motion statement (motion_statement.hpp)

std::string ptp_part(const motion::MotionModel& model) {
  std::string profiles = "trapezoid profiles";
  if (model.table) {  // named as the path is, without its folder
    const std::string& file = model.table->file_name();
    profiles = "profile table " + file.substr(file.find_last_of('/') + 1);
  }
  return fmt::format("{} PTP timing ({}{})", motion::to_string(model.timing), profiles,
                     model.timing == motion::PtpTiming::kSynchronized
                         ? ", straight line in joint space"
                         : ", each joint on its own");
}

// What the verdict claims (docs/verification.md#verdicts-and-exit-codes).
std::string claim_part(const certify::RunSettings& settings) {
  if (settings.mode == certify::ResolutionMode::kThesis) {
    return "claim: none (thesis mode, not certified)";
  }
  if (settings.claim == certify::ClearClaim::kMotion) {
    return "claim: CLEAR = robot + tolerance clear along the whole motion";
  }
  return "claim: CLEAR = robot clear along the whole motion and robot + tolerance clear at every "
         "step";
}

}  // namespace

std::string describe_path_motion(const certify::RunSettings& settings,
                                 const std::string& path_label, const std::string& ik_name) {
  return fmt::format(
      "path {}, {}, CP lines at {} length units/s, IK {} (solution nearest the previous joints), "
      "exact stops (no blending), {}",
      path_label, ptp_part(settings.motion), settings.motion.cp_speed, ik_name,
      claim_part(settings));
}

}  // namespace grpvss::batch
