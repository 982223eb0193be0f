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

#include <array>
#include <cstdint>
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

/// \brief The vertices tied at the top of a climb: its end and the vertices connected to it
/// (through tied vertices) whose \f$d \cdot p\f$ is within `tie` of the end's, in float.
///
/// A support query along a face or an edge facing d ends on a plateau; the certified checks
/// (proofs/fast-path.md#placed-separation step 2, proofs/offset-containment.md
/// #lemma-climbed-support) prove the whole set instead of one vertex: every neighbour outside
/// it no higher than the set. Which vertices count as tied only decides how much those checks
/// test, never what they claim: a vertex wrongly left out is tested as a neighbour.
/// Membership is O(1) through marks kept per thread; at most one set per thread is in use.
class TiedSupportSet {
 public:
  /// A larger plateau (a CAD hull's flat face seen head on) is left to the callers' scans.
  static constexpr int kMaxMembers = 96;

  /// Gathers the set from the climb's end \p top; false where more than kMaxMembers tie.
  bool gather(const std::vector<Eigen::Vector3d>& points, const HullSkeleton& skeleton,
              const Eigen::Vector3d& d, int top, double tie);

  int size() const { return count_; }
  int member(int k) const { return members_[static_cast<std::size_t>(k)]; }
  bool contains(int i) const;

  /// True when \p holds(y) is true for every neighbour y of a member that is not a member.
  template <class Predicate>
  bool every_outside_neighbour(const HullSkeleton& skeleton, Predicate holds) const {
    for (int k = 0; k < count_; ++k) {
      const auto row = static_cast<std::size_t>(member(k));
      for (int e = skeleton.first[row]; e < skeleton.first[row + 1]; ++e) {
        const int y = skeleton.neighbours[static_cast<std::size_t>(e)];
        if (!contains(y) && !holds(y)) return false;
      }
    }
    return true;
  }

 private:
  std::array<int, kMaxMembers> members_{};
  int count_ = 0;
  std::uint32_t generation_ = 0;  ///< the marks' generation this set was gathered in
};

}  // namespace grpvss::geometry
