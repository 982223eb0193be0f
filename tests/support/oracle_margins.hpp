#pragma once
// What the two independent float oracles (motion_oracle.cpp, urdf_cell_oracle.cpp) share:
// the margin a plane or sphere gap must clear to separate exactly, and a point set's largest
// coordinate. Defined once so that the tests' unity batches hold one definition.

#include <algorithm>
#include <vector>

#include <Eigen/Core>

namespace grpvss::test {

/// A gap larger than this separates exactly: far above double rounding for the oracles'
/// coordinates (below 10^3; a dot product's rounding ~10^-13 |v|_1 (1 + scale)).
inline double oracle_rounding_margin(double scale) { return 1e-9 * (1.0 + scale); }

/// The largest absolute coordinate of the points (0 for none).
inline double max_abs_coordinate(const std::vector<Eigen::Vector3d>& points) {
  double largest = 0.0;
  for (const auto& p : points) largest = std::max(largest, p.cwiseAbs().maxCoeff());
  return largest;
}

}  // namespace grpvss::test
