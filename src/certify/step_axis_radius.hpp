#pragma once
// The configuration-dependent motion bound M'_h: each hull's distance from each joint axis over
// the step, bounded from where the hull is at the step's ends instead of over every
// configuration within the limits (R_jh). proof: proofs/motion-bound.md#lemma-axis-distance-along-step

#include <vector>

#include <Eigen/Core>

#include "cell_probe.hpp"
#include "grpvss/certify/robot_cell.hpp"

namespace grpvss::certify {

/// Fills each hull's axis ball (LinkHull::axis_ball_center_L, axis_ball_radius_up): the centre
/// of its raw vertices' box, and their largest distance from it, rounded up. Built once with the
/// cell: a run's StepAxisRadii reads them. proof: proofs/motion-bound.md#axis-distance-evaluation
void set_axis_balls(std::vector<LinkHull>& hulls);

class StepAxisRadii {
 public:
  /// Reads each hull's axis ball and L, the largest |coordinate| of any hull vertex, from the
  /// cell (set_axis_balls, RobotCell::raw_coordinate_limit).
  explicit StepAxisRadii(const RobotCell& cell);

  /// D_jh at the probe's configuration for every hull and joint 1..N, at [hull * N + j - 1]:
  /// an upper bound on the distance of every point of the exactly placed hull from axis j
  /// (0 for joints after the hull's link). proof: proofs/motion-bound.md#axis-distance-evaluation
  void axis_distances(const ProbeResult& probe, std::vector<double>& distances) const;
  /// The probe's kept distances when they are of its configuration, else axis_distances()
  /// into `scratch`.
  const std::vector<double>& kept_or_computed(const ProbeResult& probe,
                                              std::vector<double>& scratch) const;
  /// Keeps the probe's axis distances in it (ProbeResult::axis_distances).
  void keep(ProbeResult& probe) const;

  /// M'_h rounded up, for joint increments (or variations) `increments_up` that are upper
  /// bounds, with the axis distances of both ends of the step.
  double motion_bound(int hull_index, const Eigen::VectorXd& increments_up,
                      const std::vector<double>& distances_from,
                      const std::vector<double>& distances_to) const;

  /// axis_distances() with one more row per self pair (hull b's, in RobotCell::self_pairs()
  /// order), then one per self pair with a revolution route: the proposal's D rows beside
  /// its weights (step_march.cpp).
  void proposal_axis_distances(const ProbeResult& probe, std::vector<double>& distances) const;

  int joint_count() const { return joints_; }
  /// L, the largest |coordinate| of any hull vertex.
  double coordinate_limit() const { return cell_->raw_coordinate_limit(); }
  const RobotCell& cell() const { return *cell_; }
  /// A number no other StepAxisRadii of this process has (caches keyed by it never mistake a
  /// later one at the same address for this one).
  unsigned long long identity() const { return identity_; }

 private:
  const RobotCell* cell_;
  unsigned long long identity_ = 0;
  int joints_ = 0;
};

/// |c - o - s z| rounded up, each coordinate bracketed by directed rounding (an active
/// UpwardRoundingScope is required). proof: proofs/motion-bound.md#axis-distance-evaluation
double axis_point_distance_up(const Eigen::Vector3d& c, const Eigen::Vector3d& o,
                              const Eigen::Vector3d& z, double s);

/// One transition's axis distances at both ends, with the increments (rounded up).
struct StepAxisDistances {
  const StepAxisRadii* radii = nullptr;
  std::vector<double> from, to;
  Eigen::VectorXd increments_up;
};

/// Per joint an upper bound on |q_to - q_from| (upward rounding), or |variation| when the
/// step has a joint-variation bound.
Eigen::VectorXd increments_up(const Eigen::VectorXd& q_from, const Eigen::VectorXd& q_to,
                              const Eigen::VectorXd& joint_variation);

}  // namespace grpvss::certify
