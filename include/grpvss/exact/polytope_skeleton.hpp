#pragma once
/// \file
/// \brief The vertex graph of an exact hull, in the numbering of the points it was hulled
/// from: what GJK climbs on placed offsets (geometry/hull_skeleton.hpp).

#include "grpvss/exact/convex_polytope.hpp"
#include "grpvss/geometry/hull_skeleton.hpp"

namespace grpvss::geometry {

/// \brief The skeleton of \p polytope in the numbering of the point set it was hulled from
/// (`polytope.input_indices()`), over \p point_count points; points that are not vertices
/// have no neighbours.
HullSkeleton hull_skeleton(const ConvexPolytope& polytope, int point_count);

/// \brief The skeleton of \p polytope in the numbering of `polytope.vertices()` (for a point
/// set that is the hull's vertex list, e.g. a link's raw hull).
HullSkeleton vertex_skeleton(const ConvexPolytope& polytope);

}  // namespace grpvss::geometry
