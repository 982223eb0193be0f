#include "verify_arguments.hpp"

#include <cmath>
#include <limits>
#include <memory>
#include <string>

#include "grpvss/common/input_error.hpp"
#include "program_inputs.hpp"
#include "start_option.hpp"


namespace grpvss::app {

CLI::Validator positive_number() {
  return CLI::Validator(
      [](std::string& text) -> std::string {
        std::size_t used = 0;
        double value = 0.0;
        try {
          value = std::stod(text, &used);
        } catch (const std::exception&) {
          used = 0;
        }
        if (used == text.size() && std::isfinite(value) && value > 0.0) return {};
        return "expected a finite number > 0, found " + text;
      },
      "NUMBER > 0");
}

void add_input_options(CLI::App& command, VerifyArguments& args) {
  add_model_source_options(command, args.robot_file, args.environment_file, args.cell_file,
                           args.package_paths);
  CLI::Option* path = command.add_option("--path", args.path_file, "Path file: thesis A.1.3, or a YAML path with absolute poses (.yaml, docs/input-formats.md#yaml-path)");
  CLI::Option* trajectory =
      command
          .add_option("--trajectory", args.trajectory_file,
                      "Planner joint trajectory, CSV or ROS JSON, instead of --path "
                      "(docs/trajectories.md#verifying-a-trajectory)")
          ->excludes(path);
  add_program_option(command, args.program_file, {path, trajectory});
  command.add_option("--timing", args.timing,
                     "PTP joint timing (default: independent for thesis files, synchronized "
                     "for a cell)")
      ->check(CLI::IsMember(batch::timing_choices()));
  command.add_option("--profile-table", args.profile_table,
                     "Motion-time table replacing the ideal trapezoids (docs/trajectories.md)");
  command.add_option("--ik", args.ik, "IK: auto, ibm7545, opw, ur, numeric or plugin:PATH.so (docs/ik.md)")
      ->capture_default_str();
  add_start_option(command, args.start);
}

void add_verify_options(CLI::App& command, VerifyArguments& args) {
  add_input_options(command, args);
  command.add_option("--tolerance", args.tolerance,
                     "Tolerance Delta (> 0, length units; default: the cell's)")
      ->check(positive_number());
  command.add_option("--mode", args.mode, "Step rule: certified, or thesis (never certified)")
      ->check(CLI::IsMember(batch::mode_choices()))
      ->capture_default_str();
  command.add_option("--offset", args.offset,
                     "Tolerance offset polytope: auto, cube (thesis) or rhombicuboctahedron")
      ->check(CLI::IsMember(batch::offset_choices()))
      ->capture_default_str();
  command.add_option("--claim", args.claim,
                     "What CLEAR claims (certified mode): motion (robot + tolerance clear along "
                     "the whole motion) or steps (robot clear along the motion, robot + tolerance "
                     "at every step)")
      ->check(CLI::IsMember(batch::claim_choices()))
      ->capture_default_str();
  command.add_option("--cp-speed", args.cp_speed,
                     "Nominal end-effector speed on CP lines (length units per s; default: the "
                     "cell's, else 1)")
      ->check(positive_number());
}

certify::SetupRequest make_setup_request(const VerifyArguments& args, const ModelInputs& model) {
  certify::SetupRequest request = batch::make_setup_request(batch::resolve_model_defaults(args, model));
  request.motion.start = batch::resolve_start(args, model.robot, model.from_cell);
  return request;
}

}  // namespace grpvss::app
