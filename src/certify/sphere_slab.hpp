#pragma once
// Separating slabs from two balls that contain the sets: what the probe uses when a pair is
// far apart, instead of GJK and a scan over every vertex.
// proof: proofs/separation-witness.md#sphere-slab

#include <algorithm>
#include <cmath>
#include <limits>

#include <Eigen/Core>

#include "grpvss/geometry/directed_rounding.hpp"
#include "grpvss/geometry/separation_witness.hpp"

namespace grpvss::certify {

/// \brief A slab separating the balls B(center_a, radius_a) and B(center_b, radius_b): normal
/// n = center_b - center_a, offset_a >= n.center_a + radius_a |n|, offset_b <= n.center_b -
/// radius_b |n|, all with directed rounding; `lower_bound` = (offset_b - offset_a) rounded down
/// over |n| rounded up (as certify_separation forms it, proofs/fast-path.md#certified-separation).
/// False when the rounded offsets leave no gap.
bool sphere_witness(const Eigen::Vector3d& center_a, double radius_a,
                    const Eigen::Vector3d& center_b, double radius_b,
                    geometry::SeparationWitness& witness, double& lower_bound);

/// \brief The radius of a ball around a placed centre that contains every placed point of a
/// set within \p radius_L of the template centre: |p~ - c~| <= |p - c| + 2 eps for a rigidly
/// placed p, c computed with error < eps each (rounded up).
double placed_sphere_radius(double radius_L, double placement_error);

// Inline: the probe calls these per hull and obstacle pair (a call costs ~3% of a thesis
// operation).
// proof: proofs/separation-witness.md#sphere-slab
inline bool sphere_witness(const Eigen::Vector3d& center_a, double radius_a,
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

inline double placed_sphere_radius(double radius_L, double placement_error) {
  namespace r = geometry::rounding;
  const double twice_error = 2.0 * placement_error;  // exact (no overflow for a valid cell)
  if (!std::isfinite(twice_error)) return std::numeric_limits<double>::infinity();
  return r::nearest_mode_add_up(radius_L, twice_error);
}

}  // namespace grpvss::certify
