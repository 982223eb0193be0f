#pragma once
/// \file
/// \brief A cell's `allowed_contacts` (names) as robot hull / obstacle pairs.

#include <vector>

#include "grpvss/io/input_warning.hpp"
#include "grpvss/model/cell_description.hpp"
#include "grpvss/model/environment.hpp"
#include "grpvss/model/robot_model.hpp"

namespace grpvss::cell {

/// \brief Every hull of the named link (the URDF link that declares it, or the chain link's
/// frame) with every piece of the named obstacle, sorted. A pair of two obstacles (they never
/// move) is noted in a warning; a pair of two links is a self-contact (cell_self_collision.hpp).
/// \throws InputError(cell file, line, ...) for a name that is neither a link nor an obstacle.
std::vector<AllowedContactPair> resolve_allowed_contacts(const CellDescription& cell,
                                                         const RobotModel& robot,
                                                         const Environment& environment,
                                                         std::vector<io::InputWarning>& warnings);

}  // namespace grpvss::cell
