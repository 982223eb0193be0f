// `grpvss interactive`: the menu-driven session of thesis Appendix A.2 at a terminal or with
// piped answers (src/app/interactive/session.hpp). Exit codes: 0 after EXIT or the end of
// input, 2 after too many invalid answers in a row, 3 internal error.
#include <unistd.h>

#include <cstdlib>
#include <filesystem>
#include <iostream>
#include <memory>
#include <string>
#include <system_error>

#include "commands.hpp"
#include "grpvss/common/input_error.hpp"
#include "interactive/session.hpp"
#include "model_inputs.hpp"
#include "viewer_html.hpp"

namespace grpvss::app {
namespace {

struct InteractiveArguments {
  std::string data_dir;
  int max_invalid = 20;
  ModelSources cell;  ///< --cell, --package-path
};

/// The folder holding ibm7545/robot.txt: --data-dir, else $GRPVSS_DATA_DIR, else the `data`
/// folder next to the executable or one level up (a build folder inside the repository), else
/// an installed share/grpvss/data.
std::string find_data_dir(const std::string& given) {
  if (!given.empty()) return given;
  if (const char* from_environment = std::getenv("GRPVSS_DATA_DIR")) return from_environment;
  std::error_code error;
  const std::filesystem::path executable = std::filesystem::read_symlink("/proc/self/exe", error);
  if (!error) {
    const std::filesystem::path folder = executable.parent_path();
    for (const std::filesystem::path& candidate :
         {folder / "data", folder.parent_path() / "data",
          folder.parent_path() / "share" / "grpvss" / "data"}) {
      if (std::filesystem::exists(candidate / "ibm7545" / "robot.txt", error)) {
        return candidate.string();
      }
    }
  }
  return "data";
}

int run_interactive(const InteractiveArguments& args) {
  interactive::SessionSettings settings;
  settings.data_dir = find_data_dir(args.data_dir);
  settings.max_invalid_answers = args.max_invalid;
  settings.echo_answers = isatty(STDIN_FILENO) == 0;
  settings.render_html = render_viewer_html;
  if (!args.cell.cell_file.empty()) {
    settings.cell = load_model_inputs(args.cell, false);
    settings.cell_file = args.cell.cell_file;
  } else if (!args.cell.package_paths.empty()) {
    throw InputError("--package-path", 0, "--package-path only with --cell (a URDF robot)");
  }
  interactive::Session session(std::cin, std::cout, settings);
  return interactive::exit_code(session.run());
}

}  // namespace

void register_interactive_command(CLI::App& app, int& exit_code) {
  auto args = std::make_shared<InteractiveArguments>();
  auto* command = app.add_subcommand(
      "interactive", "The menu-driven session of thesis Appendix A.2 (terminal or piped answers)");
  command->add_option("--data-dir", args->data_dir,
                      "Folder holding ibm7545/robot.txt (default: $GRPVSS_DATA_DIR, else the "
                      "data folder next to the executable)");
  command->add_option("--cell", args->cell.cell_file,
                      "Cell file: its robot and named obstacles replace the robot and environment "
                      "questions (docs/cell-format.md)");
  command->add_option("--package-path", args->cell.package_paths,
                      "Directory searched for package://NAME/... (repeatable; before the cell's)");
  command->add_option("--max-invalid", args->max_invalid,
                      "End the session (exit 2) after this many invalid answers in a row")
      ->check(CLI::PositiveNumber)
      ->capture_default_str();
  command->callback([args, &exit_code] { exit_code = run_interactive(*args); });
}

}  // namespace grpvss::app
