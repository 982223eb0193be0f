#pragma once
/// \file
/// \brief Upper bounds on how far any point of a link hull can travel between two
/// configurations joined by a joint-monotone motion.
///
/// proof: proofs/motion-bound.md#lemma-motion-bound
/// For hull h on link i and monotone joint motion from q_k to q_{k+1}:
/// \f[ M_h = \sum_{j \le i,\ \mathrm{rev}} |\Delta q_j|\, R_{jh} + \sum_{j \le i,\ \mathrm{pris}} |\Delta q_j| \f]
/// with the configuration-independent radius R_{jh} of proofs/motion-bound.md#lemma-axis-radius:
/// a recursion down the chain of two bounds, the distance from the frame's z axis and the
/// |z| extent (axial offsets of parallel axes never add to the distance from them), clamped
/// by the absolute-sum bound |a_j| + sum_{m=j+1}^{i}(|a_m| + d^max_m) + max |v|_1.
/// Every term is a sum, product or minimum of doubles, so a checker can decide it exactly.

#include <vector>

#include <Eigen/Core>

#include "grpvss/model/robot_model.hpp"

namespace grpvss::certify {

/// \brief R_{jh} for every hull of every link, computed once per robot.
class HullRadiusTable {
 public:
  explicit HullRadiusTable(const RobotModel& robot);

  /// Radius bound of hull `hull` of link `link` about the axis of joint `joint` (1-based,
  /// joint <= link). Rounded upward so that it is >= the exact real-number formula.
  double radius(int link, int hull, int joint) const;

  /// Upper bound (rounded upward) on the path length of any point of the hull for a
  /// joint-monotone motion with increments `dq` (library units).
  double hull_motion_bound(int link, int hull, const Eigen::VectorXd& dq) const;

  /// R_jh of one hull for joints 1..link at index j-1, unchecked: for loops that already keep
  /// j <= link (radius() checks every call, which the per-step sums paid for).
  const std::vector<double>& radii_of(int link, int hull) const { return radius_[link][hull]; }

  /// The coefficient of |dq_j| in M_h: R_jh for a revolute joint j <= link, 1 for a
  /// prismatic one, 0 for joints after the link (joint 1-based).
  double motion_bound_weight(int link, int hull, int joint) const;

  /// The type of joint `joint` (1-based).
  JointType joint_type(int joint) const { return joint_types_.at(joint - 1); }

  int link_count() const { return static_cast<int>(radius_.size()); }
  int hull_count(int link) const { return static_cast<int>(radius_[link].size()); }

 private:
  std::vector<JointType> joint_types_;
  // radius_[link][hull][joint-1]
  std::vector<std::vector<std::vector<double>>> radius_;
};

}  // namespace grpvss::certify
