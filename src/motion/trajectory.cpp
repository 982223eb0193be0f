#include "grpvss/motion/trajectory.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include <fmt/core.h>

namespace grpvss::motion {

const char* to_string(SegmentKind kind) {
  switch (kind) {
    case SegmentKind::kPtpJoint: return "ptp-joint";
    case SegmentKind::kPtpWorld: return "ptp-world";
    case SegmentKind::kCpLine: return "cp-line";
    case SegmentKind::kTrajectoryPiece: return "trajectory-piece";
  }
  return "?";
}

std::optional<SegmentKind> segment_kind_from_string(std::string_view text) {
  for (SegmentKind kind : {SegmentKind::kPtpJoint, SegmentKind::kPtpWorld, SegmentKind::kCpLine,
                           SegmentKind::kTrajectoryPiece}) {
    if (text == to_string(kind)) return kind;
  }
  return std::nullopt;
}
namespace {

Eigen::VectorXd home_of(const RobotModel& robot) {
  Eigen::VectorXd q(robot.joint_count());
  for (int j = 0; j < robot.joint_count(); ++j) q[j] = robot.joints[j].home;
  return q;
}

std::string joint_limit_detail(const RobotModel& robot, const Eigen::VectorXd& q, int joint) {
  const Joint& limits = robot.joints[joint];
  return fmt::format("joint {} target {} outside [{}, {}] (library units)", joint + 1, q[joint],
                     limits.minimum, limits.maximum);
}

struct Planner {
  const RobotModel& robot;
  const KinematicsAccess& kinematics;
  const MotionModel& options;

  // Joint-space PTP (IND 1, and IND 2 after IK): error 3 when the target is outside limits.
  std::optional<ThesisError> ptp(SegmentTrajectory& piece, const Eigen::VectorXd& target,
                                 const Eigen::VectorXd& velocity) const {
    const int outside = first_joint_outside_limits(robot, target, 0.0);
    if (outside >= 0) return make_thesis_error(3, piece.number, joint_limit_detail(robot, target, outside));
    piece.ptp = PtpMotion::plan(robot, piece.q_start, target, velocity, options.timing, options.table);
    piece.q_end = target;
    piece.duration = piece.ptp->duration();
    return std::nullopt;
  }

  std::optional<ThesisError> ptp_world(SegmentTrajectory& piece, const PtpWorldSegment& spec) const {
    const Eigen::Isometry3d X_WE_target =
        world_target_pose(kinematics.forward(piece.q_start), spec.target);
    const auto q = solve_within_limits(robot, kinematics, X_WE_target, piece.q_start);
    if (!q) {
      const Eigen::Vector3d& p = spec.target.position_W;
      return make_thesis_error(3, piece.number,
                               fmt::format("no IK solution within the joint limits at "
                                           "({:.2f}, {:.2f}, {:.2f})",
                                           p.x(), p.y(), p.z()));
    }
    return ptp(piece, *q, spec.velocity);
  }

