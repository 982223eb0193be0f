#pragma once
/// \file
/// \brief The vertex graph (1-skeleton) of a convex polytope, for support queries that climb
/// along edges instead of scanning every vertex.
///
/// On a convex polytope a linear function has no local maximum on the skeleton that is not a
/// global one (the simplex method's argument), so climbing from any vertex to a neighbour
/// with a larger value ends at a support vertex. GJK uses this on placed link offsets, whose
/// points are a rounded rigid image of the template: there a climb can stop a rounding error
/// short of the maximum. That is harmless because GJK only proposes (gjk.hpp): every claim is
/// certified over all points afterwards (certified_query.hpp).

#include <vector>

#include <Eigen/Core>

namespace grpvss::geometry {

/// \brief Neighbours of each point of a point set, in compressed rows: the neighbours of
/// point i are `neighbours[first[i]] .. neighbours[first[i + 1] - 1]`, ascending.
struct HullSkeleton {
  std::vector<int> first;
  std::vector<int> neighbours;

  int point_count() const { return static_cast<int>(first.size()) - 1; }
};

/// The skeleton of an exact hull: exact/polytope_skeleton.hpp builds it.

/// \brief A point of \p points maximising \f$d \cdot p\f$ reached by climbing \p skeleton from
/// \p start: the neighbour with the largest value is taken while it beats the current point.
/// Exact on the polytope the skeleton was built from (ties aside); a vertex within rounding
/// of the maximum on a rounded image of it.
int climb_support_index(const std::vector<Eigen::Vector3d>& points, const HullSkeleton& skeleton,
                        int start, const Eigen::Vector3d& d);

}  // namespace grpvss::geometry
