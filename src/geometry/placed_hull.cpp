#include "grpvss/geometry/placed_hull.hpp"

#include <algorithm>

namespace grpvss::geometry {

double max_abs_coordinate(const std::vector<Eigen::Vector3d>& points) {
  double largest = 0.0;
  for (const auto& p : points) largest = std::max(largest, p.cwiseAbs().maxCoeff());
  return largest;
}

}  // namespace grpvss::geometry
