#pragma once
// The revolution route weighed vertex by vertex: when only hull b's own joint moves it relative to
// hull a's solid of revolution, each vertex's arc is charged against that vertex's own clearance
// beyond the witness's plane, not the hull's farthest point against the nearest one.
// proof: proofs/two-ball-cover.md#revolution-vertex-bound

#include <vector>

#include <Eigen/Core>

#include "cell_probe.hpp"
#include "grpvss/certify/robot_cell.hpp"

namespace grpvss::certify {

/// Per vertex of hull b at one configuration: its clearance beyond the pair witness's plane on
/// b's side (rounded down, >= 0) and its distance from hull b's own joint axis (rounded up).
struct VertexRouteTerms {
  std::vector<double> excess;
  std::vector<double> axis_distance;
};

/// Whether pair `pair` may take the vertex bound: hull a has a solid of revolution (joint a+1
/// frozen) and the only joint left between them, b's own, is revolute (link b = link a + 2).
bool has_vertex_route(const RobotCell& cell, const SelfPairHulls& pair);

/// The terms of pair `p` (a pair with has_vertex_route) at `probe`; false, with `out` left
/// empty, when the probe proves no route distance for it (no witness or c = 0) or kept no frames.
/// \param coordinate_limit L, the largest |coordinate| of any hull vertex (the axis parameter's range)
bool vertex_route_terms(const RobotCell& cell, std::size_t p, const ProbeResult& probe,
                        double coordinate_limit, VertexRouteTerms& out);

/// M_v = max(0, max_v (V_b min(D_k(v), D_k+1(v)) - min(e_k(v), e_k+1(v)))) rounded up, for
/// `increment_up` >= the variation V_b of hull b's joint. It stands in for the route's M' in both
/// the step rule and the kept gap.
double vertex_route_bound(const VertexRouteTerms& from, const VertexRouteTerms& to,
                          double increment_up);

/// For proposals only (plain double): the weight r of b's joint with which "V_b r < 2 c" is
/// "V_b D(v) - e(v) < 2 c for every vertex", the ends assumed alike: max_v D(v) 2c / (2c + e(v)).
double vertex_route_proposal_radius(const VertexRouteTerms& at, double route_distance);

}  // namespace grpvss::certify
