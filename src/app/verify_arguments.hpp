#pragma once
// The options `verify` and `check-certificate` share (the checker must replay the same
// trajectory the verifier certified).
#include <string>

#include <CLI/CLI.hpp>

#include "grpvss/certify/verifier.hpp"
#include "grpvss/model/robot_model.hpp"

namespace grpvss::app {

struct VerifyArguments {
  std::string robot_file;
  std::string environment_file;
  std::string path_file;
  double tolerance = 0.0;
  std::string mode = "certified";
  std::string offset = "auto";
  std::string timing = "independent";
  std::string profile_table;
  std::string ik = "auto";
  double cp_speed = 1.0;
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
certify::VerifyOptions make_verify_options(const VerifyArguments& args, const RobotModel& robot);

}  // namespace grpvss::app
