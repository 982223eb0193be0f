#include "vertex_route.hpp"

#include <algorithm>
#include <cmath>
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

namespace {

// M = 16 u S / N rounded up, S = |n|_1 V + |o_b| with V >= |x|_inf for every placed point x the
// end evaluates, N >= |n|: (n.x - o_b) / N evaluated in round-to-nearest (any order, with or
// without FMA, divided by N or multiplied by RN(1/N)), less M, is at most (n.x - o_b) / |n|
// where that is >= 0. Needs an active
// UpwardRoundingScope. proof: proofs/two-ball-cover.md#vertex-excess
double excess_margin_up(const geometry::SeparationWitness& witness, double largest_coordinate,
                        double normal_length_up) {
  const double unit_roundoff = std::numeric_limits<double>::epsilon() / 2.0;
  const double normal_1 = r::add_up(r::add_up(std::fabs(witness.normal[0]), std::fabs(witness.normal[1])),
                                    std::fabs(witness.normal[2]));
  const double sum = r::add_up(r::mul_up(normal_1, largest_coordinate), std::fabs(witness.offset_b));
  return r::mul_up(r::mul_up(16.0, unit_roundoff), r::div_up(sum, normal_length_up));
}

// |fl(X v)|_inf <= |t|_inf + 3.01 max|v|_inf for a rotation X (|R_ij| <= 1 + 1e-9): the placed
// points of a hull whose link-frame coordinates are at most `largest_L`.
double placed_coordinate_bound_up(const Eigen::Isometry3d& X, double largest_L) {
  r::UpwardRoundingScope upward;
  return r::add_up(X.translation().cwiseAbs().maxCoeff(), r::mul_up(3.01, largest_L));
}

}  // namespace

bool VertexRouteEnd::is_for(const StepAxisRadii& radii, std::size_t p, const ProbeResult& probe) const {
  if (radii_ != &radii || radii_identity_ != radii.identity() || pair_ != p || q_.size() != probe.q.size() ||
      q_ != probe.q) {
    return false;
  }
  if (p >= probe.self_pairs.size()) return !usable_;
  const SelfPairEvidence& evidence = probe.self_pairs[p];
  return evidence.witness.normal == witness_.normal && evidence.witness.offset_b == witness_.offset_b &&
         evidence.revolution_distance == route_distance_;
}

bool VertexRouteEnd::reset(const StepAxisRadii& radii, std::size_t p, const ProbeResult& probe) {
  const RobotCell& cell = radii.cell();
  radii_ = &radii;
  radii_identity_ = radii.identity();
  pair_ = p;
  q_ = probe.q;
  usable_ = false;
  cluster_excess_.clear();
  witness_ = geometry::SeparationWitness{};
  route_distance_ = 0.0;
  if (p >= probe.self_pairs.size()) return false;
  const SelfPairEvidence& evidence = probe.self_pairs[p];
  witness_ = evidence.witness;
  route_distance_ = evidence.revolution_distance;
  // c_k = lambda - 2 eps unclamped: a distance clamped up to 0 would not bound dist - e.
  if (!evidence.separated || !(evidence.revolution_distance > 0.0)) return false;
  hull_ = cell.self_pairs()[p].b;
  const LinkHull& b = cell.hulls()[static_cast<std::size_t>(hull_)];
  const std::vector<geometry::VertexCluster>& clusters = b.vertex_clusters_L;
  if (probe.X_WL.size() <= static_cast<std::size_t>(b.link) || clusters.empty() ||
      b.own_axis_distances.size() != b.raw_L.size()) {
    return false;
  }
  X_WL_ = probe.X_WL[static_cast<std::size_t>(b.link)];
  // The vertices' largest coordinate bounds the clusters' centres' too (inside their box).
  const double largest_coordinate = placed_coordinate_bound_up(X_WL_, b.raw_max_abs_L);
  {
    r::UpwardRoundingScope upward;
    normal_length_up_ = r::sqrt_up(r::dot_up(witness_.normal.data(), witness_.normal.data()));
    margin_ = excess_margin_up(witness_, largest_coordinate, normal_length_up_);
  }
  inverse_normal_length_ = 1.0 / normal_length_up_;  // round-to-nearest: the margin covers it
  thread_local std::vector<Eigen::Vector3d> centers_W;
  kinematics::place_points(X_WL_, b.vertex_cluster_centers_L, centers_W);
  cluster_excess_.resize(clusters.size());
  for (std::size_t i = 0; i < clusters.size(); ++i) {
    // The ball's vertices are within its radius of the centre, placed or not
    // (proofs/two-ball-cover.md#vertex-excess).
    cluster_excess_[i] = excess_of(centers_W[i], clusters[i].radius_up);
  }
  evaluated_.assign(clusters.size(), 0);
  vertex_excess_.resize(b.raw_L.size());
  usable_ = true;
  return true;
}

