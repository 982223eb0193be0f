// `grpvss check-certificate`: re-verifies a certificate from the input files alone (the checker
// stage: a separate code path from the verifier, every inequality decided exactly). The command
// prints the checker's decision; it does not decide anything itself. Options that would change
// the motion the certificate was made for are refused when they contradict it. Exit 0 accepted,
// 1 rejected, 2 input error.
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include <fmt/core.h>
#include <nlohmann/json.hpp>

#include "commands.hpp"
#include "grpvss/checker/certificate_checker.hpp"
#include "grpvss/checker/certificate_file_check.hpp"
#include "grpvss/common/input_error.hpp"
#include "grpvss/io/environment_file.hpp"
#include "grpvss/io/path_file.hpp"
#include "grpvss/io/profile_table_file.hpp"
#include "grpvss/io/robot_file.hpp"
#include "grpvss/motion/kinematics_adapter.hpp"
#include "grpvss/motion/profile_table.hpp"
#include "grpvss/report/input_digests.hpp"
#include "grpvss/report/lower_bound_text.hpp"
#include "grpvss/motion/joint_trajectory_source.hpp"
#include "grpvss/common/file_label.hpp"
#include "program_inputs.hpp"
#include "start_option.hpp"
#include "trajectory_inputs.hpp"
#include "verify_arguments.hpp"

