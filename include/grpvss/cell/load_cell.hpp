#pragma once
/// \file
/// \brief The cell stage: a cell file (io/cell_file.hpp) turned into the model the certified
/// core verifies — a RobotModel (a URDF chain with general joint frames, or a thesis robot,
/// on the cell's base pose, its last frame moved to the TCP), an Environment of named convex
/// obstacles (boxes, circumscribing prisms and polyhedra for cylinders and spheres, mesh
/// pieces, thesis environments), both with proven bounds on their geometry's rounding
/// (proofs/cell-geometry.md#lemma-geometry-error). Format: docs/cell-format.md.
///
/// Units: the model's length unit is metres for a URDF robot (URDF is SI; the cell's lengths
/// are converted) and the cell's unit for a thesis robot (its file is in the cell's unit).

#include <string>
#include <vector>

#include "grpvss/io/input_warning.hpp"
#include "grpvss/model/cell_description.hpp"
#include "grpvss/model/environment.hpp"
#include "grpvss/model/robot_model.hpp"

namespace grpvss::cell {

/// \brief Choices the command line adds to a cell file.
struct CellLoadOptions {
  /// `--package-path DIR` (repeatable): searched before the cell's `package_paths`.
  std::vector<std::string> package_paths;
  /// Read ROS_PACKAGE_PATH too (after the cell's own paths).
  bool use_ros_package_path = true;
};

/// \brief A loaded cell: the description as read and the model built from it.
struct LoadedCell {
  CellDescription description;
  RobotModel robot;
  Environment environment;
  /// The unit of every length in robot and environment.
  LengthUnit model_unit = LengthUnit::kMetre;
  /// Model units per cell unit (1 unless a URDF robot sits in a cell in mm or in).
  double model_units_per_cell_unit = 1.0;
  /// The cell's tolerance in model units (rounded up), or 0 when the cell gives none.
  double tolerance = 0.0;
  /// Every warning of the cell file, the URDF, the SRDF, the meshes and the loader.
  std::vector<io::InputWarning> warnings;
};

/// \brief Reads the cell file and everything it names, and builds the model.
/// \throws InputError naming the file (cell, URDF, mesh, ...), the line or element and what
/// was expected.
LoadedCell load_cell(const std::string& cell_file, const CellLoadOptions& options = {});

/// \brief As load_cell() on a description already read (warnings: the reader's).
LoadedCell load_cell(CellDescription description, std::vector<io::InputWarning> warnings,
                     const CellLoadOptions& options = {});

}  // namespace grpvss::cell
