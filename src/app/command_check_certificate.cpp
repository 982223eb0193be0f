// `grpvss check-certificate`: re-verifies a certificate from the input files alone (a separate
// code path from the verifier, every inequality decided exactly). Exit 0 accepted, 1 rejected,
// 2 input error.
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include <fmt/core.h>
#include <nlohmann/json.hpp>

#include "commands.hpp"
#include "grpvss/certify/certificate_checker.hpp"
#include "grpvss/certify/certificate_file.hpp"
#include "grpvss/common/input_error.hpp"
#include "grpvss/io/environment_file.hpp"
#include "grpvss/io/path_file.hpp"
#include "grpvss/io/robot_file.hpp"
#include "grpvss/motion/kinematics_adapter.hpp"
#include "grpvss/motion/profile_table.hpp"
#include "grpvss/report/input_digests.hpp"
#include "grpvss/report/lower_bound_text.hpp"
#include "verify_arguments.hpp"

namespace grpvss::app {
namespace {

// A recorded digest, or "" when the field is missing or not a string (then it cannot match).
std::string digest_field(const nlohmann::json& inputs, const char* key) {
  const auto found = inputs.find(key);
  return found != inputs.end() && found->is_string() ? found->get<std::string>() : std::string();
}

struct CheckArguments {
  VerifyArguments inputs;
  std::string certificate_file;
  bool json = false;
  bool quiet = false;
};

int run_check(const CheckArguments& args) {
  const VerifyArguments& in = args.inputs;
  const RobotModel robot = io::read_robot_file(in.robot_file);
  const Environment environment = io::read_environment_file(in.environment_file);
  const PathProgram program = io::read_path_file(in.path_file, robot);
  certify::CheckOptions options;
  if (!in.profile_table.empty()) {
    options.profile_table = std::make_shared<const motion::ProfileTable>(
        motion::ProfileTable::read(in.profile_table));
  }
  const auto ik = motion::select_ik(in.ik, robot, in.robot_file);
  const motion::KinematicsAccess kinematics = motion::make_kinematics_access(robot, ik);

  // Read and checked one segment at a time: memory independent of the number of steps
  // (docs/reliability.md#resource-bounds).
  std::vector<std::string> digest_failures;
  std::optional<certify::CertificateCheck> check;
  std::size_t announced = 0;
  std::size_t delivered = 0;
  const auto changed = [&args] {
    return InputError(args.certificate_file, 0, "a certificate that does not change while it is read");
  };
  certify::read_certificate_file(
      args.certificate_file,
      [&](const certify::CertificateFileHeader& header) {
        const nlohmann::json& document = header.document;
        if (document.contains("inputs") && document["inputs"].is_object()) {
          const report::InputDigests digests =
              report::digest_input_files(in.robot_file, in.environment_file, in.path_file);
          const auto& inputs = document["inputs"];
          if (digest_field(inputs, "robot") != digests.robot.sha256) digest_failures.push_back("the robot file differs from the one certified");
          if (digest_field(inputs, "environment") != digests.environment.sha256) digest_failures.push_back("the environment file differs from the one certified");
          if (digest_field(inputs, "path") != digests.path.sha256) digest_failures.push_back("the path file differs from the one certified");
        }
        announced = header.segment_count;
        check.emplace(robot, environment, program, kinematics, header.certificate, announced,
                      options);
      },
      [&](const certify::SegmentCertificate& segment) {
        if (delivered++ >= announced) throw changed();
        check->add_segment(segment);
      });
  if (!check || delivered != announced) throw changed();
  certify::CheckReport report = check->finish();
  for (const auto& failure : digest_failures) report.failures.insert(report.failures.begin(), failure);
  report.accepted = report.failures.empty();
  if (!report.accepted) report.motion_clearances.clear();  // a rejected certificate proves nothing
  if (args.quiet) {
    // Nothing printed: the exit code tells.
  } else if (args.json) {
    nlohmann::json clearances = nlohmann::json::array();
    for (const auto& link : report.motion_clearances) {
      clearances.push_back({{"link", link.link}, {"lower_bound", link.lower_bound}, {"step", link.step}});
    }
    fmt::print("{}\n", nlohmann::json{{"accepted", report.accepted},
                                      {"claim", report.claim},
                                      {"inequalities_checked", report.inequalities_checked},
                                      {"failures", report.failures},
                                      {"motion_clearances", clearances}}
                           .dump(2));
  } else {
    fmt::print("{}: claim {} ({} inequalities decided exactly)\n",
               report.accepted ? "ACCEPTED" : "REJECTED", report.claim,
               report.inequalities_checked);
    for (const auto& failure : report.failures) fmt::print("  - {}\n", failure);
    // What the accepted certificate proves beyond its claim (the base, link 0, never moves).
    for (const auto& link : report.motion_clearances) {
      if (link.link == 0) continue;
      fmt::print("  link {}: stays farther than {} from every obstacle along the motion "
                 "(smallest at steps {}-{})\n",
                 link.link, report::format_lower_bound(link.lower_bound, 4), link.step - 1,
                 link.step);
    }
  }
  return report.accepted ? kExitOk : kExitFinding;
}

}  // namespace

void register_check_certificate_command(CLI::App& app, int& exit_code) {
  auto args = std::make_shared<CheckArguments>();
  auto* command = app.add_subcommand(
      "check-certificate", "Re-verify a certificate exactly from the input files alone");
  add_input_options(*command, args->inputs);
  command->add_option("CERT", args->certificate_file, "Certificate written by verify")->required();
  command->add_flag("--json", args->json, "Print the result as JSON");
  command->add_flag("--quiet", args->quiet, "Print nothing; the exit code tells the result");
  command->callback([args, &exit_code] { exit_code = run_check(*args); });
}

}  // namespace grpvss::app
