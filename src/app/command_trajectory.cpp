// `grpvss trajectory`: placeholder until the motion stage lands (issue 2, item 8).
#include <stdexcept>

#include "commands.hpp"

namespace grpvss::app {

void register_trajectory_command(CLI::App& app, int& exit_code) {
  auto* command = app.add_subcommand("trajectory", "Print the joint trajectory of a path");
  command->callback([&exit_code] {
    exit_code = 3;
    throw std::runtime_error("trajectory: not built yet");
  });
}

}  // namespace grpvss::app
