#include "grpvss/geometry/placed_box.hpp"

#include <algorithm>
#include <cmath>

#include "grpvss/geometry/directed_rounding.hpp"

namespace grpvss::geometry {
namespace {

constexpr double kUnitRoundoff = 0x1p-53;
constexpr double kUnderflowSlack = 0x1p-1000;

}  // namespace

// proof: proofs/fast-path.md#placed-box-enclosure
Aabb placed_box_enclosure(const Aabb& box_L, const Eigen::Isometry3d& X_WL) {
  using namespace rounding;
  const UpwardRoundingScope upward;
  const auto& R = X_WL.linear();
  const auto& t = X_WL.translation();
  Aabb box_W;
  for (int i = 0; i < 3; ++i) {
    double lo = t[i], hi = t[i], magnitude = std::fabs(t[i]);
    for (int j = 0; j < 3; ++j) {
      const double a = R(i, j);
      lo = add_down(lo, std::min(mul_down(a, box_L.lo[j]), mul_down(a, box_L.hi[j])));
      hi = add_up(hi, std::max(mul_up(a, box_L.lo[j]), mul_up(a, box_L.hi[j])));
      const double reach = std::max(std::fabs(box_L.lo[j]), std::fabs(box_L.hi[j]));
      magnitude = add_up(magnitude, mul_up(std::fabs(a), reach));
    }
    const double slack = add_up(mul_up(8.0 * kUnitRoundoff, magnitude), kUnderflowSlack);
    box_W.lo[i] = sub_down(lo, slack);
    box_W.hi[i] = add_up(hi, slack);
  }
  return box_W;
}

}  // namespace grpvss::geometry
