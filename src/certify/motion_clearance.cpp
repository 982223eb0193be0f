#include "motion_clearance.hpp"

#include <algorithm>
#include <limits>

#include "grpvss/geometry/directed_rounding.hpp"

namespace grpvss::certify {

double motion_clearance_lower_bound(double radius_k, double radius_k1, double motion_bound) {
  // proof: proofs/two-ball-cover.md#corollary-motion-clearance
  namespace r = geometry::rounding;
  const double sum_down = r::nearest_mode_add_down(radius_k, radius_k1);
  const double balanced = r::nearest_mode_sub_down(sum_down, motion_bound);
  // Halving is exact unless the result is subnormal; there a positive value is dropped to 0
  // (still a lower bound) rather than trusted to round down.
  double half = 0.5 * balanced;
  if (half > 0.0 && half < std::numeric_limits<double>::min()) half = 0.0;
  const double one_sided = r::nearest_mode_sub_down(std::max(radius_k, radius_k1), motion_bound);
  return std::max(half, one_sided);
}

}  // namespace grpvss::certify