namespace grpvss::app {
namespace {

struct CheckArguments {
  ModelSources model;
  std::string path_file;
  std::string trajectory_file;        ///< --trajectory instead of --path
  std::string program_file;           ///< --program instead of --path
  std::optional<std::string> timing;  ///< unset: the certificate's
  std::optional<std::string> ik;      ///< unset: "auto"
  std::string timing_text;            ///< what CLI11 parsed into `timing`
  std::string ik_text;                ///< what CLI11 parsed into `ik`
  std::string claim;                  ///< --claim; empty: the certificate's
  std::string profile_table;
  std::string start;  ///< --start; empty: the robot's home
  std::string certificate_file;
  bool json = false;
  bool quiet = false;
};

// --timing names the motion the caller expects; a certificate made for another is refused
// rather than checked against a motion it does not describe.
void refuse_other_timing(const CheckArguments& args, const certify::Certificate& header) {
  if (!args.timing || *args.timing == motion::to_string(header.timing)) return;
  throw InputError("--timing", 0,
                   fmt::format("the timing the certificate was made with ({}); it certifies "
                               "nothing about {} timing",
                               motion::to_string(header.timing), *args.timing),
                   *args.timing);
}

// --claim names what the caller expects CLEAR to mean; a certificate made with the other claim
// is refused rather than checked for a claim it does not make.
void refuse_other_claim(const CheckArguments& args, const certify::Certificate& header) {
  if (args.claim.empty() || args.claim == certify::to_string(header.clear_claim)) return;
  throw InputError("--claim", 0,
                   fmt::format("the claim the certificate was made with ({})",
                               certify::to_string(header.clear_claim)),
                   args.claim);
}

// --start names where the caller expects the path to start; a certificate made for another
// start is refused (one made for a start when none is given is rejected by the checker).
void refuse_other_start(const std::optional<Eigen::VectorXd>& start,
                        const certify::Certificate& header) {
  if (!start) return;
  if (header.start && header.start->size() == start->size() && *header.start == *start) return;
  std::string recorded = "the robot's home";
  if (header.start) {
    recorded.clear();
    for (Eigen::Index j = 0; j < header.start->size(); ++j) {
      recorded += fmt::format("{}{}", j == 0 ? "" : ",", (*header.start)[j]);
    }
  }
  throw InputError("--start", 0,
                   fmt::format("the start the certificate was made for ({}, library units)",
                               recorded),
                   "another start");
}

// The IK decides the CP configurations: it must be the one the certificate names.
void refuse_other_ik(const CheckArguments& args, const certify::Certificate& header,
                     const std::string& ik_name) {
  const auto named = header.inputs.find("ik");
  if (named == header.inputs.end() || named->second == ik_name) return;
  throw InputError("--ik", 0,
                   fmt::format("the IK the certificate was made with ('{}')", named->second),
                   fmt::format("'{}' ({})", args.ik.value_or("auto"), ik_name));
}

// `trajectory_model`: the joint trajectory's motion model, empty for a path program.
// `start`: the --start text, empty without one.
void print_text(const certify::CheckReport& report, const RobotModel& robot,
                const std::string& trajectory_model, const std::string& start) {
  fmt::print("{}: claim {} ({} inequalities decided exactly)\n",
             report.accepted ? "ACCEPTED" : "REJECTED", to_string(report.claim),
             report.inequalities_checked);
  fmt::print("  claim checked: {}\n", report.clear_claim == certify::ClearClaim::kMotion
                                          ? "motion (CLEAR = robot + tolerance clear along the "
                                            "whole motion)"
                                          : "steps (CLEAR = robot clear along the whole motion, "
                                            "robot + tolerance clear at every step)");
  for (const auto& failure : report.failures) fmt::print("  - {}\n", failure);
  if (!trajectory_model.empty()) {
    fmt::print("  motion model checked: {}, IK {}\n", trajectory_model,
               report.ik.empty() ? "(not named)" : report.ik);
  } else {
    fmt::print("  motion model checked: {} PTP timing, CP speed {} per s, IK {}{}\n",
               motion::to_string(report.timing), report.cp_speed,
               report.ik.empty() ? "(not named)" : report.ik,
               start.empty() ? "" : ", start " + start);
  }
  // What the accepted certificate proves beyond its claim (the base, link 0, never moves).
  for (const auto& link : report.motion_clearances) {
    if (link.link == 0) continue;
    fmt::print("  {}: stays farther than {} from every obstacle along the motion "
               "(smallest at steps {}-{})\n",
               link_label(robot, link.link), report::format_lower_bound(link.lower_bound, 4), link.step - 1,
               link.step);
  }
}

void print_json(const certify::CheckReport& report, const std::string& trajectory_model,
                const std::string& start) {
  nlohmann::json clearances = nlohmann::json::array();
  for (const auto& link : report.motion_clearances) {
    clearances.push_back({{"link", link.link}, {"lower_bound", link.lower_bound}, {"step", link.step}});
  }
  nlohmann::json motion_model = {{"timing", motion::to_string(report.timing)},
                                 {"cp_speed", report.cp_speed},
                                 {"ik", report.ik}};
  if (!trajectory_model.empty()) motion_model["trajectory"] = trajectory_model;
  if (!start.empty()) motion_model["start"] = start;
  fmt::print("{}\n", nlohmann::json{{"accepted", report.accepted},
                                    {"claim", to_string(report.claim)},
                                    {"clear_claim", to_string(report.clear_claim)},
                                    {"motion_model", motion_model},
                                    {"inequalities_checked", report.inequalities_checked},
                                    {"failures", report.failures},
                                    {"motion_clearances", clearances}}
                         .dump(2));
}

int run_check(const CheckArguments& args) {
  const ModelInputs model = load_model_inputs(args.model, args.quiet);
  const RobotModel& robot = model.robot;
  const Environment& environment = model.environment;
  require_one_motion_source(args.path_file, args.trajectory_file, args.program_file);
  certify::CheckOptions options;
  PathProgram program;
  std::string trajectory_model;  // the trajectory's or the program's motion model
  const bool trajectory_run = !args.trajectory_file.empty();
  const auto ik =
      motion::select_ik(parse_ik_choice(args.ik.value_or("auto")), robot, model.robot_label_file);
  std::optional<LoadedProgram> robot_program;
  if (!args.program_file.empty()) {
    refuse_with_program(args.timing && *args.timing != "synchronized", "--timing");
    refuse_with_program(!args.profile_table.empty(), "--profile-table");
    robot_program =
        load_program(args.program_file, model, *ik, args.quiet, start_of(args.start, model));
    program = robot_program->path.path;
    trajectory_model = robot_program->description;
  } else if (trajectory_run) {
    refuse_with_trajectory(args.timing.has_value(), "--timing");
    refuse_with_trajectory(!args.profile_table.empty(), "--profile-table");
    options.joint_trajectory = load_joint_trajectory(args.trajectory_file, robot);
    check_trajectory_start(args.start, model, *options.joint_trajectory);
    trajectory_model =
        motion::describe_motion_model(*options.joint_trajectory, file_label(args.trajectory_file));
  } else {
    program = read_model_path(args.path_file, model);
    options.start = start_of(args.start, model);
  }
  if (!args.profile_table.empty()) {
    options.profile_table = std::make_shared<const motion::ProfileTable>(
        io::read_profile_table_file(args.profile_table));
  }
  const motion::KinematicsAccess kinematics = motion::make_kinematics_access(robot, ik);
  const std::string motion_file =
      robot_program ? args.program_file : trajectory_run ? args.trajectory_file : args.path_file;
  const report::InputDigests digests = report::digest_input_files(
      model.robot_digest_file, model.environment_digest_file, motion_file);
  options.input_digests = {{"robot", digests.robot.sha256},
                           {"environment", digests.environment.sha256}};
  if (robot_program) {
    options.input_digests["program"] = robot_program->digest;
  } else {
    options.input_digests[trajectory_run ? "trajectory" : "path"] = digests.path.sha256;
  }

  // Read and checked one segment at a time: memory independent of the number of steps
  // (docs/reliability.md#resource-bounds).
  const certify::CheckReport report = certify::check_certificate_file(
      args.certificate_file, robot, environment, program, kinematics, options,
      [&](const certify::Certificate& header) {
        refuse_other_timing(args, header);
        refuse_other_claim(args, header);
        refuse_other_ik(args, header, ik->name());
        refuse_other_start(options.start, header);
      });
  const std::string start = options.start ? args.start : "";
  if (args.json && !args.quiet) print_json(report, trajectory_model, start);
  if (!args.json && !args.quiet) print_text(report, robot, trajectory_model, start);
  return report.accepted ? kExitOk : kExitFinding;
}

}  // namespace

void register_check_certificate_command(CLI::App& app, int& exit_code) {
  auto args = std::make_shared<CheckArguments>();
  auto* command = app.add_subcommand(
      "check-certificate", "Re-verify a certificate exactly from the input files alone");
  add_model_source_options(*command, args->model);
  CLI::Option* path = command->add_option("--path", args->path_file, "Path file: thesis A.1.3, or a YAML path with absolute poses (.yaml, docs/input-formats.md#yaml-path)");
  CLI::Option* trajectory =
      command
          ->add_option("--trajectory", args->trajectory_file,
                       "Planner joint trajectory the certificate was made for, instead of --path")
          ->excludes(path);
  add_program_option(*command, args->program_file, {path, trajectory});
  CLI::Option* timing = command->add_option(
      "--timing", args->timing_text,
      "PTP joint timing expected (default: the certificate's; another is refused)");
  timing->check(CLI::IsMember({"independent", "synchronized"}));
  command->add_option("--profile-table", args->profile_table,
                      "Motion-time table the certificate was made with (docs/trajectories.md)");
  CLI::Option* ik = command->add_option(
      "--ik", args->ik_text, "IK: auto, ibm7545, opw, ur, numeric or plugin:PATH.so (must be the certificate's)");
  add_start_option(*command, args->start);
  command->add_option("--claim", args->claim,
                      "Claim expected: motion or steps (default: the certificate's; another is "
                      "refused)")
      ->check(CLI::IsMember({"motion", "steps"}));
  command->add_option("CERT", args->certificate_file, "Certificate written by verify")->required();
  command->add_flag("--json", args->json, "Print the result as JSON");
  command->add_flag("--quiet", args->quiet, "Print nothing; the exit code tells the result");
  command->callback([args, timing, ik, &exit_code] {
    if (timing->count() > 0) args->timing = args->timing_text;
    if (ik->count() > 0) args->ik = args->ik_text;
    exit_code = run_check(*args);
  });
}

}  // namespace grpvss::app
