#pragma once
/// \file
/// \brief The self-collision pairs of a cell's URDF robot: every two hulls on chain links at
/// least two apart, minus the SRDF's `disable_collisions` and the cell's link / link
/// `allowed_contacts` (docs/cell-format.md#self-collision).

#include <vector>

#include "grpvss/io/input_warning.hpp"
#include "grpvss/model/cell_description.hpp"
#include "grpvss/model/robot_model.hpp"

namespace grpvss::cell {

/// \brief Fills robot.self_collision_pairs (sorted) and robot.unverified_link_pairs. A name is
/// matched against the URDF link that declares each hull (HullPoints::name), so a fixed link
/// merged into a chain link keeps its own pairs. Thesis robots get no pairs; a link / link
/// contact in their cell is noted in a warning.
/// \throws InputError naming the SRDF file for an unreadable SRDF.
void resolve_self_collision(const CellDescription& cell, RobotModel& robot,
                            std::vector<io::InputWarning>& warnings);

}  // namespace grpvss::cell
