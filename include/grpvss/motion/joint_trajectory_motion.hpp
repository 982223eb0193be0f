#pragma once
/// \file
/// \brief The motion a joint trajectory controller executes between a planner's waypoints
/// (ros2_control's joint_trajectory_controller): joint-linear when the waypoints carry
/// positions only, cubic Hermite per joint when they carry positions and velocities. Besides
/// evaluation it gives what the certified verifier needs: enclosures of the exact joint values
/// and a proven upper bound of every joint's total variation over any time interval, the
/// quantity the motion bound multiplies by the axis radii
/// (proofs/joint-variation.md#theorem-variation-motion-bound). Its exact counterpart for the
/// checker: motion/exact_joint_variation.hpp. Docs: docs/trajectories.md, section 10.
///
/// The motion is defined on [start_time(), end_time()], the first and the last waypoint's
/// times; what the controller does before the first waypoint (it moves from wherever the
/// robot is) is not part of the file. Every time argument must lie in that interval
/// (std::out_of_range otherwise). The evaluation functions need the default round-to-nearest
/// mode (std::logic_error otherwise).

#include <vector>

#include <Eigen/Core>

#include "grpvss/model/joint_trajectory.hpp"

namespace grpvss::motion {

enum class JointInterpolation {
  kLinear,        ///< q(t) = p_k + (t - t_k)/h_k (p_{k+1} - p_k): positions only
  kCubicHermite,  ///< per joint, the cubic with the waypoints' positions and velocities
};

/// \brief Per joint, an interval [lower_j, upper_j] that contains an exact value.
struct JointIntervals {
  Eigen::VectorXd lower, upper;
};

class JointTrajectoryMotion {
 public:
  /// \throws std::invalid_argument if the trajectory breaks an invariant of JointTrajectory
  /// (the readers never return such a trajectory).
  explicit JointTrajectoryMotion(JointTrajectory trajectory);

  const JointTrajectory& trajectory() const { return trajectory_; }
  JointInterpolation interpolation() const { return interpolation_; }
  int joint_count() const { return trajectory_.joint_count(); }
  /// Number of pieces: waypoints - 1 (0 for a single waypoint).
  int piece_count() const { return trajectory_.waypoint_count() - 1; }
  double start_time() const { return trajectory_.times.front(); }
  double end_time() const { return trajectory_.times.back(); }
  /// The waypoint times t_0 < ... < t_n: piece k is [t_k, t_{k+1}]; q is a polynomial on each.
  const std::vector<double>& piece_breaks() const { return trajectory_.times; }
  /// The piece that time t falls in: k with t_k <= t < t_{k+1}, the last piece at t = t_n;
  /// -1 when there is no piece (a single waypoint).
  int piece_at(double t) const;

  /// q(t) in double (round to nearest); exactly the waypoint's positions at a waypoint time.
  Eigen::VectorXd q_at(double t) const;
  /// dq/dt; at a waypoint time the right-hand derivative (the left-hand one at t_n): linear
  /// interpolation has a velocity jump at every interior waypoint.
  Eigen::VectorXd qdot_at(double t) const;
  /// Intervals that contain the exact q_j(t) of the interpolation of the stored doubles.
  /// proof: proofs/joint-variation.md#rounded-evaluation
  JointIntervals q_enclosure_at(double t) const;

  /// V_j >= the total variation of q_j on [t0, t1] (t0 <= t1), for every joint: the sum over
  /// the pieces [t0, t1] overlaps of the bound of the theorem, evaluated so that it is never
  /// below the exact evaluation (exact_variation_bound()). Equals the smallest double
  /// >= |q_j(t1) - q_j(t0)| when q_j is monotone on a whole piece [t0, t1] = [t_k, t_{k+1}].
  /// proof: proofs/joint-variation.md#corollary-interval-variation
  Eigen::VectorXd variation_bound(double t0, double t1) const;
  /// The bound for a step whose ends the verifier places at q_at(t0) and q_at(t1): the
  /// variation of the path q_at(t0) -> q(t0) -> (the motion) -> q(t1) -> q_at(t1), i.e.
  /// variation_bound(t0, t1) plus |q_at(t_i) - q(t_i)| bounded from q_enclosure_at(t_i).
  /// proof: proofs/joint-variation.md#corollary-sampled-ends
  Eigen::VectorXd variation_bound_from_samples(double t0, double t1) const;

 private:
  void check_time(double t, const char* what) const;
  /// p_j, v_j of waypoint k (v = 0 when the interpolation is linear).
  double position(int k, int j) const { return trajectory_.positions[k][j]; }
  double velocity(int k, int j) const;

  JointTrajectory trajectory_;
  JointInterpolation interpolation_ = JointInterpolation::kLinear;
};

}  // namespace grpvss::motion
