// proofs/fast-path.md#placed-box-enclosure: the box from a link-frame box contains every
// computed placed point, and is not much larger than the placed corners' box.
#include "grpvss/geometry/placed_box.hpp"

#include <random>
#include <vector>

#include <gtest/gtest.h>

#include "grpvss/kinematics/forward_kinematics.hpp"

namespace grpvss::geometry {
namespace {

Eigen::Isometry3d random_box_pose(std::mt19937_64& rng, double reach) {
  std::normal_distribution<double> normal;
  std::uniform_real_distribution<double> uniform(-reach, reach);
  Eigen::Quaterniond rotation(normal(rng), normal(rng), normal(rng), normal(rng));
  rotation.normalize();
  Eigen::Isometry3d X = Eigen::Isometry3d::Identity();
  X.linear() = rotation.toRotationMatrix();
  X.translation() = Eigen::Vector3d(uniform(rng), uniform(rng), uniform(rng));
  return X;
}

bool contains(const Aabb& box, const Eigen::Vector3d& p) {
  return (box.lo.array() <= p.array()).all() && (p.array() <= box.hi.array()).all();
}

TEST(PlacedBox, ContainsEveryComputedPlacedPoint) {
  std::mt19937_64 rng(225);
  for (int trial = 0; trial < 2000; ++trial) {
    const double scale = std::pow(10.0, (trial % 7) - 3);  // 1e-3 .. 1e3
    std::uniform_real_distribution<double> coordinate(-scale, scale);
    std::vector<Eigen::Vector3d> points_L(40);
    for (auto& p : points_L) p = {coordinate(rng), coordinate(rng), coordinate(rng)};
    const Aabb box_L = Aabb::of_points(points_L);
    // The box's corners are the extreme cases of the interval image.
    for (int corner = 0; corner < 8; ++corner) {
      points_L.emplace_back(corner & 1 ? box_L.hi.x() : box_L.lo.x(),
                            corner & 2 ? box_L.hi.y() : box_L.lo.y(),
                            corner & 4 ? box_L.hi.z() : box_L.lo.z());
    }
    const Eigen::Isometry3d X_WL = random_box_pose(rng, 10.0 * scale);
    std::vector<Eigen::Vector3d> points_W;
    kinematics::place_points(X_WL, points_L, points_W);
    const Aabb box_W = placed_box_enclosure(box_L, X_WL);
    for (std::size_t k = 0; k < points_W.size(); ++k) {
      ASSERT_TRUE(contains(box_W, points_W[k])) << "trial " << trial << " point " << k;
    }
    // Tight: the corners' placed box grown by at most 1e-12 of the scale per side.
    const Aabb corners_W = Aabb::of_points(
        std::vector<Eigen::Vector3d>(points_W.end() - 8, points_W.end()));
    EXPECT_LE((corners_W.lo - box_W.lo).maxCoeff(), 1e-12 * 20.0 * scale);
    EXPECT_LE((box_W.hi - corners_W.hi).maxCoeff(), 1e-12 * 20.0 * scale);
  }
}

TEST(PlacedBox, TheIdentityKeepsTheBoxUpToTheRoundingSlack) {
  Aabb box_L;
  box_L.lo = {-1.0, 2.0, -0.5};
  box_L.hi = {3.0, 4.0, 0.25};
  const Aabb box_W = placed_box_enclosure(box_L, Eigen::Isometry3d::Identity());
  // slack_i = 8u * max|p_i| + 2^-1000, then the end rounded outward (one more ulp, <= 2u|x|):
  // a few ulps outside the box, never inside.
  for (int i = 0; i < 3; ++i) {
    EXPECT_LT(box_W.lo[i], box_L.lo[i]);
    EXPECT_GT(box_W.hi[i], box_L.hi[i]);
    const double reach = std::max(std::fabs(box_L.lo[i]), std::fabs(box_L.hi[i]));
    EXPECT_LE(box_L.lo[i] - box_W.lo[i], 12.0 * 0x1p-53 * reach);
    EXPECT_LE(box_W.hi[i] - box_L.hi[i], 12.0 * 0x1p-53 * reach);
  }
}

}  // namespace
}  // namespace grpvss::geometry
