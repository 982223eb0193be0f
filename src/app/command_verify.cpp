// `grpvss verify`: the simulation loop of thesis Figures 10-11 with the certified (default) or
// the thesis step rule; writes the thesis output file, the JSON report and the certificate.
// Exit codes: one per verdict (commands.hpp, docs/user-guide.md#exit-codes). On a terminal a
// progress bar runs on stderr (never when stderr is piped, never with --quiet). An output "-"
// is standard output; the summary then goes to stderr.
#include <cstdio>
#include <memory>
#include <optional>
#include <stdexcept>
#include <string>
#include <vector>

#include <fmt/core.h>
#include <nlohmann/json.hpp>

#include "commands.hpp"
#include "grpvss/batch/motion_statement.hpp"
#include "grpvss/certify/verifier.hpp"
#include "grpvss/common/input_error.hpp"
#include "grpvss/io/length_unit.hpp"
#include "grpvss/io/path_file.hpp"
#include "grpvss/motion/kinematics_adapter.hpp"
#include "grpvss/motion/trajectory.hpp"
#include "grpvss/report/atomic_output.hpp"
#include "grpvss/report/certificate_output.hpp"
#include "grpvss/report/file_units.hpp"
#include "grpvss/report/input_digests.hpp"
#include "grpvss/report/json_report.hpp"
#include "grpvss/report/json_report_stream.hpp"
#include "grpvss/report/scene_json.hpp"
#include "grpvss/report/thesis_output.hpp"
#include "grpvss/common/file_label.hpp"
#include "interactive/verdict_summary.hpp"
#include "output_paths.hpp"
#include "program_inputs.hpp"
#include "progress_bar.hpp"
#include "setup_cache_options.hpp"
#include "start_option.hpp"
#include "trajectory_inputs.hpp"
#include "verify_arguments.hpp"
#include "viewer_html_stream.hpp"

