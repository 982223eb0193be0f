// `grpvss render --report REPORT.json --step K --svg FILE`: the thesis's wireframe picture of
// one step for a given view (defaults ANGLEX, ANGLEY, ANGLEZ = -75, 0, 170; SCALE 1; window
// -50..50 for a scene of the thesis's size, else fitted to the scene: svg_window.hpp),
// interference points as red stars. Reads only the JSON report.
#include <cstdio>
#include <memory>
#include <string>
#include <vector>

#include <fmt/core.h>

#include "commands.hpp"
#include "grpvss/common/input_error.hpp"
#include "grpvss/report/atomic_output.hpp"
#include "grpvss/report/svg_render.hpp"
#include "output_paths.hpp"
#include "report_file.hpp"
#include "interactive/svg_window.hpp"

namespace grpvss::app {
namespace {

struct RenderArguments {
  std::string report_file;
  int step = 1;
  std::string svg;
  report::SvgView view;
  std::vector<double> window;  ///< empty: default_svg_window() of the report
  bool force = false;
};

int run_render(RenderArguments args) {
  check_requested_outputs({{"--svg", args.svg}}, {args.report_file}, args.force);
  const nlohmann::json report = read_report_file(args.report_file);
  if (args.window.empty()) {
    const std::array<double, 2> fitted = default_svg_window(report);
    args.window = {fitted[0], fitted[1]};
  }
  args.view.window_min = args.window.at(0);
  args.view.window_max = args.window.at(1);
  report::write_file_atomically(
      args.svg, report::render_step_svg(report, args.step, args.view, args.report_file),
      args.force);
  // With --svg - the picture is standard output: the note goes to stderr.
  fmt::print(args.svg == report::kStandardOutput ? stderr : stdout,
             "SVG picture of step {}: {}\n", args.step, args.svg);
  return kExitOk;
}

}  // namespace

void register_render_command(CLI::App& app, int& exit_code) {
  auto args = std::make_shared<RenderArguments>();
  auto* command = app.add_subcommand("render", "SVG wireframe of one step of a JSON report");
  // The report is positional, as for `animate REPORT`; --report stays as an alias.
  auto* positional = command->add_option("REPORT", args->report_file,
                                         "JSON report (grpvss verify --json)");
  auto* named = command->add_option("--report", args->report_file, "Same as REPORT");
  positional->excludes(named);
  command->add_option("--step", args->step, "Step index (1-based, as in the report)")->required();
  command->add_option("--svg", args->svg, "SVG file to write")->required();
  command->add_option("--anglex", args->view.angle_x_deg, "View angle about x, deg")
      ->capture_default_str();
  command->add_option("--angley", args->view.angle_y_deg, "View angle about the new y, deg")
      ->capture_default_str();
  command->add_option("--anglez", args->view.angle_z_deg, "View angle about the new z, deg")
      ->capture_default_str();
  command->add_option("--scale", args->view.scale, "Scale factor")->capture_default_str();
  command->add_option("--shiftx", args->view.shift[0], "Window shift in x (before scaling)");
  command->add_option("--shifty", args->view.shift[1], "Window shift in y (before scaling)");
  command->add_option("--shiftz", args->view.shift[2], "Window shift in z (before scaling)");
  command->add_option("--window", args->window,
                      "View scope lo,hi in each dimension (default: -50,50 for a scene of the "
                      "thesis's size, else fitted to the scene)")
      ->delimiter(',')
      ->expected(2);
  command->add_flag("--force", args->force, "Overwrite an existing output file");
  command->callback([args, &exit_code] {
    if (args->report_file.empty()) throw InputError("render", 0, "a report file (REPORT or --report)");
    exit_code = run_render(*args);
  });
}

}  // namespace grpvss::app
