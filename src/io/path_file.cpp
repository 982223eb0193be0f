#include "grpvss/io/path_file.hpp"

#include <cfloat>
#include <climits>
#include <optional>

#include <fmt/format.h>

#include "number_reader.hpp"
#include "yaml_path.hpp"
#include "grpvss/io/text_file.hpp"
#include "grpvss/io/units.hpp"

namespace grpvss::io {
namespace {

/// Largest accepted NOMS; each segment needs at least one line, so this only bounds memory.
constexpr long long kMaxSegments = 1000000;

/// Joint values and speeds of revolute joints are degrees (per second) in the file.
double joint_unit(const RobotModel& robot, int j, double value) {
  return robot.joints[static_cast<std::size_t>(j)].type == JointType::kRevolute
             ? degrees_to_radians(value)
             : value;
}

double read_velocity(NumberReader& reader, double value, int line, int joint, int segment) {
  if (!(value > 0.0)) {
    reader.fail(line,
                fmt::format("a positive desired velocity VELDES_{} in segment {}", joint, segment),
                fmt::format("{}", value));
  }
  return value;
}

WorldTarget read_world_target(NumberReader& reader, int segment) {
  const NumberLine row = reader.read_numbers(
      7, fmt::format("the target of segment {} (XEND, YEND, ZEND, KX, KY, KZ, KTHETA)", segment));
  const std::vector<double>& v = row.values;
  WorldTarget target;
  target.position_W = Eigen::Vector3d(v[0], v[1], v[2]);
  const Eigen::Vector3d axis_W(v[3], v[4], v[5]);
  target.angle = degrees_to_radians(v[6]);
  if (v[6] == 0.0) {
    // No rotation: any axis will do; keep a unit one so consumers can always normalise.
    target.axis_W = axis_W.squaredNorm() >= DBL_MIN ? axis_W : Eigen::Vector3d::UnitZ();
  } else {
    // |K|^2 must be a normal double so that K / |K| is accurate.
    if (!(axis_W.squaredNorm() >= DBL_MIN)) {
      reader.fail(row.line,
                  fmt::format("a rotation axis (KX, KY, KZ) of nonzero length for KTHETA = {} in "
                              "segment {}",
                              v[6], segment),
                  fmt::format("({}, {}, {})", v[3], v[4], v[5]));
    }
    target.axis_W = axis_W;
  }
  return target;
}

PtpJointSegment read_ptp_joint(NumberReader& reader, const RobotModel& robot, int segment) {
  const int n = robot.joint_count();
  PtpJointSegment spec;
  spec.target.resize(n);
  spec.velocity.resize(n);
  for (int j = 0; j < n; ++j) {
    const NumberLine row = reader.read_numbers(
        2, fmt::format("joint {} of segment {} (q_target, VELDES)", j + 1, segment));
    // Targets outside the joint limits are the motion stage's thesis error 3, not a parse error.
    spec.target[j] = joint_unit(robot, j, row.values[0]);
    spec.velocity[j] =
        joint_unit(robot, j, read_velocity(reader, row.values[1], row.line, j + 1, segment));
  }
  return spec;
}

Eigen::VectorXd read_velocities(NumberReader& reader, const RobotModel& robot, int segment) {
  const int n = robot.joint_count();
  Eigen::VectorXd velocity(n);
  for (int j = 0; j < n; ++j) {
    const double value = reader.read_number(
        fmt::format("the desired velocity VELDES_{} of segment {}", j + 1, segment));
    velocity[j] = joint_unit(robot, j, read_velocity(reader, value, reader.line(), j + 1, segment));
  }
  return velocity;
}

PathSegment read_thesis_segment(NumberReader& reader, const RobotModel& robot, int segment) {
  const long long type = reader.read_integer(
      fmt::format("the segment type IND of segment {}", segment), LLONG_MIN, LLONG_MAX);
  PathSegment result;
  result.source_line = reader.line();
  switch (type) {
    case 1:
      result.spec = read_ptp_joint(reader, robot, segment);
      break;
    case 2: {
      PtpWorldSegment spec;
      spec.target = read_world_target(reader, segment);
      spec.velocity = read_velocities(reader, robot, segment);
      result.spec = std::move(spec);
      break;
    }
    case 3:
      result.spec = CpLineSegment{read_world_target(reader, segment), /*speed=*/std::nullopt};
      break;
    default:
      reader.fail(reader.line(),
                  fmt::format("segment type 1, 2 or 3 (thesis error 6 in segment {})", segment),
                  std::to_string(type));
  }
  return result;
}

}  // namespace

PathProgram parse_path_file(std::string_view text, const std::string& file_name,
                            const RobotModel& robot, const PathPlacement& placement) {
  if (robot.joint_count() < 1) {
    throw std::logic_error("parse_path_file: the robot model has no joints");
  }
  if (is_yaml_path_file_name(file_name)) return parse_yaml_path(text, file_name, robot, placement);
  NumberReader reader(text, file_name);
  const long long count =
      reader.read_integer("the number of motion segments NOMS", 1, kMaxSegments);
  PathProgram program;
  program.segments.reserve(static_cast<std::size_t>(std::min<long long>(count, 1024)));
  for (int s = 1; s <= count; ++s) program.segments.push_back(read_thesis_segment(reader, robot, s));
  reader.expect_end(fmt::format("segment {}", count));
  return program;
}

PathProgram read_path_file(const std::string& path, const RobotModel& robot,
                           const PathPlacement& placement) {
  return parse_path_file(read_text_file(path), path, robot, placement);
}

}  // namespace grpvss::io
