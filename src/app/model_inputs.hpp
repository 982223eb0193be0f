#pragma once
// The robot and the obstacles of a run, from thesis files (--robot, --env) or a cell file
// (--cell, docs/cell-format.md): one loader for every subcommand that takes a robot.
#include <optional>
#include <string>
#include <vector>

#include <CLI/CLI.hpp>

#include "grpvss/model/environment.hpp"
#include "grpvss/model/path_program.hpp"
#include "grpvss/model/robot_model.hpp"

namespace grpvss::app {

/// \brief Where the model comes from, as the command line says.
struct ModelSources {
  std::string robot_file;
  std::string environment_file;
  std::string cell_file;
  std::vector<std::string> package_paths;
};

/// --robot, --env, --cell, --package-path (either --cell, or --robot with --env).
void add_model_source_options(CLI::App& command, ModelSources& sources);
/// The same options into separate fields (`verify`'s arguments keep them apart).
void add_model_source_options(CLI::App& command, std::string& robot_file,
                              std::string& environment_file, std::string& cell_file,
                              std::vector<std::string>& package_paths);

/// \brief The model of a run and what the reports and the certificate bind it to.
struct ModelInputs {
  RobotModel robot;
  Environment environment;
  bool from_cell = false;
  /// The file that names the robot for messages and IK plugins (the robot or cell file).
  std::string robot_label_file;
  /// Files digested as "robot" and "environment" (both the cell file for a cell).
  std::string robot_digest_file;
  std::string environment_digest_file;
  /// Every input file named on the command line (outputs may not overwrite them).
  std::vector<std::string> input_files;
  /// Model units per cell unit: a thesis path file used with a cell has its lengths in the
  /// cell's unit (docs/input-formats.md).
  double model_units_per_cell_unit = 1.0;
  /// The cell's tolerance (model units), when it gives one.
  std::optional<double> tolerance;
  /// The cell's CP speed (model units per s), when it gives one.
  std::optional<double> cp_speed;
};

/// \brief Which inputs a command needs besides the robot.
enum class ObstaclesNeeded { kYes, kNo };

/// \brief Loads the model; prints the inputs' warnings to stderr unless `quiet`. With
/// ObstaclesNeeded::kNo, `--robot` alone is enough (a cell still loads its obstacles).
/// \throws InputError for a wrong combination of options or a bad file.
ModelInputs load_model_inputs(const ModelSources& sources, bool quiet,
                              ObstaclesNeeded obstacles = ObstaclesNeeded::kYes);

/// \brief The path file's lengths (world positions, prismatic joint values and speeds) from
/// cell units into model units. Angles are unchanged.
void convert_path_lengths(PathProgram& program, const RobotModel& robot, double scale);

}  // namespace grpvss::app
