// `grpvss animate REPORT.json --html FILE [--force]`: the 3-D animation of a verification run
// as one self-contained HTML file (docs/viewer.md). Reads only the JSON report.
#include <cstdio>
#include <memory>
#include <string>

#include <fmt/core.h>

#include "commands.hpp"
#include "grpvss/report/atomic_output.hpp"
#include "output_paths.hpp"
#include "report_file.hpp"
#include "viewer_html.hpp"

namespace grpvss::app {
namespace {

struct AnimateArguments {
  std::string report_file;
  std::string html;
  bool force = false;
};

int run_animate(const AnimateArguments& args) {
  check_requested_outputs({{"--html", args.html}}, {args.report_file}, args.force);
  const nlohmann::json report = read_report_file(args.report_file);
  report::write_file_atomically(args.html, render_viewer_html(report, args.report_file), args.force);
  // With --html - the page is standard output: the note goes to stderr.
  fmt::print(args.html == report::kStandardOutput ? stderr : stdout, "HTML animation: {}\n",
             args.html);
  return kExitOk;
}

}  // namespace

void register_animate_command(CLI::App& app, int& exit_code) {
  auto args = std::make_shared<AnimateArguments>();
  auto* command = app.add_subcommand("animate", "3-D animation of a JSON report as one HTML file");
  command->add_option("report", args->report_file, "JSON report (grpvss verify --json)")
      ->required();
  command->add_option("--html", args->html, "HTML file to write (self-contained, offline)")
      ->required();
  command->add_flag("--force", args->force, "Overwrite an existing output file");
  command->callback([args, &exit_code] { exit_code = run_animate(*args); });
}

}  // namespace grpvss::app
