#include "vertex_route.hpp"

#include <algorithm>
#include <limits>

#include "grpvss/geometry/directed_rounding.hpp"
#include "grpvss/kinematics/forward_kinematics.hpp"  // place_points: the expression the FK bound covers
#include "step_axis_radius.hpp"

namespace grpvss::certify {
namespace r = geometry::rounding;

bool has_vertex_route(const RobotCell& cell, const SelfPairHulls& pair) {
  const LinkHull& a = cell.hulls()[static_cast<std::size_t>(pair.a)];
  const LinkHull& b = cell.hulls()[static_cast<std::size_t>(pair.b)];
  return a.revolution_L.has_value() && b.link == a.link + 2 &&
         b.link <= cell.chain().joint_count() &&
         cell.radii().joint_type(b.link) == JointType::kRevolute;
}

// e(v) = (n.v - o_b) / |n| rounded down (the witness holds n.v >= o_b exactly at every placed
// vertex, so a negative rounded value stands for 0) and D(v) = |v - o - s z| + eps rounded up.
// proof: proofs/two-ball-cover.md#revolution-vertex-bound, proofs/motion-bound.md#axis-distance-evaluation
bool vertex_route_terms(const RobotCell& cell, std::size_t p, const ProbeResult& probe,
                        double coordinate_limit, VertexRouteTerms& out) {
  out.excess.clear();
  out.axis_distance.clear();
  if (p >= probe.self_pairs.size()) return false;
  const SelfPairEvidence& evidence = probe.self_pairs[p];
  // c_k = lambda - 2 eps unclamped: a distance clamped up to 0 would not bound dist - e.
  if (!evidence.separated || !(evidence.revolution_distance > 0.0)) return false;
  const LinkHull& b = cell.hulls()[static_cast<std::size_t>(cell.self_pairs()[p].b)];
  const auto joint = static_cast<std::size_t>(b.link);
  if (probe.X_WJ.size() < joint || probe.X_WL.size() <= joint) return false;
  thread_local std::vector<Eigen::Vector3d> placed_W;
  thread_local std::vector<double> parameters;
  kinematics::place_points(probe.X_WL[joint], b.raw_L, placed_W);
  const Eigen::Isometry3d& X_WJ = probe.X_WJ[joint - 1];
  const Eigen::Vector3d o_W = X_WJ.translation();
  const Eigen::Vector3d z_W = X_WJ.linear().col(2);
  parameters.resize(placed_W.size());
  for (std::size_t i = 0; i < placed_W.size(); ++i) {
    // Near the foot of the perpendicular, within the FK bound's reach (any |s| <= L is sound).
    parameters[i] = std::clamp(z_W.dot(placed_W[i] - o_W), -coordinate_limit, coordinate_limit);
  }
  const geometry::SeparationWitness& witness = evidence.witness;
  out.excess.resize(placed_W.size());
  out.axis_distance.resize(placed_W.size());
  r::UpwardRoundingScope upward;
  const double normal_length_up = r::sqrt_up(r::dot_up(witness.normal.data(), witness.normal.data()));
  for (std::size_t i = 0; i < placed_W.size(); ++i) {
    const double beyond = r::sub_down(r::dot_down(witness.normal.data(), placed_W[i].data()), witness.offset_b);
    out.excess[i] = beyond > 0.0 ? r::div_down(beyond, normal_length_up) : 0.0;
    out.axis_distance[i] = r::add_up(axis_point_distance_up(placed_W[i], o_W, z_W, parameters[i]),
                                     cell.placement_error());
  }
  return true;
}

// proof: proofs/two-ball-cover.md#revolution-vertex-bound
double vertex_route_bound(const VertexRouteTerms& from, const VertexRouteTerms& to,
                          double increment_up) {
  if (from.excess.empty() || from.excess.size() != to.excess.size()) {
    return std::numeric_limits<double>::infinity();
  }
  r::UpwardRoundingScope upward;
  double bound = 0.0;
  for (std::size_t i = 0; i < from.excess.size(); ++i) {
    // D(v) is the same at every configuration (the arc is about b's own axis): either end bounds it.
    const double arc = r::mul_up(increment_up, std::min(from.axis_distance[i], to.axis_distance[i]));
    bound = std::max(bound, r::sub_up(arc, std::min(from.excess[i], to.excess[i])));
  }
  return bound;
}

double vertex_route_proposal_radius(const VertexRouteTerms& at, double route_distance) {
  const double both_ends = 2.0 * route_distance;
  double radius = 0.0;
  for (std::size_t i = 0; i < at.excess.size(); ++i) {
    radius = std::max(radius, at.axis_distance[i] * both_ends / (both_ends + at.excess[i]));
  }
  return radius;
}

}  // namespace grpvss::certify
