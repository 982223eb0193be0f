#pragma once
// A robot program (`--program FILE`) as `verify`, `trajectory` and `check-certificate` read it
// (docs/robot-programs.md#verifying-a-program): read, resolved into synchronized PTP motions,
// and what the certificate records about it.
#include <optional>
#include <string>
#include <vector>

#include <CLI/CLI.hpp>

#include "grpvss/batch/robot_program_input.hpp"
#include "grpvss/kinematics/inverse_kinematics.hpp"
#include "model_inputs.hpp"

namespace grpvss::app {

/// The program as the motion verified (the library's loader: batch/robot_program_input.hpp).
using LoadedProgram = batch::LoadedRobotProgram;
using batch::program_certificate_inputs;

/// \brief batch::load_robot_program() placed by the model's cell, from `start`, else the
/// robot's home; prints each reader warning to stderr unless `quiet`.
/// \throws InputError as batch::load_robot_program().
LoadedProgram load_program(const std::string& file, const ModelInputs& model,
                           const kinematics::InverseKinematics& ik, bool quiet,
                           const std::optional<Eigen::VectorXd>& start = std::nullopt);

/// \brief `--program FILE`, excluding each of `others` (--path, --trajectory).
void add_program_option(CLI::App& command, std::string& program_file,
                        const std::vector<CLI::Option*>& others);

/// \brief Exactly one of --path, --trajectory and --program. \throws InputError otherwise.
void require_one_motion_source(const std::string& path_file, const std::string& trajectory_file,
                               const std::string& program_file);

/// Why a motion option is refused with --program.
inline constexpr const char* kProgramIsTheMotion =
    "a program is verified as the controller runs it: synchronized PTP, exact stops";

/// \brief `option` given with --program is refused. \throws InputError(option, 0, ...) when `given`.
void refuse_with_program(bool given, const std::string& option,
                         const std::string& why = kProgramIsTheMotion);

}  // namespace grpvss::app
