#pragma once
/// \file
/// \brief A world-frame box around a placed hull from its link-frame box: O(1) instead of
/// placing every vertex and taking their box. The broadphase only needs a box that contains
/// the computed placed points; the vertices are placed later, and only for hulls that meet
/// a candidate obstacle.

#include <Eigen/Geometry>

#include "grpvss/geometry/broadphase.hpp"

namespace grpvss::geometry {

/// \brief A box containing the computed `X_WL * p` (double arithmetic, as
/// kinematics::place_points does it, in any summation order, with or without FMA) for every
/// point p of \p box_L: the interval image of the box under X_WL, widened by the bound
/// 8u (sum_j |R_ij| max|p_j| + |t_i|) + 2^-1000 on the rounding of each coordinate.
/// proof: proofs/fast-path.md#placed-box-enclosure
Aabb placed_box_enclosure(const Aabb& box_L, const Eigen::Isometry3d& X_WL);

}  // namespace grpvss::geometry
