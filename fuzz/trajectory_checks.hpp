#pragma once
// Shared by the trajectory fuzz targets: a trajectory that a reader accepted must also be
// accepted by the motion stage, and its rounded variation bound must never be below the exact
// one (proofs/joint-variation.md#rounded-evaluation). A broken promise traps (a finding).
#include <algorithm>
#include <limits>
#include <vector>

#include "grpvss/io/trajectory_file.hpp"
#include "grpvss/motion/exact_joint_variation.hpp"
#include "grpvss/motion/joint_limit_check.hpp"
#include "grpvss/motion/joint_trajectory_motion.hpp"

namespace grpvss::fuzz {

inline void check_accepted_trajectory(const JointTrajectory& trajectory) {
  // Reordering into reversed order exercises match_joints on every accepted file.
  std::vector<std::string> reversed(trajectory.joint_names.rbegin(), trajectory.joint_names.rend());
  const motion::JointTrajectoryMotion motion(io::match_joints(trajectory, reversed));
  const double start = motion.start_time(), end = motion.end_time();
  // The exact evaluation is costly under the sanitizers: at most the first 16 pieces.
  const double exact_end = motion.piece_breaks()[std::min(motion.piece_count(), 16)];
  const double middle = start + (exact_end - start) / 3;
  for (const auto& [a, b] : {std::pair{start, exact_end}, std::pair{middle, exact_end}}) {
    const Eigen::VectorXd rounded = motion.variation_bound(a, b);
    const std::vector<mpq_class> exact = motion::exact_variation_bound(motion, a, b);
    for (int j = 0; j < motion.joint_count(); ++j) {
      if (mpq_class(rounded[j]) < exact[j]) __builtin_trap();
    }
  }
  (void)motion.variation_bound(start, end);
  (void)motion.q_at(middle);
  (void)motion.qdot_at(middle);
  const int joints = motion.joint_count();
  const motion::JointLimits limits{Eigen::VectorXd::Constant(joints, -1.0), Eigen::VectorXd::Constant(joints, 1.0),
                                   Eigen::VectorXd::Constant(joints, 2.0)};
  if (const auto violation = motion::first_limit_violation(motion, limits)) {
    (void)motion::describe(*violation, motion.trajectory());
  }
}

}  // namespace grpvss::fuzz
