#pragma once
// The CP model the certified march relies on (proofs/cp-joint-path.md#model): between two
// samples of a CP line the joints move linearly, and that motion must stay near the commanded
// line. Also the line's failure modes the model cannot absorb: singular configurations and
// unreachable stretches next to a joint limit.

#include <Eigen/Core>

#include "grpvss/certify/robot_cell.hpp"
#include "grpvss/evidence/setup.hpp"
#include "grpvss/kinematics/forward_kinematics.hpp"
#include "segment_path.hpp"

namespace grpvss::certify {

class CpModelCheck {
 public:
  CpModelCheck(const RobotCell& cell, const CpModelSettings& settings);

  /// How far the joint-linear motion from (s0, q0) to (s1, q1) strays from the commanded line,
  /// as a multiple of what the model allows (the largest of the position and orientation
  /// ratios at the sampled fractions): the model holds iff it is <= 1 (NaN: it fails).
  double deviation(const SegmentPath& path, double s0, const Eigen::VectorXd& q0, double s1,
                   const Eigen::VectorXd& q1) const;
  bool holds(const SegmentPath& path, double s0, const Eigen::VectorXd& q0, double s1,
             const Eigen::VectorXd& q1) const {
    return deviation(path, s0, q0, s1, q1) <= 1.0;
  }
  /// The longest step from (s, q) (to `resolution`) over which the model holds, found by
  /// bisection below s_failing (where it fails). Proposals only: the march decides.
  double reach(const SegmentPath& path, double s, const Eigen::VectorXd& q, double s_failing,
               double resolution) const;
  /// The position Jacobian's smallest singular value at q is below the threshold.
  bool near_singularity(const Eigen::VectorXd& q);
  /// A joint at (within a tiny band of) its limit at s, and the line unreachable just ahead:
  /// a stretch shorter than any step whose IK samples on both sides succeed
  /// (proofs/cp-joint-path.md#ik-failure; the long oracle run's case 1199).
  bool unreachable_next_to_a_limit(const SegmentPath& path, double s,
                                   const Eigen::VectorXd& q) const;

 private:
  const RobotCell* cell_;
  CpModelSettings settings_;
  double end_link_reach_ = 1.0;  ///< max |p_L| over the last link's hulls (at least 1)
  kinematics::Workspace workspace_;
  mutable Eigen::VectorXd q_mid_;  ///< deviation()'s scratch (a check runs every CP step)
};

}  // namespace grpvss::certify
