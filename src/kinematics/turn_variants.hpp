#pragma once
// Private helpers of AnalyticIk: the 2 pi turns of revolute joint values that fit the limits.

#include <vector>

#include <Eigen/Core>

#include "grpvss/kinematics/kinematic_chain.hpp"

namespace grpvss::kinematics::detail {

/// Values within this much outside a limit count as on it (and are clamped onto it): roundoff
/// of the closed form may put an exact boundary solution a few ulps outside.
constexpr double kLimitSlack = 1e-10;

/// Every q + 2 pi k (per joint, all combinations) within the chain's limits.
std::vector<Eigen::VectorXd> turn_variants(const KinematicChain& chain, const Eigen::VectorXd& q);

/// Per joint the turn of q nearest to q_near within the limits; false when a joint has none.
/// No allocation.
bool nearest_turns(const KinematicChain& chain, const Eigen::Matrix<double, 6, 1>& q,
                   const Eigen::VectorXd& q_near, Eigen::Matrix<double, 6, 1>& out);

}  // namespace grpvss::kinematics::detail
