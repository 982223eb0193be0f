#include "krl_target.hpp"

#include <algorithm>
#include <cmath>
#include <sstream>

#include "grpvss/io/program_orientation.hpp"
#include "grpvss/io/units.hpp"

namespace grpvss::io::krl {
namespace {

const std::vector<std::string> kJointNames = {"A1", "A2", "A3", "A4", "A5", "A6"};
const std::vector<std::string> kPoseNames = {"X", "Y", "Z", "A", "B", "C"};
const std::vector<std::string> kExternalNames = {"E1", "E2", "E3", "E4", "E5", "E6"};

bool contains(const std::vector<std::string>& names, const std::string& name) {
  return std::find(names.begin(), names.end(), name) != names.end();
}

bool any_of_names(const Value& value, const std::vector<std::string>& names) {
  return std::any_of(value.names.begin(), value.names.end(),
                     [&](const std::string& name) { return contains(names, name); });
}


/// Joint or Cartesian; every component known and a number.
bool classify(const Value& value, const std::string& what, const TokenCursor& cursor, int line) {
  if (value.is_unknown()) cursor.fail_at(line, "a target the reader can compute for " + what, value.text);
  if (value.kind != Value::Kind::kStructure) {
    cursor.fail_at(line, "an AXIS, E6AXIS, POS, E6POS or FRAME for " + what, describe(value));
  }
  const bool joint = any_of_names(value, kJointNames);
  if (joint == any_of_names(value, kPoseNames)) {
    cursor.fail_at(line, "components A1..A6 (AXIS) or X, Y, Z, A, B, C (POS) for " + what,
                   joint ? "both kinds" : "neither");
  }
  for (std::size_t i = 0; i < value.names.size(); ++i) {
    const std::string& name = value.names[i];
    const bool allowed = contains(kExternalNames, name) ||
                         (joint ? contains(kJointNames, name)
                                : contains(kPoseNames, name) || name == "S" || name == "T");
    if (!allowed) {
      cursor.fail_at(line, std::string("a component of ") + (joint ? "E6AXIS (A1..A6, E1..E6)" : "E6POS (X, Y, Z, A, B, C, S, T, E1..E6)") + " in the target of " + what,
                     quote_source(name));
    }
    const Value& component = value.values[i];
    if (component.is_unknown()) cursor.fail_at(line, "a computed " + name + " for " + what, component.text);
    if (component.kind != Value::Kind::kNumber) cursor.fail_at(line, "a number for " + name + " of " + what, describe(component));
  }
  return joint;
}

Value completed(const Value& value, bool joint, const std::string& what,
                const std::optional<PreviousTarget>& previous, const std::string& tool_name,
                const std::string& base_name, const TokenCursor& cursor, int line) {
  const std::vector<std::string>& required = joint ? kJointNames : kPoseNames;
  Value result = value;
  for (const std::string& name : required) {
    if (result.component(name)) continue;
    const bool usable = previous && previous->joint == joint &&
                        (joint || (previous->tool_name == tool_name && previous->base_name == base_name));
    if (!usable) {
      cursor.fail_at(line,
                     std::string("a complete ") + (joint ? "AXIS (A1..A6)" : "POS (X, Y, Z, A, B, C)") +
                         " for " + what + " (a partial one is completed only from the previous target of the same kind, tool and base)",
                     "no " + name);
    }
    result.set_component(name, *previous->value.component(name));
  }
  return result;
}

int configuration_bits(const Value& value, const char* name, const std::string& what,
                       const TokenCursor& cursor, int line) {
  const double bits = value.component(name)->number;
  if (bits < 0 || bits > 2147483647.0 || bits != std::floor(bits)) {
    cursor.fail_at(line, std::string("a non-negative integer ") + name + " for " + what, number_text(bits));
  }
  return static_cast<int>(bits);
}

ProgramTarget to_target(const Value& value, bool joint, const std::string& what,
                        const TokenCursor& cursor, int line) {
  const auto number = [&](const std::string& name) { return value.component(name)->number; };
  if (joint) {
    Eigen::VectorXd q(6);
    for (int i = 0; i < 6; ++i) q[i] = degrees_to_radians(number(kJointNames[static_cast<std::size_t>(i)]));
    return JointTarget{q};
  }
  CartesianTarget target;
  target.p_BT = Eigen::Vector3d(millimetres_to_metres(number("X")), millimetres_to_metres(number("Y")),
                                millimetres_to_metres(number("Z")));
  target.R_BT = krl_abc_rotation(degrees_to_radians(number("A")), degrees_to_radians(number("B")),
                                 degrees_to_radians(number("C")));
  KrlStatusTurn bits;
  if (value.component("S")) bits.status = configuration_bits(value, "S", what, cursor, line);
  if (value.component("T")) bits.turn = configuration_bits(value, "T", what, cursor, line);
  target.configuration = bits;
  return target;
}

}  // namespace

KrlTarget krl_target(const Value& value, const std::string& what,
                     const std::optional<PreviousTarget>& previous, const std::string& tool_name,
                     const std::string& base_name, const TokenCursor& cursor, int line) {
  KrlTarget result;
  result.joint = classify(value, what, cursor, line);
  result.completed = completed(value, result.joint, what, previous, tool_name, base_name, cursor, line);
  result.target = to_target(result.completed, result.joint, what, cursor, line);
  for (const std::string& name : kExternalNames) {
    const Value* axis = value.component(name);
    if (axis && axis->number != 0.0) result.external_axes.push_back(name + " = " + number_text(axis->number));
  }
  return result;
}

}  // namespace grpvss::io::krl
