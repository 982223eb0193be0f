#pragma once
/// \file
/// \brief Tolerance offsets H (+) P_r with P_r a polytope containing the ball B(0, r), and the
/// exact check that a double polytope contains H (+) B(0, r).
///
/// Soundness rests only on contains_ball_sum_exactly(): every offset returned by
/// minkowski_offset() has passed it against the REQUESTED radius.
/// proof: proofs/tolerance-offset.md#ball-containment

#include <vector>

#include <Eigen/Core>

#include "grpvss/exact/convex_polytope.hpp"
#include "grpvss/geometry/offset_shape.hpp"

namespace grpvss::geometry {

/// \brief The offset polytope P_r itself (centred at the origin), with B(0, r) inside it
/// verified exactly.
/// \throws std::invalid_argument unless r is finite and > 0.
ConvexPolytope offset_shape_polytope(double radius, OffsetShape shape);

/// \brief Exact check that B(0, radius) is inside \p p: for every face plane n.x <= c of p
/// (exact plane through the face's double vertices), \f$c \ge 0\f$ and
/// \f$c^2 \ge r^2 |n|^2\f$, in exact arithmetic.
bool contains_ball_exactly(const ConvexPolytope& p, double radius);

/// \brief A double polytope containing hull (+) B(0, radius), verified exactly.
///
/// Candidate = exact hull of the correctly rounded pairwise sums fl(h + q), h a vertex of
/// \p hull, q a vertex of P_r (these are the rounded vertices of the exact rational sum,
/// plus any sum that rounding pushed onto the hull). The candidate is accepted only if
/// contains_ball_sum_exactly(candidate, hull, radius); otherwise P is inflated to
/// \f$r' = r + 2^k (2^{-40} r + 8\,\mathrm{ulp}(\max|h|))\f$, k = 0, 1, ..., and the sum
/// rebuilt (the check is always against the requested r). Build offsets ONCE (per link
/// hull in its link frame, per obstacle in the world); never rotate an offset in floating point.
/// \throws std::invalid_argument unless radius is finite and > 0;
///         std::logic_error if no candidate verifies after several inflations.
ConvexPolytope minkowski_offset(const ConvexPolytope& hull, double radius, OffsetShape shape);

/// \brief Exact decision: is inner (+) B(0, radius) contained in outer?
///
/// For every face plane n.x <= c of \p outer (exact plane through its double vertices):
/// \f$\max_{h \in inner} n\cdot h + r|n| \le c\f$, decided exactly by squaring
/// (\f$g = c - \max n\cdot h \ge 0\f$ and \f$g^2 \ge r^2|n|^2\f$). radius >= 0 required.
bool contains_ball_sum_exactly(const ConvexPolytope& outer, const ConvexPolytope& inner,
                               double radius);
/// \brief The same decision, each face's max n.h taken at a vertex of \p inner found by climbing
/// its edge graph and proven maximal by its neighbours (interval arithmetic); faces where no
/// vertex is proven are scanned as above. Same answer, O(climb) instead of O(|inner|) per
/// face: what the verifier uses (minkowski_offset, recheck_offset). The certificate checker
/// keeps the scan. proof: proofs/offset-containment.md#lemma-climbed-support
/// \p faces_climbed, when given, receives how many faces the climbed set decided or passed to
/// the exact test without a scan (the rest were scanned).
bool contains_ball_sum_by_climbing(const ConvexPolytope& outer, const ConvexPolytope& inner,
                                   double radius, int* faces_climbed = nullptr);
/// \brief Same, with inner given as points (only their convex hull matters; a single point
/// {0,0,0} checks ball containment).
bool contains_ball_sum_exactly(const ConvexPolytope& outer,
                               const std::vector<Eigen::Vector3d>& inner, double radius);

/// \brief Diagnostic form of contains_ball_sum_exactly() (used to audit the thesis's
/// floating-point expansion).
struct BallSumContainmentReport {
  /// Exact verdict: inner (+) B(0, radius) is inside outer.
  bool contained = false;
  /// How far the worst point of inner (+) B(0, radius) lies outside outer's worst face plane,
  /// \f$\max_{faces}(\max_h n\cdot h + r|n| - c)/|n|\f$, evaluated in double AFTER the exact
  /// decision (<= 0 means inside by that much; its sign may disagree with `contained` only
  /// within rounding — trust `contained`).
  double worst_protrusion = 0.0;
  /// The point realizing worst_protrusion: \f$h^* + r\,n/|n|\f$ (double).
  Eigen::Vector3d worst_point = Eigen::Vector3d::Zero();
  /// Index into outer.faces() of the worst face.
  int worst_face = -1;
};

/// \brief Exact verdict plus the double-evaluated worst protrusion.
BallSumContainmentReport ball_sum_containment_report(const ConvexPolytope& outer,
                                                     const std::vector<Eigen::Vector3d>& inner,
                                                     double radius);

}  // namespace grpvss::geometry
