#include "krl_motion_state.hpp"

#include <algorithm>
#include <sstream>
#include <vector>

#include "grpvss/io/units.hpp"

namespace grpvss::io::krl {
namespace {

enum class Range { kNonNegative, kPercent };


/// One numeric parameter: where it lives and what it accepts.
struct Parameter {
  const char* name;
  std::optional<double> MotionState::*field;
  Range range;
};

/// The components of $VEL, $ACC and $APO the reader follows.
const std::vector<Parameter>& structure_parameters(const std::string& variable) {
  static const std::vector<Parameter> kVel = {{"CP", &MotionState::vel_cp, Range::kNonNegative},
                                              {"ORI1", &MotionState::vel_ori1, Range::kNonNegative},
                                              {"ORI2", &MotionState::vel_ori2, Range::kNonNegative}};
  static const std::vector<Parameter> kAcc = {{"CP", &MotionState::acc_cp, Range::kNonNegative},
                                              {"ORI1", &MotionState::acc_ori1, Range::kNonNegative}};
  static const std::vector<Parameter> kApo = {{"CDIS", &MotionState::apo_cdis, Range::kNonNegative},
                                              {"CPTP", &MotionState::apo_cptp, Range::kPercent},
                                              {"CORI", &MotionState::apo_cori, Range::kNonNegative},
                                              {"CVEL", &MotionState::apo_cvel, Range::kPercent}};
  static const std::vector<Parameter> kNone;
  if (variable == "$VEL") return kVel;
  if (variable == "$ACC") return kAcc;
  if (variable == "$APO") return kApo;
  return kNone;
}

std::string component_list(const std::vector<Parameter>& parameters) {
  std::string list;
  for (const Parameter& parameter : parameters) list += (list.empty() ? "" : ", ") + std::string(parameter.name);
  return list;
}

/// Sets one number; an unknown value unsets it (with a warning).
void set_number(std::optional<double>& field, Range range, const std::string& name,
                const Value& value, const TokenCursor& cursor, ProgramRecorder& recorder) {
  const int line = cursor.range().line;
  if (value.is_unknown()) {
    recorder.warn(cursor.file_name(), line,
                  name + " is not computed (" + value.text + "): it is unset from here");
    field.reset();
    return;
  }
  if (value.kind != Value::Kind::kNumber) {
    cursor.fail_at(line, "a number for " + name, describe(value));
  }
  const bool fits = range == Range::kPercent ? (value.number > 0.0 && value.number <= 100.0)
                                             : value.number >= 0.0;
  if (!fits) {
    cursor.fail_at(line,
                   (range == Range::kPercent ? "a percentage in (0, 100] for " : "a non-negative number for ") + name,
                   number_text(value.number));
  }
  field = value.number;
}

bool assign_structure_parameter(MotionState& state, const Designator& target, const Value& value,
                                const TokenCursor& cursor, ProgramRecorder& recorder) {
  const std::vector<Parameter>& parameters = structure_parameters(target.key);
  if (parameters.empty() || target.components.size() > 1) return false;
  if (target.components.size() == 1) {
    for (const Parameter& parameter : parameters) {
      if (target.components[0] == parameter.name) {
        set_number(state.*parameter.field, parameter.range, target.key + "." + parameter.name, value, cursor, recorder);
        return true;
      }
    }
    return false;
  }
  if (value.kind != Value::Kind::kStructure) {
    cursor.fail_at(cursor.range().line, "a structure {" + component_list(parameters) + "} for " + target.key, describe(value));
  }
  for (std::size_t i = 0; i < value.names.size(); ++i) {
    const auto parameter = std::find_if(parameters.begin(), parameters.end(),
                                        [&](const Parameter& p) { return value.names[i] == p.name; });
    if (parameter == parameters.end()) {
      cursor.fail_at(cursor.range().line, "a component of " + target.key + " the reader reads (" + component_list(parameters) + ")",
                     quote_source(value.names[i]));
    }
    set_number(state.*parameter->field, parameter->range, target.key + "." + parameter->name, value.values[i], cursor, recorder);
  }
  return true;
}

bool assign_axis_parameter(MotionState& state, const Designator& target, const Value& value,
                           const TokenCursor& cursor, ProgramRecorder& recorder) {
  if (!target.components.empty()) return false;
  for (long long axis = 1; axis <= 6; ++axis) {
    const auto index = static_cast<std::size_t>(axis - 1);
    if (target.key == element_key("$VEL_AXIS", {axis})) {
      set_number(state.vel_axis[index], Range::kPercent, target.key, value, cursor, recorder);
      return true;
    }
    if (target.key == element_key("$ACC_AXIS", {axis})) {
      set_number(state.acc_axis[index], Range::kPercent, target.key, value, cursor, recorder);
      return true;
    }
  }
  return false;
}

bool assign_frame(MotionState& state, const Designator& target, const Value& value,
                  const std::string& value_text, const TokenCursor& cursor) {
  if ((target.key != "$TOOL" && target.key != "$BASE") || !target.components.empty()) return false;
  if (value.kind != Value::Kind::kStructure) {
    cursor.fail_at(cursor.range().line, "a FRAME the reader can compute for " + target.key, describe(value));
  }
  const Value frame = frame_value(frame_components(value));
  if (target.key == "$TOOL") {
    state.tool = frame;
    state.tool_name = value_text;
  } else {
    state.base = frame;
    state.base_name = value_text;
  }
  return true;
}

std::optional<double> in_si(const std::optional<double>& value, double factor) {
  if (!value) return std::nullopt;
  return *value * factor;
}

std::vector<std::optional<double>> percentages(const std::array<std::optional<double>, 6>& axes) {
  const bool any = std::any_of(axes.begin(), axes.end(), [](const auto& axis) { return axis.has_value(); });
  if (!any) return {};
  return std::vector<std::optional<double>>(axes.begin(), axes.end());
}

}  // namespace

void MotionState::reset_motion_parameters() {
  vel_cp.reset();
  vel_ori1.reset();
  vel_ori2.reset();
  acc_cp.reset();
  acc_ori1.reset();
  vel_axis = {};
  acc_axis = {};
  apo_cdis.reset();
  apo_cptp.reset();
  apo_cori.reset();
  apo_cvel.reset();
}

MotionSpeed MotionState::speed() const {
  MotionSpeed speed;
  speed.tcp_speed = vel_cp;
  speed.orientation_speed = in_si(vel_ori1, kRadiansPerDegree);
  speed.orientation_speed_2 = in_si(vel_ori2, kRadiansPerDegree);
  speed.tcp_acceleration = acc_cp;
  speed.orientation_acceleration = in_si(acc_ori1, kRadiansPerDegree);
  speed.joint_speed_percent = percentages(vel_axis);
  speed.joint_acceleration_percent = percentages(acc_axis);
  return speed;
}

std::optional<Value> MotionState::system_value(const std::string& key) const {
  if (key == "$TOOL" || key == "$BASE") {
    const std::optional<Value>& frame = key == "$TOOL" ? tool : base;
    if (frame) return *frame;
    return Value::unknown(key + ", which the program has not set");
  }
  const std::vector<Parameter>& parameters = structure_parameters(key);
  if (!parameters.empty()) {
    Value value = Value::structure("");
    for (const Parameter& parameter : parameters) {
      if (const auto& number = this->*parameter.field) value.set_component(parameter.name, Value::of_number(*number));
    }
    return value;
  }
  for (long long axis = 1; axis <= 6; ++axis) {
    const auto index = static_cast<std::size_t>(axis - 1);
    for (const auto& [name, axes] : {std::pair{"$VEL_AXIS", &vel_axis}, std::pair{"$ACC_AXIS", &acc_axis}}) {
      if (key != element_key(name, {axis})) continue;
      if ((*axes)[index]) return Value::of_number(*(*axes)[index]);
      return Value::unknown(key + ", which the program has not set");
    }
  }
  return std::nullopt;
}

bool assign_system_variable(MotionState& state, const Designator& target, const Value& value,
                            const std::string& value_text, const TokenCursor& cursor,
                            ProgramRecorder& recorder) {
  if (target.key == "$IPO_MODE" && target.components.empty()) {
    if (value.kind == Value::Kind::kEnum && value.text == "BASE") return true;
    cursor.fail_at(cursor.range().line, "$IPO_MODE = #BASE (a robot-held tool; an external TCP is not read)",
                   describe(value));
  }
  if (target.key == "$TOOL" || target.key == "$BASE") {
    if (value.is_unknown()) {
      cursor.fail_at(cursor.range().line, "a FRAME the reader can compute for " + target.key, value.text);
    }
    return assign_frame(state, target, value, value_text, cursor);
  }
  return assign_structure_parameter(state, target, value, cursor, recorder) ||
         assign_axis_parameter(state, target, value, cursor, recorder);
}

}  // namespace grpvss::io::krl
