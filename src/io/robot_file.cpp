#include "grpvss/io/robot_file.hpp"

#include <climits>

#include <fmt/format.h>

#include "hull_file_section.hpp"
#include "number_reader.hpp"
#include "grpvss/io/text_file.hpp"
#include "grpvss/io/units.hpp"

namespace grpvss::io {
namespace {

/// Row layout of thesis A.1.1.1 (the sample proves the limits read home, MIN, MAX).
enum RowField { kAngleOrTheta, kDOrAlpha, kA, kHome, kMin, kMax, kAcc, kDec, kRowSize };

Joint read_joint(NumberReader& reader, int i) {
  const std::string name = "joint " + std::to_string(i);
  const long long type =
      reader.read_integer("the joint type IND_" + std::to_string(i), LLONG_MIN, LLONG_MAX);
  if (type != 0 && type != 1) {
    reader.fail(reader.line(),
                "the joint type IND_" + std::to_string(i) + ": 0 (revolute) or 1 (prismatic)",
                std::to_string(type));
  }
  const bool revolute = type == 0;
  const NumberLine row = reader.read_numbers(
      kRowSize, name + (revolute ? " (alpha, d, a, home, MIN, MAX, acc, dec)"
                                 : " (theta, alpha, a, home, MIN, MAX, acc, dec)"));
  const std::vector<double>& v = row.values;

  // Validation on the numbers as written, before any unit conversion.
  if (v[kMin] > v[kMax]) {
    reader.fail(row.line, "MIN <= MAX for " + name,
                fmt::format("MIN {} > MAX {}", v[kMin], v[kMax]));
  }
  if (v[kHome] < v[kMin] || v[kHome] > v[kMax]) {
    reader.fail(row.line, fmt::format("home within [MIN, MAX] = [{}, {}] for {}", v[kMin],
                                      v[kMax], name),
                fmt::format("home {}", v[kHome]));
  }
  if (!(v[kAcc] > 0.0)) {
    reader.fail(row.line, "a positive maximum acceleration acc for " + name,
                fmt::format("{}", v[kAcc]));
  }
  if (!(v[kDec] > 0.0)) {
    reader.fail(row.line, "a positive maximum deceleration dec for " + name,
                fmt::format("{}", v[kDec]));
  }

  Joint joint;
  // Revolute joint values are degrees in the file; prismatic ones are lengths.
  const auto joint_unit = [revolute](double x) { return revolute ? degrees_to_radians(x) : x; };
  if (revolute) {
    joint.type = JointType::kRevolute;
    joint.dh.alpha = degrees_to_radians(v[kAngleOrTheta]);
    joint.dh.d = v[kDOrAlpha];
  } else {
    joint.type = JointType::kPrismatic;
    joint.dh.theta = degrees_to_radians(v[kAngleOrTheta]);
    joint.dh.alpha = degrees_to_radians(v[kDOrAlpha]);
  }
  joint.dh.a = v[kA];
  joint.home = joint_unit(v[kHome]);
  joint.minimum = joint_unit(v[kMin]);
  joint.maximum = joint_unit(v[kMax]);
  joint.acceleration = joint_unit(v[kAcc]);
  joint.deceleration = joint_unit(v[kDec]);
  return joint;
}

Link read_link(NumberReader& reader, int i, PointBudget& budget) {
  const std::string name = "link " + std::to_string(i);
  Link link;
  if (i > 0) {  // the thesis omits D_0 (the base)
    link.thickness = reader.read_number("the thickness D_" + std::to_string(i) + " of " + name);
    if (!(link.thickness > 0.0)) {
      reader.fail(reader.line(), "a positive thickness D_" + std::to_string(i) + " of " + name,
                  fmt::format("{}", link.thickness));
    }
  }
  const long long hull_count = reader.read_integer(
      "the number of hulls NOBAR_" + std::to_string(i) + " of " + name, 0, kMaxHullsPerList);
  link.hulls = read_hull_list(reader, hull_count, name, budget);
  return link;
}

}  // namespace

RobotModel parse_robot_file(std::string_view text, const std::string& file_name) {
  NumberReader reader(text, file_name);
  const int n = static_cast<int>(reader.read_integer("the number of joints N", 1, kMaxJoints));
  RobotModel robot;
  robot.name = file_name;
  robot.joints.reserve(static_cast<std::size_t>(n));
  for (int i = 1; i <= n; ++i) robot.joints.push_back(read_joint(reader, i));
  PointBudget budget;
  robot.links.reserve(static_cast<std::size_t>(n) + 1);
  for (int i = 0; i <= n; ++i) robot.links.push_back(read_link(reader, i, budget));
  reader.expect_end("the hulls of link " + std::to_string(n));
  return robot;
}

RobotModel read_robot_file(const std::string& path) {
  return parse_robot_file(read_text_file(path), path);
}

}  // namespace grpvss::io
