#pragma once
/// \file
/// \brief The choices of one verification as words (what `grpvss verify` takes as options and
/// a batch manifest takes as keys), checked and turned into the typed request in one place for
/// both front ends (docs/batch.md, docs/user-guide.md).

#include <optional>
#include <string>
#include <vector>

#include <Eigen/Core>

#include "grpvss/cell/model_inputs.hpp"
#include "grpvss/evidence/setup.hpp"
#include "grpvss/kinematics/inverse_kinematics.hpp"

namespace grpvss::batch {

/// The words of one verification's inputs and choices; file names as given. Tolerance, timing
/// and CP speed may stay unset (0, "", 0): resolve_model_defaults() fills them from the model
/// (a cell's values and synchronized timing; a thesis robot's independent timing and 1).
struct VerifyOptions {
  std::string robot_file;
  std::string environment_file;
  std::string cell_file;                   ///< instead of robot_file + environment_file
  std::vector<std::string> package_paths;  ///< searched before the cell's own
  std::string path_file;
  /// A planner's joint trajectory (CSV or ROS JSON) instead of path_file
  /// (docs/trajectories.md#verifying-a-trajectory).
  std::string trajectory_file;
  /// A robot program (URScript, KRL, RAPID) instead of path_file
  /// (docs/robot-programs.md#verifying-a-program).
  std::string program_file;
  double tolerance = 0.0;  ///< Delta > 0, length units (of the cell, with a cell); 0: unset
  std::string mode = "certified";
  std::string offset = "auto";
  /// What CLEAR claims in certified mode: motion | steps (docs/verification.md#claim).
  std::string claim = "motion";
  std::string timing;  ///< independent | synchronized; "": unset
  std::string profile_table;  ///< empty: the ideal trapezoids
  std::string ik = "auto";
  double cp_speed = 0.0;  ///< length units per s (of the cell, with a cell); 0: unset
  /// The path's start, "q1,q2,..." in the model files' units (cell::start_configuration);
  /// empty: the robot's home (a cell's `home`).
  std::string start;
};

/// The model sources the options name.
cell::ModelSources model_sources(const VerifyOptions& options);

/// The accepted words of `mode`, `offset` and `timing`.
const std::vector<std::string>& mode_choices();
const std::vector<std::string>& offset_choices();
const std::vector<std::string>& timing_choices();
/// motion, steps
const std::vector<std::string>& claim_choices();

/// \brief Checks every choice (not the files): tolerance and cp_speed finite and > 0 when set,
/// the words of mode, offset, claim, timing (when set) and ik.
/// \throws InputError(file, line, expected, found) naming the key, e.g.
///         "expected `tolerance`: a finite number > 0, found -1".
void check_verify_options(const VerifyOptions& options, const std::string& file, int line);

/// \brief The options with what the model supplies where they leave it unset: a cell's
/// tolerance and CP speed and synchronized timing, a thesis robot's independent timing and CP
/// speed 1; lengths given with a cell are converted from its unit (docs/cell-format.md).
/// \throws InputError("--tolerance", 0, ...) when neither gives a tolerance.
VerifyOptions resolve_model_defaults(const VerifyOptions& options, const cell::ModelInputs& model);

/// The words turned into the typed request, once (reads the profile table file). Tolerance and
/// CP speed must be set (resolve_model_defaults()).
certify::SetupRequest make_setup_request(const VerifyOptions& options);

/// \brief The start configuration `options.start` names for `robot` (units: a cell's when
/// `from_cell`, else the thesis files'), in library units; nullopt when it is empty.
/// \throws InputError(source, 0, ...) as cell::parse_start_list(), cell::start_configuration().
std::optional<Eigen::VectorXd> resolve_start(const VerifyOptions& options, const RobotModel& robot,
                                             bool from_cell, const std::string& source = "--start");

/// `ik`: auto, ibm7545, opw, ur, numeric or plugin:PATH.so. \throws InputError ("--ik", line 0).
kinematics::IkChoice parse_ik_choice(const std::string& text);

}  // namespace grpvss::batch
