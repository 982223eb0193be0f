#pragma once
/// \file
/// \brief Reader of the path-input file (thesis Appendix A.1.3). Format and every message:
/// docs/input-formats.md.

#include <optional>
#include <string>
#include <string_view>

#include <Eigen/Geometry>

#include "grpvss/model/path_program.hpp"
#include "grpvss/model/cell_description.hpp"
#include "grpvss/model/robot_model.hpp"

namespace grpvss::io {

/// \brief Where a path's robot stands, for the YAML path's units and `frame: base` poses.
struct PathPlacement {
  std::optional<LengthUnit> model_unit;                    ///< the model's length unit (a cell's)
  Eigen::Isometry3d X_WR = Eigen::Isometry3d::Identity();  ///< robot base R in the world, model unit
};

/// \brief Reads and validates a path file for `robot` (which fixes N and the joint types).
/// A `.yaml`/`.yml` file is a YAML path (absolute poses, declared units,
/// docs/input-formats.md#yaml-path); anything else is the thesis format (A.1.3), where
/// revolute targets and speeds are degrees and deg/s in the file, radians inside.
/// Joint targets outside the joint limits are NOT rejected here (thesis error 3 belongs to
/// the motion stage).
/// \throws InputError (file, line, expected) on any defect; never returns a partial program.
PathProgram read_path_file(const std::string& path, const RobotModel& robot,
                           const PathPlacement& placement = {});

/// \brief True when read_path_file() reads `file_name` as a YAML path (.yaml or .yml,
/// ignoring case).
bool is_yaml_path_file_name(const std::string& file_name);

/// \brief As read_path_file() on text already in memory (`file_name` picks the format).
PathProgram parse_path_file(std::string_view text, const std::string& file_name,
                            const RobotModel& robot, const PathPlacement& placement = {});

}  // namespace grpvss::io
