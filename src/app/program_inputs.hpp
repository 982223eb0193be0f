#pragma once
// A robot program (`--program FILE`) as `verify`, `trajectory` and `check-certificate` read it
// (docs/robot-programs.md#verifying-a-program): read, resolved into synchronized PTP motions,
// and what the certificate records about it.
#include <map>
#include <optional>
#include <string>
#include <vector>

#include <CLI/CLI.hpp>

#include "grpvss/kinematics/inverse_kinematics.hpp"
#include "grpvss/motion/program_path.hpp"
#include "model_inputs.hpp"

namespace grpvss::app {

/// \brief The program as the motion verified.
struct LoadedProgram {
  std::string file;
  motion::ProgramPath path;  ///< its `path` is what the verifier and the checker plan
  std::string digest;        ///< SHA-256 over every file the program read, in order
  std::string description;   ///< describe_program_motion()
};

/// \brief Reads FILE (io::read_robot_program), prints each reader warning to stderr unless
/// `quiet`, and resolves it against the model (from `start`, else the robot's home; the cell's
/// base and tool).
/// \throws InputError for a robot without joint names (programs need a URDF robot in a cell:
/// their lengths are metres), a refused or unreachable motion, or a defect of the file.
LoadedProgram load_program(const std::string& file, const ModelInputs& model,
                           const kinematics::InverseKinematics& ik, bool quiet,
                           const std::optional<Eigen::VectorXd>& start = std::nullopt);

/// The certificate's "inputs" entries of a program: its digest, language and joint targets.
std::map<std::string, std::string> program_certificate_inputs(const LoadedProgram& program);

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
