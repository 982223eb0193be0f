#include "interactive/session.hpp"

#include <filesystem>
#include <system_error>

#include <fmt/core.h>

#include "grpvss/certify/verifier.hpp"
#include "grpvss/common/input_error.hpp"
#include "grpvss/io/environment_file.hpp"
#include "grpvss/io/path_file.hpp"
#include "grpvss/io/profile_table_file.hpp"
#include "grpvss/io/robot_file.hpp"
#include "grpvss/io/units.hpp"
#include "grpvss/motion/kinematics_adapter.hpp"
#include "grpvss/motion/thesis_error.hpp"
#include "grpvss/motion/trajectory.hpp"
#include "grpvss/report/atomic_output.hpp"
#include "grpvss/report/file_units.hpp"
#include "grpvss/report/thesis_output.hpp"
#include "interactive/animation_output.hpp"
#include "interactive/answer_parsing.hpp"
#include "interactive/verdict_summary.hpp"

namespace grpvss::app::interactive {
namespace {

constexpr const char* kCommaLine = "USE A COMMA AFTER EACH DATA INCLUDING THE LAST ONE";
/// Joint limits are compared as motion::first_joint_outside_limits() does.
constexpr double kLimitSlack = 1e-9;

/// File units of a joint value: degrees for revolute joints, lengths for prismatic ones.
double to_file_units(const Joint& joint, double value) {
  return joint.type == JointType::kRevolute ? value / io::kRadiansPerDegree : value;
}
double to_library_units(const Joint& joint, double value) {
  return joint.type == JointType::kRevolute ? io::degrees_to_radians(value) : value;
}

std::string base_name(const std::string& path) {
  return std::filesystem::path(path).filename().string();
}

bool path_exists(const std::string& name) {
  std::error_code error;
  return std::filesystem::exists(std::filesystem::symlink_status(name, error));
}

}  // namespace

int exit_code(SessionEnd end) { return end == SessionEnd::kTooManyInvalidAnswers ? 2 : 0; }

Session::Session(std::istream& in, std::ostream& out, SessionSettings settings)
    : prompter_(in, out, settings.max_invalid_answers, settings.echo_answers),
      out_(out),
      settings_(std::move(settings)) {}

SessionEnd Session::run() {
  out_ << "GRPVSS - GENERAL ROBOT PATH VERIFICATION SIMULATION SYSTEM\n"
          "(INTERACTIVE SESSION OF THESIS APPENDIX A.2; END THE INPUT OR CHOOSE 6 TO EXIT)\n\n";
  try {
    Stage stage = Stage::kRobot;
    for (;;) {
      run_from(stage);
      for (;;) {
        const int option = main_menu();
        if (option == 6) {
          out_ << "GRPVSS SESSION ENDED\n" << std::flush;
          return SessionEnd::kExitChosen;
        }
        if (option == 5) {
          if (!last_motion_) {
            prompter_.reject("no motion has been processed yet");
            continue;
          }
          animate();
          continue;
        }
        stage = option == 1   ? Stage::kRobot
                : option == 2 ? Stage::kEnvironment
                : option == 3 ? Stage::kTolerance
                              : Stage::kMotion;
        break;
      }
    }
  } catch (const EndOfInput&) {
    out_ << "END OF INPUT: GRPVSS SESSION ENDED\n" << std::flush;
    return SessionEnd::kEndOfInput;
  } catch (const TooManyInvalidAnswers& too_many) {
    out_ << fmt::format("{} INVALID ANSWERS IN A ROW: GRPVSS SESSION ENDED\n", too_many.count)
         << std::flush;
    return SessionEnd::kTooManyInvalidAnswers;
  }
}

void Session::run_from(Stage stage) {
  // Each menu option re-enters the thesis's sequence at its stage and goes on from there.
  if (stage <= Stage::kRobot) choose_robot();
  if (stage <= Stage::kTrajectoryWay) choose_trajectory_way();
  if (stage <= Stage::kEnvironment) choose_environment();
  if (stage <= Stage::kTolerance) choose_tolerance();
  if (stage <= Stage::kView) {
    show_configuration();
    change_view();
  }
  perform_motion();
}

void Session::take_cell_robot() {
  robot_ = settings_.cell->robot;
  ik_ = motion::select_ik({}, *robot_, settings_.cell_file);
  cell_.reset();
  kinematics_ = motion::make_kinematics_access(*robot_, ik_);
  robot_file_ = settings_.cell_file;
  if (tolerance_ == 0.0 && settings_.cell->tolerance) tolerance_ = *settings_.cell->tolerance;
  out_ << fmt::format("CELL FILE {}: ROBOT {}, {} JOINTS, IK {}\n", settings_.cell_file,
                      robot_->name, robot_->joint_count(), ik_->name());
}

void Session::take_cell_environment() {
  environment_ = settings_.cell->environment;
  cell_.reset();
  environment_file_ = settings_.cell_file;
  std::string names;
  for (int i = 0; i < static_cast<int>(environment_->obstacles.size()); ++i) {
    names += (i == 0 ? " (" : ", ") + obstacle_label(*environment_, i);
  }
  out_ << fmt::format("CELL FILE {}: {} OBSTACLE HULLS{}\n", settings_.cell_file,
                      environment_->obstacles.size(), names.empty() ? "" : names + ")");
}

void Session::choose_robot() {
  if (settings_.cell) return take_cell_robot();
  for (;;) {
    const int option = prompter_.ask_option("WHICH ROBOT ARE YOU GOING TO SIMULATE ?",
                                            {"IBM 7545 ROBOT", "OTHERS"});
    std::string file;
    if (option == 1) {
      file = (std::filesystem::path(settings_.data_dir) / "ibm7545" / "robot.txt").string();
    } else {
      file = prompter_.ask_name({"THE KINEMATIC AND SHAPE PARAMETERS OF THE",
                                 "TO-BE-SIMULATED ROBOT SHOULD BE IN A FILE",
                                 "(FORMAT: docs/input-formats.md, THESIS A.1.1.1)",
                                 "ENTER THE FILE NAME"});
    }
    try {
      RobotModel robot = io::read_robot_file(file);
      ik_ = motion::select_ik({}, robot, file);
      robot_ = std::move(robot);
      cell_.reset();
      kinematics_ = motion::make_kinematics_access(*robot_, ik_);
      robot_file_ = file;
      out_ << fmt::format("ROBOT FILE {}: {} JOINTS, IK {}\n", file, robot_->joint_count(),
                          ik_->name());
      prompter_.accept();
      return;
    } catch (const InputError& error) {
      prompter_.reject(option == 1 ? fmt::format("the built-in IBM 7545 robot file cannot be "
                                                 "read ({}); set GRPVSS_DATA_DIR or choose 2",
                                                 error.what())
                                   : std::string(error.what()));
    }
  }
}

void Session::choose_trajectory_way() {
  for (;;) {
    const int option = prompter_.ask_option(
        "ENTER THE WAY TO GENERATE THE PTP TRAJECTORY",
        {"IDEAL TRAPEZOID FUNCTIONS",
         "MOTION-TIME PROFILES (FOR THIS OPTION, YOU MUST ALREADY HAVE A MOTION-TIME TABLE "
         "FILE, docs/trajectories.md)"});
    if (option == 1) {
      profile_table_.reset();
      return;
    }
    const std::string file = prompter_.ask_name({"ENTER THE FILE NAME OF THE MOTION-TIME TABLE"});
    try {
      auto table = std::make_shared<const motion::ProfileTable>(io::read_profile_table_file(file));
      if (table->joint_count() != robot_->joint_count()) {
        throw InputError(file, table->header_line(),
                         fmt::format("joints {} (the robot's joint count)", robot_->joint_count()),
                         fmt::format("joints {}", table->joint_count()));
      }
      profile_table_ = std::move(table);
      prompter_.accept();
      return;
    } catch (const InputError& error) {
      prompter_.reject(error.what());
    }
  }
}

void Session::choose_environment() {
  if (settings_.cell) return take_cell_environment();
  std::vector<std::string> lines{"THE VERTICES OF THE OBSTACLES IN THE WORKING",
                                 "ENVIRONMENT SHOULD BE IN A FILE",
                                 "(FORMAT: docs/input-formats.md, THESIS A.1.1.2)",
                                 "ENTER THE FILE NAME"};
  if (environment_) lines.back() += fmt::format(" (DEFAULT = {})", environment_file_);
  for (;;) {
    std::string file = prompter_.ask(lines);
    if (file.empty() && environment_) file = environment_file_;
    if (file.empty()) {
      prompter_.reject("enter a file name");
      continue;
    }
    try {
      environment_ = io::read_environment_file(file);
      cell_.reset();
      environment_file_ = file;
      out_ << fmt::format("ENVIRONMENT FILE {}: {} OBSTACLES\n", file,
                          environment_->obstacles.size());
      prompter_.accept();
      return;
    } catch (const InputError& error) {
      prompter_.reject(error.what());
    }
  }
}

void Session::choose_tolerance() {
  std::vector<std::string> lines{"ENTER THE TOLERANCE VALUE"};
  if (tolerance_ > 0.0) lines.back() += fmt::format(" (DEFAULT = {})", tolerance_);
  lines.push_back(settings_.cell ? "(THE MODEL'S LENGTH UNIT: METRES FOR A URDF ROBOT, > 0)"
                                 : "(SAME LENGTH UNITS AS THE ROBOT FILE, > 0)");
  const double current = tolerance_;
  tolerance_ = prompter_.ask_until<double>(
      lines, [current](const std::string& answer, std::string& why) -> std::optional<double> {
        if (answer.empty() && current > 0.0) return current;
        std::optional<std::vector<double>> numbers = parse_number_list(answer, why);
        if (!numbers) return std::nullopt;
        if (numbers->size() != 1 || !((*numbers)[0] > 0.0)) {
          why = "enter one number > 0";
          return std::nullopt;
        }
        return (*numbers)[0];
      });
  if (cell_ && cell_->cell.tolerance() != tolerance_) cell_.reset();
  // The thesis prints two decimals (inches); a cell's 0.005 m needs its own digits.
  out_ << (settings_.cell ? fmt::format("THE TOLERANCE VALUE = {}\n", tolerance_)
                          : fmt::format("THE TOLERANCE VALUE = {:.2f}\n", tolerance_));
}

std::shared_ptr<const SessionCell> Session::current_cell() {
  if (!cell_) {
    // The session always verifies in certified mode with its default offset shape.
    certify::SetupRequest request;
    request.tolerance = tolerance_;
    cell_ = std::make_shared<const SessionCell>(*robot_, *environment_,
                                                certify::resolve_setup(request).cell);
  }
  return cell_;
}

void Session::show_configuration() {
  // The thesis displays the robot here with the joints and the end-effector pose at the
  // current configuration; this build prints them.
  Eigen::VectorXd home(robot_->joint_count());
  std::string joints;
  for (int j = 0; j < robot_->joint_count(); ++j) {
    home[j] = robot_->joints[j].home;
    joints += fmt::format(" {:8.2f}", to_file_units(robot_->joints[j], home[j]));
  }
  const Eigen::Isometry3d X_WE = kinematics_.forward(home);
  const Eigen::Vector3d p_W = X_WE.translation();
  out_ << "CURRENT CONFIGURATION (HOME)\n"
       << "JOINT VALUES" << joints << '\n'
       << (settings_.cell  // metres need four decimals (a tenth of a millimetre)
               ? fmt::format("END EFFECTOR POSITION {:9.4f} {:9.4f} {:9.4f}\n", p_W.x(), p_W.y(), p_W.z())
               : fmt::format("END EFFECTOR POSITION {:8.2f} {:8.2f} {:8.2f}\n", p_W.x(), p_W.y(),
                             p_W.z()));
}

void Session::change_view() {
  if (prompter_.ask_yes_no({"WANT TO CHANGE THE VIEW ANGLES ?"}, false)) {
    const auto& a = view_.angles_deg;
    const std::vector<double> angles = prompter_.ask_numbers(
        {"ENTER THE DESIRED VIEW ANGLES IN DEGREE",
         fmt::format("(NOW {:.2f}, {:.2f}, {:.2f}; THESIS DEFAULT -75., 0., 170.)", a[0], a[1],
                     a[2]),
         "ENTER ANGLEX, ANGLEY, ANGLEZ,", "USE A COMMA AFTER EACH DATA INCLUDING THE LAST DATA"},
        3);
    view_.angles_deg = {angles[0], angles[1], angles[2]};
  }
  if (prompter_.ask_yes_no({"WANT TO CHANGE THE SCALE AND SHIFT THE WINDOW ?"}, false)) {
    const std::vector<double> values = prompter_.ask_numbers(
        {"ENTER THE SCALING FACTOR (SCALE)", "AND THE SHIFTING OF WINDOW (SHIFTX, SHIFTY, SHIFTZ)",
         fmt::format("(NOW {:.2f}, {:.2f}, {:.2f}, {:.2f}; DEFAULT 1., 0., 0., 0.)", view_.scale,
                     view_.shift[0], view_.shift[1], view_.shift[2]),
         "ENTER SCALE, SHIFTX, SHIFTY, SHIFTZ,", kCommaLine},
        4, [](const std::vector<double>& v, std::string& why) {
          if (v[0] > 0.0) return true;
          why = "the scale factor must be > 0";
          return false;
        });
    view_.scale = values[0];
    view_.shift = {values[1], values[2], values[3]};
  }
}

void Session::perform_motion() {
  PathProgram program;
  std::string label;
  report::InputFileDigest path_digest;
  std::string typed_text;
  choose_path(program, label, path_digest, typed_text);
  const std::string results_file = choose_results_file();

  out_ << "PROCESSING\n" << std::flush;
  certify::SetupRequest request;
  request.tolerance = tolerance_;
  request.motion.table = profile_table_;
  if (settings_.cell) {
    // What controllers do, as `grpvss verify --cell`; the cell's CP speed when it gives one.
    request.motion.timing = motion::PtpTiming::kSynchronized;
    request.motion.cp_speed = settings_.cell->cp_speed.value_or(request.motion.cp_speed);
  }
  request.path_label = label;
  const certify::RunSettings settings = certify::resolve_setup(request).run;
  try {
    const std::shared_ptr<const SessionCell> cell = current_cell();
    certify::VerificationRun run = certify::verify(cell->cell, program, kinematics_, settings);
    ++motions_processed_;
    out_ << (report::thesis_reports_collision(run.result) ? "COLLISIONS DETECTED IN THIS PATH\n"
                                                          : "NO COLLISION DETECTED IN THIS PATH\n");
    out_ << verdict_summary(run.result, ModelNames{&cell->robot, &cell->environment});
    last_digests_ = {{robot_file_, report::sha256_hex_of_file(robot_file_)},
                     {environment_file_, report::sha256_hex_of_file(environment_file_)},
                     path_digest,
                     /*length_unit=*/{}};
    if (!results_file.empty()) {
      report::write_file_atomically(results_file,
                                    report::render_thesis_output(
                                        run.result, report::joint_types_of(*robot_),
                                        report::ThesisNames::of(*robot_, *environment_)),
                                    false);
      out_ << fmt::format("THE RESULTS ARE STORED IN {}\n", results_file);
      if (!typed_text.empty()) {
        // The typed path, so `grpvss verify --path` can repeat this motion.
        const std::string typed_file = results_file + ".path.txt";
        if (!path_exists(typed_file)) {
          report::write_file_atomically(typed_file, typed_text, false);
          out_ << fmt::format("THE TYPED PATH IS STORED IN {}\n", typed_file);
        }
      }
    }
    last_motion_ = ProcessedMotion{std::move(run.result), cell, results_file, ""};
    last_animation_base_ =
        !results_file.empty()
            ? results_file
            : (std::filesystem::path(settings_.animation_dir) /
               fmt::format("grpvss-motion-{}", motions_processed_))
                  .string();
  } catch (const InputError& error) {
    // E.g. the output directory vanished: the session goes on at the main menu.
    out_ << "ERROR: " << error.what() << '\n';
    return;
  }
  animate();
}

bool Session::choose_path(PathProgram& program, std::string& label,
                          report::InputFileDigest& digest, std::string& typed_text) {
  const int way = prompter_.ask_option("ENTER THE WAY YOU WANT TO INPUT THE PATH",
                                       {"FROM DATA FILE", "INTERACTIVELY INPUT ON THE SCREEN"});
  if (way == 2) {
    const std::vector<TypedSegment> segments = type_path();
    typed_text = path_file_text(segments);
    program = typed_program(segments, *robot_);
    if (settings_.cell) {
      cell::convert_path_lengths(program, *robot_, settings_.cell->model_units_per_cell_unit);
    }
    label = "SCREEN";
    digest = {"(typed at the terminal)", report::sha256_hex(typed_text)};
    return true;
  }
  for (;;) {
    const std::string file =
        prompter_.ask_name({"THE SPECIFICATIONS OF ALL SEGMENTS OF THE PATH SHOULD",
                            "BE STORED IN A FILE (FORMAT: docs/input-formats.md, THESIS A.1.3)",
                            "ENTER THE FILE NAME"});
    try {
      program = io::read_path_file(file, *robot_);
      if (settings_.cell) {
        cell::convert_path_lengths(program, *robot_, settings_.cell->model_units_per_cell_unit);
      }
      digest = {file, report::sha256_hex_of_file(file)};
      label = base_name(file);
      prompter_.accept();
      return true;
    } catch (const InputError& error) {
      prompter_.reject(error.what());
    }
  }
}

std::vector<TypedSegment> Session::type_path() {
  std::vector<TypedSegment> segments;
  for (;;) {
    TypedSegment segment = type_segment(segments);
    if (!prompter_.ask_yes_no({"ARE THE INPUT DATA CORRECT ?"}, true)) continue;
    segments.push_back(std::move(segment));
    if (!prompter_.ask_yes_no({"ANOTHER MOTION SEGMENT IN THIS PATH ?"}, false)) return segments;
  }
}

TypedSegment Session::type_segment(const std::vector<TypedSegment>& earlier) {
  TypedSegment segment;
  segment.kind = prompter_.ask_option("WHICH TYPE OF OPERATION FOR THIS MOTION SEGMENT ?",
                                      {"PTP OPERATION SPECIFIED IN JOINT COORD. SYSTEM",
                                       "PTP OPERATION SPECIFIED IN WORLD COORD. SYSTEM",
                                       "CP STRAIGHT-LINE OPERATION"});
  if (segment.kind == 1) {
    type_joint_segment(segment);
    return segment;
  }
  while (!type_world_target(segment, earlier)) {
  }
  if (segment.kind == 2) type_velocities(segment);
  return segment;
}

void Session::type_joint_segment(TypedSegment& segment) {
  for (int j = 0; j < robot_->joint_count(); ++j) {
    const Joint& joint = robot_->joints[j];
    const std::vector<double> values = prompter_.ask_numbers(
        {fmt::format("ENTER THE JOINT VALUE OF JOINT {} AT ENDING POINT", j + 1),
         fmt::format("MIN VALUE = {:.2f} MAX VALUE = {:.2f} HOME POSITION = {:.2f}",
                     to_file_units(joint, joint.minimum), to_file_units(joint, joint.maximum),
                     to_file_units(joint, joint.home)),
         "AND THE DESIRED JOINT VELOCITY", kCommaLine},
        2, [&joint](const std::vector<double>& v, std::string& why) {
          const double q = to_library_units(joint, v[0]);
          if (q < joint.minimum - kLimitSlack || q > joint.maximum + kLimitSlack) {
            why = fmt::format("the joint value {} is out of range (MIN {:.2f}, MAX {:.2f}); "
                              "enter the values again",
                              v[0], to_file_units(joint, joint.minimum),
                              to_file_units(joint, joint.maximum));
            return false;
          }
          if (!(v[1] > 0.0)) {
            why = "the desired joint velocity must be > 0; enter the values again";
            return false;
          }
          return true;
        });
    segment.joint_targets.push_back(values[0]);
    segment.velocities.push_back(values[1]);
  }
}

bool Session::type_world_target(TypedSegment& segment, const std::vector<TypedSegment>& earlier) {
  const std::vector<double> position = prompter_.ask_numbers(
      {"ENTER THE FINAL POSITION (X, Y, Z) OF THE END EFFECTOR", kCommaLine}, 3);
  const std::vector<double> rotation = prompter_.ask_numbers(
      {"ENTER THE AXIS (KX,KY,KZ) ABOUT WHICH THE", "ORIENTATION OF END EFFECTOR CHANGES",
       "AND THE CORRESPONDING CHANGING ANGLE (KTHETA) IN DEGREES", kCommaLine},
      4, [](const std::vector<double>& v, std::string& why) {
        if (v[3] != 0.0 && v[0] == 0.0 && v[1] == 0.0 && v[2] == 0.0) {
          why = "a nonzero angle needs a nonzero axis";
          return false;
        }
        return true;
      });
  segment.pose = {position[0], position[1], position[2], rotation[0],
                  rotation[1], rotation[2], rotation[3]};
  // The reachability of the end pose depends on the segment's start (the previous segments'
  // end): plan the path so far with this segment appended. Velocities do not change where
  // the segment ends, so placeholders stand in for the ones asked next.
  std::vector<TypedSegment> candidate = earlier;
  candidate.push_back(segment);
  if (segment.kind == 2) candidate.back().velocities.assign(robot_->joint_count(), 1.0);
  const int number = static_cast<int>(candidate.size());
  try {
    motion::MotionModel options;
    options.table = profile_table_;
    const motion::Trajectory plan =
        motion::Trajectory::plan(*robot_, typed_program(candidate, *robot_), kinematics_, options);
    for (const motion::ThesisError& error : plan.errors()) {
      if (error.segment != number) continue;
      if (error.code == 3) {
        prompter_.reject("THE SPECIFIED ENDING ROBOT STATE IS OUT OF THE WORKSPACE; enter the "
                         "specifications of this operation again");
        return false;
      }
      if (error.code == 4) {
        prompter_.reject("ERROR 1: " + motion::thesis_error_text(1, number) +
                         " Enter the specifications of this operation again");
        return false;
      }
    }
  } catch (const InputError& error) {
    prompter_.reject(error.what());
    return false;
  }
  return true;
}

void Session::type_velocities(TypedSegment& segment) {
  segment.velocities.clear();
  for (int j = 0; j < robot_->joint_count(); ++j) {
    const bool revolute = robot_->joints[j].type == JointType::kRevolute;
    const std::vector<double> velocity = prompter_.ask_numbers(
        {fmt::format("ENTER THE DESIRED JOINT VELOCITY OF JOINT {}", j + 1),
         revolute ? "FOR REVOLUTE JOINTS, THE UNIT IS DEGREE/SEC"
                  : "FOR PRISMATIC JOINTS, THE UNIT IS LENGTH UNITS/SEC",
         kCommaLine},
        1, [](const std::vector<double>& v, std::string& why) {
          if (v[0] > 0.0) return true;
          why = "the desired joint velocity must be > 0";
          return false;
        });
    segment.velocities.push_back(velocity[0]);
  }
}

std::string Session::choose_results_file() {
  if (!prompter_.ask_yes_no({"DO YOU WISH TO STORE THE RESULTS OF THIS PATH", "IN A FILE ?"},
                            true)) {
    return {};
  }
  return prompter_.ask_until<std::string>(
      {"THE RESULTS WILL BE STORED IN A FILE NAMED", "ENTER THE FILE NAME",
       "MAKE SURE THE FILE YOU SPECIFIED DOES NOT EXIST", "IN THE DISK."},
      [](const std::string& answer, std::string& why) -> std::optional<std::string> {
        if (answer.empty()) {
          why = "enter a file name";
          return std::nullopt;
        }
        if (path_exists(answer)) {
          why = fmt::format("the file {} already exists; enter another name", answer);
          return std::nullopt;
        }
        const std::filesystem::path parent = std::filesystem::path(answer).parent_path();
        std::error_code error;
        if (!parent.empty() && !std::filesystem::is_directory(parent, error)) {
          why = fmt::format("the folder {} does not exist", parent.string());
          return std::nullopt;
        }
        return answer;
      });
}

void Session::animate() {
  change_view();
  const std::string image = prompter_.ask({"WHAT TYPE OF MOTION IMAGE DO YOU LIKE?",
                                           "CONTINUOUS MOTION OR STEPPING MOTION",
                                           "IF STEPPING, ENTER 1 (THE ANIMATION THEN ADVANCES "
                                           "ONE STEP PER KEY)",
                                           "IF CONTINUOUS, ENTER ANY CHARACTER OTHER THAN 1"});
  view_.stepping = image == "1" || image == "1," || image == "1.";
  prompter_.accept();
  const AnimationRequest request{last_motion_->result, last_motion_->cell->cell, last_digests_,
                                 view_};
  try {
    const AnimationFiles files =
        write_animation(request, last_animation_base_, settings_.render_html);
    last_motion_->animation_file = files.html.empty() ? files.json : files.html;
    if (!files.html.empty()) {
      out_ << fmt::format("THE ANIMATION OF THIS PATH IS IN {} (OPEN IT IN A WEB BROWSER)\n",
                          files.html);
    } else if (!files.html_error.empty()) {
      out_ << fmt::format("NO HTML ANIMATION: {}\n", files.html_error);
    }
    if (!files.svg.empty()) {
      out_ << fmt::format("THE PICTURE OF STEP {} IN THIS VIEW IS IN {}\n", files.svg_step,
                          files.svg);
    }
    out_ << fmt::format("THE REPORT OF THIS PATH (WITH THE SCENE) IS IN {}\n", files.json);
  } catch (const InputError& error) {
    out_ << "THE ANIMATION COULD NOT BE WRITTEN: " << error.what() << '\n';
  }
}

int Session::main_menu() {
  return prompter_.ask_option("ENTER ONE OF THE FOLLOWING OPTION NUMBERS",
                              {"SIMULATE ANOTHER ROBOT", "CHANGE THE ENVIRONMENT",
                               "CHANGE THE TOLERANCE VALUE", "PERFORM ANOTHER MOTION",
                               "SEE THE ANIMATION AGAIN", "EXIT"},
                              "ENTER ONE OF THE OPTION NUMBERS");
}

}  // namespace grpvss::app::interactive
