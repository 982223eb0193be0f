#pragma once
// What the jobs of a batch share, read-only: robot and environment files (read and parsed
// once per path), profile tables (once per path) and robot cells (built once per robot and
// environment content, tolerance and offset shape).
#include <memory>
#include <string>
#include <tuple>

#include "grpvss/cell/model_inputs.hpp"
#include "grpvss/certify/robot_cell.hpp"
#include "grpvss/evidence/setup.hpp"
#include "grpvss/model/environment.hpp"
#include "grpvss/model/robot_model.hpp"
#include "grpvss/motion/profile_table.hpp"
#include "once_cache.hpp"

namespace grpvss::batch {

struct LoadedRobot {
  RobotModel model;
  std::string sha256;  ///< of the file's bytes
};

struct LoadedEnvironment {
  Environment model;
  std::string sha256;
};

/// A cell file's model: its robot and environment (each digested as the cell file's bytes, as
/// `grpvss verify --cell` does) and what it supplies besides (tolerance, units, warnings; the
/// `inputs`' own robot and environment are left empty).
struct LoadedCellModel {
  std::shared_ptr<const LoadedRobot> robot;
  std::shared_ptr<const LoadedEnvironment> environment;
  cell::ModelInputs inputs;
};

/// A cell with the models it refers to (RobotCell keeps references: they live here).
struct SharedCell {
  SharedCell(std::shared_ptr<const LoadedRobot> robot_in,
             std::shared_ptr<const LoadedEnvironment> environment_in,
             const certify::CellSettings& settings)
      : robot(std::move(robot_in)),
        environment(std::move(environment_in)),
        cell(robot->model, environment->model, settings) {}

  std::shared_ptr<const LoadedRobot> robot;
  std::shared_ptr<const LoadedEnvironment> environment;
  certify::RobotCell cell;
};

class SharedInputs {
 public:
  /// \throws InputError from the readers (the same error for every job naming the file).
  std::shared_ptr<const LoadedRobot> robot(const std::string& path);
  std::shared_ptr<const LoadedEnvironment> environment(const std::string& path);
  std::shared_ptr<const motion::ProfileTable> profile_table(const std::string& path);
  /// A cell file's model, loaded once per cell file and package paths.
  std::shared_ptr<const LoadedCellModel> cell_model(const cell::ModelSources& sources);
  /// The cell for this robot and environment content and these settings.
  std::shared_ptr<const SharedCell> cell(const std::shared_ptr<const LoadedRobot>& robot,
                                         const std::shared_ptr<const LoadedEnvironment>& environment,
                                         const certify::CellSettings& settings);

  std::size_t cells_built() const { return cells_.builds(); }
  std::size_t robots_parsed() const { return robots_.builds(); }
  std::size_t environments_parsed() const { return environments_.builds(); }

 private:
  /// robot sha256, environment sha256, tolerance, offset shape
  using CellKey = std::tuple<std::string, std::string, double, int>;

  OnceCache<std::string, LoadedRobot> robots_;
  OnceCache<std::string, LoadedEnvironment> environments_;
  OnceCache<std::string, motion::ProfileTable> tables_;
  OnceCache<std::string, LoadedCellModel> cell_models_;
  OnceCache<CellKey, SharedCell> cells_;
};

}  // namespace grpvss::batch
