#pragma once
/// \file
/// \brief The report's `scene` object: the geometry a viewer needs to draw every step of a run
/// (docs/report-schema.md#scene, docs/viewer.md).
///
/// Every link hull (vertices in its link frame L, faces, edges), its tolerance expansion
/// (the offset polytopes the run's certify::RobotCell tested), every obstacle (world frame W) and, per step, the link poses
/// X_WL from forward kinematics of the step's joint values. Deterministic: the same inputs give
/// the same numbers bit for bit (no clock, no randomness).

#include <memory>

#include <nlohmann/json_fwd.hpp>

#include "grpvss/certify/robot_cell.hpp"
#include "grpvss/evidence/verification_result.hpp"
#include "grpvss/model/robot_model.hpp"

namespace grpvss::report {

/// \brief The `scene` object for `result`, drawn from the cell the run used.
///
/// Poses: `steps[k].X_WL[i]` is the 4x4 homogeneous pose of link frame i in W, row-major
/// (16 numbers), for the k-th entry of `result.steps`; `start.X_WL` likewise for the start
/// configuration (null when the run has none).
/// \throws std::logic_error when a step's joint vector does not match the robot.
nlohmann::json scene_to_json(const certify::VerificationResult& result,
                             const certify::RobotCell& cell);

/// \brief The elements of the scene's `steps` array one at a time, for writers that stream
/// the steps (docs/reliability.md#resource-bounds): step(s) is the element scene_to_json()
/// writes for s.
class SceneStepPoses {
 public:
  explicit SceneStepPoses(const RobotModel& robot);
  SceneStepPoses(const SceneStepPoses&) = delete;
  SceneStepPoses& operator=(const SceneStepPoses&) = delete;
  ~SceneStepPoses();

  /// `{"step": index, "X_WL": [...]}`. \throws std::logic_error on a joint vector of the wrong size.
  nlohmann::json step(const certify::StepRecord& step);

 private:
  struct Kinematics;
  std::unique_ptr<Kinematics> kinematics_;
};

}  // namespace grpvss::report
