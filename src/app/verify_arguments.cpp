#include "verify_arguments.hpp"

#include <cmath>
#include <memory>
#include <string>


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
  command.add_option("--robot", args.robot_file, "Robot file (thesis A.1.1.1)")->required();
  command.add_option("--env", args.environment_file, "Environment file (thesis A.1.1.2)")->required();
  command.add_option("--path", args.path_file, "Path file (thesis A.1.3)")->required();
  command.add_option("--timing", args.timing, "PTP joint timing")
      ->check(CLI::IsMember(batch::timing_choices()))
      ->capture_default_str();
  command.add_option("--profile-table", args.profile_table,
                     "Motion-time table replacing the ideal trapezoids (docs/trajectories.md)");
  command.add_option("--ik", args.ik, "IK: auto, ibm7545, opw, ur, numeric or plugin:PATH.so (docs/ik.md)")
      ->capture_default_str();
}

void add_verify_options(CLI::App& command, VerifyArguments& args) {
  add_input_options(command, args);
  command.add_option("--tolerance", args.tolerance, "Tolerance Delta (> 0, length units)")
      ->required()
      ->check(positive_number());
  command.add_option("--mode", args.mode, "Step rule: certified, or thesis (never certified)")
      ->check(CLI::IsMember(batch::mode_choices()))
      ->capture_default_str();
  command.add_option("--offset", args.offset,
                     "Tolerance offset polytope: auto, cube (thesis) or rhombicuboctahedron")
      ->check(CLI::IsMember(batch::offset_choices()))
      ->capture_default_str();
  command.add_option("--cp-speed", args.cp_speed,
                     "Nominal end-effector speed on CP lines (length units per s)")
      ->check(positive_number())
      ->capture_default_str();
}

}  // namespace grpvss::app
