#pragma once
/// \file
/// \brief Exact volumes (times 6, as GMP rationals) of convex polytopes and triangle
/// surfaces: for the decomposition's volume ratios and convexity test.

#include <array>
#include <vector>

#include <Eigen/Core>
#include <gmpxx.h>

#include "grpvss/exact/convex_polytope.hpp"

namespace grpvss::geometry {

/// \brief 6 x the volume of \p p, exactly (fan of every face loop from the origin).
mpq_class six_volume(const ConvexPolytope& p);

/// \brief 6 x the signed volume enclosed by the triangles, exactly:
/// \f$\sum_t a_t \cdot (b_t \times c_t)\f$. For a closed surface oriented counter-clockwise
/// seen from outside, this is 6 x the volume of the solid it bounds (the integral of the
/// winding number); negative when the surface is oriented inward.
mpq_class six_signed_volume(const std::vector<Eigen::Vector3d>& vertices,
                            const std::vector<std::array<int, 3>>& triangles);

}  // namespace grpvss::geometry