double VertexRouteEnd::excess_of(const Eigen::Vector3d& placed_W, double radius) const {
  // Round-to-nearest: the margin covers the rounding, and the radius is taken off with room to
  // spare (a negative result stands for 0: every vertex's exact e is >= 0).
  const double excess = (witness_.normal.dot(placed_W) - witness_.offset_b) * inverse_normal_length_ - margin_ -
                        radius * (1.0 + 4.0 * std::numeric_limits<double>::epsilon());
  return excess > 0.0 ? excess : 0.0;
}

void VertexRouteEnd::evaluate(std::size_t cluster) {
  if (evaluated_[cluster]) return;
  evaluated_[cluster] = 1;
  const LinkHull& b = radii_->cell().hulls()[static_cast<std::size_t>(hull_)];
  const std::vector<int>& members = b.vertex_clusters_L[cluster].members;
  for (const int v : members) {
    // One vertex as place_points places it (the FK bound covers any summation order).
    const Eigen::Vector3d placed_W = X_WL_ * b.raw_L[static_cast<std::size_t>(v)];
    vertex_excess_[static_cast<std::size_t>(v)] = excess_of(placed_W, 0.0);
  }
}

VertexRouteEnd* vertex_route_end(const StepAxisRadii& radii, std::size_t p, const ProbeResult& probe) {
  constexpr std::size_t kKept = 6;
  thread_local std::vector<VertexRouteEnd> kept(kKept);
  thread_local std::vector<unsigned long> last_use(kKept, 0);
  thread_local unsigned long clock = 0;
  ++clock;
  std::size_t oldest = 0;
  for (std::size_t i = 0; i < kKept; ++i) {
    if (kept[i].is_for(radii, p, probe)) {
      last_use[i] = clock;
      return kept[i].usable() ? &kept[i] : nullptr;
    }
    if (last_use[i] < last_use[oldest]) oldest = i;
  }
  last_use[oldest] = clock;
  return kept[oldest].reset(radii, p, probe) ? &kept[oldest] : nullptr;
}

namespace {

// Branch and bound: the largest value(v) over the vertices (at least 0), where bound(i) >=
// value(v) for every vertex v of cluster i; `evaluate(i)` readies cluster i's vertices.
template <typename ClusterBound, typename Evaluate, typename Value>
double largest_over_vertices(const std::vector<geometry::VertexCluster>& clusters, ClusterBound bound,
                             Evaluate evaluate, Value value) {
  thread_local std::vector<std::pair<double, std::size_t>> order;
  order.clear();
  for (std::size_t i = 0; i < clusters.size(); ++i) order.emplace_back(bound(i), i);
  std::sort(order.begin(), order.end(), [](const auto& x, const auto& y) { return x.first > y.first; });
  double best = 0.0;
  for (const auto& [cluster_bound, i] : order) {
    if (!(cluster_bound > best)) break;  // no vertex of this or any later cluster does better
    evaluate(i);
    for (const int v : clusters[i].members) best = std::max(best, value(v));
  }
  return best;
}

}  // namespace

// proof: proofs/two-ball-cover.md#revolution-vertex-bound
double vertex_route_bound(const StepAxisRadii& radii, VertexRouteEnd& from, VertexRouteEnd& to,
                          double increment_up) {
  if (from.hull() != to.hull() || from.cluster_count() == 0 || from.cluster_count() != to.cluster_count()) {
    return std::numeric_limits<double>::infinity();
  }
  const LinkHull& b = radii.cell().hulls()[static_cast<std::size_t>(from.hull())];
  const std::vector<double>& axis_distance = b.own_axis_distances;
  const std::vector<double>& cluster_axis_distance = b.cluster_own_axis_distances;
  r::UpwardRoundingScope upward;
  // A cluster's largest D less its least e bounds each of its vertices' charge.
  return largest_over_vertices(
      b.vertex_clusters_L,
      [&](std::size_t i) {
        return r::sub_up(r::mul_up(increment_up, cluster_axis_distance[i]),
                         std::min(from.cluster_excess(i), to.cluster_excess(i)));
      },
      [&](std::size_t i) {
        from.evaluate(i);
        to.evaluate(i);
      },
      [&](int v) {
        return r::sub_up(r::mul_up(increment_up, axis_distance[static_cast<std::size_t>(v)]),
                         std::min(from.vertex_excess(v), to.vertex_excess(v)));
      });
}

double vertex_route_proposal_radius(const StepAxisRadii& radii, VertexRouteEnd& at, double route_distance) {
  const double both_ends = 2.0 * route_distance;
  const LinkHull& b = radii.cell().hulls()[static_cast<std::size_t>(at.hull())];
  const std::vector<double>& axis_distance = b.own_axis_distances;
  const std::vector<double>& cluster_axis_distance = b.cluster_own_axis_distances;
  return largest_over_vertices(
      b.vertex_clusters_L,
      [&](std::size_t i) { return cluster_axis_distance[i] * both_ends / (both_ends + at.cluster_excess(i)); },
      [&](std::size_t i) { at.evaluate(i); },
      [&](int v) {
        return axis_distance[static_cast<std::size_t>(v)] * both_ends / (both_ends + at.vertex_excess(v));
      });
}

}  // namespace grpvss::certify
