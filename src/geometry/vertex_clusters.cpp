#include "grpvss/geometry/vertex_clusters.hpp"

#include <algorithm>
#include <deque>

#include "grpvss/geometry/directed_rounding.hpp"

namespace grpvss::geometry {
namespace {

struct Box {
  Eigen::Vector3d lo, hi;
};

Box box_of(const std::vector<Eigen::Vector3d>& points, const std::vector<int>& members) {
  Box box{points[static_cast<std::size_t>(members.front())], points[static_cast<std::size_t>(members.front())]};
  for (const int m : members) {
    box.lo = box.lo.cwiseMin(points[static_cast<std::size_t>(m)]);
    box.hi = box.hi.cwiseMax(points[static_cast<std::size_t>(m)]);
  }
  return box;
}

VertexCluster enclose(const std::vector<Eigen::Vector3d>& points, std::vector<int> members) {
  namespace r = rounding;
  const Box box = box_of(points, members);
  VertexCluster cluster;
  cluster.center_L = (box.lo + box.hi) * 0.5;  // any centre is sound: the radius is measured from it
  r::UpwardRoundingScope upward;
  double largest_square = 0.0;
  for (const int m : members) {
    const Eigen::Vector3d& u = points[static_cast<std::size_t>(m)];
    double square = 0.0;
    for (int k = 0; k < 3; ++k) {
      const double lo = r::sub_down(u[k], cluster.center_L[k]);
      const double hi = r::sub_up(u[k], cluster.center_L[k]);
      square = r::add_up(square, r::square_up_of_range(lo, hi));
    }
    largest_square = std::max(largest_square, square);
  }
  cluster.radius_up = r::sqrt_up(largest_square);
  cluster.members = std::move(members);
  return cluster;
}

}  // namespace

std::vector<VertexCluster> cluster_vertices(const std::vector<Eigen::Vector3d>& points_L, int leaves) {
  std::vector<VertexCluster> clusters;
  if (points_L.empty()) return clusters;
  std::vector<int> all(points_L.size());
  for (std::size_t i = 0; i < all.size(); ++i) all[i] = static_cast<int>(i);
  // Breadth first: the widest groups are halved first, so every group shrinks about evenly.
  std::deque<std::vector<int>> groups{std::move(all)};
  while (static_cast<int>(groups.size()) < std::max(1, leaves) && groups.front().size() > 1) {
    std::vector<int> group = std::move(groups.front());
    groups.pop_front();
    const Box box = box_of(points_L, group);
    Eigen::Index side = 0;
    (box.hi - box.lo).maxCoeff(&side);
    const auto middle = group.begin() + static_cast<std::ptrdiff_t>(group.size() / 2);
    std::nth_element(group.begin(), middle, group.end(), [&](int x, int y) {
      const double px = points_L[static_cast<std::size_t>(x)][side];
      const double py = points_L[static_cast<std::size_t>(y)][side];
      return px < py || (px == py && x < y);  // a strict total order: the split is deterministic
    });
    groups.emplace_back(group.begin(), middle);
    groups.emplace_back(middle, group.end());
  }
  for (std::vector<int>& group : groups) clusters.push_back(enclose(points_L, std::move(group)));
  return clusters;
}

}  // namespace grpvss::geometry
