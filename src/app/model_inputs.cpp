#include "model_inputs.hpp"

#include <cstdio>

#include <fmt/core.h>

namespace grpvss::app {
namespace {

void print_warnings(const std::vector<io::InputWarning>& warnings) {
  for (const io::InputWarning& warning : warnings) {
    if (warning.line > 0) {
      fmt::print(stderr, "warning: {}:{}: {}\n", warning.file, warning.line, warning.text);
    } else {
      fmt::print(stderr, "warning: {}: {}\n", warning.file, warning.text);
    }
  }
}

}  // namespace

void add_model_source_options(CLI::App& command, std::string& robot_file,
                              std::string& environment_file, std::string& cell_file,
                              std::vector<std::string>& package_paths) {
  command.add_option("--robot", robot_file, "Robot file (thesis A.1.1.1)");
  command.add_option("--env", environment_file, "Environment file (thesis A.1.1.2)");
  command.add_option("--cell", cell_file,
                     "Cell file: robot (URDF or thesis) and named obstacles (docs/cell-format.md)");
  command.add_option("--package-path", package_paths,
                     "Directory searched for package://NAME/... (repeatable; before the cell's)");
}

void add_model_source_options(CLI::App& command, ModelSources& sources) {
  add_model_source_options(command, sources.robot_file, sources.environment_file,
                           sources.cell_file, sources.package_paths);
}

ModelInputs load_model_inputs(const ModelSources& sources, bool quiet, ObstaclesNeeded obstacles) {
  ModelInputs inputs = cell::load_model_inputs(sources, obstacles);
  if (!quiet) print_warnings(inputs.warnings);
  return inputs;
}

}  // namespace grpvss::app
