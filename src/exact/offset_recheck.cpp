#include "grpvss/exact/offset_recheck.hpp"

#include "grpvss/exact/minkowski_offset.hpp"

namespace grpvss::geometry {

// proof: proofs/offset-containment.md#lemma-cached-offset
std::optional<ConvexPolytope> recheck_offset(const std::vector<Eigen::Vector3d>& proposed,
                                             const ConvexPolytope& hull, double radius) {
  for (const Eigen::Vector3d& p : proposed) {
    if (!p.allFinite()) return std::nullopt;
  }
  std::optional<ConvexPolytope> offset;
  try {
    offset = ConvexPolytope::from_points(proposed);
  } catch (const DegenerateHullError&) {
    return std::nullopt;  // fewer than 4 points, or flat: not an offset of a solid hull
  }
  // Vertices are the first occurrences of extreme input points: equal counts mean every
  // proposed point is a distinct vertex.
  if (offset->vertices().size() != proposed.size()) return std::nullopt;
  if (!contains_ball_sum_by_climbing(*offset, hull, radius)) return std::nullopt;
  return offset;
}

}  // namespace grpvss::geometry
