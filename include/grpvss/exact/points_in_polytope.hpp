#pragma once
/// \file
/// \brief Exact test that points lie in a convex polytope (on or below every face plane),
/// fast for the common case of a hull checked against the very points it was built from.

#include <vector>

#include <Eigen/Core>

#include "grpvss/exact/convex_polytope.hpp"

namespace grpvss::geometry {

/// \brief Exact: is every point inside \p p (for every face, orient(v0, v1, v2, x) <= 0 with
/// v0, v1, v2 the face's first loop vertices, which are never collinear)?
///
/// A point bit-identical to a vertex of the face is on its plane (sign 0, no arithmetic);
/// the others go through Shewchuk's orient3d error bound A in double and, only when it
/// cannot decide, exact GMP rationals. When \p points are the input of
/// ConvexPolytope::from_points(points), pass them unchanged: input_indices() then names the
/// face vertices among them. O(points x faces).
bool points_inside_exactly(const ConvexPolytope& p, const std::vector<Eigen::Vector3d>& points);

}  // namespace grpvss::geometry
