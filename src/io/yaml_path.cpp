#include "yaml_path.hpp"

#include <algorithm>
#include <cctype>
#include <filesystem>

#include <Eigen/Geometry>
#include <fmt/format.h>
#include <yaml-cpp/yaml.h>

#include "cell_sections.hpp"
#include "cell_yaml.hpp"
#include "grpvss/common/input_error.hpp"
#include "grpvss/io/length_unit.hpp"
#include "grpvss/io/units.hpp"
#include "yaml_document.hpp"

namespace grpvss::io {
namespace {

constexpr std::size_t kMaxPathFileBytes = 64u << 20;

/// The declared units: lengths are scaled into the model's unit, angles into radians.
struct PathUnits {
  double model_units_per_length = 1.0;
  bool angles_in_degrees = true;

  double angle(double value) const { return angles_in_degrees ? degrees_to_radians(value) : value; }
};

PathUnits read_units(const CellYaml& yaml, const YAML::Node& root, const PathPlacement& placement) {
  const YAML::Node units = yaml.required(root, "units", "the path");
  yaml.require_keys(units, "units", {"length", "angle"});
  const YAML::Node length_node = yaml.required(units, "length", "units");
  const LengthUnit length = read_length_unit(yaml, length_node, "units.length");
  if (!placement.model_unit) {
    yaml.fail(length_node, "units.length",
              "a robot with a declared length unit (a cell); thesis robot files take the thesis path format");
  }
  PathUnits result;
  result.model_units_per_length = length_unit_factor(length, *placement.model_unit);
  const YAML::Node angle = yaml.required(units, "angle", "units");
  const std::string angle_name = yaml.name(angle, "units.angle");
  if (angle_name != "deg" && angle_name != "rad") yaml.fail(angle, "units.angle", "deg or rad");
  result.angles_in_degrees = angle_name == "deg";
  return result;
}

/// Joint values (or speeds) of `what`: N numbers, revolute ones in the declared angle unit.
Eigen::VectorXd joint_values(const CellYaml& yaml, const YAML::Node& node, std::string_view what,
                             const RobotModel& robot, const PathUnits& units) {
  const std::size_t n = static_cast<std::size_t>(robot.joint_count());
  const std::vector<double> values = yaml.numbers(node, what, n);
  if (values.size() != n) yaml.fail(node, what, fmt::format("a list of {} numbers (one per joint)", n));
  Eigen::VectorXd q(robot.joint_count());
  for (std::size_t j = 0; j < n; ++j) {
    const bool revolute = robot.joints[j].type == JointType::kRevolute;
    q[static_cast<Eigen::Index>(j)] =
        revolute ? units.angle(values[j]) : values[j] * units.model_units_per_length;
  }
  return q;
}

/// `speed`: one number for every joint or one per joint, each > 0 (angle unit/s, length unit/s).
Eigen::VectorXd joint_speeds(const CellYaml& yaml, const YAML::Node& motion, std::string_view what,
                             const RobotModel& robot, const PathUnits& units) {
  const YAML::Node node = yaml.required(motion, "speed", what);
  const std::string name = fmt::format("{}.speed", what);
  if (!node.IsScalar()) {
    const Eigen::VectorXd speeds = joint_values(yaml, node, name, robot, units);
    if (!(speeds.array() > 0.0).all()) yaml.fail(node, name, "joint speeds > 0");
    return speeds;
  }
  const double speed = yaml.positive(node, name);
  Eigen::VectorXd speeds(robot.joint_count());
  for (Eigen::Index j = 0; j < speeds.size(); ++j) {
    const bool revolute = robot.joints[static_cast<std::size_t>(j)].type == JointType::kRevolute;
    speeds[j] = revolute ? units.angle(speed) : speed * units.model_units_per_length;
  }
  return speeds;
}

Eigen::Matrix3d rpy_rotation(const Eigen::Vector3d& rpy_rad) {
  return (Eigen::AngleAxisd(rpy_rad.z(), Eigen::Vector3d::UnitZ()) *
          Eigen::AngleAxisd(rpy_rad.y(), Eigen::Vector3d::UnitY()) *
          Eigen::AngleAxisd(rpy_rad.x(), Eigen::Vector3d::UnitX()))
      .toRotationMatrix();
}

/// The orientation R_FE of a pose in its frame F, or nothing ("keep the orientation").
std::optional<Eigen::Matrix3d> read_orientation(const CellYaml& yaml, const YAML::Node& pose,
                                                const std::string& what, const PathUnits& units) {
  const int given = (pose["rpy"] ? 1 : 0) + (pose["quaternion"] ? 1 : 0) + (pose["axis_angle"] ? 1 : 0);
  if (given > 1) yaml.fail(pose, what, "at most one of rpy, quaternion and axis_angle");
  if (const YAML::Node rpy = pose["rpy"]) {
    const Eigen::Vector3d angles = yaml.vector3(rpy, what + ".rpy");
    return rpy_rotation({units.angle(angles.x()), units.angle(angles.y()), units.angle(angles.z())});
  }
  if (const YAML::Node q = pose["quaternion"]) {
    const std::string name = what + ".quaternion";
    yaml.require_keys(q, name, {"w", "x", "y", "z"});
    const auto part = [&](const char* key) { return yaml.number(yaml.required(q, key, name), name + "." + key); };
    const Eigen::Quaterniond quaternion(part("w"), part("x"), part("y"), part("z"));
    if (std::abs(quaternion.norm() - 1.0) > 1e-6) {
      yaml.fail(q, name, fmt::format("a unit quaternion (norm 1 within 1e-6), norm {}", quaternion.norm()));
    }
    return quaternion.normalized().toRotationMatrix();
  }
  if (const YAML::Node axis_angle = pose["axis_angle"]) {
    const std::string name = what + ".axis_angle";
    const std::vector<double> v = yaml.numbers(axis_angle, name, 4);
    const Eigen::Vector3d axis(v.size() == 4 ? Eigen::Vector3d(v[0], v[1], v[2]) : Eigen::Vector3d::Zero());
    if (v.size() != 4 || !(axis.norm() > 1e-9)) {
      yaml.fail(axis_angle, name, "[kx, ky, kz, angle] with a nonzero axis");
    }
    return Eigen::AngleAxisd(units.angle(v[3]), axis.normalized()).toRotationMatrix();
  }
  return std::nullopt;
}

/// A pose target of the end-effector frame E, in the world (`frame: world`, the default) or
/// the robot's base (`frame: base`, mapped through X_WR).
WorldTarget read_pose(const CellYaml& yaml, const YAML::Node& motion, const std::string& what,
                      const PathUnits& units, const PathPlacement& placement) {
  const YAML::Node pose = yaml.required(motion, "pose", what);
  const std::string name = what + ".pose";
  yaml.require_keys(pose, name, {"xyz", "rpy", "quaternion", "axis_angle", "frame"});
  const Eigen::Vector3d p_F = yaml.vector3(yaml.required(pose, "xyz", name), name + ".xyz") *
                              units.model_units_per_length;
  std::optional<Eigen::Matrix3d> R_FE = read_orientation(yaml, pose, name, units);
  Eigen::Isometry3d X_WF = Eigen::Isometry3d::Identity();
  if (const YAML::Node frame = pose["frame"]) {
    const std::string frame_name = yaml.name(frame, name + ".frame");
    if (frame_name == "base") {
      X_WF = placement.X_WR;
    } else if (frame_name != "world") {
      yaml.fail(frame, name + ".frame", "world or base");
    }
  }
  WorldTarget target;
  target.position_W = X_WF * p_F;
  if (R_FE) {
    const Eigen::AngleAxisd R_WE(X_WF.linear() * *R_FE);
    target.orientation_is_absolute = true;
    target.axis_W = R_WE.angle() == 0.0 ? Eigen::Vector3d::UnitZ() : R_WE.axis();
    target.angle = R_WE.angle();
  }
  return target;
}

PathSegment read_segment(const CellYaml& yaml, const YAML::Node& entry, int number,
                         const RobotModel& robot, const PathUnits& units, const PathPlacement& placement) {
  const std::string what = fmt::format("segment {}", number);
  yaml.require_keys(entry, what, {"ptp", "lin"});
  if (entry.size() != 1) yaml.fail(entry, what, "exactly one of ptp and lin");
  PathSegment segment;
  segment.source_line = yaml_line(entry);
  if (const YAML::Node ptp = entry["ptp"]) {
    const std::string name = what + " ptp";
    yaml.require_keys(ptp, name, {"joints", "pose", "speed"});
    if ((ptp["joints"] ? 1 : 0) + (ptp["pose"] ? 1 : 0) != 1) yaml.fail(ptp, name, "exactly one of joints and pose");
    const Eigen::VectorXd speeds = joint_speeds(yaml, ptp, name, robot, units);
    if (ptp["joints"]) {
      segment.spec = PtpJointSegment{joint_values(yaml, ptp["joints"], name + ".joints", robot, units), speeds};
    } else {
      segment.spec = PtpWorldSegment{read_pose(yaml, ptp, name, units, placement), speeds};
    }
    return segment;
  }
  const YAML::Node lin = entry["lin"];
  const std::string name = what + " lin";
  yaml.require_keys(lin, name, {"pose"});
  segment.spec = CpLineSegment{read_pose(yaml, lin, name, units, placement), /*speed=*/std::nullopt};
  return segment;
}

}  // namespace

bool is_yaml_path_file_name(const std::string& file_name) {
  std::string extension = std::filesystem::path(file_name).extension().string();
  std::transform(extension.begin(), extension.end(), extension.begin(),
                 [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  return extension == ".yaml" || extension == ".yml";
}

PathProgram parse_yaml_path(std::string_view text, const std::string& file_name,
                            const RobotModel& robot, const PathPlacement& placement) {
  if (text.size() > kMaxPathFileBytes) {
    throw InputError(file_name, 0, fmt::format("a path file of at most {} bytes", kMaxPathFileBytes),
                     fmt::format("{} bytes", text.size()));
  }
  CellYaml yaml(file_name, {}, false);
  try {
    const YAML::Node root = load_single_yaml_document(text, file_name, "the path");
    yaml.require_keys(root, "the path", {"units", "segments"});
    const PathUnits units = read_units(yaml, root, placement);
    const YAML::Node segments = yaml.required(root, "segments", "the path");
    if (!segments.IsSequence() || segments.size() == 0) yaml.fail(segments, "segments", "a list of at least one segment");
    PathProgram program;
    int number = 0;
    for (const YAML::Node& entry : segments) {
      program.segments.push_back(read_segment(yaml, entry, ++number, robot, units, placement));
    }
    return program;
  } catch (const YAML::Exception& error) {
    const int line = error.mark.is_null() ? 0 : error.mark.line + 1;
    throw InputError(file_name, line, "well-formed YAML", error.msg);
  }
}

}  // namespace grpvss::io
