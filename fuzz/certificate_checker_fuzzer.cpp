// Fuzz target: the certificate CHECKER. A (mutated) certificate for the IBM 7545 robot and
// environment and a one-segment path (fuzz/inputs/tiny-path.txt) is parsed and re-verified
// exactly. Acceptance or rejection are both fine; InputError for a malformed certificate too.
// A crash, leak, UB, hang or any other exception is a finding: the checker is the last word
// on soundness and must survive hostile certificates.
#include <memory>

#include <nlohmann/json.hpp>

#include "fuzz_input.hpp"
#include "grpvss/evidence/certificate.hpp"
#include "grpvss/checker/certificate_checker.hpp"
#include "grpvss/common/input_error.hpp"
#include "grpvss/io/environment_file.hpp"
#include "grpvss/io/path_file.hpp"
#include "grpvss/io/robot_file.hpp"
#include "grpvss/motion/kinematics_adapter.hpp"

namespace {

struct Cell {
  grpvss::RobotModel robot;
  grpvss::Environment environment;
  grpvss::PathProgram program;
  grpvss::motion::KinematicsAccess kinematics;
};

const Cell& cell() {
  static const Cell instance = [] {
    const std::string root = GRPVSS_SOURCE_DIR;
    Cell c;
    c.robot = grpvss::io::read_robot_file(root + "/data/ibm7545/robot.txt");
    c.environment = grpvss::io::read_environment_file(root + "/data/ibm7545/environment.txt");
    c.program = grpvss::io::read_path_file(root + "/fuzz/inputs/tiny-path.txt", c.robot);
    const auto ik = grpvss::motion::select_ik({}, c.robot, "robot.txt");
    c.kinematics = grpvss::motion::make_kinematics_access(c.robot, ik);
    return c;
  }();
  return instance;
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const Cell& c = cell();
  nlohmann::json document;
  try {
    document = nlohmann::json::parse(grpvss::fuzz::as_text(data, size));
  } catch (const nlohmann::json::exception&) {
    return 0;  // parse_error, or out_of_range (406) for a number beyond double: the CLI's InputError
  }
  try {
    const grpvss::certify::Certificate certificate =
        grpvss::certify::certificate_from_json(document, "fuzz-certificate.json");
    (void)grpvss::certify::check_certificate(c.robot, c.environment, c.program, c.kinematics,
                                             certificate);
  } catch (const grpvss::InputError&) {
  }
  return 0;
}
