#pragma once
// The revolution route weighed vertex by vertex: when only hull b's own joint moves it relative to
// hull a's solid of revolution, each vertex's arc is charged against that vertex's own clearance
// beyond the witness's plane, not the hull's farthest point against the nearest one. The largest
// charge over hundreds of vertices is found by branch and bound over a few vertex clusters
// (geometry::cluster_vertices): a cluster's ball bounds its vertices' terms, and only the
// clusters that might hold the largest are placed vertex by vertex.
// proof: proofs/two-ball-cover.md#revolution-vertex-bound

#include <vector>

#include <Eigen/Core>

#include "cell_probe.hpp"
#include "grpvss/certify/robot_cell.hpp"

namespace grpvss::certify {

class StepAxisRadii;

/// Whether pair `pair` may take the vertex bound: hull a has a solid of revolution (joint a+1
/// frozen) and the only joint left between them, b's own, is revolute (link b = link a + 2).
bool has_vertex_route(const RobotCell& cell, const SelfPairHulls& pair);

/// \brief One end (probe) of a pair's vertex bound: e, lower bounds (>= 0) of hull b's vertices'
/// clearance beyond the pair witness's plane on b's side, per cluster at reset and per vertex once
/// its cluster is evaluated. The vertices' distances from b's own axis never change: they are
/// the cell's (LinkHull::own_axis_distances).
class VertexRouteEnd {
 public:
  /// The cluster bounds of pair `p` (with has_vertex_route) at `probe`; false when the probe
  /// proves no route distance for the pair (no witness, or c = 0) or kept no frames.
  bool reset(const StepAxisRadii& radii, std::size_t p, const ProbeResult& probe);
  /// Whether this end was reset for pair p of the same StepAxisRadii (by identity: another at
  /// the same address is another run) at a probe of configuration q with the same evidence for
  /// the pair (a probe of the same q may prove another slab; e and c must share theirs).
  bool is_for(const StepAxisRadii& radii, std::size_t p, const ProbeResult& probe) const;
  bool usable() const { return usable_; }

  int hull() const { return hull_; }
  std::size_t cluster_count() const { return cluster_excess_.size(); }
  /// A lower bound of e over the cluster's vertices.
  double cluster_excess(std::size_t cluster) const { return cluster_excess_[cluster]; }
  /// Places the vertices of `cluster` and evaluates their e (once per reset).
  void evaluate(std::size_t cluster);
  double vertex_excess(int vertex) const { return vertex_excess_[static_cast<std::size_t>(vertex)]; }

 private:
  /// e of a placed point, less `radius`, at least 0 (round-to-nearest less the margin).
  double excess_of(const Eigen::Vector3d& placed_W, double radius) const;

  const StepAxisRadii* radii_ = nullptr;
  unsigned long long radii_identity_ = 0;
  std::size_t pair_ = 0;
  double route_distance_ = 0.0;
  Eigen::VectorXd q_;
  bool usable_ = false;
  int hull_ = 0;
  Eigen::Isometry3d X_WL_ = Eigen::Isometry3d::Identity();  ///< hull b's link at this end
  geometry::SeparationWitness witness_;
  double normal_length_up_ = 0.0;
  double inverse_normal_length_ = 0.0;  ///< RN(1 / normal_length_up_)
  double margin_ = 0.0;  ///< round-off allowance of e (proofs/two-ball-cover.md#vertex-excess)
  std::vector<double> cluster_excess_;
  std::vector<char> evaluated_;
  std::vector<double> vertex_excess_;
};

/// The end of pair `p` at `probe`, reset or taken from a few kept ones (the march asks for the
/// same ends in its proposal and in each trial from a step); nullptr when the probe proves no
/// route distance for the pair. Valid until five more ends are asked for.
VertexRouteEnd* vertex_route_end(const StepAxisRadii& radii, std::size_t p, const ProbeResult& probe);

/// M_v = max(0, max_v (V_b D(v) - min(e_k(v), e_k+1(v)))) rounded up, for `increment_up` >=
/// the variation V_b of hull b's joint. It stands in for the route's M' in both the step rule and
/// the kept gap.
double vertex_route_bound(const StepAxisRadii& radii, VertexRouteEnd& from, VertexRouteEnd& to,
                          double increment_up);

/// For proposals only (plain double): the weight r of b's joint with which "V_b r < 2 c" is
/// "V_b D(v) - e(v) < 2 c for every vertex", the ends assumed alike: max_v D(v) 2c / (2c + e(v)).
double vertex_route_proposal_radius(const StepAxisRadii& radii, VertexRouteEnd& at, double route_distance);

}  // namespace grpvss::certify
