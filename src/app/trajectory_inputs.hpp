#pragma once
// The options of a planner's joint trajectory (`--trajectory T`) as `verify`, `trajectory` and
// `check-certificate` take them (docs/trajectories.md#verifying-a-trajectory); the loader is
// the library's (grpvss/batch/joint_trajectory_input.hpp).
#include <string>

#include "grpvss/batch/joint_trajectory_input.hpp"

namespace grpvss::app {

/// The one loader the CLI, batch and Python share.
using batch::load_joint_trajectory;

/// Why a motion option is refused with --trajectory.
inline constexpr const char* kTrajectoryIsTheMotion =
    "the trajectory's waypoint times and interpolation are the motion";

/// \brief `option` (e.g. "--timing") given with --trajectory is refused, saying `why`.
/// \throws InputError(option, 0, ...) when `given`.
void refuse_with_trajectory(bool given, const std::string& option,
                            const std::string& why = kTrajectoryIsTheMotion);

/// \brief Exactly one of --path and --trajectory. \throws InputError otherwise.
void require_path_or_trajectory(const std::string& path_file, const std::string& trajectory_file);

}  // namespace grpvss::app
