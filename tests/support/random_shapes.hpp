#pragma once
// Random convex point sets with fixed seeds for the geometry fast-path tests and benchmarks.

#include <random>
#include <vector>

#include <Eigen/Core>
#include <Eigen/Geometry>

namespace grpvss::test {

/// A random rotation (uniform quaternion) from \p rng.
Eigen::Matrix3d random_rotation(std::mt19937_64& rng);

/// 16 points: an irregular octagonal prism (like the thesis's hulls) of circumradius about
/// \p radius, rotated at random and centred at \p center.
std::vector<Eigen::Vector3d> random_prism(std::mt19937_64& rng, const Eigen::Vector3d& center,
                                          double radius);

/// The 8 vertices of the axis-aligned cube [lo, lo + side]^3.
std::vector<Eigen::Vector3d> cube(const Eigen::Vector3d& lo, double side);

/// \p points translated by \p t (exactly when the sums are representable).
std::vector<Eigen::Vector3d> translated(std::vector<Eigen::Vector3d> points,
                                        const Eigen::Vector3d& t);

}  // namespace grpvss::test
