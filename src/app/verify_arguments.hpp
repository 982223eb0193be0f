#pragma once
// The options `verify` and `check-certificate` share (the checker must replay the same
// trajectory the verifier certified).
#include <string>
#include <vector>

#include <CLI/CLI.hpp>

#include "grpvss/batch/verify_options.hpp"
#include "model_inputs.hpp"

namespace grpvss::app {

/// The inputs and choices (shared with `grpvss batch`'s manifests), and the outputs.
struct VerifyArguments : batch::VerifyOptions {
  std::string program_file;  ///< --program: a robot program instead of --path
  std::string out;
  std::string json;
  std::string certificate;
  std::string html;
  bool force = false;
  bool quiet = false;
  std::string cache_dir;  ///< --cache-dir; empty: the default (docs/cache.md)
  bool no_cache = false;  ///< --no-cache
};

/// Accepts a finite number > 0; the message names what was found ("a finite number > 0,
/// found -1"), unlike CLI::PositiveNumber's range text.
CLI::Validator positive_number();

/// --robot --env --path|--trajectory --tolerance --mode --offset --claim --timing --profile-table --ik --cp-speed --start
void add_verify_options(CLI::App& command, VerifyArguments& args);
void add_input_options(CLI::App& command, VerifyArguments& args);

// The words turned into the typed request: one implementation for verify and batch.
using batch::make_setup_request;
using batch::parse_ik_choice;

using batch::model_sources;

/// The arguments with what the model supplies when they leave it unset (a cell's tolerance,
/// CP speed and synchronized timing; lengths given with a cell are in its unit), as the typed
/// request. \throws InputError("--tolerance", 0, ...) when neither gives a tolerance.
certify::SetupRequest make_setup_request(const VerifyArguments& args, const ModelInputs& model);

}  // namespace grpvss::app
