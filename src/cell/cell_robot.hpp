#pragma once
/// \file
/// \brief The robot of a cell: a URDF chain or a thesis robot file as a RobotModel on the
/// cell's base pose, frame N moved to the TCP.

#include <vector>

#include "cell_pose.hpp"
#include "grpvss/cell/load_cell.hpp"

namespace grpvss::cell {

/// \brief Builds the cell's robot in model units (`scale` model units per cell unit).
/// \throws InputError naming the robot file or the cell line.
RobotModel load_cell_robot(const CellDescription& cell, const CellLoadOptions& options,
                           double scale, std::vector<io::InputWarning>& warnings);

/// \brief Puts frame 0 at the base pose X_WB and frame N at the TCP (X_ET on the tip):
/// joint 1 and joint N get general frames, link 0 and link N hulls are re-expressed, the
/// rounding goes into hull_point_error. proof: proofs/cell-geometry.md#lemma-geometry-error
void place_base_and_tool(RobotModel& robot, const ScaledPose& base, const ScaledPose& tool);

}  // namespace grpvss::cell
