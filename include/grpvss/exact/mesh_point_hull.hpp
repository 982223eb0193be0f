#pragma once
/// \file
/// \brief The exact convex hull of a group of mesh vertices, verified to contain every one
/// of them, with the documented fallback for flat groups (thickening).

#include <string>
#include <vector>

#include <Eigen/Core>

#include "grpvss/exact/convex_polytope.hpp"
#include "grpvss/exact/shape_warning.hpp"

namespace grpvss::geometry {

/// \brief conv(points) as an exact ConvexPolytope (vertices are input doubles, bit for bit),
/// accepted only after the exact check that every point is inside it
/// (points_inside_exactly: the hull is not taken on trust).
///
/// Flat groups (all points exactly coplanar, not collinear): if \p flat_thickness > 0 every
/// point p is replaced by p +- (flat_thickness / 2) e_k, k the axis closest to the plane's
/// normal, each coordinate rounded away from p (so p lies on the segment between the two);
/// the slab is at least flat_thickness / sqrt(3) thick across the plane; a warning
/// `source: what: ... thickened ...` is appended to \p warnings. With flat_thickness == 0 a
/// flat group is an input error.
/// proof: proofs/shape-containment.md#lemma-hull-cover
/// \throws grpvss::InputError(source, 0, ...) when the points are coincident or collinear,
///         or coplanar with flat_thickness == 0;
///         std::invalid_argument unless flat_thickness is finite and in [0, 1e6].
ConvexPolytope mesh_point_hull(const std::vector<Eigen::Vector3d>& points, double flat_thickness,
                               const std::string& source, const std::string& what,
                               std::vector<ShapeWarning>& warnings);

}  // namespace grpvss::geometry
