#pragma once
/// \file
/// \brief How close a hull can come to the obstacles between two steps, from the radii the
/// probe proved at both steps and the motion bound of the transition.

namespace grpvss::certify {

/// \brief A lower bound, rounded down, of
/// \f$g = \max\bigl((r_k + r_{k+1} - M)/2,\ \max(r_k, r_{k+1}) - M\bigr)\f$: every point of the
/// true hull stays farther than g from every obstacle throughout the transition.
/// proof: proofs/two-ball-cover.md#corollary-motion-clearance
/// \pre radius_k, radius_k1 >= 0 are proven radii, motion_bound >= 0 bounds every point's path.
/// A result <= 0 proves nothing (the transition was not certified by its clearances).
double motion_clearance_lower_bound(double radius_k, double radius_k1, double motion_bound);

}  // namespace grpvss::certify
