#pragma once
/// \file
/// \brief GJK (Gilbert, Johnson, Keerthi 1988) in double precision on two point sets.
///
/// This is the "floating point proposes" half of the fast path: its answers are NEVER used as
/// decisions. certified_query.hpp turns them into proofs (or falls back to exact arithmetic).
/// The support function runs over the raw points, so no hull topology is needed:
/// \f$\mathrm{conv}(A) - \mathrm{conv}(B) = \mathrm{conv}\{a - b\}\f$.

#include <array>
#include <vector>

#include <Eigen/Core>

#include "grpvss/geometry/hull_skeleton.hpp"
#include "grpvss/geometry/placed_hull.hpp"

namespace grpvss::geometry {

/// \brief What double-precision GJK believes about two point sets.
enum class GjkStatus {
  kSeparated,    ///< converged to a positive distance; `closest_vector` points from B to A
  kOverlapping,  ///< a tetrahedron of Minkowski-difference points encloses the origin
  kNearContact,  ///< distance below GJK's resolution: neither claim is worth certifying
};

/// \brief The double-precision GJK result. Indices refer to the input point vectors.
struct GjkResult {
  GjkStatus status = GjkStatus::kNearContact;
  /// Closest point of \f$\mathrm{conv}(A)-\mathrm{conv}(B)\f$ to the origin, \f$v = a^* - b^*\f$.
  Eigen::Vector3d closest_vector = Eigen::Vector3d::Zero();
  Eigen::Vector3d closest_a = Eigen::Vector3d::Zero();  ///< \f$a^*\f$ (estimate)
  Eigen::Vector3d closest_b = Eigen::Vector3d::Zero();  ///< \f$b^*\f$ (estimate)
  double distance = 0.0;  ///< \f$\lvert v\rvert\f$, 0 unless separated
  /// Final simplex: vertex k is a[simplex_a[k]] - b[simplex_b[k]], k < simplex_size.
  int simplex_size = 0;
  std::array<int, 4> simplex_a{};
  std::array<int, 4> simplex_b{};
  int iterations = 0;
  int last_support_a = 0;  ///< index into a of the last support point of A computed
  int last_support_b = 0;  ///< index into b of the last support point of B computed
};

/// \brief Runs GJK on the convex hulls of \p a and \p b (each non-empty).
/// \param warm_start_normal optional direction believed to separate A (below) from B (above),
///        e.g. the previous step's witness normal; GJK starts from \f$v = -n\f$.
/// \param a_skeleton optional vertex graph of conv(a) in a's numbering (hull_skeleton.hpp):
///        A's support points are then climbed to from the last one instead of scanned for.
/// \param a_climb_start with a_skeleton: where the first climb starts (an index into a, e.g.
///        the previous query's last support point); 0 if null or out of range.
/// \param b_skeleton, b_climb_start the same for B (e.g. two link hulls of a self pair).
/// \throws std::invalid_argument if a point set is empty or a skeleton does not fit its set.
GjkResult gjk(const std::vector<Eigen::Vector3d>& a, const std::vector<Eigen::Vector3d>& b,
              const Eigen::Vector3d* warm_start_normal = nullptr,
              const HullSkeleton* a_skeleton = nullptr, int a_climb_start = 0,
              const HullSkeleton* b_skeleton = nullptr, int b_climb_start = 0);

/// \brief A separated pair's final GJK simplex (vertex indices), kept for the pair's next
/// query: consecutive steps move a pair little, so starting from those vertices at their new
/// places takes GJK fewer iterations than starting from one support point. size 0: none.
struct GjkSimplexHint {
  int size = 0;
  std::array<int, 4> a{};
  std::array<int, 4> b{};
};

/// \brief GJK on two placed link-frame hulls: each support point is climbed to on the
/// template's skeleton in direction \f$\hat R^T d\f$ and placed alone (PlacedHull::point_W),
/// so a query visits a few vertices instead of placing all. Indices refer to vertices_L.
/// Proposes like the overload above (the climb may end a rounding error short of the placed
/// set's maximum). \throws std::invalid_argument if a hull lacks its vertices or skeleton.
/// \param simplex_hint optional, in: where the query starts (ignored when empty or out of
///        range), out: this query's final simplex if separated, else empty.
GjkResult gjk(const PlacedHull& a, const PlacedHull& b,
              const Eigen::Vector3d* warm_start_normal = nullptr, int a_climb_start = 0,
              int b_climb_start = 0, GjkSimplexHint* simplex_hint = nullptr);

/// \brief GJK on a placed link-frame hull and a set of world points (an obstacle).
GjkResult gjk(const PlacedHull& a, const std::vector<Eigen::Vector3d>& b,
              const Eigen::Vector3d* warm_start_normal = nullptr, int a_climb_start = 0,
              GjkSimplexHint* simplex_hint = nullptr);

/// \brief Index of the point of \p points maximising \f$d \cdot p\f$ (first on ties).
int support_index(const std::vector<Eigen::Vector3d>& points, const Eigen::Vector3d& d);

}  // namespace grpvss::geometry
