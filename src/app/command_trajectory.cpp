// `grpvss trajectory`: plans the joint trajectory of a path (motion stage) and prints it
// (docs/trajectories.md). Exit codes: 0 path planned, 1 a thesis error 3-6 stopped the path,
// 2 input error.
#include <cmath>
#include <cstdio>
#include <memory>
#include <string>
#include <vector>

#include <fmt/core.h>

#include "commands.hpp"
#include "grpvss/common/input_error.hpp"
#include "grpvss/io/length_unit.hpp"
#include "grpvss/io/path_file.hpp"
#include "grpvss/io/profile_table_file.hpp"
#include "grpvss/motion/kinematics_adapter.hpp"
#include "grpvss/motion/profile_table.hpp"
#include "grpvss/motion/trajectory.hpp"
#include "grpvss/report/trajectory_report.hpp"
#include "program_inputs.hpp"
#include "start_option.hpp"
#include "trajectory_inputs.hpp"
#include "verify_arguments.hpp"

namespace grpvss::app {
namespace {

struct TrajectoryArguments {
  ModelSources model;
  std::string path_file;
  std::string trajectory_file;  ///< --trajectory instead of --path
  std::string program_file;     ///< --program instead of --path
  std::string timing;  ///< empty: independent for thesis files, synchronized for a cell
  std::string profile_table;
  std::string ik = "auto";
  std::string start;  ///< --start; empty: the home
  std::vector<double> at;
  double step = 0.0;
  double cp_speed = 1.0;
  double cp_spacing = 0.0;  ///< 0: the cell's motion.cp_spacing, else default_cp_spacing()
  bool json = false;
};

/// The default CP sample spacing, 0.5 in (the thesis's), in the model's unit: 0.5 for thesis
/// files (inches, or whatever unit they use), 0.0127 for a URDF robot (metres).
constexpr double kDefaultCpSpacingInches = 0.5;

double default_cp_spacing(const ModelInputs& model) {
  if (model.cp_spacing) return *model.cp_spacing;
  if (!model.model_unit) return kDefaultCpSpacingInches;
  return kDefaultCpSpacingInches * io::length_unit_factor(LengthUnit::kInch, *model.model_unit);
}

/// Most time samples --step may produce (a guard against an accidental tiny step).
constexpr double kMaxSteps = 1e6;

std::vector<double> requested_times(const TrajectoryArguments& args, double total) {
  std::vector<double> times = args.at;
  if (args.step > 0.0) {
    if (total / args.step > kMaxSteps)
      throw InputError("--step", 0, fmt::format("at most {:.0f} samples over {} s", kMaxSteps, total),
                       fmt::format("{}", args.step));
    const auto count = static_cast<long long>(std::floor(total / args.step));
    for (long long k = 0; k <= count; ++k) times.push_back(static_cast<double>(k) * args.step);
    if (times.empty() || times.back() < total) times.push_back(total);
  }
  return times;
}

// Prints `trajectory` with the settings `args` ask for; exit 0 without errors, 1 with.
int print_trajectory(const TrajectoryArguments& args, const ModelInputs& model,
                     const motion::Trajectory& trajectory, const std::string& motion_file,
                     const std::string& ik_name) {
  report::TrajectoryReportSettings settings;
  settings.robot_file = model.robot_label_file;
  settings.path_file = motion_file;
  settings.ik_name = ik_name;
  settings.times = requested_times(args, trajectory.duration());
  if (args.json)
    fmt::print("{}\n", report::trajectory_json(model.robot, trajectory, settings).dump(2));
  else
    fmt::print("{}", report::trajectory_text(model.robot, trajectory, settings));
  return trajectory.errors().empty() ? kExitOk : kExitFinding;
}

// A planner's joint trajectory: read, joints matched, limits checked, interpolated.
int run_joint_trajectory(const TrajectoryArguments& args, const ModelInputs& model) {
  refuse_with_trajectory(!args.timing.empty(), "--timing");
  refuse_with_trajectory(!args.profile_table.empty(), "--profile-table");
  const auto joint_motion = load_joint_trajectory(args.trajectory_file, model.robot);
  check_trajectory_start(args.start, model, *joint_motion);
  const motion::Trajectory trajectory =
      motion::Trajectory::from_joint_motion(model.robot, joint_motion);
  return print_trajectory(args, model, trajectory, args.trajectory_file, "(not used)");
}

int run_trajectory(const TrajectoryArguments& args) {
  const ModelInputs model = load_model_inputs(args.model, false, ObstaclesNeeded::kNo);
  require_one_motion_source(args.path_file, args.trajectory_file, args.program_file);
  if (!args.trajectory_file.empty()) return run_joint_trajectory(args, model);
  const RobotModel& robot = model.robot;
  const auto ik = motion::select_ik(parse_ik_choice(args.ik), robot, model.robot_label_file);
  PathProgram program;
  if (!args.program_file.empty()) {
    refuse_with_program(!args.timing.empty() && args.timing != "synchronized", "--timing");
    refuse_with_program(!args.profile_table.empty(), "--profile-table");
    const LoadedProgram loaded =
        load_program(args.program_file, model, *ik, false, start_of(args.start, model));
    if (!args.json) fmt::print("motion: {}\n", loaded.description);
    program = loaded.path.path;
  } else {
    program = read_model_path(args.path_file, model);
  }
  motion::MotionModel options;
  options.timing = motion::ptp_timing_from_string(args.timing)
                       .value_or(model.from_cell ? motion::PtpTiming::kSynchronized
                                                 : motion::PtpTiming::kIndependent);
  if (!args.profile_table.empty())
    options.table = std::make_shared<const motion::ProfileTable>(
        io::read_profile_table_file(args.profile_table));
  options.cp_speed = args.cp_speed;
  options.cp_spacing = args.cp_spacing > 0.0 ? args.cp_spacing : default_cp_spacing(model);
  options.start = start_of(args.start, model);
  const motion::Trajectory trajectory =
      motion::Trajectory::plan(robot, program, motion::make_kinematics_access(robot, ik), options);

  return print_trajectory(args, model, trajectory,
                          args.program_file.empty() ? args.path_file : args.program_file,
                          ik->name());
}

}  // namespace

void register_trajectory_command(CLI::App& app, int& exit_code) {
  auto args = std::make_shared<TrajectoryArguments>();
  auto* command = app.add_subcommand("trajectory", "Print the joint trajectory of a path");
  command->add_option("--robot", args->model.robot_file, "Robot file (thesis A.1.1.1)");
  command->add_option("--cell", args->model.cell_file,
                      "Cell file: its robot (docs/cell-format.md)");
  command->add_option("--package-path", args->model.package_paths,
                      "Directory searched for package://NAME/... (repeatable; before the cell's)");
  CLI::Option* path = command->add_option("--path", args->path_file, "Path file: thesis A.1.3, or a YAML path with absolute poses (.yaml, docs/input-formats.md#yaml-path)");
  CLI::Option* trajectory =
      command
          ->add_option("--trajectory", args->trajectory_file,
                       "Planner joint trajectory (CSV or ROS JSON) instead of --path")
          ->excludes(path);
  add_program_option(*command, args->program_file, {path, trajectory});
  command->add_option("--timing", args->timing,
                      "PTP joint timing (default: independent for thesis files, synchronized "
                      "for a cell)")
      ->check(CLI::IsMember({"independent", "synchronized"}));
  command->add_option("--profile-table", args->profile_table,
                      "Motion-time table replacing the ideal trapezoids (docs/trajectories.md)");
  command->add_option("--ik", args->ik, "IK: auto, ibm7545, opw, ur, numeric or plugin:PATH.so (docs/ik.md)")
      ->capture_default_str();
  add_start_option(*command, args->start);
  command->add_option("--at", args->at, "Path times (s) at which to print the joints")
      ->delimiter(',')
      ->check(CLI::NonNegativeNumber);
  command->add_option("--step", args->step, "Print the joints every DT seconds")
      ->check(positive_number());
  command->add_option("--cp-speed", args->cp_speed,
                      "Nominal end-effector speed on CP lines (length units per s)")
      ->check(positive_number())
      ->capture_default_str();
  command->add_option("--cp-spacing", args->cp_spacing,
                      "Largest path-length spacing of the CP IK samples, in the model's length "
                      "unit (m for a URDF robot, else the cell's or the robot file's; default: "
                      "the cell's motion.cp_spacing, else 0.5 in: 0.5 for thesis files, "
                      "0.0127 m for a URDF robot)")
      ->check(positive_number());
  command->add_flag("--json", args->json, "Print a JSON document instead of text");
  command->callback([args, &exit_code] { exit_code = run_trajectory(*args); });
}

}  // namespace grpvss::app
