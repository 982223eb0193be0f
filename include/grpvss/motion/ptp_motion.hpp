#pragma once
/// \file
/// \brief Joint-space PTP motion of all joints (thesis Sections 1.1.2.1.1, 3.2.3.1): each
/// joint follows the ideal trapezoid or a user table, either independently or synchronised.

#include <memory>
#include <vector>

#include <Eigen/Core>

#include "grpvss/model/robot_model.hpp"
#include "grpvss/motion/motion_model.hpp"
#include "grpvss/motion/profile_table.hpp"
#include "grpvss/motion/trapezoid_profile.hpp"

namespace grpvss::motion {

/// \brief One joint's motion in one PTP move: a trapezoid or a table column, possibly
/// stretched in time (PtpTiming::kSynchronized).
class JointMotion {
 public:
  static JointMotion trapezoid(const TrapezoidProfile& profile);
  /// Column `joint` of `table`, applied to the move q_s -> q_f. A zero increment lasts 0 s.
  static JointMotion table(std::shared_ptr<const ProfileTable> table, int joint, double q_s,
                           double q_f);

  /// Duration before any stretching.
  double natural_duration() const { return natural_duration_; }
  /// Duration after stretching.
  double duration() const { return duration_; }
  /// Stretches the motion in time to last `total` >= natural_duration() seconds.
  void stretch_to(double total);
  /// Position and velocity at time t since the start of the move (clamped to the move).
  JointState at(double t) const;

 private:
  JointState natural_at(double t) const;
  TrapezoidProfile trapezoid_;
  std::shared_ptr<const ProfileTable> table_;  // null for a trapezoid
  int column_ = 0;
  double q_s_ = 0.0, q_f_ = 0.0;
  double natural_duration_ = 0.0, duration_ = 0.0;
};

/// \brief All joints of one PTP move.
class PtpMotion {
 public:
  /// \param velocity desired joint speeds v_m (> 0), rad/s or length/s.
  /// \param table user motion-time table, or null for the ideal trapezoids; its joint count
  ///        must equal the robot's (grpvss::InputError naming the table's header otherwise).
  static PtpMotion plan(const RobotModel& robot, const Eigen::VectorXd& q_start,
                        const Eigen::VectorXd& q_end, const Eigen::VectorXd& velocity,
                        PtpTiming timing, std::shared_ptr<const ProfileTable> table = nullptr);

  double duration() const { return duration_; }
  Eigen::VectorXd joints_at(double t) const;
  Eigen::VectorXd velocities_at(double t) const;
  const std::vector<JointMotion>& joints() const { return joints_; }

 private:
  std::vector<JointMotion> joints_;
  double duration_ = 0.0;
};

}  // namespace grpvss::motion
