#pragma once
/// \file
/// \brief Straight-line CP motion (thesis Section 4.2.2.2 A, Eq. 4-17, 4-18) and the world
/// target of a PTP(WCS) segment.

#include <optional>
#include <variant>
#include <vector>

#include <Eigen/Core>
#include <Eigen/Geometry>

#include "grpvss/model/path_program.hpp"
#include "grpvss/model/robot_model.hpp"
#include "grpvss/motion/kinematics_access.hpp"
#include "grpvss/motion/thesis_error.hpp"

namespace grpvss::motion {

/// A CP line shorter than this (length units) has zero movement (thesis errors 1 and 4).
constexpr double kMinCpLength = 1e-9;

/// \brief Rot(K, theta) with K normalised (identity when theta = 0 or K = 0).
Eigen::Matrix3d rotation_about(const Eigen::Vector3d& axis, double angle);

/// \brief The end pose of a segment with world target `target` that starts at X_WE_start:
/// position P_f, orientation \f$o_f = Rot(K,\theta)\,o_s\f$ (Eq. 4-18: the change is applied to
/// the orientation at the segment's START, in the world frame), or \f$Rot(K,\theta)\f$ itself
/// for an absolute orientation (YAML paths).
Eigen::Isometry3d world_target_pose(const Eigen::Isometry3d& X_WE_start, const WorldTarget& target);

/// \brief The turn of a segment in the world frame, from the orientation at X_WE_start to its
/// target's: Rot(K, theta) for a change (zero axis when theta = 0), the shortest turn (angle in
/// [0, pi]) to an absolute orientation.
Eigen::AngleAxisd orientation_change_W(const Eigen::Isometry3d& X_WE_start, const WorldTarget& target);

/// \brief The straight line of one CP segment, parametrised by path length l in [0, L]:
/// \f$P(l) = P_s + (P_f - P_s)\,l/L\f$ (Eq. 4-17), \f$o(l) = Rot(K, \theta l/L)\,o_s\f$
/// (Eq. 4-18).
class CpLine {
 public:
  CpLine(const Eigen::Isometry3d& X_WE_start, const WorldTarget& target);

  double length() const { return length_; }
  bool is_zero_length() const { return length_ < kMinCpLength; }
  /// X_WE at path length l (clamped to [0, L]). \pre !is_zero_length().
  Eigen::Isometry3d pose_at(double l) const;
  const Eigen::Isometry3d& start_pose() const { return X_WE_start_; }
  Eigen::Isometry3d end_pose() const { return pose_at(length_); }

 private:
  Eigen::Isometry3d X_WE_start_;
  Eigen::Vector3d p_W_end_;
  Eigen::Vector3d axis_W_;  // unit, or zero when there is no rotation
  double angle_ = 0.0;
  double length_ = 0.0;
};

/// \brief Joints at one CP point: IK of `X_WE` nearest `q_near`, accepted only within the
/// joint limits (the thesis checks every returned solution against them, 4.2.2.2 B).
std::optional<Eigen::VectorXd> solve_within_limits(const RobotModel& robot,
                                                   const KinematicsAccess& kinematics,
                                                   const Eigen::Isometry3d& X_WE,
                                                   const Eigen::VectorXd& q_near);

/// \brief One sample of a CP line: path length and the IK joints there.
struct CpSample {
  double l = 0.0;
  Eigen::VectorXd q;
};

/// \brief Samples of a CP line, or the thesis error that stopped it.
struct CpSampling {
  std::vector<CpSample> samples;  ///< l = 0 (q_start) .. L, uniform spacing <= the requested
  std::optional<ThesisError> error;
};

/// \brief Samples the line at a uniform spacing of at most `spacing` in path length, each
/// sample's IK solved nearest the previous sample's joints (q_start at l = 0).
///
/// Errors (segment > 0 / segment == 0 for "no segment context"): zero length -> 4 / 1; the
/// end pose not reachable within the limits from q_start -> 3 / 2; an intermediate sample not
/// reachable -> 5 / 2. Samples are the place where unreachability is detected: a point between
/// two samples that is unreachable passes unnoticed (as in the thesis); the certified verifier
/// owns the step rule.
CpSampling sample_cp_line(const RobotModel& robot, const KinematicsAccess& kinematics,
                          const CpLine& line, const Eigen::VectorXd& q_start, double spacing,
                          int segment);

}  // namespace grpvss::motion
