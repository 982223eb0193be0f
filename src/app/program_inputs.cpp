#include "program_inputs.hpp"

#include <cstdio>
#include <vector>

#include <fmt/core.h>

#include "grpvss/common/input_error.hpp"
#include "grpvss/io/robot_program_file.hpp"
#include "grpvss/report/input_digests.hpp"

namespace grpvss::app {
namespace {

std::string file_label(const std::string& path) {
  const auto slash = path.find_last_of('/');
  return slash == std::string::npos ? path : path.substr(slash + 1);
}

Eigen::VectorXd home_of(const RobotModel& robot) {
  Eigen::VectorXd q(robot.joint_count());
  for (int j = 0; j < robot.joint_count(); ++j) q[j] = robot.joints[static_cast<std::size_t>(j)].home;
  return q;
}

// One digest binds every file a program read (a KRL .src, its .dat and $config.dat).
std::string digest_of_files(const std::vector<std::string>& files) {
  std::string digests;
  for (const std::string& file : files) digests += report::sha256_hex_of_file(file) + "\n";
  return files.size() == 1 ? report::sha256_hex_of_file(files.front()) : report::sha256_hex(digests);
}

void require_named_joints(const std::string& file, const RobotModel& robot) {
  for (const Joint& joint : robot.joints) {
    if (!joint.name.empty()) continue;
    throw InputError(file, 0,
                     "a URDF robot in a cell (--cell): a program's lengths are metres and its "
                     "axes the robot's joints in order",
                     "a thesis robot file");
  }
}

}  // namespace

LoadedProgram load_program(const std::string& file, const ModelInputs& model,
                           const kinematics::InverseKinematics& ik, bool quiet,
                           const std::optional<Eigen::VectorXd>& start) {
  require_named_joints(file, model.robot);
  const RobotProgram program = io::read_robot_program(file);
  if (!quiet) {
    for (const ProgramWarning& warning : program.warnings) {
      fmt::print(stderr, "warning: {}:{}: {}\n", warning.file, warning.line, warning.text);
    }
  }
  LoadedProgram loaded;
  loaded.file = file;
  const motion::ProgramFrames frames{
      model.X_WR * motion::controller_base_in_root(program.language), model.X_FE};
  loaded.path = motion::resolve_program(program, model.robot, frames, ik,
                                        start ? *start : home_of(model.robot));
  loaded.digest = digest_of_files(program.files);
  loaded.description = motion::describe_program_motion(loaded.path, file_label(file));
  return loaded;
}

std::map<std::string, std::string> program_certificate_inputs(const LoadedProgram& program) {
  return {{"program", program.digest},
          {"program_language", motion::to_string(program.path.language)},
          {"program_targets", motion::resolved_targets_text(program.path)}};
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
