#pragma once
/// \file
/// \brief An obstacle or link mesh as convex pieces whose union provably contains it: the
/// three `decompose:` modes of a cell file (hull, parts, exact).
/// proof: proofs/shape-containment.md#theorem-mesh-cover
///
/// What "contains the mesh" means (proofs/shape-containment.md#solid): every triangle is
/// inside some piece, and when the mesh is closed (every edge used by an even number of
/// triangles) so is every point of the solid it bounds (odd ray-crossing parity). An open
/// mesh bounds no solid; its open triangles are covered by one hull, which also contains
/// any closing of its holes by triangles on its own vertices.

#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include <Eigen/Core>

#include "grpvss/exact/shape_warning.hpp"
#include "grpvss/model/triangle_mesh.hpp"

namespace grpvss::geometry {

/// \brief How a mesh becomes convex pieces.
enum class DecomposeMode {
  /// One exact convex hull of all (used) vertices. The default.
  kHull,
  /// One exact hull per closed connected group: connected components (triangles sharing a
  /// vertex, after welding equal coordinates), split further by named part
  /// (TriangleMesh::part_names) where a part's component is closed by itself. Triangles of
  /// groups that are not closed are covered together by one more hull.
  kParts,
  /// As `parts`, but each closed group that is a connected, consistently oriented,
  /// manifold, non-self-intersecting surface and not convex is split exactly by CGAL's Nef
  /// `convex_decomposition_3`, the pieces verified (verify_exact_cover) and rounded outward;
  /// any other group, or a failed verification, falls back to the group's hull (warning).
  kExact,
};

/// \brief "hull", "parts" or "exact" -> the mode; nullopt for anything else.
std::optional<DecomposeMode> parse_decompose_mode(std::string_view name);
/// \brief The mode's name as a cell file spells it.
std::string_view decompose_mode_name(DecomposeMode mode);

/// \brief Options of decompose_mesh().
struct DecompositionOptions {
  DecomposeMode mode = DecomposeMode::kHull;
  /// Thickness (model units) given to a group whose vertices are all coplanar; 0 makes a
  /// flat group an input error (a flat mesh bounds no solid). See mesh_point_hull().
  double flat_thickness = 0.0;
  /// Warn when the pieces' total volume exceeds this multiple of the mesh volume.
  double warn_volume_ratio = 1.2;
  /// `exact` only: thin pieces are merged into hulls of unions while the added volume stays
  /// within this fraction of each component's volume (0: keep every piece).
  double merge_volume_fraction = 1e-3;
};

/// \brief The convex pieces of one mesh, for the certified core.
struct ConvexPieces {
  /// Each piece: the vertices of an exact convex hull, in the mesh frame. In `hull` and
  /// `parts` modes (and exact pieces that are the hull of a convex group) they are mesh
  /// vertices, bit for bit; exact-decomposition pieces have rational vertices, replaced by
  /// the corners of their enclosing double boxes (proofs/shape-containment.md#lemma-outward-rounding).
  std::vector<std::vector<Eigen::Vector3d>> pieces;
  /// Where each piece came from, for messages ("component of triangle 12", "exact piece 2
  /// of component of triangle 0", "part 'lid', component of triangle 40", "open triangles").
  std::vector<std::string> piece_origins;
  /// Warnings (file = mesh.source, line 0): open mesh, unused vertices, thickened flat
  /// groups, exact-mode fallbacks, large added volume.
  std::vector<ShapeWarning> warnings;
  /// Sum of the pieces' exact volumes / the mesh's exact volume (rounded); only for a
  /// closed, consistently oriented mesh with non-zero volume. Overlapping pieces count twice.
  std::optional<double> volume_ratio;
};

/// \brief Validates the mesh (validate_mesh: throws grpvss::InputError) and returns its
/// convex pieces. Every piece has passed the exact check that it contains the vertices it
/// was built from; exact-decomposition pieces passed verify_exact_cover().
/// \throws grpvss::InputError for invalid meshes and for flat or lower-dimensional groups
///         that cannot be thickened (mesh_point_hull);
///         std::invalid_argument for bad options.
ConvexPieces decompose_mesh(const TriangleMesh& mesh, const DecompositionOptions& options = {});

}  // namespace grpvss::geometry
