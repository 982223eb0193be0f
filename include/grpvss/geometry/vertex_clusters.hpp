#pragma once
/// \file
/// \brief A hull's vertices split into a few groups, each inside a ball: per-vertex bounds
/// (a vertex's clearance beyond a plane, its distance from an axis) evaluated per group at the
/// cost of a few balls instead of hundreds of vertices (proofs/two-ball-cover.md#revolution-vertex-bound).

#include <vector>

#include <Eigen/Core>

namespace grpvss::geometry {

/// Vertices `members` (indices into the hull's points) inside the ball (center_L, radius_up).
struct VertexCluster {
  Eigen::Vector3d center_L = Eigen::Vector3d::Zero();
  double radius_up = 0.0;  ///< the members' largest distance from center_L, rounded up
  std::vector<int> members;
};

/// Up to `leaves` clusters covering every point once: the points are halved at the median of
/// their box's longest side until there are `leaves` groups (or a group has one point); each
/// group's ball is centred at its box's midpoint. Deterministic (the checker rebuilds it and
/// verifies each radius exactly). Empty for no points.
std::vector<VertexCluster> cluster_vertices(const std::vector<Eigen::Vector3d>& points_L, int leaves);

/// Clusters per hull for the self pairs' vertex bounds (enough to follow a link's length).
inline constexpr int kVertexClusterLeaves = 16;

}  // namespace grpvss::geometry
