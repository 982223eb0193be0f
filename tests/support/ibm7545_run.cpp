#include "support/ibm7545_run.hpp"

#include "grpvss/io/environment_file.hpp"
#include "grpvss/io/path_file.hpp"
#include "grpvss/io/robot_file.hpp"
#include "grpvss/motion/kinematics_adapter.hpp"

#include "support/data_paths.hpp"
namespace grpvss::test {
namespace {

Ibm7545Run run(Ibm7545Run inputs, certify::ClearClaim claim) {
  inputs.kinematics = motion::make_kinematics_access(
      inputs.robot, motion::select_ik({}, inputs.robot, "robot.txt"));
  certify::SetupRequest request;
  request.tolerance = kIbm7545Tolerance;
  request.claim = claim;
  inputs.setup = certify::resolve_setup(request);
  inputs.run = certify::verify(inputs.robot, inputs.environment, inputs.program,
                               inputs.kinematics, inputs.setup);
  return inputs;
}

}  // namespace

Ibm7545Run verify_ibm7545(const std::string& environment_file, const std::string& path_text,
                          certify::ClearClaim claim) {
  Ibm7545Run inputs;
  inputs.robot = io::read_robot_file(ibm7545_file("robot.txt"));
  inputs.environment = io::read_environment_file(ibm7545_file(environment_file));
  inputs.program = io::parse_path_file(path_text, "path.txt", inputs.robot);
  return run(std::move(inputs), claim);
}

Ibm7545Run verify_ibm7545_files(const std::string& environment_file, const std::string& path_file,
                                certify::ClearClaim claim) {
  Ibm7545Run inputs;
  inputs.robot = io::read_robot_file(ibm7545_file("robot.txt"));
  inputs.environment = io::read_environment_file(ibm7545_file(environment_file));
  inputs.program = io::read_path_file(ibm7545_file(path_file), inputs.robot);
  return run(std::move(inputs), claim);
}

}  // namespace grpvss::test
