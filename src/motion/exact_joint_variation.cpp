#include "grpvss/motion/exact_joint_variation.hpp"

#include <algorithm>
#include <stdexcept>
#include <string>

#include "exact_number_traits.hpp"
#include "hermite_piece.hpp"
#include "variation_arithmetic.hpp"

namespace grpvss::motion {
namespace {

using detail::ExactPiece;

void check_time(const JointTrajectoryMotion& motion, double t, const char* what) {
  if (!(t >= motion.start_time() && t <= motion.end_time())) {
    throw std::out_of_range(std::string(what) + ": time " + std::to_string(t) +
                            " s outside the trajectory");
  }
}

}  // namespace

std::vector<mpq_class> exact_q_at(const JointTrajectoryMotion& motion, double t) {
  check_time(motion, t, "exact_q_at");
  const JointTrajectory& trajectory = motion.trajectory();
  const int k = motion.piece_at(t);
  std::vector<mpq_class> q(static_cast<std::size_t>(motion.joint_count()));
  for (int j = 0; j < motion.joint_count(); ++j) {
    q[j] = k < 0 ? mpq_class(trajectory.positions[0][j]) : ExactPiece(trajectory, k, j).end_at(t).q;
  }
  return q;
}

std::vector<mpq_class> exact_variation_bound(const JointTrajectoryMotion& motion, double t0,
                                             double t1) {
  check_time(motion, t0, "exact_variation_bound");
  check_time(motion, t1, "exact_variation_bound");
  if (t0 > t1) throw std::invalid_argument("exact_variation_bound: t0 > t1");
  std::vector<mpq_class> bound(static_cast<std::size_t>(motion.joint_count()));
  if (motion.piece_count() == 0) return bound;
  const std::vector<double>& times = motion.piece_breaks();
  // proof: proofs/joint-variation.md#corollary-interval-variation
  for (int k = motion.piece_at(t0); k < motion.piece_count() && times[k] < t1; ++k) {
    const double a = std::max(t0, times[k]), b = std::min(t1, times[k + 1]);
    if (!(a < b)) continue;
    for (int j = 0; j < motion.joint_count(); ++j) {
      const ExactPiece piece(motion.trajectory(), k, j);
      const std::vector<double> breaks = detail::part_breaks(motion.trajectory(), k, j, a, b);
      for (std::size_t i = 0; i + 1 < breaks.size(); ++i) {
        bound[j] += detail::piece_variation<detail::ExactArithmetic>(
            piece.polynomial(), piece.end_at(breaks[i]), piece.end_at(breaks[i + 1]));
      }
    }
  }
  return bound;
}

std::vector<mpq_class> exact_variation_bound_from_samples(const JointTrajectoryMotion& motion,
                                                          double t0, const Eigen::VectorXd& q_hat0,
                                                          double t1, const Eigen::VectorXd& q_hat1) {
  if (q_hat0.size() != motion.joint_count() || q_hat1.size() != motion.joint_count()) {
    throw std::invalid_argument("exact_variation_bound_from_samples: one value per joint");
  }
  std::vector<mpq_class> bound = exact_variation_bound(motion, t0, t1);
  // proof: proofs/joint-variation.md#corollary-sampled-ends
  const std::vector<mpq_class> q0 = exact_q_at(motion, t0), q1 = exact_q_at(motion, t1);
  for (int j = 0; j < motion.joint_count(); ++j) {
    bound[j] += abs(mpq_class(q_hat0[j]) - q0[j]) + abs(mpq_class(q_hat1[j]) - q1[j]);
  }
  return bound;
}

}  // namespace grpvss::motion
