#pragma once
/// \file
/// \brief The exact (GMP rational) counterparts of JointTrajectoryMotion's enclosures and
/// variation bounds, for the certificate checker. Same recursion as the verifier's rounded
/// evaluation, every operation exact; JointTrajectoryMotion::variation_bound() is never below
/// exact_variation_bound() (proofs/joint-variation.md#rounded-evaluation).

#include <vector>

#include <gmpxx.h>
#include <Eigen/Core>

#include "grpvss/motion/joint_trajectory_motion.hpp"

namespace grpvss::motion {

/// The exact q_j(t) of the interpolation of the stored doubles, per joint.
/// \throws std::out_of_range outside [start_time(), end_time()].
std::vector<mpq_class> exact_q_at(const JointTrajectoryMotion& motion, double t);

/// The bound of proofs/joint-variation.md#corollary-interval-variation on [t0, t1] in exact
/// arithmetic: >= the total variation of every q_j there; = |q_j(t1) - q_j(t0)| whenever
/// q_j is monotone on [t0, t1] and [t0, t1] lies in one piece.
std::vector<mpq_class> exact_variation_bound(const JointTrajectoryMotion& motion, double t0,
                                             double t1);

/// The variation of the path q_hat0 -> q(t0) -> (the motion) -> q(t1) -> q_hat1:
/// exact_variation_bound(t0, t1) + |q_hat0 - q(t0)| + |q(t1) - q_hat1| per joint
/// (proofs/joint-variation.md#corollary-sampled-ends). `q_hat` are the configurations a
/// certificate records for the two step ends.
std::vector<mpq_class> exact_variation_bound_from_samples(const JointTrajectoryMotion& motion,
                                                          double t0, const Eigen::VectorXd& q_hat0,
                                                          double t1, const Eigen::VectorXd& q_hat1);

}  // namespace grpvss::motion
