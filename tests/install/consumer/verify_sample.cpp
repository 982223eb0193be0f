// Verifies a thesis-format robot, environment and path through the installed library's public
// API and prints the verdict and the step count: what a user's own program does.
// Usage: verify_sample ROBOT ENVIRONMENT PATH TOLERANCE
#include <cstdio>
#include <cstdlib>
#include <exception>

#include "grpvss/certify/verifier.hpp"
#include "grpvss/common/input_error.hpp"
#include "grpvss/io/environment_file.hpp"
#include "grpvss/io/path_file.hpp"
#include "grpvss/io/robot_file.hpp"
#include "grpvss/motion/kinematics_adapter.hpp"

int main(int argc, char** argv) {
  if (argc != 5) {
    std::fprintf(stderr, "usage: verify_sample ROBOT ENVIRONMENT PATH TOLERANCE\n");
    return 2;
  }
  try {
    const grpvss::RobotModel robot = grpvss::io::read_robot_file(argv[1]);
    const grpvss::Environment environment = grpvss::io::read_environment_file(argv[2]);
    const grpvss::PathProgram program = grpvss::io::read_path_file(argv[3], robot);
    grpvss::certify::SetupRequest request;
    request.tolerance = std::strtod(argv[4], nullptr);
    const grpvss::certify::VerificationSetup setup = grpvss::certify::resolve_setup(request);
    const auto ik = grpvss::motion::select_ik({}, robot, argv[1]);
    const grpvss::certify::VerificationRun run = grpvss::certify::verify(
        robot, environment, program, grpvss::motion::make_kinematics_access(robot, ik), setup);
    std::printf("verdict %s, %zu steps\n", grpvss::certify::to_string(run.result.verdict),
                run.result.steps.size());
    return 0;
  } catch (const grpvss::InputError& error) {
    std::fprintf(stderr, "%s\n", error.what());
    return 2;
  }
}
