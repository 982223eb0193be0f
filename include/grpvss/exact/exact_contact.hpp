#pragma once
/// \file
/// \brief Exact three-way classification of two convex point sets, and the thesis's
/// interference points (Section 4.2.3) computed exactly, containment included.
///
/// This is the decision the certified verifier trusts: no floating-point rounding can change
/// its answer. Points are arbitrary doubles (e.g. produced by floating-point forward
/// kinematics); only the convex hull of each set matters.
/// proof: proofs/interference.md#exact-sat

#include <vector>

#include <Eigen/Core>

#include "grpvss/exact/convex_polytope.hpp"
#include "grpvss/geometry/interference_kind.hpp"

namespace grpvss::geometry {

/// \brief How two closed convex bodies A and B meet.
enum class Contact {
  kSeparated,    ///< A and B share no point (distance > 0).
  kTouching,     ///< They share boundary points only: distance 0, interiors disjoint.
  kOverlapping,  ///< Interiors intersect (includes containment of either in the other).
};

/// \brief Printable name: "separated", "touching", "overlapping".
const char* to_string(Contact contact);

/// \brief Exact classification of conv(a) against conv(b).
///
/// Method: an exact bounding-box test (double comparisons are exact) answers far pairs
/// without hulls; otherwise exact hulls of both sets, then the separating-axis test over every face normal of
/// either hull and every edge(A) x edge(B) direction whose Gauss-map arcs cross (the facet
/// normals of A - B), each projection decided in interval arithmetic with an exact
/// (big-float) fallback. Separated iff some axis separates strictly; touching iff none does and
/// some axis has the projections meeting at one value; overlapping otherwise.
/// \throws DegenerateHullError if either set does not span 3-D.
Contact classify_exact(const std::vector<Eigen::Vector3d>& a,
                       const std::vector<Eigen::Vector3d>& b);

/// \brief Same decision on prebuilt exact hulls (saves the hull construction, ~0.3 ms for a
/// rotated 16-point hull, when one side is reused, e.g. a static obstacle or its offset).
Contact classify_exact(const ConvexPolytope& a, const ConvexPolytope& b);

/// \brief One point of conv(a) ∩ conv(b).
struct InterferencePoint {
  /// The exact (rational) point, rounded to double at the very end (each coordinate
  /// within one ulp of the exact value).
  Eigen::Vector3d point = Eigen::Vector3d::Zero();
  InterferenceKind kind = InterferenceKind::kEdgeOfAOnFaceOfB;
  /// Feature indices into ConvexPolytope::from_points(a) / from_points(b):
  /// edge index (edge kinds) or vertex index (vertex kinds) of the first-named hull ...
  int feature_first = -1;
  /// ... and face index of the second hull (edge kinds) or -1 (vertex kinds).
  int feature_second = -1;
};

/// \brief The thesis's interference points, exactly: edges of A crossing faces of B, edges of
/// B crossing faces of A (an edge lying IN a face plane contributes the two end points of its
/// part inside the face), plus vertices of either hull inside the other (the containment case
/// the thesis's edge-face test misses). Exact duplicates within one kind are reported once.
/// Empty iff classify_exact(a, b) == Contact::kSeparated.
/// \throws DegenerateHullError if either set does not span 3-D.
std::vector<InterferencePoint> interference_points(const std::vector<Eigen::Vector3d>& a,
                                                   const std::vector<Eigen::Vector3d>& b);

/// \brief Same on prebuilt exact hulls; feature indices refer to a and b directly.
std::vector<InterferencePoint> interference_points(const ConvexPolytope& a,
                                                   const ConvexPolytope& b);

}  // namespace grpvss::geometry