namespace grpvss::app {
namespace {

std::vector<RequestedOutput> requested_outputs(const VerifyArguments& args) {
  return {{"--out", args.out}, {"--json", args.json}, {"--html", args.html},
          {"--certificate", args.certificate}};
}

std::string output_label(const std::string& path) {
  return path == report::kStandardOutput ? "standard output" : path;
}

void print_summary(std::FILE* stream, const certify::VerificationRun& run,
                   const VerifyArguments& args, const ModelNames& names) {
  if (!run.result.motion_model.empty()) fmt::print(stream, "motion: {}\n", run.result.motion_model);
  fmt::print(stream, "{}", verdict_summary(run.result, names));
  if (!args.out.empty()) fmt::print(stream, "thesis output file: {}\n", output_label(args.out));
  if (!args.json.empty()) fmt::print(stream, "JSON report: {}\n", output_label(args.json));
  if (!args.certificate.empty()) {
    fmt::print(stream, "certificate: {}\n", output_label(args.certificate));
  }
  if (!args.html.empty()) fmt::print(stream, "HTML animation: {}\n", output_label(args.html));
}

// The report's scratch files go beside the report (or the page), in the temporary folder for
// standard output.
std::string scratch_location(const VerifyArguments& args) {
  return args.json.empty() ? args.html : args.json;
}

// The robot cell, its link offsets proposed by the set-up cache unless --no-cache (every
// proposal re-checked exactly by the cell: docs/cache.md). Cache trouble is a note, never an error.
certify::RobotCell build_cell(const RobotModel& robot, const Environment& environment,
                              const certify::CellSettings& settings, const VerifyArguments& args) {
  std::vector<std::string> notes;
  std::optional<certify::SetupCache> cache;
  if (auto options = setup_cache_options(args.cache_dir, args.no_cache, notes)) {
    cache.emplace(std::move(*options));
  }
  certify::RobotCell cell(robot, environment, settings, cache ? &*cache : nullptr);
  if (cache) notes.insert(notes.end(), cache->notes().begin(), cache->notes().end());
  if (!args.quiet) {
    for (const std::string& note : notes) fmt::print(stderr, "{}\n", note);
  }
  return cell;
}

// A trajectory brings its own motion: options that would choose another, and the thesis
// output file and step rule (made for path programs), are refused.
void refuse_trajectory_conflicts(const VerifyArguments& args) {
  if (args.trajectory_file.empty()) return;
  refuse_with_trajectory(!args.timing.empty(), "--timing");
  refuse_with_trajectory(!args.profile_table.empty(), "--profile-table");
  refuse_with_trajectory(args.cp_speed > 0.0, "--cp-speed");
  refuse_with_trajectory(args.mode == "thesis", "--mode thesis",
                         "the thesis step rule is defined for PTP and CP segments");
}

// The motion: the path program, the joint trajectory (`joint_motion` set), or the robot
// program's synchronized PTP path (`robot_program` set).
struct MotionInput {
  PathProgram program;
  std::shared_ptr<const motion::JointTrajectoryMotion> joint_motion;
  std::optional<LoadedProgram> robot_program;
  std::string file;
};

MotionInput read_motion(const VerifyArguments& args, const ModelInputs& model,
                        const kinematics::InverseKinematics& ik) {
  require_one_motion_source(args.path_file, args.trajectory_file, args.program_file);
  refuse_trajectory_conflicts(args);
  MotionInput input;
  if (!args.program_file.empty()) {
    refuse_with_program(!args.timing.empty() && args.timing != "synchronized", "--timing");
    refuse_with_program(!args.profile_table.empty(), "--profile-table");
    input.file = args.program_file;
    input.robot_program =
        load_program(args.program_file, model, ik, args.quiet, start_of(args.start, model));
    input.program = input.robot_program->path.path;
    return input;
  }
  if (!args.trajectory_file.empty()) {
    input.file = args.trajectory_file;
    input.joint_motion = load_joint_trajectory(args.trajectory_file, model.robot);
    return input;
  }
  input.file = args.path_file;
  input.program = read_model_path(args.path_file, model);
  return input;
}

int run_verify(const VerifyArguments& args) {
  const ModelInputs model = load_model_inputs(model_sources(args), args.quiet);
  const RobotModel& robot = model.robot;
  const Environment& environment = model.environment;
  const auto ik = motion::select_ik(parse_ik_choice(args.ik), robot, model.robot_label_file);
  const MotionInput motion_input = read_motion(args, model, *ik);
  const PathProgram& program = motion_input.program;
  report::InputDigests digests = report::digest_input_files(
      model.robot_digest_file, model.environment_digest_file, motion_input.file);
  if (model.model_unit) digests.length_unit = io::length_unit_name(*model.model_unit);
  certify::SetupRequest request = make_setup_request(args, model);
  if (motion_input.joint_motion) {  // a trajectory starts at its first point
    check_trajectory_start(args.start, model, *motion_input.joint_motion);
    request.motion.start.reset();
  }
  request.path_label = file_label(motion_input.file);
  certify::VerificationSetup setup = certify::resolve_setup(request);
  if (!motion_input.joint_motion) {  // a trajectory states its own (certify::verify)
    setup.run.motion_model = batch::describe_path_motion(setup.run, request.path_label, ik->name());
  }
  if (!args.certificate.empty() && setup.run.mode != certify::ResolutionMode::kCertified) {
    throw InputError("--certificate", 0, "--mode certified (thesis mode proves nothing)");
  }
  // Refused before a long run rather than after it; the publication itself still never
  // clobbers (a file that appears meanwhile is refused then).
  const std::vector<RequestedOutput> requested = requested_outputs(args);
  std::vector<std::string> inputs = model.input_files;
  inputs.push_back(motion_input.file);
  inputs.push_back(args.profile_table);
  check_requested_outputs(requested, inputs, args.force);

  // The outputs are written while the verification runs, in memory independent of the number
  // of steps (docs/reliability.md#resource-bounds); each is published only at its finish().
  certify::RunHooks hooks;
  hooks.keep_steps = false;
  std::optional<report::ThesisOutputStream> thesis_output;
  std::optional<report::JsonReportStream> json_report;
  std::optional<report::CertificateStream> certificate;
  if (!args.out.empty()) {
    thesis_output.emplace(args.out, args.force, report::joint_types_of(robot),
                          report::ThesisNames::of(robot, environment));
    hooks.observers.push_back(&*thesis_output);
  }
  if (!args.json.empty() || !args.html.empty()) {
    if (!args.html.empty()) require_viewer_bundle(args.html);
    report::JsonReportStream::Outputs outputs;
    outputs.json_path = args.json;
    outputs.script_safe = !args.html.empty();  // the page embeds the report
    outputs.scratch_path = scratch_location(args);
    outputs.force = args.force;
    json_report.emplace(robot, std::move(outputs));
    hooks.observers.push_back(&*json_report);
  }
  if (!args.certificate.empty()) {
    certificate.emplace(args.certificate, args.force);
    hooks.observers.push_back(&*certificate);
  }

  const certify::RobotCell cell = build_cell(robot, environment, setup.cell, args);
  certify::VerificationRun run;
  {
    ProgressBar bar("verifying", !args.quiet && stderr_is_terminal());
    hooks.progress = bar.callback();
    const motion::KinematicsAccess kinematics = motion::make_kinematics_access(robot, ik);
    if (motion_input.joint_motion) {
      run = certify::verify(cell, motion::Trajectory::from_joint_motion(robot, motion_input.joint_motion),
                            kinematics, setup.run, hooks);
    } else {
      run = certify::verify(cell, program, kinematics, setup.run, hooks);
    }
  }

  if (motion_input.robot_program) run.result.motion_model = motion_input.robot_program->description;
  const std::string generated_at = report::utc_timestamp_now();
  if (thesis_output) thesis_output->finish(run.result);
  if (json_report) json_report->finish(run.result, cell, digests, generated_at);
  if (!args.html.empty()) {
    write_viewer_html(args.html, args.force, robot.name, [&](report::AtomicOutputFile& output) {
      json_report->write_script_safe_report(output);
    });
  }
  if (certificate) {
    nlohmann::json inputs = {{"robot", digests.robot.sha256},
                             {"environment", digests.environment.sha256},
                             {"ik", ik->name()}};
    if (motion_input.robot_program) {
      for (const auto& [name, value] : program_certificate_inputs(*motion_input.robot_program)) {
        inputs[name] = value;
      }
    } else {
      inputs[motion_input.joint_motion ? "trajectory" : "path"] = digests.path.sha256;
    }
    certificate->finish(run.certificate, inputs);
  }
  if (!args.quiet) {
    print_summary(writes_to_standard_output(requested) ? stderr : stdout, run, args,
                  ModelNames{&robot, &environment});
  }
  return exit_code_of(run.result.verdict);
}

}  // namespace

void register_verify_command(CLI::App& app, int& exit_code) {
  auto args = std::make_shared<VerifyArguments>();
  auto* command = app.add_subcommand("verify", "Verify a path: simulate, test, certify");
  add_verify_options(*command, *args);
  command->add_option("--out", args->out, "Thesis output file (Appendix A.3 layout)");
  command->add_option("--json", args->json, "JSON report (docs/report-schema.md); - for stdout");
  command->add_option("--html", args->html, "3-D animation of the run, one offline HTML file");
  command->add_option("--certificate", args->certificate,
                      "Certificate for check-certificate (docs/certificate.md)");
  command->add_flag("--force", args->force, "Overwrite existing output files");
  command->add_flag("--quiet", args->quiet, "Print nothing; the exit code tells the verdict");
  command->add_option("--cache-dir", args->cache_dir,
                      "Set-up cache directory (default $XDG_CACHE_HOME/grpvss or "
                      "~/.cache/grpvss; docs/cache.md)");
  command->add_flag("--no-cache", args->no_cache, "Build the set-up; read and write no cache");
  command->callback([args, &exit_code] { exit_code = run_verify(*args); });
}

}  // namespace grpvss::app
