#include "grpvss/geometry/hull_skeleton.hpp"

#include <algorithm>

namespace grpvss::geometry {
namespace {

/// Which vertices are in the current tied set, in O(1): vertex i is marked when its stamp is
/// the current generation (one array per thread, grown to the largest point set seen; a new
/// generation clears every mark at once).
class TiedMarks {
 public:
  std::uint32_t begin(std::size_t points) {
    if (stamps_.size() < points) stamps_.resize(points, 0);
    if (++generation_ == 0) {  // wrapped: old stamps could equal the new generation
      std::fill(stamps_.begin(), stamps_.end(), 0);
      generation_ = 1;
    }
    return generation_;
  }
  void mark(int i) { stamps_[static_cast<std::size_t>(i)] = generation_; }
  bool marked(int i, std::uint32_t generation) const {
    return static_cast<std::size_t>(i) < stamps_.size() &&
           stamps_[static_cast<std::size_t>(i)] == generation;
  }

 private:
  std::vector<std::uint32_t> stamps_;
  std::uint32_t generation_ = 0;
};

thread_local TiedMarks tied_marks;

}  // namespace

int climb_support_index(const std::vector<Eigen::Vector3d>& points, const HullSkeleton& skeleton,
                        int start, const Eigen::Vector3d& d) {
  int best = start;
  double best_value = points[static_cast<std::size_t>(best)].dot(d);
  // Steepest ascent: each move strictly increases the value, so no point is visited twice and
  // the climb ends (NaN values never compare greater).
  for (int at = -1; at != best;) {
    at = best;
    const int end = skeleton.first[static_cast<std::size_t>(at) + 1];
    for (int k = skeleton.first[static_cast<std::size_t>(at)]; k < end; ++k) {
      const int next = skeleton.neighbours[static_cast<std::size_t>(k)];
      const double value = points[static_cast<std::size_t>(next)].dot(d);
      if (value > best_value) {
        best = next;
        best_value = value;
      }
    }
  }
  return best;
}

bool TiedSupportSet::gather(const std::vector<Eigen::Vector3d>& points,
                            const HullSkeleton& skeleton, const Eigen::Vector3d& d, int top,
                            double tie) {
  generation_ = tied_marks.begin(points.size());
  count_ = 0;
  members_[static_cast<std::size_t>(count_++)] = top;
  tied_marks.mark(top);
  const double top_value = d.dot(points[static_cast<std::size_t>(top)]);
  for (int k = 0; k < count_; ++k) {
    const auto row = static_cast<std::size_t>(member(k));
    for (int e = skeleton.first[row]; e < skeleton.first[row + 1]; ++e) {
      const int y = skeleton.neighbours[static_cast<std::size_t>(e)];
      if (contains(y) || !(d.dot(points[static_cast<std::size_t>(y)]) >= top_value - tie)) continue;
      if (count_ == kMaxMembers) return false;
      members_[static_cast<std::size_t>(count_++)] = y;
      tied_marks.mark(y);
    }
  }
  return true;
}

// One set in use per thread: a later gather can only unmark this set's members, whose checks
// then test them as neighbours too, which only makes them stricter.
bool TiedSupportSet::contains(int i) const { return tied_marks.marked(i, generation_); }

}  // namespace grpvss::geometry
