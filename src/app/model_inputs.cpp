#include "model_inputs.hpp"

#include <cstdio>
#include <utility>
#include <variant>

#include <fmt/core.h>

#include "grpvss/cell/load_cell.hpp"
#include "grpvss/common/input_error.hpp"
#include "grpvss/io/environment_file.hpp"
#include "grpvss/io/robot_file.hpp"

namespace grpvss::app {
namespace {

void print_warnings(const std::vector<io::InputWarning>& warnings) {
  for (const io::InputWarning& warning : warnings) {
    if (warning.line > 0) {
      fmt::print(stderr, "warning: {}:{}: {}\n", warning.file, warning.line, warning.text);
    } else {
      fmt::print(stderr, "warning: {}: {}\n", warning.file, warning.text);
    }
  }
}

ModelInputs load_cell_inputs(const ModelSources& sources, bool quiet) {
  cell::CellLoadOptions options;
  options.package_paths = sources.package_paths;
  cell::LoadedCell loaded = cell::load_cell(sources.cell_file, options);
  if (!quiet) print_warnings(loaded.warnings);
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
  return inputs;
}

}  // namespace

void add_model_source_options(CLI::App& command, std::string& robot_file,
                              std::string& environment_file, std::string& cell_file,
                              std::vector<std::string>& package_paths) {
  command.add_option("--robot", robot_file, "Robot file (thesis A.1.1.1)");
  command.add_option("--env", environment_file, "Environment file (thesis A.1.1.2)");
  command.add_option("--cell", cell_file,
                     "Cell file: robot (URDF or thesis) and named obstacles (docs/cell-format.md)");
  command.add_option("--package-path", package_paths,
                     "Directory searched for package://NAME/... (repeatable; before the cell's)");
}

void add_model_source_options(CLI::App& command, ModelSources& sources) {
  add_model_source_options(command, sources.robot_file, sources.environment_file,
                           sources.cell_file, sources.package_paths);
}

ModelInputs load_model_inputs(const ModelSources& sources, bool quiet, ObstaclesNeeded obstacles) {
  const bool thesis_files = !sources.robot_file.empty() || !sources.environment_file.empty();
  if (!sources.cell_file.empty()) {
    if (thesis_files) {
      throw InputError("--cell", 0, "either --cell or --robot with --env, not both");
    }
    return load_cell_inputs(sources, quiet);
  }
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

}  // namespace grpvss::app