  std::optional<ThesisError> cp(SegmentTrajectory& piece, const CpLineSegment& spec) const {
    piece.cp.emplace(kinematics.forward(piece.q_start), spec.target);
    CpSampling sampling = sample_cp_line(robot, kinematics, *piece.cp, piece.q_start,
                                         options.cp_spacing, piece.number);
    if (sampling.error) return sampling.error;
    piece.cp_samples = std::move(sampling.samples);
    piece.q_end = piece.cp_samples.back().q;
    piece.cp_speed = spec.speed.value_or(options.cp_speed);  // a program's line: its own speed
    piece.duration = piece.cp->length() / piece.cp_speed;
    return std::nullopt;
  }
};

}  // namespace

Trajectory Trajectory::plan(const RobotModel& robot, const PathProgram& program,
                            const KinematicsAccess& kinematics, const MotionModel& options) {
  if (!(options.cp_speed > 0.0) || !std::isfinite(options.cp_speed))
    throw std::invalid_argument("Trajectory::plan: cp_speed must be positive and finite");
  Trajectory trajectory;
  trajectory.robot_ = &robot;
  trajectory.kinematics_ = kinematics;
  trajectory.options_ = options;
  trajectory.home_ = options.start ? *options.start : home_of(robot);
  if (trajectory.home_.size() != robot.joint_count()) {
    throw std::invalid_argument("Trajectory::plan: the start has another joint count than the robot");
  }
  const Planner planner{robot, kinematics, options};
  Eigen::VectorXd q = trajectory.home_;
  double time = 0.0;
  for (std::size_t i = 0; i < program.segments.size(); ++i) {
    SegmentTrajectory piece;
    piece.number = static_cast<int>(i) + 1;
    piece.q_start = q;
    piece.start_time = time;
    std::optional<ThesisError> error;
    const SegmentSpec& spec = program.segments[i].spec;
    if (const auto* joint = std::get_if<PtpJointSegment>(&spec)) {
      piece.kind = SegmentKind::kPtpJoint;
      error = planner.ptp(piece, joint->target, joint->velocity);
    } else if (const auto* world = std::get_if<PtpWorldSegment>(&spec)) {
      piece.kind = SegmentKind::kPtpWorld;
      error = planner.ptp_world(piece, *world);
    } else {
      piece.kind = SegmentKind::kCpLine;
      error = planner.cp(piece, std::get<CpLineSegment>(spec));
    }
    if (error) {  // the thesis terminates the simulation at this segment
      trajectory.errors_.push_back(std::move(*error));
      break;
    }
    q = piece.q_end;
    time = piece.end_time();
    trajectory.segments_.push_back(std::move(piece));
  }
  return trajectory;
}

namespace {

// Last segment starting at or before t (a zero-duration segment is passed through).
std::vector<SegmentTrajectory>::const_iterator segment_containing(
    const std::vector<SegmentTrajectory>& segments, double t) {
  const auto after = std::upper_bound(
      segments.begin(), segments.end(), t,
      [](double time, const SegmentTrajectory& s) { return time < s.start_time; });
  return after - 1;
}

}  // namespace

int Trajectory::segment_at(double t) const {
  if (segments_.empty()) return 0;
  return segment_containing(segments_, std::clamp(t, segments_.front().start_time, duration()))->number;
}

std::optional<Eigen::VectorXd> Trajectory::joints_at(double t) const {
  if (segments_.empty()) return home_;
  t = std::clamp(t, segments_.front().start_time, duration());
  const SegmentTrajectory& piece = *segment_containing(segments_, t);
  const double local = t - piece.start_time;
  if (piece.joint_motion) {
    const JointTrajectoryMotion& motion = *piece.joint_motion;
    return motion.q_at(std::clamp(t, motion.start_time(), motion.end_time()));
  }
  if (piece.ptp) return piece.ptp->joints_at(local);
  const double l = std::min(piece.cp_speed * local, piece.cp->length());
  const auto sample = std::upper_bound(piece.cp_samples.begin(), piece.cp_samples.end(), l,
                                       [](double value, const CpSample& s) { return value < s.l; });
  const CpSample& before = *(sample - 1);
  if (before.l == l) return before.q;
  return solve_within_limits(*robot_, kinematics_, piece.cp->pose_at(l), before.q);
}

Trajectory Trajectory::from_joint_motion(const RobotModel& robot,
                                         std::shared_ptr<const JointTrajectoryMotion> motion) {
  if (motion->joint_count() != robot.joint_count()) {
    throw std::invalid_argument("Trajectory::from_joint_motion: joint count differs from the robot's");
  }
  Trajectory trajectory;
  trajectory.robot_ = &robot;
  trajectory.home_ = motion->q_at(motion->start_time());
  const std::vector<double>& times = motion->piece_breaks();
  for (int k = 0; k < motion->piece_count(); ++k) {
    SegmentTrajectory piece;
    piece.number = k + 1;
    piece.kind = SegmentKind::kTrajectoryPiece;
    piece.q_start = motion->q_at(times[k]);
    piece.q_end = motion->q_at(times[k + 1]);
    piece.start_time = times[k];
    piece.duration = times[k + 1] - times[k];
    piece.joint_motion = motion;
    trajectory.segments_.push_back(std::move(piece));
  }
  trajectory.joint_motion_ = std::move(motion);
  return trajectory;
}

}  // namespace grpvss::motion
