#pragma once
/// \file
/// \brief The independent check that convex pieces with exact rational vertices cover the
/// solid bounded by a closed surface, and their outward rounding to doubles. Does not trust
/// the decomposition that proposed the pieces: every condition of
/// proofs/shape-containment.md#lemma-exact-cover is decided in GMP rationals here.

#include <array>
#include <string>
#include <vector>

#include <Eigen/Core>

#include "grpvss/exact/rational_piece.hpp"

namespace grpvss::geometry {

/// \brief Outcome of verify_exact_cover(): `covered`, or the first failed condition.
struct ExactCoverCheck {
  bool covered = false;
  std::string failure;
};

/// \brief Decides, exactly, the hypotheses (B) and (F) of the exact-cover lemma:
/// - (B) each piece's triangles form a closed surface (every directed edge once, its
///   reverse once), every piece vertex lies on or below every triangle plane of its piece,
///   and the piece's vertex centroid lies strictly below every one (so the triangles are
///   the whole boundary of conv(vertices), and the piece is full-dimensional);
/// - (F) every piece triangle t is covered, up to a set of zero area, by the surface
///   triangles in t's plane together with the triangles of OTHER pieces lying in t's plane
///   with the opposite outward normal. Decided per facet (a piece's triangles in one plane
///   merged into their convex hull, which they tile once (B) holds): exact plane keys, a 2-D
///   projection, exact convex clipping of the facet by each coverer.
/// There must be at least one piece. The lemma's remaining hypothesis — the surface is a
/// connected, closed, embedded 2-manifold — is the caller's (oriented_manifold_problem(),
/// surface_self_intersects()). Then the union of conv(piece vertices) contains the solid.
/// proof: proofs/shape-containment.md#lemma-exact-cover
ExactCoverCheck verify_exact_cover(const std::vector<RationalPiece>& pieces,
                                   const std::vector<Eigen::Vector3d>& surface_vertices,
                                   const std::vector<std::array<int, 3>>& surface_triangles);

/// \brief Double points whose convex hull contains the piece: for each vertex, the corners
/// of the smallest double box around it (the vertex itself when it is a double). Duplicates
/// removed. proof: proofs/shape-containment.md#lemma-outward-rounding
std::vector<Eigen::Vector3d> enclosing_double_points(const RationalPiece& piece);

}  // namespace grpvss::geometry
