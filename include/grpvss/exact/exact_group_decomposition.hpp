#pragma once
/// \file
/// \brief The `exact` mode for one closed group of a mesh: Nef convex decomposition,
/// independent verification, outward rounding — or the reason it fell back to the hull.

#include <array>
#include <optional>
#include <string>
#include <vector>

#include <Eigen/Core>

#include "grpvss/exact/convex_polytope.hpp"

namespace grpvss::geometry {

/// \brief Pieces for one group, or why the caller must use the group's hull instead.
struct ExactGroupPieces {
  /// Empty when fallback_reason is set.
  std::vector<ConvexPolytope> pieces;
  /// The group is convex: `pieces` is its hull alone (no decomposition needed).
  bool convex = false;
  std::optional<std::string> fallback_reason;
};

/// \brief Exact convex pieces covering the solid bounded by a closed surface.
///
/// Precondition: \p triangles form a connected, closed, consistently oriented, edge- and
/// vertex-manifold surface without degenerate triangles (oriented_manifold_problem() found
/// nothing); \p hull is conv(vertices) (mesh_point_hull). Steps: orient outward (exact
/// signed volume); if the hull's exact volume equals the solid's, the hull is the answer;
/// else reject self-intersecting surfaces (surface_self_intersects), decompose
/// (nef_convex_decomposition), verify (verify_exact_cover) and round each piece outward
/// (enclosing_double_points, exact hull); finally merge thin pieces (merge_pieces) while the
/// added volume stays within merge_volume_fraction of the solid's volume.
/// proof: proofs/shape-containment.md#lemma-exact-cover
ExactGroupPieces exact_group_pieces(const std::vector<Eigen::Vector3d>& vertices,
                                    std::vector<std::array<int, 3>> triangles,
                                    const ConvexPolytope& hull, double merge_volume_fraction);

}  // namespace grpvss::geometry
