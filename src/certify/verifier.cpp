#include "grpvss/certify/verifier.hpp"

#include <memory>
#include <optional>
#include <stdexcept>
#include <utility>

#include "certificate_recorder.hpp"
#include "grpvss/motion/joint_trajectory_source.hpp"
#include "run_recorder.hpp"
#include "segment_path.hpp"
#include "step_march.hpp"

namespace grpvss::certify {
namespace {

// The simulation loop of thesis Figures 10-11: plans the trajectory, evaluates the start, lets
// the march walk every segment, and records what it finds (steps, errors; in certified mode the
// certificate).
class PathVerifier : public MarchListener {
 public:
  PathVerifier(const RobotCell& cell, const PathProgram& program,
               const motion::KinematicsAccess& kinematics, const RunSettings& settings,
               const RunHooks& hooks, const motion::Trajectory* given_trajectory = nullptr)
      : cell_(cell),
        given_trajectory_(given_trajectory),
        program_(program),
        kinematics_(kinematics),
        settings_(settings),
        hooks_(hooks),
        recorder_(cell, settings, hooks) {
    if (settings.mode == ResolutionMode::kCertified) {
      certificate_.emplace(cell, settings, hooks);
      march_ = std::make_unique<CertifiedMarch>(cell, settings_, *this);
    } else {
      march_ = std::make_unique<ThesisMarch>(cell, settings_, *this);
    }
  }

  VerificationRun run();

  void on_accepted_step(const AcceptedStep& step) override {
    recorder_.record_step(step);
    if (certificate_) certificate_->record_step(step, recorder_.last_step_index());
  }
  void on_error(int code, int segment, std::string message) override {
    recorder_.add_error(code, segment, std::move(message));
  }
  void on_uncertified_step() override { recorder_.note_uncertified(); }
  void on_progress(int segment, double segment_fraction) override {
    if (!hooks_.progress) return;
    hooks_.progress((segment - 1 + segment_fraction) /
                    static_cast<double>(program_.segments.size()));
  }

 private:
  /// Marches one simulated segment; false when the path stops in it.
  bool verify_segment(const motion::SegmentTrajectory& segment);
  /// Segments the motion stage refused (thesis errors 3-6) stop the path there.
  void record_refused_segments(const motion::Trajectory& trajectory, bool path_went_on);

  const RobotCell& cell_;
  const motion::Trajectory* given_trajectory_;  ///< a joint trajectory's; else planned
  const PathProgram& program_;
  const motion::KinematicsAccess& kinematics_;
  const RunSettings& settings_;
  const RunHooks& hooks_;
  RunRecorder recorder_;
  std::optional<CertificateRecorder> certificate_;  ///< certified mode only
  std::unique_ptr<StepMarch> march_;
};

bool PathVerifier::verify_segment(const motion::SegmentTrajectory& segment) {
  SegmentRecord record;
  record.number = segment.number;
  record.input = program_.segments[segment.number - 1];
  record.start_q = segment.q_start;
  record.end_q = segment.q_end;
  record.cycle_time = segment.duration;
  record.trajectory_piece = segment.kind == motion::SegmentKind::kTrajectoryPiece;
  const SegmentPath path(cell_.robot(), kinematics_, segment);
  if (certificate_) {
    certificate_->begin_segment(segment, path.parameter_end(), march_->current(),
                                recorder_.last_step_index());
  }
  const int first_step = recorder_.last_step_index() + 1;
  const bool keep_going = march_->march_segment(path, segment.number);
  // Step indices of this segment (0, 0 when it produced none).
  record.last_step = recorder_.last_step_index();
  record.first_step = record.last_step >= first_step ? first_step : 0;
  if (record.first_step == 0) record.last_step = 0;
  record.simulated = keep_going;
  recorder_.add_segment(std::move(record));
  if (certificate_) certificate_->end_segment();
  return keep_going;
}

void PathVerifier::record_refused_segments(const motion::Trajectory& trajectory,
                                           bool path_went_on) {
  for (const motion::ThesisError& error : trajectory.errors()) {
    if (path_went_on) recorder_.add_error(error.code, error.segment, error.message);
    if (error.segment > 0 && error.segment <= static_cast<int>(program_.segments.size())) {
      SegmentRecord refused;
      refused.number = error.segment;
      refused.input = program_.segments[error.segment - 1];
      refused.start_q = recorder_.last_q();
      refused.simulated = false;
      recorder_.add_segment(std::move(refused));
    }
  }
}

VerificationRun PathVerifier::run() {
  std::optional<motion::Trajectory> planned;
  if (given_trajectory_ == nullptr) {
    planned = motion::Trajectory::plan(cell_.robot(), program_, kinematics_, settings_.motion);
  }
  const motion::Trajectory& trajectory = planned ? *planned : *given_trajectory_;
  // Step 0: the start configuration (home), evaluated like every other step; it is never
  // printed in the thesis file, whose steps start at 1.
  recorder_.record_start(march_->start(trajectory.home()));
  bool keep_going = true;
  for (const motion::SegmentTrajectory& segment : trajectory.segments()) {
    if (!keep_going) break;
    keep_going = verify_segment(segment);
  }
  record_refused_segments(trajectory, keep_going);
  VerificationRun run;
  run.result = recorder_.finish();
  if (certificate_) run.certificate = certificate_->finish(run.result);
  return run;
}

// The records' input of each piece of a joint trajectory: a joint target (the next waypoint,
// no speeds), named by the waypoint's line.
PathProgram pieces_as_program(const motion::JointTrajectoryMotion& motion) {
  PathProgram program;
  const JointTrajectory& trajectory = motion.trajectory();
  for (int k = 1; k < trajectory.waypoint_count(); ++k) {
    PathSegment piece;
    piece.spec = PtpJointSegment{trajectory.positions[static_cast<std::size_t>(k)], {}};
    piece.source_line = k < static_cast<int>(trajectory.source_lines.size())
                            ? trajectory.source_lines[static_cast<std::size_t>(k)]
                            : 0;
    program.segments.push_back(std::move(piece));
  }
  return program;
}

}  // namespace

VerificationRun verify(const RobotCell& cell, const motion::Trajectory& trajectory,
                       const motion::KinematicsAccess& kinematics, const RunSettings& settings,
                       const RunHooks& hooks) {
  const motion::JointTrajectoryMotion* motion = trajectory.joint_motion();
  if (motion == nullptr) throw std::invalid_argument("verify: not a joint trajectory");
  if (settings.mode != ResolutionMode::kCertified) {
    throw std::invalid_argument("verify: a joint trajectory is verified in certified mode only");
  }
  RunSettings trajectory_settings = settings;
  trajectory_settings.motion_model = motion::describe_motion_model(*motion, settings.path_label);
  trajectory_settings.trajectory_interpolation = motion::to_string(motion->interpolation());
  const PathProgram program = pieces_as_program(*motion);
  PathVerifier verifier(cell, program, kinematics, trajectory_settings, hooks, &trajectory);
  return verifier.run();
}

VerificationRun verify(const RobotCell& cell, const PathProgram& program,
                       const motion::KinematicsAccess& kinematics, const RunSettings& settings,
                       const RunHooks& hooks) {
  PathVerifier verifier(cell, program, kinematics, settings, hooks);
  return verifier.run();
}

VerificationRun verify(const RobotModel& robot, const Environment& environment,
                       const PathProgram& program, const motion::KinematicsAccess& kinematics,
                       const VerificationSetup& setup, const RunHooks& hooks) {
  const RobotCell cell(robot, environment, setup.cell);
  return verify(cell, program, kinematics, setup.run, hooks);
}

}  // namespace grpvss::certify
