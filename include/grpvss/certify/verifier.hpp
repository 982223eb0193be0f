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

#include <functional>
#include <optional>
#include <string>
#include <vector>

#include "grpvss/certify/certificate.hpp"
#include "grpvss/certify/robot_cell.hpp"
#include "grpvss/certify/verification_observer.hpp"
#include "grpvss/certify/verification_result.hpp"
#include "grpvss/geometry/minkowski_offset.hpp"
#include "grpvss/model/environment.hpp"
#include "grpvss/model/path_program.hpp"
#include "grpvss/model/robot_model.hpp"
#include "grpvss/motion/kinematics_access.hpp"
#include "grpvss/motion/trajectory.hpp"

namespace grpvss::certify {

struct VerifyOptions {
  double tolerance = 0.0;
  ResolutionMode mode = ResolutionMode::kCertified;
  /// Offset polytope of the tolerance expansion; unset: rhombicuboctahedron (certified) or
  /// the thesis's cube (thesis mode).
  std::optional<geometry::OffsetShape> offset_shape;
  motion::TrajectoryOptions trajectory;
  /// Smallest step, as a fraction of the segment's parameter range, before a transition is
  /// accepted uncertified (the verdict then cannot be CLEAR).
  double min_step_fraction = 1e-9;
  /// Smallest step, as a fraction of the segment's parameter range, that the certified rule
  /// keeps shrinking towards; below it the thesis's basic resolution (2 Delta per step)
  /// takes over until a step certifies again (near a first contact the proven steps would
  /// otherwise converge on the contact time without passing it).
  double certify_floor_fraction = 1e-6;
  /// Hard cap on evaluated configurations for the whole path (bounded time and memory).
  long long max_probes = 2'000'000;
  /// CP model: largest allowed deviation of the joint-linear midpoint from the commanded
  /// line, as a fraction of the tolerance (proofs/cp-joint-path.md#model).
  double cp_deviation_fraction = 1.0;
  /// CP singularity: smallest singular value of the position Jacobian, length units per rad.
  double cp_singular_value_threshold = 1e-3;
  std::string path_label = "PATH";  ///< printed in "... INPUT FROM FILE <label>"
  /// Optional: called with the fraction of the path done (0..1, non-decreasing) after each
  /// accepted step, e.g. for a progress bar. Never changes the result.
  std::function<void(double fraction)> progress;
  /// Optional: told every step and certificate step as the run produces them (in this order;
  /// not owned, must outlive verify()). Streaming writers use them (docs/reliability.md#resource-bounds).
  std::vector<VerificationObserver*> observers;
  /// true: VerificationResult::steps and the certificate's per-segment steps hold every step.
  /// false: both stay empty (the observers saw them) and memory does not grow with the number
  /// of steps; everything else in the result (segments, errors, start, summaries, verdict) is
  /// the same.
  bool keep_steps = true;
};

struct VerificationRun {
  VerificationResult result;
  Certificate certificate;  ///< empty segments in thesis mode
};

/// The cell options a verification with `options` needs (tolerance, offset shape).
CellOptions make_cell_options(const VerifyOptions& options);

/// \brief Runs the verification on a prebuilt cell (the offsets are built once per robot,
/// environment and tolerance; build the cell with make_cell_options(options)).
/// \throws std::invalid_argument if the cell was built for other options.
VerificationRun verify(const RobotCell& cell, const Environment& environment,
                       const PathProgram& program, const motion::KinematicsAccess& kinematics,
                       const VerifyOptions& options);

/// \brief Runs the verification. Bad inputs were rejected by the readers; everything found
/// about the path (thesis errors, collisions) is in the result.
VerificationRun verify(const RobotModel& robot, const Environment& environment,
                       const PathProgram& program, const motion::KinematicsAccess& kinematics,
                       const VerifyOptions& options);

/// New error codes beyond the thesis's 1-6 (docs/user-guide.md#errors).
constexpr int kErrorCpJointJump = 7;     ///< CP: IK branch change or joint jump between samples
constexpr int kErrorCpSingularity = 8;   ///< CP: the line passes (near) a singularity
constexpr int kErrorProbeLimit = 9;      ///< the configuration budget was exhausted

}  // namespace grpvss::certify
