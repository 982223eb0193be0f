#pragma once
/// \file
/// \brief Fewer convex pieces for a small price in volume: two pieces are replaced by the
/// hull of their union (which contains both, so containment is kept:
/// proofs/shape-containment.md#merging) while the total added volume stays within a budget.
/// Exact decompositions of curved parts produce many thin slivers; each costs the verifier a
/// hull pair test per link per step.

#include <vector>

#include "grpvss/exact/convex_polytope.hpp"

namespace grpvss::geometry {

/// \brief Greedy merging: the thinnest piece not yet settled is merged with the partner
/// (bounding boxes touching) whose union's hull adds the least volume, if the running total
/// of added volume stays <= \p volume_budget (model units cubed); otherwise it is settled.
/// Volumes are the ConvexPolytope ones (exact, rounded); the budget is a tightness knob,
/// not a soundness condition. Order of the result: survivors in input order.
std::vector<ConvexPolytope> merge_pieces(std::vector<ConvexPolytope> pieces, double volume_budget);

}  // namespace grpvss::geometry
