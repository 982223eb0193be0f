#pragma once
/// \file
/// \brief A conservative bound on the floating-point error of forward_kinematics +
/// place_hull_points (needed by the certified verifier).

#include "grpvss/kinematics/kinematic_chain.hpp"

namespace grpvss::kinematics {

/// \brief Bound on \f$\|\hat p_W - p_W\|_2\f$ for every hull point placed by
/// forward_kinematics + place_hull_points in IEEE double (round to nearest), for every q within
/// the joint limits and every link point with \f$\|p_L\|_\infty \le\f$ max_abs_coordinate.
/// \f$p_W\f$ is the exact real value of the chain's formula for the same double inputs
/// (q, DH parameters), with exact sin/cos. Assumes libm sin/cos within 2 ulp.
/// proof: proofs/fk-rounding.md#fk-rounding
double forward_kinematics_error_bound(const KinematicChain& chain, double max_abs_coordinate);

}  // namespace grpvss::kinematics
