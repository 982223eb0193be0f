#pragma once
// Each subcommand lives in its own command_<name>.cpp and registers itself on the CLI11 app.
// A registered command returns its exit code through the shared `exit_code` slot.

#include <CLI/CLI.hpp>

#include "exit_codes.hpp"

namespace grpvss::app {

void register_trajectory_command(CLI::App& app, int& exit_code);
void register_verify_command(CLI::App& app, int& exit_code);
void register_batch_command(CLI::App& app, int& exit_code);
void register_check_certificate_command(CLI::App& app, int& exit_code);
void register_expansion_audit_command(CLI::App& app, int& exit_code);
void register_animate_command(CLI::App& app, int& exit_code);
void register_render_command(CLI::App& app, int& exit_code);
void register_interactive_command(CLI::App& app, int& exit_code);

}  // namespace grpvss::app
