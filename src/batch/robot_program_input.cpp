#include "grpvss/batch/robot_program_input.hpp"

#include "grpvss/common/input_error.hpp"
#include "grpvss/io/robot_program_file.hpp"
#include "grpvss/report/input_digests.hpp"
#include "grpvss/common/file_label.hpp"

namespace grpvss::batch {
namespace {

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

LoadedRobotProgram load_robot_program(const std::string& file, const RobotModel& robot,
                                      const ProgramPlacement& placement,
                                      const kinematics::InverseKinematics& ik,
                                      const std::optional<Eigen::VectorXd>& start) {
  require_named_joints(file, robot);
  RobotProgram program = io::read_robot_program(file);
  LoadedRobotProgram loaded;
  loaded.file = file;
  const motion::ProgramFrames frames{
      placement.X_WR * motion::controller_base_in_root(program.language), placement.X_FE};
  loaded.path = motion::resolve_program(program, robot, frames, ik, start ? *start : home_of(robot));
  loaded.digest = digest_of_files(program.files);
  loaded.description = motion::describe_program_motion(loaded.path, file_label(file));
  loaded.warnings = std::move(program.warnings);
  return loaded;
}

LoadedRobotProgram load_robot_program(const std::string& file, const cell::ModelInputs& model,
                                      const kinematics::InverseKinematics& ik,
                                      const std::optional<Eigen::VectorXd>& start) {
  return load_robot_program(file, model.robot, ProgramPlacement{model.X_WR, model.X_FE}, ik, start);
}

std::map<std::string, std::string> program_certificate_inputs(const LoadedRobotProgram& program) {
  return {{"program", program.digest},
          {"program_language", motion::to_string(program.path.language)},
          {"program_targets", motion::resolved_targets_text(program.path)}};
}

}  // namespace grpvss::batch
