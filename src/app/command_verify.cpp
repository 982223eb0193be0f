// `grpvss verify`: the simulation loop of thesis Figures 10-11 with the certified (default) or
// the thesis step rule; writes the thesis output file, the JSON report and the certificate.
// Exit codes: 0 CLEAR, 1 any other verdict, 2 input error (docs/user-guide.md). On a terminal
// a progress bar runs on stderr (never when stderr is piped, never with --quiet).
#include <cstdio>
#include <memory>
#include <string>

#include <fmt/core.h>
#include <nlohmann/json.hpp>

#include "commands.hpp"
#include "grpvss/certify/verifier.hpp"
#include "grpvss/io/environment_file.hpp"
#include "grpvss/io/path_file.hpp"
#include "grpvss/io/robot_file.hpp"
#include "grpvss/motion/kinematics_adapter.hpp"
#include "grpvss/report/atomic_output.hpp"
#include "grpvss/report/input_digests.hpp"
#include "grpvss/report/json_report.hpp"
#include "grpvss/report/scene_json.hpp"
#include "grpvss/report/thesis_output.hpp"
#include "interactive/verdict_summary.hpp"
#include "progress_bar.hpp"
#include "verify_arguments.hpp"
#include "viewer_html.hpp"

namespace grpvss::app {
namespace {

std::string file_label(const std::string& path) {
  const auto slash = path.find_last_of('/');
  return slash == std::string::npos ? path : path.substr(slash + 1);
}

void print_summary(const certify::VerificationRun& run, const VerifyArguments& args) {
  fmt::print("{}", verdict_summary(run.result));
  if (!args.out.empty()) fmt::print("thesis output file: {}\n", args.out);
  if (!args.json.empty()) fmt::print("JSON report: {}\n", args.json);
  if (!args.certificate.empty()) fmt::print("certificate: {}\n", args.certificate);
  if (!args.html.empty()) fmt::print("HTML animation: {}\n", args.html);
}

int run_verify(const VerifyArguments& args) {
  const RobotModel robot = io::read_robot_file(args.robot_file);
  const Environment environment = io::read_environment_file(args.environment_file);
  const PathProgram program = io::read_path_file(args.path_file, robot);
  const report::InputDigests digests =
      report::digest_input_files(args.robot_file, args.environment_file, args.path_file);
  certify::VerifyOptions options = make_verify_options(args, robot);
  options.path_label = file_label(args.path_file);
  const auto ik = motion::select_ik(args.ik, robot, args.robot_file);
  certify::VerificationRun run;
  {
    ProgressBar bar("verifying", !args.quiet && stderr_is_terminal());
    options.progress = bar.callback();
    run = certify::verify(robot, environment, program, motion::make_kinematics_access(robot, ik),
                          options);
  }

  // All outputs are rendered first, then published: a refused name leaves nothing half-done.
  if (!args.certificate.empty() && run.result.mode != certify::ResolutionMode::kCertified) {
    throw InputError("--certificate", 0, "--mode certified (thesis mode proves nothing)");
  }
  if (!args.out.empty()) {
    report::write_file_atomically(args.out, report::render_thesis_output(run.result, robot),
                                  args.force);
  }
  if (!args.json.empty() || !args.html.empty()) {
    nlohmann::json json_report = report::report_to_json(run.result, robot, digests);
    json_report["scene"] = report::scene_to_json(
        run.result, robot, environment,
        options.offset_shape.value_or(report::default_offset_shape(run.result.mode)));
    const std::string html =
        args.html.empty() ? std::string() : render_viewer_html(json_report, args.html);
    if (!args.json.empty()) {
      report::write_file_atomically(args.json, report::render_json_report(json_report), args.force);
    }
    if (!args.html.empty()) report::write_file_atomically(args.html, html, args.force);
  }
  if (!args.certificate.empty()) {
    nlohmann::json certificate = certify::certificate_to_json(run.certificate);
    certificate["inputs"] = {{"robot", digests.robot.sha256},
                             {"environment", digests.environment.sha256},
                             {"path", digests.path.sha256},
                             {"ik", ik->name()}};
    report::write_file_atomically(args.certificate, certificate.dump(1) + "\n", args.force);
  }
  if (!args.quiet) print_summary(run, args);
  return run.result.verdict == certify::Verdict::kClear ? kExitOk : kExitFinding;
}

}  // namespace

void register_verify_command(CLI::App& app, int& exit_code) {
  auto args = std::make_shared<VerifyArguments>();
  auto* command = app.add_subcommand("verify", "Verify a path: simulate, test, certify");
  add_verify_options(*command, *args);
  command->add_option("--out", args->out, "Thesis output file (Appendix A.3 layout)");
  command->add_option("--json", args->json, "JSON report (docs/report-schema.md)");
  command->add_option("--html", args->html, "3-D animation of the run, one offline HTML file");
  command->add_option("--certificate", args->certificate,
                      "Certificate for check-certificate (docs/certificate.md)");
  command->add_flag("--force", args->force, "Overwrite existing output files");
  command->add_flag("--quiet", args->quiet, "Print nothing; the exit code tells the verdict");
  command->callback([args, &exit_code] { exit_code = run_verify(*args); });
}

}  // namespace grpvss::app
