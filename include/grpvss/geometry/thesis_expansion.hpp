#pragma once
/// \file
/// \brief The thesis's floating-point robot expansion (Section 4.2.1, Eq. 4-1 .. 4-12),
/// implemented faithfully FOR COMPARISON ONLY.
///
/// This is not a sound tolerance offset: it offsets the edges of the two 8-gon faces of a
/// 16-vertex prism (thesis Figure 7) in floating point and takes midpoints of nearly
/// intersecting lines. Nothing proves that the result contains every point within
/// \f$\Delta\f$ of the hull; `grpvss expansion-audit` measures exactly how far it misses
/// (docs/expansion-audit.md). The certified pipeline uses the exact Minkowski offsets of
/// geometry/exact instead.
///
/// Vertex numbering (thesis Section 3.2.1, Figure 7): vertices 1-8 (indices 0-7) form a
/// polygon in one plane ("surface A"), vertices 9-16 (indices 8-15) the same polygon in a
/// parallel plane ("surface B"), listed in the same rotational order; vertex k+8 is the
/// partner of vertex k.
///
/// ### Our reading of the text (figures 12-14 are missing from the scanned thesis)
/// For each cap and each cap edge \f$\overline{P_2P_3}\f$ (consecutive cap vertices, cyclic),
/// with \f$P_1\f$ the cap vertex before \f$P_2\f$ and \f$P_4\f$ the one after \f$P_3\f$:
/// - \f$N\f$ (Eq. 4-1/4-2, "normal of plane Ax+By+Cz+D=0") is the normal of the CAP plane.
///   The text does not say how it is obtained; we use Newell's method over the 8 cap vertices
///   (it works with collinear consecutive vertices, which the IBM 7545 data has everywhere),
///   so N is oriented by the vertex order (right-hand rule). \f$D = -N\cdot P_3\f$.
/// - Eq. 4-1: \f$P_0 = P_3 \pm \frac{(P_3-P_2)\times N}{\|(P_3-P_2)\times N\|}\Delta\f$, an
///   in-plane step of \f$\Delta\f$ perpendicular to the edge. Sign: the text asks for
///   \f$(P_0-P_3)\cdot(P_4-P_3)\le 0\f$ "or" \f$(P_0-P_3)\cdot(P_1-P_3)\le 0\f$. Read
///   literally the "or" picks "+" whenever either product is 0, i.e. whenever P4 (or P1) is
///   collinear with the edge, which happens on every rectangle-with-midpoints cap of the
///   IBM 7545 data. We read it as "use the non-degenerate test": the product with the larger
///   magnitude decides (at a strictly convex corner both agree). With Newell's N,
///   \f$(P_3-P_2)\times N\f$ already points out of a convex cap, so "+" is selected either
///   way; the literal reading would go wrong only for an N oriented independently of the
///   vertex order (then half of the edges next to a midpoint would move INWARD).
/// - Eq. 4-2: \f$P_l = P_0 \pm \frac{N}{\|N\|}\Delta\f$, a step of \f$\Delta\f$ out of the cap
///   plane; together with Eq. 4-1 the line is \f$\sqrt2\Delta\f$ from the edge, as the text
///   says. Sign rule of the text: "+" if (1) P3 and the origin are on different sides of the
///   plane and N points to the origin, or (2) they are on the same side and N points away
///   from the origin; "-" otherwise. P3 lies ON the cap plane, so literally the rule is void;
///   its evident purpose is to step away from the hull, so we read "P3" as the partner vertex
///   of P3 on the other cap (index +-8), a point of the hull off the plane. The origin is the
///   origin of the frame the points are given in (the link frame). When the origin lies on
///   the cap plane (D == 0 exactly) neither (1) nor (2) holds and the text's "otherwise"
///   selects "-", whatever N's orientation: we do exactly that and count such decisions
///   (ThesisExpansion::origin_on_cap_plane).
/// - The parallel line is \f$P_l + \lambda (P_3 - P_2)\f$.
/// - Eq. 4-3 .. 4-12: expanded vertex k is the "intersection" of the parallel lines of the two
///   cap edges meeting at original vertex k: line 1 = edge (k-1, k) with base point
///   \f$P_l\f$ built at vertex k, line 2 = edge (k, k+1) with base point built at vertex k+1.
///   \f$\lambda_1^*, \lambda_2^*\f$ from Eq. 4-8/4-9 (Eq. 4-6/4-7 carry sign/index typos; 4-8
///   and 4-9 are the correct solution of the normal equations), points by Eq. 4-10/4-11,
///   vertex = midpoint Eq. 4-12. When DENO == 0 exactly (parallel lines: collinear
///   neighbouring edges) the text says "arbitrarily pick \f$\lambda_1^*\f$" and takes
///   \f$\lambda_2^*\f$ from Eq. 4-5; we pick \f$\lambda_1^* = 0\f$, i.e. line 1's base point,
///   which is the offset of vertex k itself.
/// - The "midpoint gap" is \f$\|P_1^* - P_2^*\|\f$, the shortest distance the thesis reports
///   ("less than 3.0E-06 in single precision" for the IBM 7545).
///
/// Every step is computed in `Scalar` (float = the thesis's single precision "short floating"
/// numbers on the IBM 4341, or double): the input coordinates and \f$\Delta\f$ are first
/// rounded to `Scalar`.

