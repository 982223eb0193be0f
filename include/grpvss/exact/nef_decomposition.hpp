#pragma once
/// \file
/// \brief The two CGAL-heavy steps of the `exact` mesh decomposition, in one translation unit
/// (src/geometry/exact/nef_decomposition.cpp; Nef polyhedra are very slow to compile): the
/// self-intersection test of a closed surface and CGAL 5.5's `convex_decomposition_3`.
///
/// Neither result is trusted by the certified core: the pieces are verified by
/// verify_exact_cover() (proofs/shape-containment.md#lemma-exact-cover). The self-intersection
/// test is an exact-predicate input check (the lemma's embedding hypothesis).

#include <array>
#include <vector>

#include <Eigen/Core>

#include "grpvss/exact/rational_piece.hpp"

namespace grpvss::geometry {

/// \brief True if two triangles of the closed, manifold, consistently oriented surface
/// intersect other than in their shared vertex or edge (CGAL
/// `Polygon_mesh_processing::does_self_intersect`, exact predicates).
/// Precondition: every edge bounds exactly two triangles, with opposite directions; every
/// vertex's triangles form one fan; no triangle repeats a vertex.
bool surface_self_intersects(const std::vector<Eigen::Vector3d>& vertices,
                             const std::vector<std::array<int, 3>>& triangles);

/// \brief Convex pieces of the solid bounded by the surface (same preconditions, plus no
/// self-intersection and outward orientation): the bounded marked volumes of the Nef
/// polyhedron after CGAL::convex_decomposition_3, each as the exact convex hull of the
/// volume's vertices (exact constructions kernel) with its outward hull triangles.
std::vector<RationalPiece> nef_convex_decomposition(
    const std::vector<Eigen::Vector3d>& vertices,
    const std::vector<std::array<int, 3>>& triangles);

}  // namespace grpvss::geometry
