#pragma once
/// \file
/// \brief The joint trajectory of a whole path program: one timed piece per segment, from
/// the robot's home, stopped at the first thesis error (docs/trajectories.md).

#include <memory>
#include <optional>
#include <string_view>
#include <vector>

#include <Eigen/Core>

#include "grpvss/model/path_program.hpp"
#include "grpvss/model/robot_model.hpp"
#include "grpvss/motion/cp_line.hpp"
#include "grpvss/motion/joint_trajectory_motion.hpp"
#include "grpvss/motion/kinematics_access.hpp"
#include "grpvss/motion/motion_model.hpp"
#include "grpvss/motion/profile_table.hpp"
#include "grpvss/motion/ptp_motion.hpp"
#include "grpvss/motion/thesis_error.hpp"

namespace grpvss::motion {

/// The thesis's IND (1-3); 4: one piece of a planner's joint trajectory between two waypoints
/// (docs/trajectories.md#verifying-a-trajectory).
enum class SegmentKind { kPtpJoint = 1, kPtpWorld = 2, kCpLine = 3, kTrajectoryPiece = 4 };

/// "ptp-joint", "ptp-world", "cp-line", "trajectory-piece" (the reports' and the certificate's
/// spelling).
const char* to_string(SegmentKind kind);
/// The kind spelled `text`, or nullopt.
std::optional<SegmentKind> segment_kind_from_string(std::string_view text);

/// \brief One simulated segment.
struct SegmentTrajectory {
  int number = 0;  ///< 1-based segment number
  SegmentKind kind = SegmentKind::kPtpJoint;
  Eigen::VectorXd q_start, q_end;
  double start_time = 0.0;  ///< path time at which the segment starts
  double duration = 0.0;    ///< the segment's cycle time
  std::optional<PtpMotion> ptp;  ///< PTP segments
  std::optional<CpLine> cp;      ///< CP segments
  std::vector<CpSample> cp_samples;  ///< CP segments: l = 0 .. L
  double cp_speed = 0.0;             ///< CP segments: the TCP speed the line is timed by
  /// Trajectory pieces: the whole joint trajectory; this segment is its piece number - 1, from
  /// waypoint time start_time to the next waypoint's time (both exact doubles of the file).
  std::shared_ptr<const JointTrajectoryMotion> joint_motion;
  double end_time() const { return start_time + duration; }
};

/// \brief A planned path. Keeps a pointer to the RobotModel given to plan(): the model must
/// outlive the trajectory.
class Trajectory {
 public:
  /// Plans every segment from `options.start`, else the robot's home. Thesis errors 3-5 stop the plan at the
  /// failing segment: `segments()` holds the earlier ones, `errors()` the error.
  /// \throws grpvss::InputError if the table's joint count differs from the robot's.
  static Trajectory plan(const RobotModel& robot, const PathProgram& program,
                         const KinematicsAccess& kinematics, const MotionModel& options);

  /// A planner's joint trajectory (joints in the robot's order, limits already checked) as a
  /// path: one kTrajectoryPiece segment per piece, home = the first waypoint, path time = the
  /// trajectory's time. No thesis errors. \throws std::invalid_argument if the joint count
  /// differs from the robot's.
  static Trajectory from_joint_motion(const RobotModel& robot,
                                      std::shared_ptr<const JointTrajectoryMotion> motion);

  const std::vector<SegmentTrajectory>& segments() const { return segments_; }
  const std::vector<ThesisError>& errors() const { return errors_; }
  const Eigen::VectorXd& home() const { return home_; }
  /// The motion model the trajectory was planned with.
  const MotionModel& motion_model() const { return options_; }
  /// The joint trajectory from_joint_motion() was given; null for a planned path.
  const JointTrajectoryMotion* joint_motion() const { return joint_motion_.get(); }
  /// Total cycle time of the simulated segments.
  double duration() const { return segments_.empty() ? 0.0 : segments_.back().end_time(); }

  /// Joints at path time t (clamped to [0, duration()]). On a CP segment: IK of the line's
  /// pose at l = cp_speed (t - start) nearest the joints of the sample just before l;
  /// std::nullopt if that point has no IK solution within the limits (an unreachable point
  /// the samples missed).
  std::optional<Eigen::VectorXd> joints_at(double t) const;
  /// 1-based number of the segment that path time t (clamped) falls in; 0 when no segment was
  /// simulated. At a boundary the later segment is reported.
  int segment_at(double t) const;

 private:
  const RobotModel* robot_ = nullptr;
  KinematicsAccess kinematics_;
  MotionModel options_;
  Eigen::VectorXd home_;
  std::vector<SegmentTrajectory> segments_;
  std::vector<ThesisError> errors_;
  std::shared_ptr<const JointTrajectoryMotion> joint_motion_;  ///< from_joint_motion() only
};

}  // namespace grpvss::motion
