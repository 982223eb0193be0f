// Vertex clusters (include/grpvss/geometry/vertex_clusters.hpp): every point in exactly one
// cluster, inside its ball exactly, the split deterministic and following a long link's length.

#include <algorithm>
#include <random>
#include <vector>

#include <gmpxx.h>
#include <gtest/gtest.h>

#include "grpvss/geometry/vertex_clusters.hpp"

namespace grpvss::geometry {
namespace {

std::vector<Eigen::Vector3d> box_cloud(const Eigen::Vector3d& size, int count, unsigned seed) {
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> u(-0.5, 0.5);
  std::vector<Eigen::Vector3d> points;
  for (int i = 0; i < count; ++i) points.emplace_back(size.x() * u(rng), size.y() * u(rng), size.z() * u(rng));
  return points;
}

TEST(VertexClusters, EveryPointIsInExactlyOneClusterAndInsideItsBallExactly) {
  const std::vector<Eigen::Vector3d> points = box_cloud({0.5, 0.1, 0.1}, 997, 4);
  const std::vector<VertexCluster> clusters = cluster_vertices(points, kVertexClusterLeaves);
  ASSERT_EQ(clusters.size(), static_cast<std::size_t>(kVertexClusterLeaves));
  std::vector<int> seen(points.size(), 0);
  for (const VertexCluster& cluster : clusters) {
    const mpq_class radius_square = mpq_class(cluster.radius_up) * mpq_class(cluster.radius_up);
    mpq_class largest = 0;
    for (const int v : cluster.members) {
      ++seen[static_cast<std::size_t>(v)];
      mpq_class square = 0;
      for (int k = 0; k < 3; ++k) {
        const mpq_class d = mpq_class(points[static_cast<std::size_t>(v)][k]) - mpq_class(cluster.center_L[k]);
        square += d * d;
      }
      EXPECT_LE(square, radius_square);
      largest = std::max(largest, square);
    }
    // Rounded up by a hair, not padded: within 1e-12 of the exact largest distance.
    EXPECT_LT(cluster.radius_up * cluster.radius_up - largest.get_d(), 1e-12);
  }
  EXPECT_TRUE(std::all_of(seen.begin(), seen.end(), [](int n) { return n == 1; }));
}

TEST(VertexClusters, AreDeterministicAndFollowALongLinksLength) {
  const std::vector<Eigen::Vector3d> points = box_cloud({0.5, 0.1, 0.1}, 600, 8);
  const std::vector<VertexCluster> first = cluster_vertices(points, 16);
  const std::vector<VertexCluster> again = cluster_vertices(points, 16);
  ASSERT_EQ(first.size(), again.size());
  for (std::size_t i = 0; i < first.size(); ++i) {
    EXPECT_EQ(first[i].members, again[i].members);
    EXPECT_EQ(first[i].center_L, again[i].center_L);
    EXPECT_EQ(first[i].radius_up, again[i].radius_up);
  }
  // Halving the widest side first: 16 pieces of a 0.5 x 0.1 x 0.1 box are about 0.06 x 0.05 x
  // 0.05 (radius ~0.046), far below the whole box's 0.26.
  double largest = 0.0;
  for (const VertexCluster& cluster : first) largest = std::max(largest, cluster.radius_up);
  EXPECT_LT(largest, 0.06);
}

TEST(VertexClusters, SmallInputs) {
  EXPECT_TRUE(cluster_vertices({}, 16).empty());
  const std::vector<VertexCluster> one = cluster_vertices({Eigen::Vector3d(1, 2, 3)}, 16);
  ASSERT_EQ(one.size(), 1u);
  EXPECT_EQ(one[0].radius_up, 0.0);
  EXPECT_EQ(one[0].members, std::vector<int>{0});
  // Fewer points than leaves: one point per cluster at most.
  const std::vector<VertexCluster> few = cluster_vertices(box_cloud({1, 1, 1}, 5, 1), 16);
  EXPECT_LE(few.size(), 5u);
  std::size_t members = 0;
  for (const VertexCluster& cluster : few) members += cluster.members.size();
  EXPECT_EQ(members, 5u);
}

}  // namespace
}  // namespace grpvss::geometry
