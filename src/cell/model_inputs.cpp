#include "grpvss/cell/model_inputs.hpp"

#include <cmath>
#include <limits>
#include <utility>
#include <variant>

#include "grpvss/cell/load_cell.hpp"
#include "grpvss/common/input_error.hpp"
#include "grpvss/io/environment_file.hpp"
#include "grpvss/io/text_file.hpp"
#include "grpvss/io/robot_file.hpp"

namespace grpvss::cell {
namespace {

// The pose as a double isometry (Trans(xyz scale) R), for composing program frames; the
// verified geometry uses the bounded factors of cell_pose.hpp instead.
Eigen::Isometry3d isometry_of(const CellPose& pose, double scale) {
  Eigen::Isometry3d X = Eigen::Isometry3d::Identity();
  if (pose.quaternion) {
    const Eigen::Vector4d& q = *pose.quaternion;
    X.linear() = Eigen::Quaterniond(q[0], q[1], q[2], q[3]).normalized().toRotationMatrix();
  } else {
    X.linear() = (Eigen::AngleAxisd(pose.rpy.z(), Eigen::Vector3d::UnitZ()) *
                  Eigen::AngleAxisd(pose.rpy.y(), Eigen::Vector3d::UnitY()) *
                  Eigen::AngleAxisd(pose.rpy.x(), Eigen::Vector3d::UnitX()))
                     .toRotationMatrix();
  }
  X.translation() = pose.xyz * scale;
  return X;
}

ModelInputs load_cell_inputs(const ModelSources& sources) {
  CellLoadOptions options;
  options.package_paths = sources.package_paths;
  LoadedCell loaded = load_cell(sources.cell_file, options);
  ModelInputs inputs;
  inputs.robot = std::move(loaded.robot);
  inputs.environment = std::move(loaded.environment);
  inputs.from_cell = true;
  inputs.robot_label_file = sources.cell_file;
  inputs.robot_digest_file = sources.cell_file;
  inputs.environment_digest_file = sources.cell_file;
  inputs.input_files = {sources.cell_file};
  inputs.model_units_per_cell_unit = loaded.model_units_per_cell_unit;
  if (loaded.tolerance > 0.0) inputs.tolerance = loaded.tolerance;
  if (loaded.description.motion.cp_speed) {
    inputs.cp_speed = *loaded.description.motion.cp_speed * loaded.model_units_per_cell_unit;
  }
  inputs.X_WR = isometry_of(loaded.description.robot.base, loaded.model_units_per_cell_unit);
  inputs.X_FE = isometry_of(loaded.description.robot.tool, loaded.model_units_per_cell_unit);
  if (loaded.description.motion.cp_spacing) {
    inputs.cp_spacing = *loaded.description.motion.cp_spacing * loaded.model_units_per_cell_unit;
  }
  inputs.model_unit = loaded.model_unit;
  inputs.warnings = std::move(loaded.warnings);
  return inputs;
}

ModelInputs load_thesis_inputs(const ModelSources& sources, ObstaclesNeeded obstacles) {
  const bool environment_needed = obstacles == ObstaclesNeeded::kYes;
  if (sources.robot_file.empty() || (environment_needed && sources.environment_file.empty())) {
    throw InputError(sources.robot_file.empty() ? "--robot" : "--env", 0,
                     environment_needed
                         ? "--cell CELL.yaml, or both --robot ROBOT and --env ENVIRONMENT"
                         : "--cell CELL.yaml or --robot ROBOT");
  }
  if (!sources.package_paths.empty()) {
    throw InputError("--package-path", 0, "--package-path only with --cell (a URDF robot)");
  }
  ModelInputs inputs;
  inputs.robot = io::read_robot_file(sources.robot_file);
  inputs.robot_label_file = sources.robot_file;
  inputs.robot_digest_file = sources.robot_file;
  inputs.input_files = {sources.robot_file};
  if (!sources.environment_file.empty()) {
    inputs.environment = io::read_environment_file(sources.environment_file);
    inputs.environment_digest_file = sources.environment_file;
    inputs.input_files.push_back(sources.environment_file);
  }
  return inputs;
}

}  // namespace

ModelInputs load_model_inputs(const ModelSources& sources, ObstaclesNeeded obstacles) {
  if (sources.cell_file.empty()) return load_thesis_inputs(sources, obstacles);
  if (!sources.robot_file.empty() || !sources.environment_file.empty()) {
    throw InputError("--cell", 0, "either --cell or --robot with --env, not both");
  }
  return load_cell_inputs(sources);
}

void convert_path_lengths(PathProgram& program, const RobotModel& robot, double scale) {
  if (scale == 1.0) return;
  const auto scale_prismatic = [&](Eigen::VectorXd& values) {
    for (int j = 0; j < values.size() && j < robot.joint_count(); ++j) {
      if (robot.joints[static_cast<std::size_t>(j)].type == JointType::kPrismatic) values[j] *= scale;
    }
  };
  for (PathSegment& segment : program.segments) {
    if (auto* joint = std::get_if<PtpJointSegment>(&segment.spec)) {
      scale_prismatic(joint->target);
      scale_prismatic(joint->velocity);
    } else if (auto* world = std::get_if<PtpWorldSegment>(&segment.spec)) {
      world->target.position_W *= scale;
      scale_prismatic(world->velocity);
    } else if (auto* line = std::get_if<CpLineSegment>(&segment.spec)) {
      line->target.position_W *= scale;
    }
  }
}

PathProgram parse_model_path(std::string_view text, const std::string& file_name,
                             const RobotModel& robot, double model_units_per_cell_unit,
                             const io::PathPlacement& placement) {
  PathProgram program = io::parse_path_file(text, file_name, robot, placement);
  // A YAML path declares its units and is read in model units already.
  if (!io::is_yaml_path_file_name(file_name)) convert_path_lengths(program, robot, model_units_per_cell_unit);
  return program;
}

PathProgram read_model_path(const std::string& file, const ModelInputs& model) {
  return parse_model_path(io::read_text_file(file), file, model.robot,
                          model.model_units_per_cell_unit, path_placement(model));
}

io::PathPlacement path_placement(const ModelInputs& model) {
  return io::PathPlacement{model.model_unit, model.X_WR};
}

double to_model_units(double length, const ModelInputs& model) {
  const double converted = length * model.model_units_per_cell_unit;
  if (model.model_units_per_cell_unit == 1.0) return converted;
  return std::nextafter(converted, std::numeric_limits<double>::infinity());
}

}  // namespace grpvss::cell
