#pragma once
// The options `verify` and `check-certificate` share (the checker must replay the same
// trajectory the verifier certified).
#include <string>

#include <CLI/CLI.hpp>

#include "grpvss/batch/verify_options.hpp"

namespace grpvss::app {

/// The inputs and choices (shared with `grpvss batch`'s manifests), and the outputs.
struct VerifyArguments : batch::VerifyOptions {
  std::string out;
  std::string json;
  std::string certificate;
  std::string html;
  bool force = false;
  bool quiet = false;
};

/// Accepts a finite number > 0; the message names what was found ("a finite number > 0,
/// found -1"), unlike CLI::PositiveNumber's range text.
CLI::Validator positive_number();

/// --robot --env --path --tolerance --mode --offset --timing --profile-table --ik --cp-speed
void add_verify_options(CLI::App& command, VerifyArguments& args);
void add_input_options(CLI::App& command, VerifyArguments& args);

// The words turned into the typed request: one implementation for verify and batch.
using batch::make_setup_request;
using batch::parse_ik_choice;

}  // namespace grpvss::app
