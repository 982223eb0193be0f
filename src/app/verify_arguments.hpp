#pragma once
// The options `verify` and `check-certificate` share (the checker must replay the same
// trajectory the verifier certified).
#include <string>

#include <CLI/CLI.hpp>

#include "grpvss/evidence/setup.hpp"
#include "grpvss/kinematics/inverse_kinematics.hpp"
#include "model_inputs.hpp"

namespace grpvss::app {

struct VerifyArguments {
  std::string robot_file;
  std::string environment_file;
  std::string cell_file;
  std::vector<std::string> package_paths;
  std::string path_file;
  double tolerance = 0.0;  ///< 0: the cell's (an error without a cell)
  std::string mode = "certified";
  std::string offset = "auto";
  /// Empty: independent for thesis files, synchronized for a cell (what controllers do).
  std::string timing;
  std::string profile_table;
  std::string ik = "auto";
  double cp_speed = 0.0;  ///< 0: the cell's, else 1 length unit per s
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

/// --robot --env --path --tolerance --mode --offset --timing --profile-table --ik --cp-speed
void add_verify_options(CLI::App& command, VerifyArguments& args);
void add_input_options(CLI::App& command, VerifyArguments& args);

/// The model sources the arguments name.
ModelSources model_sources(const VerifyArguments& args);

/// The CLI's words turned into the typed request, once (reads the profile table file). The
/// model supplies the defaults a cell sets (tolerance, timing, CP speed) and its units.
/// \throws InputError("--tolerance", 0, ...) when neither the command line nor the cell gives one.
certify::SetupRequest make_setup_request(const VerifyArguments& args, const ModelInputs& model);
/// `--ik`: auto, ibm7545, opw, ur, numeric or plugin:PATH.so. \throws InputError ("--ik", line 0).
kinematics::IkChoice parse_ik_choice(const std::string& text);

}  // namespace grpvss::app
