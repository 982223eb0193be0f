#include "grpvss/geometry/rounded_bounds.hpp"

#include <algorithm>
#include <cmath>

#include "grpvss/geometry/directed_rounding.hpp"

namespace grpvss::geometry {

double trig_magnitude_upper(double computed) {
  // proof: proofs/fk-rounding.md#trig-rounding (libm within 2 ulp; an ulp of |x| <= 1 is at
  // most 2^-52), so |true| <= |computed| + 2^-51, and never above 1.
  namespace r = rounding;
  r::UpwardRoundingScope upward;
  return std::min(1.0, r::add_up(std::abs(computed), 0x1p-51));
}

double radial_extent_upper(const HullPoints& hull) {
  namespace r = rounding;
  double largest = 0.0;
  r::UpwardRoundingScope upward;
  for (const auto& p : hull.points) {
    const double x = std::abs(p.x());
    const double y = std::abs(p.y());
    largest = std::max(largest, r::sqrt_up(r::add_up(r::mul_up(x, x), r::mul_up(y, y))));
  }
  return largest;
}

}  // namespace grpvss::geometry
