#pragma once
// The thesis's step rule, kept as a labelled comparison mode (never "certified"): each
// link-frame origin moves at most delta_l = max{min[2D/cos(theta/2), 2D + L], Dmin} per step
// (Eq. 3-3; PTP: Eq. 4-13..4-16, CP: Figure 16). proofs/thesis-rule.md says what this does and
// does not guarantee.

#include <vector>

#include <Eigen/Core>

#include "grpvss/certify/robot_cell.hpp"
#include "grpvss/kinematics/forward_kinematics.hpp"
#include "segment_path.hpp"

namespace grpvss::certify {

class ThesisStepRule {
 public:
  ThesisStepRule(const RobotCell& cell, double min_step_fraction);

  /// The parameter of the step after (s, q): PTP from the joint speeds and the previous step,
  /// CP by the ratio iteration on the end effector's increment. On a CP line that becomes
  /// unreachable, the unreachable parameter (the caller reports error 5).
  double next_parameter(const SegmentPath& path, double s, const Eigen::VectorXd& q,
                        double previous_step);

 private:
  /// delta_l_i at the origin of every link frame i (index 1..N) at configuration q.
  std::vector<double> allowed_displacements(const Eigen::VectorXd& q);
  double next_ptp_parameter(const SegmentPath& path, double s, const Eigen::VectorXd& q,
                            double previous_step, const std::vector<double>& allowed);
  double next_cp_parameter(const SegmentPath& path, double s, const Eigen::VectorXd& q,
                           const std::vector<double>& allowed);

  const RobotCell* cell_;
  double min_step_fraction_;
  kinematics::Workspace workspace_;
};

}  // namespace grpvss::certify
