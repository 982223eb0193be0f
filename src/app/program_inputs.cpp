#include "program_inputs.hpp"

#include <cstdio>
#include <vector>

#include <fmt/core.h>

#include "grpvss/common/input_error.hpp"

namespace grpvss::app {

LoadedProgram load_program(const std::string& file, const ModelInputs& model,
                           const kinematics::InverseKinematics& ik, bool quiet,
                           const std::optional<Eigen::VectorXd>& start) {
  LoadedProgram loaded = batch::load_robot_program(file, model, ik, start);
  if (!quiet) {
    for (const ProgramWarning& warning : loaded.warnings) {
      fmt::print(stderr, "warning: {}:{}: {}\n", warning.file, warning.line, warning.text);
    }
  }
  return loaded;
}

void add_program_option(CLI::App& command, std::string& program_file,
                        const std::vector<CLI::Option*>& others) {
  CLI::Option* program = command.add_option(
      "--program", program_file,
      "Robot program (URScript .script, KUKA KRL .src, ABB RAPID .mod) instead of --path "
      "(docs/robot-programs.md#verifying-a-program)");
  for (CLI::Option* other : others) program->excludes(other);
}

void require_one_motion_source(const std::string& path_file, const std::string& trajectory_file,
                               const std::string& program_file) {
  const int given = (path_file.empty() ? 0 : 1) + (trajectory_file.empty() ? 0 : 1) +
                    (program_file.empty() ? 0 : 1);
  if (given == 1) return;
  throw InputError("--path", 0, "exactly one of --path, --trajectory and --program",
                   given == 0 ? "none" : "several");
}

void refuse_with_program(bool given, const std::string& option, const std::string& why) {
  if (!given) return;
  throw InputError(option, 0, "no " + option + " with --program (" + why + ")", option);
}

}  // namespace grpvss::app
