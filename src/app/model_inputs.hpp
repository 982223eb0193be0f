#pragma once
// The model options of every subcommand that takes a robot (--robot, --env, --cell,
// --package-path) and the loader that prints the inputs' warnings; the loading itself is the
// cell stage's (grpvss/cell/model_inputs.hpp), shared with batch and Python.
#include <string>
#include <vector>

#include <CLI/CLI.hpp>

#include "grpvss/cell/model_inputs.hpp"

namespace grpvss::app {

using cell::convert_path_lengths;
using cell::ModelInputs;
using cell::ModelSources;
using cell::ObstaclesNeeded;

/// --robot, --env, --cell, --package-path (either --cell, or --robot with --env).
void add_model_source_options(CLI::App& command, ModelSources& sources);
/// The same options into separate fields (`verify`'s arguments keep them apart).
void add_model_source_options(CLI::App& command, std::string& robot_file,
                              std::string& environment_file, std::string& cell_file,
                              std::vector<std::string>& package_paths);

/// \brief Loads the model (cell::load_model_inputs); prints the inputs' warnings to stderr
/// unless `quiet`.
ModelInputs load_model_inputs(const ModelSources& sources, bool quiet,
                              ObstaclesNeeded obstacles = ObstaclesNeeded::kYes);

}  // namespace grpvss::app
