#pragma once
/// \file
/// \brief The simulation loop of thesis Figures 10-11: every segment generates its
/// intermediate configurations, the expanded robot is tested against every obstacle at each
/// step, then the next segment. Two labelled step rules (docs/verification.md):
///
/// - certified (default): between consecutive steps every point of every hull moves at most
///   r_k + r_{k+1}, the radii proven obstacle-free at both ends (two-ball cover);
///   proof: proofs/two-ball-cover.md#corollary-step, proofs/motion-bound.md#lemma-motion-bound
/// - thesis: delta_l = max{min[2D/cos(theta/2), 2D + L], Dmin} at the link-frame origins
///   (Eq. 3-3, 4-13..4-16, Figure 16). Reproduces the thesis; never called certified.

#include "grpvss/evidence/certificate.hpp"
#include "grpvss/certify/robot_cell.hpp"
#include "grpvss/certify/run_hooks.hpp"
#include "grpvss/evidence/setup.hpp"
#include "grpvss/evidence/verification_result.hpp"
#include "grpvss/model/environment.hpp"
#include "grpvss/model/path_program.hpp"
#include "grpvss/model/robot_model.hpp"
#include "grpvss/motion/kinematics_access.hpp"
#include "grpvss/motion/trajectory.hpp"

namespace grpvss::certify {

struct VerificationRun {
  VerificationResult result;
  Certificate certificate;  ///< empty segments in thesis mode
};

/// \brief Runs the verification on a prebuilt cell (its exact offsets are built once per robot,
/// environment and CellSettings; the tolerance and offset shape are the cell's). Bad inputs
/// were rejected by the readers; everything found about the path (thesis errors, collisions)
/// is in the result.
VerificationRun verify(const RobotCell& cell, const PathProgram& program,
                       const motion::KinematicsAccess& kinematics, const RunSettings& settings,
                       const RunHooks& hooks = {});

/// \brief Verifies a planner's joint trajectory (motion::Trajectory::from_joint_motion; joints
/// matched and limits checked by motion::certified_joint_motion) in certified mode: one
/// segment per piece between waypoints, steps at times in [t_k, t_{k+1}], each transition's
/// motion bound from the joints' total variation (non-monotone cubic pieces included;
/// proofs/joint-variation.md#theorem-variation-motion-bound). The result and the certificate
/// state the motion model (settings.path_label names the file).
/// \throws std::invalid_argument for a planned path or thesis mode.
VerificationRun verify(const RobotCell& cell, const motion::Trajectory& trajectory,
                       const motion::KinematicsAccess& kinematics, const RunSettings& settings,
                       const RunHooks& hooks = {});

/// \brief Builds the cell for setup.cell, then verifies with setup.run.
VerificationRun verify(const RobotModel& robot, const Environment& environment,
                       const PathProgram& program, const motion::KinematicsAccess& kinematics,
                       const VerificationSetup& setup, const RunHooks& hooks = {});

/// New error codes beyond the thesis's 1-6 (docs/user-guide.md#errors).
constexpr int kErrorCpJointJump = 7;     ///< CP: IK branch change or joint jump between samples
constexpr int kErrorCpSingularity = 8;   ///< CP: the line passes (near) a singularity
constexpr int kErrorProbeLimit = 9;      ///< the configuration budget was exhausted

}  // namespace grpvss::certify
