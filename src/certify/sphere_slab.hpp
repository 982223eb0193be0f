#pragma once
// Separating slabs from two balls that contain the sets: what the probe uses when a pair is
// far apart, instead of GJK and a scan over every vertex.
// proof: proofs/separation-witness.md#sphere-slab

#include <Eigen/Core>

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

}  // namespace grpvss::certify
