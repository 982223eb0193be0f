#include "support/random_shapes.hpp"

#include <cmath>

namespace grpvss::test {

Eigen::Matrix3d random_rotation(std::mt19937_64& rng) {
  std::normal_distribution<double> normal(0.0, 1.0);
  Eigen::Quaterniond q(normal(rng), normal(rng), normal(rng), normal(rng));
  q.normalize();
  return q.toRotationMatrix();
}

std::vector<Eigen::Vector3d> random_prism(std::mt19937_64& rng, const Eigen::Vector3d& center,
                                          double radius) {
  std::uniform_real_distribution<double> jitter(0.7, 1.0);
  std::uniform_real_distribution<double> height(0.5, 1.5);
  const Eigen::Matrix3d rotation = random_rotation(rng);
  const double h = height(rng) * radius;
  std::vector<Eigen::Vector3d> points;
  for (int layer = 0; layer < 2; ++layer) {
    for (int k = 0; k < 8; ++k) {
      const double angle = k * M_PI / 4.0;
      const double r = radius * jitter(rng);
      const Eigen::Vector3d p_L(r * std::cos(angle), r * std::sin(angle), layer == 0 ? -h / 2 : h / 2);
      points.push_back(center + rotation * p_L);
    }
  }
  return points;
}

std::vector<Eigen::Vector3d> cube(const Eigen::Vector3d& lo, double side) {
  std::vector<Eigen::Vector3d> points;
  for (int k = 0; k < 8; ++k) {
    points.push_back(lo + side * Eigen::Vector3d(k & 1, (k >> 1) & 1, (k >> 2) & 1));
  }
  return points;
}

std::vector<Eigen::Vector3d> translated(std::vector<Eigen::Vector3d> points,
                                        const Eigen::Vector3d& t) {
  for (auto& p : points) p += t;
  return points;
}

}  // namespace grpvss::test
