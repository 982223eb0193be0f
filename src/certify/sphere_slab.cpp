#include "sphere_slab.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include "grpvss/geometry/directed_rounding.hpp"

namespace grpvss::certify {

// proof: proofs/separation-witness.md#sphere-slab
bool sphere_witness(const Eigen::Vector3d& center_a, double radius_a,
                    const Eigen::Vector3d& center_b, double radius_b,
                    geometry::SeparationWitness& witness, double& lower_bound) {
  namespace r = geometry::rounding;
  const Eigen::Vector3d normal = center_b - center_a;
  if (!(normal.squaredNorm() > 0.0)) return false;
  r::UpwardRoundingScope upward;
  const double norm_up = r::sqrt_up(r::dot_up(normal.data(), normal.data()));
  const double offset_a = r::add_up(r::dot_up(normal.data(), center_a.data()),
                                    r::mul_up(radius_a, norm_up));
  const double offset_b = r::sub_down(r::dot_down(normal.data(), center_b.data()),
                                      r::mul_up(radius_b, norm_up));
  if (!(offset_b > offset_a)) return false;
  witness.normal = normal;
  witness.offset_a = offset_a;
  witness.offset_b = offset_b;
  lower_bound = std::max(0.0, r::div_down(r::sub_down(offset_b, offset_a), norm_up));
  return true;
}

double placed_sphere_radius(double radius_L, double placement_error) {
  namespace r = geometry::rounding;
  const double twice_error = 2.0 * placement_error;  // exact (no overflow for a valid cell)
  if (!std::isfinite(twice_error)) return std::numeric_limits<double>::infinity();
  return r::nearest_mode_add_up(radius_L, twice_error);
}

}  // namespace grpvss::certify
