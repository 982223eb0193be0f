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

}  // namespace grpvss::geometry