#include <array>

#include <Eigen/Core>

#include "grpvss/model/hull_points.hpp"

namespace grpvss::geometry {

/// Number of vertices of the thesis's primitive model (Figure 7).
inline constexpr int kThesisPrismVertexCount = 16;

/// \brief Result of expanding one 16-vertex prism by the thesis's algorithm.
/// \tparam Scalar float (the thesis's single precision) or double.
template <typename Scalar>
struct ThesisExpansion {
  using Vector3 = Eigen::Matrix<Scalar, 3, 1>;
  /// Expanded vertex k (Eq. 4-12) replaces original vertex k; same frame as the input.
  std::array<Vector3, kThesisPrismVertexCount> vertices;
  /// \f$\|P_1^* - P_2^*\|\f$ (Eq. 4-10/4-11) for vertex k, computed in Scalar.
  std::array<Scalar, kThesisPrismVertexCount> midpoint_gaps{};
  /// True when DENO == 0 for vertex k (parallel lines, \f$\lambda_1^* = 0\f$ picked).
  std::array<bool, kThesisPrismVertexCount> parallel_lines{};
  /// Largest entry of midpoint_gaps.
  Scalar max_midpoint_gap = 0;
  /// Number of Eq. 4-2 sign decisions (one per edge, 16 in all) taken with the origin on the
  /// cap plane, where the text's rule falls through to "-".
  int origin_on_cap_plane = 0;
  /// Number of Eq. 4-1 sign decisions (one per edge) that selected "-". With Newell's N this
  /// is 0 for every convex cap: \f$(P_3-P_2)\times N\f$ already points outward.
  int in_plane_minus = 0;
  /// Number of Eq. 4-1 sign decisions where both of the text's dot products were exactly 0
  /// (P1, P2, P3, P4 collinear); "+" was then taken.
  int degenerate_in_plane_sign = 0;
};

/// \brief Expand a 16-vertex prism hull by the tolerance \f$\Delta\f$ exactly as the thesis's
/// Eq. 4-1 .. 4-12 do (see the file comment for the reading of ambiguous steps).
/// \param hull 16 points in thesis Figure 7 order, in the frame whose origin Eq. 4-2's sign
///        rule refers to (the link frame).
/// \param delta the tolerance \f$\Delta > 0\f$ (rounded to Scalar).
/// \throws std::invalid_argument if the hull does not have exactly 16 points, delta is not
///         positive, or a cap has no normal (all 8 points collinear) or an edge has length 0.
template <typename Scalar>
ThesisExpansion<Scalar> expand_prism_as_thesis(const HullPoints& hull, double delta);

extern template ThesisExpansion<float> expand_prism_as_thesis<float>(const HullPoints&, double);
extern template ThesisExpansion<double> expand_prism_as_thesis<double>(const HullPoints&, double);

}  // namespace grpvss::geometry
