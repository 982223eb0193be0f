#pragma once
/// \file
/// \brief The interactive session of thesis Appendix A.2.2 ("Running Sample"): which robot,
/// how PTP trajectories are generated, the environment, the tolerance, the view, the path
/// (from a file or typed segment by segment), storing the results, processing (a certified
/// verification), the animation, and the main menu 1-6. Reads answers from any std::istream
/// and writes to any std::ostream, so a test drives it with a scripted transcript.
///
/// Ending: option 6 or the end of input ends the session (exit code 0, after a goodbye
/// line); `max_invalid_answers` invalid answers in a row end it with exit code 2.

#include <istream>
#include <memory>
#include <optional>
#include <ostream>
#include <string>
#include <vector>

#include "grpvss/cell/model_inputs.hpp"
#include "grpvss/certify/robot_cell.hpp"
#include "grpvss/evidence/verification_result.hpp"
#include "grpvss/kinematics/inverse_kinematics.hpp"
#include "grpvss/model/environment.hpp"
#include "grpvss/model/path_program.hpp"
#include "grpvss/model/robot_model.hpp"
#include "grpvss/motion/kinematics_access.hpp"
#include "grpvss/motion/profile_table.hpp"
#include "grpvss/report/input_digests.hpp"
#include "interactive/animation_output.hpp"
#include "interactive/prompter.hpp"
#include "interactive/typed_path.hpp"
#include "interactive/view_settings.hpp"

namespace grpvss::app::interactive {

struct SessionSettings {
  /// Folder holding ibm7545/robot.txt, the built-in IBM 7545 robot (option 1).
  std::string data_dir;
  /// Where animation documents go when the results are not stored under a name.
  std::string animation_dir = ".";
  int max_invalid_answers = 20;
  /// Repeat each answer after its prompt (piped input is not echoed by a terminal).
  bool echo_answers = false;
  /// The viewer's HTML page writer; without it only the JSON report and the SVG are written.
  HtmlRenderer render_html;
  /// `--cell`: the cell's robot and obstacles replace the robot and environment questions, its
  /// tolerance is the default, PTP timing is synchronized, path lengths are in its unit.
  std::optional<cell::ModelInputs> cell;
  std::string cell_file;
};

enum class SessionEnd {
  kExitChosen,             ///< main menu option 6
  kEndOfInput,             ///< the input ended while a question waited
  kTooManyInvalidAnswers,  ///< SessionSettings::max_invalid_answers in a row
};

/// 0 for kExitChosen and kEndOfInput, 2 for kTooManyInvalidAnswers.
int exit_code(SessionEnd end);

/// The cell motions are verified in, with the robot and environment it refers to (a later
/// choice of robot or environment builds a new one; a processed motion keeps its own).
struct SessionCell {
  SessionCell(RobotModel robot_model, Environment cell_environment,
              const certify::CellSettings& settings)
      : robot(std::move(robot_model)),
        environment(std::move(cell_environment)),
        cell(robot, environment, settings) {}
  RobotModel robot;
  Environment environment;
  certify::RobotCell cell;
};

/// What the last processed motion produced.
struct ProcessedMotion {
  certify::VerificationResult result;
  std::shared_ptr<const SessionCell> cell;  ///< the cell it was verified in
  std::string results_file;    ///< the thesis output file, empty when not stored
  std::string animation_file;  ///< the HTML animation, else the JSON report, last written
};

class Session {
 public:
  Session(std::istream& in, std::ostream& out, SessionSettings settings);

  /// Runs the whole session. \throws std::exception only for internal errors (exit code 3).
  SessionEnd run();

  const ViewSettings& view() const { return view_; }
  int motions_processed() const { return motions_processed_; }

 private:
  /// The stages in session order; the main menu re-enters the sequence at one of them.
  enum class Stage { kRobot, kTrajectoryWay, kEnvironment, kTolerance, kView, kMotion };

  void run_from(Stage stage);
  void choose_robot();
  void take_cell_robot();
  void take_cell_environment();
  void choose_trajectory_way();
  void choose_environment();
  void choose_tolerance();
  void show_configuration();
  void change_view();
  void perform_motion();
  /// The cell for the current robot, environment and tolerance (built once for all of them).
  std::shared_ptr<const SessionCell> current_cell();
  bool choose_path(PathProgram& program, std::string& label, report::InputFileDigest& digest,
                   std::string& typed_text);
  std::vector<TypedSegment> type_path();
  TypedSegment type_segment(const std::vector<TypedSegment>& earlier);
  void type_joint_segment(TypedSegment& segment);
  bool type_world_target(TypedSegment& segment, const std::vector<TypedSegment>& earlier);
  void type_velocities(TypedSegment& segment);
  std::string choose_results_file();
  void animate();
  int main_menu();

  Prompter prompter_;
  std::ostream& out_;
  SessionSettings settings_;

  std::optional<RobotModel> robot_;
  std::string robot_file_;
  std::shared_ptr<const kinematics::InverseKinematics> ik_;
  motion::KinematicsAccess kinematics_;
  std::shared_ptr<const motion::ProfileTable> profile_table_;
  std::optional<Environment> environment_;
  std::string environment_file_;
  double tolerance_ = 0.0;
  std::shared_ptr<const SessionCell> cell_;  ///< reset whenever one of its inputs changes
  ViewSettings view_;

  std::optional<ProcessedMotion> last_motion_;
  report::InputDigests last_digests_;
  std::string last_animation_base_;
  int motions_processed_ = 0;
};

}  // namespace grpvss::app::interactive
