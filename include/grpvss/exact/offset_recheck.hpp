#pragma once
/// \file
/// \brief The exact re-check of a tolerance offset that was NOT built in this process (read
/// from the set-up cache): it is used only if it provably contains hull (+) B(0, r).
/// proof: proofs/offset-containment.md#lemma-cached-offset

#include <optional>
#include <vector>

#include <Eigen/Core>

#include "grpvss/exact/convex_polytope.hpp"

namespace grpvss::geometry {

/// \brief conv(\p proposed) if it is an offset of \p hull for \p radius, decided exactly now;
/// nullopt otherwise. Accepted only if
/// - every coordinate is finite and the points span 3-D (the exact hull is rebuilt here from
///   the points themselves, never read);
/// - every proposed point is a vertex of that hull (no duplicates, no interior points), so
///   the points can serve as the offset's vertex list (`LinkHull::expanded_L`) unchanged;
/// - contains_ball_sum_by_climbing(hull of proposed, hull, radius) (Lemmas 4 and 4a of
///   proofs/offset-containment.md, decided in exact arithmetic).
/// Nothing about where the points came from is assumed.
/// \throws std::invalid_argument unless radius is finite and >= 0.
std::optional<ConvexPolytope> recheck_offset(const std::vector<Eigen::Vector3d>& proposed,
                                             const ConvexPolytope& hull, double radius);

}  // namespace grpvss::geometry
