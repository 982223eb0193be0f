#pragma once
// Random convex point sets with fixed seeds for the geometry fast-path tests and benchmarks.
// Header-only so that the benchmark binary (which does not compile tests/support/*.cpp) can use it.

#include <cmath>
#include <random>
#include <vector>

#include <Eigen/Core>
#include <Eigen/Geometry>

namespace grpvss::test {

/// A random rotation (uniform quaternion) from \p rng.
inline Eigen::Matrix3d random_rotation(std::mt19937_64& rng) {
  std::normal_distribution<double> normal(0.0, 1.0);
  Eigen::Quaterniond q(normal(rng), normal(rng), normal(rng), normal(rng));
  q.normalize();
  return q.toRotationMatrix();
}

/// 16 points: an irregular octagonal prism (like the thesis's hulls) of circumradius about
/// \p radius, rotated at random and centred at \p center.
inline std::vector<Eigen::Vector3d> random_prism(std::mt19937_64& rng,
                                                 const Eigen::Vector3d& center, double radius) {
  std::uniform_real_distribution<double> jitter(0.7, 1.0);
  std::uniform_real_distribution<double> height(0.5, 1.5);
  const Eigen::Matrix3d rotation = random_rotation(rng);
  const double h = height(rng) * radius;
  std::vector<Eigen::Vector3d> points;
  for (int layer = 0; layer < 2; ++layer) {
    for (int k = 0; k < 8; ++k) {
      const double angle = k * M_PI / 4.0;
      const double r = radius * jitter(rng);
      const double z = layer == 0 ? -h / 2 : h / 2;
      const Eigen::Vector3d p_L(r * std::cos(angle), r * std::sin(angle), z);
      points.push_back(center + rotation * p_L);
    }
  }
  return points;
}

/// The 8 vertices of the axis-aligned cube [lo, lo + side]^3.
inline std::vector<Eigen::Vector3d> cube(const Eigen::Vector3d& lo, double side) {
  std::vector<Eigen::Vector3d> points;
  for (int k = 0; k < 8; ++k) {
    points.push_back(lo + side * Eigen::Vector3d(k & 1, (k >> 1) & 1, (k >> 2) & 1));
  }
  return points;
}

/// \p points translated by \p t (exactly when the sums are representable).
inline std::vector<Eigen::Vector3d> translated(std::vector<Eigen::Vector3d> points,
                                        const Eigen::Vector3d& t) {
  for (auto& p : points) p += t;
  return points;
}

}  // namespace grpvss::test
