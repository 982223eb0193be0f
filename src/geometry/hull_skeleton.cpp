#include "grpvss/geometry/hull_skeleton.hpp"


namespace grpvss::geometry {

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

}  // namespace grpvss::geometry
