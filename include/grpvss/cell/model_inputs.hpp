#pragma once
/// \file
/// \brief The robot and the obstacles of a run, from thesis files (robot + environment) or a
/// cell file (docs/cell-format.md): one loader for the command line, batch manifests and the
/// Python module, with what the reports and the certificate bind the model to and the defaults
/// a cell supplies (tolerance, CP speed, units of a thesis path file).

#include <optional>
#include <string>
#include <vector>

#include <Eigen/Geometry>

#include "grpvss/io/input_warning.hpp"
#include "grpvss/io/path_file.hpp"
#include "grpvss/model/cell_description.hpp"
#include "grpvss/model/environment.hpp"
#include "grpvss/model/path_program.hpp"
#include "grpvss/model/robot_model.hpp"

namespace grpvss::cell {

/// \brief Where the model comes from: a cell file, or a thesis robot (and environment) file.
struct ModelSources {
  std::string robot_file;
  std::string environment_file;
  std::string cell_file;
  /// `--package-path DIR` (repeatable), searched before the cell's own `package_paths`.
  std::vector<std::string> package_paths;
};

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
  /// Every input file named by the sources (outputs may not overwrite them).
  std::vector<std::string> input_files;
  /// Model units per cell unit: a thesis path file used with a cell has its lengths in the
  /// cell's unit (docs/input-formats.md).
  double model_units_per_cell_unit = 1.0;
  /// The cell's tolerance (model units, rounded up), when it gives one.
  std::optional<double> tolerance;
  /// The cell's CP speed (model units per s), when it gives one.
  std::optional<double> cp_speed;
  /// A cell's `base` (X_WR: the robot's base frame R in the world) and `tool` (X_FE: the model's
  /// end-effector frame E, the cell's TCP, in the tip link F), in model units; identity for
  /// thesis files. Robot programs compose their own tool and base with them
  /// (docs/robot-programs.md#verifying-a-program).
  Eigen::Isometry3d X_WR = Eigen::Isometry3d::Identity();
  Eigen::Isometry3d X_FE = Eigen::Isometry3d::Identity();
  /// The cell's CP sample spacing `motion.cp_spacing` (model units), when it gives one.
  std::optional<double> cp_spacing;
  /// The unit of every length of the model, for a cell (metres for a URDF robot, the cell's
  /// unit for a thesis robot); unset for thesis files, whose unit is whatever they use.
  std::optional<LengthUnit> model_unit;
  /// Every warning of the files read (the library never prints them).
  std::vector<io::InputWarning> warnings;
};

/// \brief Which inputs a caller needs besides the robot.
enum class ObstaclesNeeded { kYes, kNo };

/// \brief Loads the model. With ObstaclesNeeded::kNo a robot file alone is enough (a cell
/// still loads its obstacles).
/// \throws InputError for a wrong combination of sources (named as the command line's
/// `--cell`, `--robot`, `--env`, `--package-path`) or a bad file.
ModelInputs load_model_inputs(const ModelSources& sources,
                              ObstaclesNeeded obstacles = ObstaclesNeeded::kYes);

/// \brief Scales the lengths of a thesis path file (prismatic joint values and speeds, world
/// positions) by `scale` model units per file unit; angles are untouched.
void convert_path_lengths(PathProgram& program, const RobotModel& robot, double scale);

/// \brief A path file's text for a model: a thesis-format path (lengths in the cell's unit,
/// scaled by `model_units_per_cell_unit`) or a YAML path (its own declared units, converted
/// to `placement.model_unit`, `frame: base` poses through `placement.X_WR`), in model units.
PathProgram parse_model_path(std::string_view text, const std::string& file_name,
                             const RobotModel& robot, double model_units_per_cell_unit,
                             const io::PathPlacement& placement);

/// \brief parse_model_path() of a file, for the model `model` loaded.
PathProgram read_model_path(const std::string& file, const ModelInputs& model);

/// \brief Where `model`'s robot stands, for YAML paths: its unit and X_WR.
io::PathPlacement path_placement(const ModelInputs& model);

/// \brief A length given with a cell (in the cell's unit) in model units, rounded up when
/// converted so that a tolerance never shrinks by the conversion.
double to_model_units(double length, const ModelInputs& model);

}  // namespace grpvss::cell
