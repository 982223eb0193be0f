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
#include "grpvss/certify/verifier.hpp"
#include "grpvss/common/input_error.hpp"
#include "grpvss/io/path_file.hpp"
#include "grpvss/motion/kinematics_adapter.hpp"
#include "grpvss/report/atomic_output.hpp"
#include "grpvss/report/certificate_output.hpp"
#include "grpvss/report/file_units.hpp"
#include "grpvss/report/input_digests.hpp"
#include "grpvss/report/json_report.hpp"
#include "grpvss/report/json_report_stream.hpp"
#include "grpvss/report/scene_json.hpp"
#include "grpvss/report/thesis_output.hpp"
#include "interactive/verdict_summary.hpp"
#include "output_paths.hpp"
#include "progress_bar.hpp"
#include "setup_cache_options.hpp"
#include "verify_arguments.hpp"
#include "viewer_html_stream.hpp"

namespace grpvss::app {
namespace {

std::string file_label(const std::string& path) {
  const auto slash = path.find_last_of('/');
  return slash == std::string::npos ? path : path.substr(slash + 1);
}

std::vector<RequestedOutput> requested_outputs(const VerifyArguments& args) {
  return {{"--out", args.out}, {"--json", args.json}, {"--html", args.html},
          {"--certificate", args.certificate}};
}

std::string output_label(const std::string& path) {
  return path == report::kStandardOutput ? "standard output" : path;
}

void print_summary(std::FILE* stream, const certify::VerificationRun& run,
                   const VerifyArguments& args, const ModelNames& names) {
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

int run_verify(const VerifyArguments& args) {
  const ModelInputs model = load_model_inputs(model_sources(args), args.quiet);
  const RobotModel& robot = model.robot;
  const Environment& environment = model.environment;
  PathProgram program = io::read_path_file(args.path_file, robot);
  convert_path_lengths(program, robot, model.model_units_per_cell_unit);
  const report::InputDigests digests = report::digest_input_files(
      model.robot_digest_file, model.environment_digest_file, args.path_file);
  certify::SetupRequest request = make_setup_request(args, model);
  request.path_label = file_label(args.path_file);
  const certify::VerificationSetup setup = certify::resolve_setup(request);
  const auto ik = motion::select_ik(parse_ik_choice(args.ik), robot, model.robot_label_file);
  if (!args.certificate.empty() && setup.run.mode != certify::ResolutionMode::kCertified) {
    throw InputError("--certificate", 0, "--mode certified (thesis mode proves nothing)");
  }
  // Refused before a long run rather than after it; the publication itself still never
  // clobbers (a file that appears meanwhile is refused then).
  const std::vector<RequestedOutput> requested = requested_outputs(args);
  std::vector<std::string> inputs = model.input_files;
  inputs.push_back(args.path_file);
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
    run = certify::verify(cell, program, motion::make_kinematics_access(robot, ik), setup.run,
                          hooks);
  }

  const std::string generated_at = report::utc_timestamp_now();
  if (thesis_output) thesis_output->finish(run.result);
  if (json_report) json_report->finish(run.result, cell, digests, generated_at);
  if (!args.html.empty()) {
    write_viewer_html(args.html, args.force, robot.name, [&](report::AtomicOutputFile& output) {
      json_report->write_script_safe_report(output);
    });
  }
  if (certificate) {
    certificate->finish(run.certificate, {{"robot", digests.robot.sha256},
                                          {"environment", digests.environment.sha256},
                                          {"path", digests.path.sha256},
                                          {"ik", ik->name()}});
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
