#include "rapid_data.hpp"

#include <cmath>
#include <sstream>

#include "grpvss/io/program_orientation.hpp"
#include "grpvss/io/units.hpp"

namespace grpvss::io::rapid {
namespace {

/// The reason vmax's components carry: they are the robot's own maximum.
const char* const kRobotMaximum = "the robot's maximum speed (vmax)";

/// RAPID marks an external axis that is not in use by 9E9.
constexpr double kUnusedAxis = 9e9;

Value numbers(std::initializer_list<double> values, std::string type = {}) {
  std::vector<Value> elements;
  for (const double value : values) elements.push_back(Value::of_number(value));
  return Value::aggregate(std::move(elements), std::move(type));
}

Value identity_pose() {
  return Value::aggregate({numbers({0, 0, 0}, "POS"), numbers({1, 0, 0, 0}, "ORIENT")}, "POSE");
}

Value load(double mass) {
  return Value::aggregate({Value::of_number(mass), numbers({0, 0, 0.001}, "POS"),
                           numbers({1, 0, 0, 0}, "ORIENT"), Value::of_number(0), Value::of_number(0),
                           Value::of_number(0)},
                          "LOADDATA");
}

void add_speeds(std::map<std::string, Value>& data) {
  for (const int v : {5, 10, 20, 30, 40, 50, 60, 80, 100, 150, 200, 300, 400, 500, 600, 800, 1000,
                      1500, 2000, 2500, 3000, 4000, 5000, 6000, 7000}) {
    data["V" + std::to_string(v)] = numbers({double(v), 500, 5000, 1000}, "SPEEDDATA");
  }
  data["VMAX"] = Value::aggregate({Value::unknown(kRobotMaximum), Value::unknown(kRobotMaximum),
                                   Value::unknown(kRobotMaximum), Value::unknown(kRobotMaximum)},
                                  "SPEEDDATA");
}

void add_zones(std::map<std::string, Value>& data) {
  const auto zone = [](bool fine, std::initializer_list<double> sizes) {
    Value value = numbers(sizes, "ZONEDATA");
    value.elements.insert(value.elements.begin(), Value::of_boolean(fine));
    return value;
  };
  data["FINE"] = zone(true, {0, 0, 0, 0, 0, 0});
  data["Z0"] = zone(false, {0.3, 0.3, 0.3, 0.03, 0.3, 0.03});
  data["Z1"] = zone(false, {1, 1, 1, 0.1, 1, 0.1});
  data["Z5"] = zone(false, {5, 8, 8, 0.8, 8, 0.8});
  data["Z10"] = zone(false, {10, 15, 15, 1.5, 15, 1.5});
  data["Z15"] = zone(false, {15, 23, 23, 2.3, 23, 2.3});
  data["Z20"] = zone(false, {20, 30, 30, 3.0, 30, 3.0});
  data["Z30"] = zone(false, {30, 45, 45, 4.5, 45, 4.5});
  data["Z40"] = zone(false, {40, 60, 60, 6.0, 60, 6.0});
  data["Z50"] = zone(false, {50, 75, 75, 7.5, 75, 7.5});
  data["Z60"] = zone(false, {60, 90, 90, 9.0, 90, 9.0});
  data["Z80"] = zone(false, {80, 120, 120, 12, 120, 12});
  data["Z100"] = zone(false, {100, 150, 150, 15, 150, 15});
  data["Z150"] = zone(false, {150, 225, 225, 23, 225, 23});
  data["Z200"] = zone(false, {200, 300, 300, 30, 300, 30});
}


/// Requires a computed value of the type; returns it conformed.
Value checked(const Value& value, const std::string& type, const Context& context) {
  std::string name = type;
  for (char& c : name) c = (c >= 'A' && c <= 'Z') ? char(c - 'A' + 'a') : c;
  if (value.is_unknown()) {
    context.cursor.fail_at(context.line, "a " + name + " the reader can compute for " + context.what, value.text);
  }
  Value result = value;
  if (const std::string problem = conform(result, type); !problem.empty()) {
    context.cursor.fail_at(context.line, problem + " for " + context.what, describe(value));
  }
  // conform() lets unknown parts through; a motion needs every part (vmax's speeds excepted).
  const Value* unknown = first_unknown_part(result);
  if (unknown && !(type == "SPEEDDATA" && unknown->text == kRobotMaximum)) {
    context.cursor.fail_at(context.line, "a " + name + " the reader can compute for " + context.what, unknown->text);
  }
  return result;
}

/// A num component that must be computed (conform() lets unknown ones through).
double number(const Value& value, const std::string& name, const Context& context) {
  if (value.is_unknown()) context.cursor.fail_at(context.line, "a computed " + name + " for " + context.what, value.text);
  return value.number;
}

Eigen::Isometry3d pose_of(const Value& pose, const std::string& name, const Context& context) {
  const auto& t = pose.elements[0].elements;
  const auto& r = pose.elements[1].elements;
  const Eigen::Vector3d position(number(t[0], name, context), number(t[1], name, context), number(t[2], name, context));
  const auto q = rapid_quaternion(number(r[0], name, context), number(r[1], name, context),
                                  number(r[2], name, context), number(r[3], name, context));
  if (!q) {
    context.cursor.fail_at(context.line, "a unit quaternion (norm 1 within 1e-3) in " + name + " of " + context.what,
                           "norm " + number_text(Eigen::Vector4d(r[0].number, r[1].number, r[2].number, r[3].number).norm()));
  }
  return rapid_pose(position, *q);
}

void external_axes_in_use(const Value& extax, std::vector<std::string>& out) {
  static const char* const kNames[] = {"eax_a", "eax_b", "eax_c", "eax_d", "eax_e", "eax_f"};
  for (std::size_t i = 0; i < 6; ++i) {
    const Value& axis = extax.elements[i];
    if (!axis.is_unknown() && std::fabs(axis.number) < kUnusedAxis) {
      out.push_back(std::string(kNames[i]) + " = " + number_text(axis.number));
    }
  }
}

double non_negative(const Value& value, const std::string& name, const Context& context) {
  const double x = number(value, name, context);
  if (x < 0) context.cursor.fail_at(context.line, "a non-negative " + name + " for " + context.what, number_text(x));
  return x;
}

}  // namespace

const std::map<std::string, Value>& predefined_data() {
  static const std::map<std::string, Value> kData = [] {
    std::map<std::string, Value> data;
    data["TOOL0"] = Value::aggregate({Value::of_boolean(true), identity_pose(), load(0.001)}, "TOOLDATA");
    data["WOBJ0"] = Value::aggregate({Value::of_boolean(false), Value::of_boolean(true), Value(),
                                      identity_pose(), identity_pose()},
                                     "WOBJDATA");
    data["WOBJ0"].elements[2].kind = Value::Kind::kString;
    data["LOAD0"] = load(0.001);
    add_speeds(data);
    add_zones(data);
    return data;
  }();
  return kData;
}

CartesianTarget robtarget_target(const Value& value, const Context& context,
                                 std::vector<std::string>& external_axes) {
  const Value target = checked(value, "ROBTARGET", context);
  const Eigen::Isometry3d X_BT = pose_of(Value::aggregate({target.elements[0], target.elements[1]}), "the robtarget", context);
  CartesianTarget result;
  result.p_BT = X_BT.translation();
  result.R_BT = Eigen::Quaterniond(X_BT.linear());
  int cf[4];
  for (std::size_t i = 0; i < 4; ++i) {
    const double bits = number(target.elements[2].elements[i], "confdata", context);
    if (bits != std::floor(bits) || std::fabs(bits) > 1e6) {
      context.cursor.fail_at(context.line, "integer confdata [cf1, cf4, cf6, cfx] for " + context.what, number_text(bits));
    }
    cf[i] = static_cast<int>(bits);
  }
  result.configuration = RapidConfData{cf[0], cf[1], cf[2], cf[3]};
  external_axes_in_use(target.elements[3], external_axes);
  return result;
}

JointTarget jointtarget_target(const Value& value, const Context& context,
                               std::vector<std::string>& external_axes) {
  const Value target = checked(value, "JOINTTARGET", context);
  Eigen::VectorXd q(6);
  for (std::size_t i = 0; i < 6; ++i) {
    q[static_cast<Eigen::Index>(i)] = degrees_to_radians(number(target.elements[0].elements[i], "rax_" + std::to_string(i + 1), context));
  }
  external_axes_in_use(target.elements[1], external_axes);
  return JointTarget{q};
}

Eigen::Isometry3d tool_pose(const Value& value, const Context& context) {
  const Value tool = checked(value, "TOOLDATA", context);
  if (tool.elements[0].is_unknown() || !tool.elements[0].boolean) {
    context.cursor.fail_at(context.line, "a robot-held tool (robhold TRUE) for " + context.what + "; a stationary tool is not read",
                           "robhold FALSE");
  }
  return pose_of(tool.elements[1], "tframe", context);
}

Eigen::Isometry3d work_object_pose(const Value& value, const Context& context) {
  const Value wobj = checked(value, "WOBJDATA", context);
  if (wobj.elements[0].is_unknown() || wobj.elements[0].boolean) {
    context.cursor.fail_at(context.line, "a fixed work object (robhold FALSE) for " + context.what + "; a robot-held one is not read",
                           "robhold TRUE");
  }
  if (wobj.elements[1].is_unknown() || !wobj.elements[1].boolean) {
    context.cursor.fail_at(context.line, "a fixed user frame (ufprog TRUE) for " + context.what + "; a moving (coordinated) one is not read",
                           "ufprog FALSE");
  }
  return pose_of(wobj.elements[3], "uframe", context) * pose_of(wobj.elements[4], "oframe", context);
}

MotionSpeed speed_data(const Value& value, const Context& context) {
  const Value speed = checked(value, "SPEEDDATA", context);
  MotionSpeed result;
  const auto component = [&](std::size_t i, const char* name, double factor) -> std::optional<double> {
    const Value& item = speed.elements[i];
    if (item.is_unknown() && item.text == kRobotMaximum) return std::nullopt;
    return non_negative(item, name, context) * factor;
  };
  result.tcp_speed = component(0, "v_tcp", 1e-3);
  result.orientation_speed = component(1, "v_ori", kRadiansPerDegree);
  result.external_linear_speed = component(2, "v_leax", 1e-3);
  result.external_rotation_speed = component(3, "v_reax", kRadiansPerDegree);
  return result;
}

MotionBlend zone_data(const Value& value, const Context& context) {
  const Value zone = checked(value, "ZONEDATA", context);
  MotionBlend blend;
  if (zone.elements[0].is_unknown()) context.cursor.fail_at(context.line, "a computed finep for " + context.what, zone.elements[0].text);
  if (zone.elements[0].boolean) return blend;
  blend.kind = BlendKind::kDistance;
  blend.radius = millimetres_to_metres(non_negative(zone.elements[1], "pzone_tcp", context));
  blend.orientation_radius = millimetres_to_metres(non_negative(zone.elements[2], "pzone_ori", context));
  blend.orientation_angle = degrees_to_radians(non_negative(zone.elements[4], "zone_ori", context));
  return blend;
}

}  // namespace grpvss::io::rapid
