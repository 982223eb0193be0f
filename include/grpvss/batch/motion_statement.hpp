#pragma once
/// \file
/// \brief The one line that states a path program's motion model (issue #20 point 1): PTP
/// timing and interpolation, CP speed, IK and its choice of configuration, blending and what
/// the verdict claims. `verify` prints it first (`motion: ...`) and the JSON report carries it
/// as `motion_model`, for the command line and batch manifests alike (docs/verification.md#motion-model).
/// A joint trajectory has its own line (motion::describe_motion_model).

#include <string>

#include "grpvss/evidence/setup.hpp"

namespace grpvss::batch {

/// \brief "path P, synchronized PTP timing (trapezoid profiles, straight line in joint space),
/// CP lines at 1 length units/s, IK IBM 7545 closed form (solution nearest the previous
/// joints), exact stops (no blending), claim: ..." for the run `settings` of path `path_label`
/// with the IK named `ik_name`.
std::string describe_path_motion(const certify::RunSettings& settings,
                                 const std::string& path_label, const std::string& ik_name);

}  // namespace grpvss::batch
