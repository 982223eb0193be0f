// grpvss: the command-line front end. Library exceptions become exit codes here and only here.
#include <cstdio>
#include <exception>
#include <string>

#include <CLI/CLI.hpp>
#include <fmt/core.h>

#include "commands.hpp"
#include "grpvss/common/input_error.hpp"
#include "grpvss/report/program_version.hpp"

int main(int argc, char** argv) {
  CLI::App app{"GRPVSS - General Robot Path Verification Simulation System"};
  app.require_subcommand(1);
  app.set_version_flag("--version", std::string("grpvss ") + grpvss::report::program_version());
  int exit_code = grpvss::app::kExitOk;
  grpvss::app::register_trajectory_command(app, exit_code);
  grpvss::app::register_verify_command(app, exit_code);
  grpvss::app::register_batch_command(app, exit_code);
  grpvss::app::register_check_certificate_command(app, exit_code);
  grpvss::app::register_expansion_audit_command(app, exit_code);
  grpvss::app::register_animate_command(app, exit_code);
  grpvss::app::register_render_command(app, exit_code);
  grpvss::app::register_interactive_command(app, exit_code);
  try {
    app.parse(argc, argv);
  } catch (const CLI::ParseError& error) {
    const int cli_code = app.exit(error);
    return cli_code == 0 ? 0 : grpvss::app::kExitInputError;
  } catch (const grpvss::InputError& error) {
    fmt::print(stderr, "grpvss: error: {}\n", error.what());
    return grpvss::app::kExitInputError;
  } catch (const std::exception& error) {
    fmt::print(stderr, "grpvss: internal error: {}\n", error.what());
    return grpvss::app::kExitInternalError;
  }
  return exit_code;
}
