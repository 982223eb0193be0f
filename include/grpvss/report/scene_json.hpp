#pragma once
/// \file
/// \brief The report's `scene` object: the geometry a viewer needs to draw every step of a run
/// (docs/report-schema.md#scene, docs/viewer.md).
///
/// Every link hull (vertices in its link frame L, faces, edges), its tolerance expansion
/// (the same offset polytope the verifier tested, built by certify::RobotCell with the run's
/// expansion radius and shape), every obstacle (world frame W) and, per step, the link poses
/// X_WL from forward kinematics of the step's joint values. Deterministic: the same inputs give
/// the same numbers bit for bit (no clock, no randomness).

#include <nlohmann/json_fwd.hpp>

#include "grpvss/certify/verification_result.hpp"
#include "grpvss/geometry/minkowski_offset.hpp"
#include "grpvss/model/environment.hpp"
#include "grpvss/model/robot_model.hpp"

namespace grpvss::report {

/// The offset shape a run used when none was requested (certify::VerifyOptions::offset_shape
/// unset): the thesis's cube in thesis mode, the rhombicuboctahedron in certified mode.
geometry::OffsetShape default_offset_shape(certify::ResolutionMode mode);

/// \brief The `scene` object for `result` (which must come from `robot` and `environment`).
///
/// Poses: `steps[k].X_WL[i]` is the 4x4 homogeneous pose of link frame i in W, row-major
/// (16 numbers), for the k-th entry of `result.steps`; `start.X_WL` likewise for the start
/// configuration (null when the run has none).
/// \throws std::logic_error when a step's joint vector does not match the robot.
nlohmann::json scene_to_json(const certify::VerificationResult& result, const RobotModel& robot,
                             const Environment& environment, geometry::OffsetShape offset_shape);

}  // namespace grpvss::report
