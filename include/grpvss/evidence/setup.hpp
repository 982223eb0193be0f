#pragma once
/// \file
/// \brief Every choice a verification depends on, resolved ONCE (from the CLI or an API call)
/// into one typed value (docs/architecture.md#one-resolved-setup). The robot cell owns the part
/// its exact offsets are built for (CellSettings); the run owns the rest (RunSettings).
/// resolve_setup() is the only place a default that depends on another choice is decided.

#include <optional>
#include <string>

#include "grpvss/evidence/verification_result.hpp"
#include "grpvss/geometry/offset_shape.hpp"
#include "grpvss/motion/motion_model.hpp"

namespace grpvss::certify {

/// What a RobotCell is built for: the tolerance offsets depend on these two only.
struct CellSettings {
  double tolerance = 0.0;  ///< Delta > 0, length units
  geometry::OffsetShape offset_shape = geometry::OffsetShape::kRhombicuboctahedron;
};

/// The CP model (proofs/cp-joint-path.md#model) and its singularity guard.
struct CpModelSettings {
  /// Largest allowed deviation of the joint-linear motion from the commanded line, as a
  /// fraction of the tolerance.
  double deviation_fraction = 1.0;
  /// Smallest singular value of the position Jacobian, length units per rad.
  double singular_value_threshold = 1e-3;
};

/// Bounds on the step search: time and memory stay bounded on any input.
struct MarchLimits {
  /// Smallest step, as a fraction of the segment's parameter range, before a transition is
  /// accepted uncertified (the verdict then cannot be CLEAR).
  double min_step_fraction = 1e-9;
  /// Smallest step, as a fraction of the segment's parameter range, that the certified rule
  /// keeps shrinking towards; below it the thesis's basic resolution (2 Delta per step) takes
  /// over until a step certifies again (near a first contact the proven steps would otherwise
  /// converge on the contact time without passing it).
  double certify_floor_fraction = 1e-6;
  /// Hard cap on evaluated configurations for the whole path.
  long long max_probes = 2'000'000;
};

/// What a run does with a cell.
struct RunSettings {
  ResolutionMode mode = ResolutionMode::kCertified;
  motion::MotionModel motion;
  CpModelSettings cp_model;
  MarchLimits limits;
  /// What CLEAR claims (certified mode; docs/verification.md#claim).
  ClearClaim claim = ClearClaim::kMotion;
  std::string path_label = "PATH";  ///< printed in "... INPUT FROM FILE <label>"
  /// A planner's joint trajectory run (set by certify::verify for a trajectory): the motion
  /// model's statement for the reports and the interpolation for the certificate; empty for
  /// a path program.
  std::string motion_model;
  std::string trajectory_interpolation;
};

/// The resolved setup of one verification.
struct VerificationSetup {
  CellSettings cell;
  RunSettings run;
};

/// What a caller asks for; the unset choices take the defaults resolve_setup() decides.
struct SetupRequest {
  double tolerance = 0.0;
  ResolutionMode mode = ResolutionMode::kCertified;
  /// Unset: the thesis's cube in thesis mode, the rhombicuboctahedron in certified mode.
  std::optional<geometry::OffsetShape> offset_shape;
  motion::MotionModel motion;
  CpModelSettings cp_model;
  MarchLimits limits;
  ClearClaim claim = ClearClaim::kMotion;
  std::string path_label = "PATH";
};

/// The one place the defaults are decided. Does not validate (the readers and the CLI did).
VerificationSetup resolve_setup(const SetupRequest& request);

}  // namespace grpvss::certify
