#include "vertex_route_check.hpp"

#include <algorithm>
#include <cmath>

#include "grpvss/kinematics/forward_kinematics.hpp"

namespace grpvss::certify {
namespace {

Rational squared_distance(const Eigen::Vector3d& x, const Eigen::Vector3d& y) {
  Rational square = 0;
  for (int k = 0; k < 3; ++k) {
    const Rational d = exact(x[k]) - exact(y[k]);
    square += d * d;
  }
  return square;
}

// The witness's side at hull b, as e(x) = (n.x - o_b) / N with N >= |n|: exact, and a lower bound
// of x's clearance beyond the plane wherever n.x >= o_b.
class WitnessSide {
 public:
  explicit WitnessSide(const geometry::SeparationWitness& witness) : witness_(witness) {
    usable_ = witness.normal.allFinite() && !witness.normal.isZero(0.0) && std::isfinite(witness.offset_b);
    if (!usable_) return;
    Rational normal_square = 0;
    for (int k = 0; k < 3; ++k) normal_square += exact(witness.normal[k]) * exact(witness.normal[k]);
    normal_length_up_ = Rational(root_up(normal_square));
  }
  bool usable() const { return usable_; }
  /// (n.x - o_b) / N exactly (negative on the plane's other side).
  Rational beyond(const Eigen::Vector3d& x) const {
    Rational value = -exact(witness_.offset_b);
    for (int k = 0; k < 3; ++k) value += exact(witness_.normal[k]) * exact(x[k]);
    return value / normal_length_up_;
  }

 private:
  geometry::SeparationWitness witness_;
  bool usable_ = false;
  Rational normal_length_up_ = 1;
};

}  // namespace

VertexRouteCheck::VertexRouteCheck(const CheckedCell& cell, const Certificate& header)
    : cell_(&cell), header_(&header), hull_terms_(cell.hulls().size()) {}

bool VertexRouteCheck::applies(std::size_t p) const {
  const auto [a, b] = cell_->self_pairs()[p];
  const CheckedHull& hull_a = cell_->hulls()[static_cast<std::size_t>(a)];
  const CheckedHull& hull_b = cell_->hulls()[static_cast<std::size_t>(b)];
  return hull_a.revolution_L.has_value() && hull_b.link == hull_a.link + 2 &&
         hull_b.link <= cell_->robot().joint_count() &&
         cell_->robot().joints[static_cast<std::size_t>(hull_b.link - 1)].type == JointType::kRevolute;
}

// The clusters by the verifier's rule, each radius decided exactly over its members; D(v) =
// |v - o - s z| + eps at the middle of the joint limits, the root rounded up: the distance from
// the hull's own joint axis is the same at every configuration.
// proof: proofs/motion-bound.md#axis-distance-evaluation, proofs/two-ball-cover.md#revolution-vertex-bound
const VertexRouteCheck::HullTerms& VertexRouteCheck::terms(int hull_index) {
  HullTerms& terms = hull_terms_[static_cast<std::size_t>(hull_index)];
  if (terms.built) return terms;
  terms.built = true;
  const CheckedHull& hull = cell_->hulls()[static_cast<std::size_t>(hull_index)];
  const kinematics::KinematicChain& chain = cell_->chain();
  if (hull.raw_L.empty() || hull.link < 1 || hull.link > chain.joint_count()) return terms;
  terms.clusters = geometry::cluster_vertices(hull.raw_L, geometry::kVertexClusterLeaves);
  std::vector<char> covered(hull.raw_L.size(), 0);
  for (const geometry::VertexCluster& cluster : terms.clusters) {
    const Rational radius_square = exact(cluster.radius_up) * exact(cluster.radius_up);
    for (const int v : cluster.members) {
      if (v < 0 || static_cast<std::size_t>(v) >= hull.raw_L.size()) return terms;
      if (squared_distance(hull.raw_L[static_cast<std::size_t>(v)], cluster.center_L) > radius_square) return terms;
      covered[static_cast<std::size_t>(v)] = 1;
    }
  }
  if (std::find(covered.begin(), covered.end(), 0) != covered.end()) return terms;
  const kinematics::PlacedAtOwnJoint placed =
      kinematics::place_at_middle_of_limits(chain, cell_->robot(), hull.link, hull.raw_L);
  const Eigen::Vector3d o = placed.X_WJ.translation();
  const Eigen::Vector3d z = placed.X_WJ.linear().col(2);
  const double limit = cell_->hull_coordinate_limit();
  for (const Eigen::Vector3d& v : placed.points_W) {
    const double s = std::clamp(z.dot(v - o), -limit, limit);  // any |s| <= L is sound
    Rational square = 0;
    for (int k = 0; k < 3; ++k) {
      const Rational d = exact(v[k]) - exact(o[k]) - exact(s) * exact(z[k]);
      square += d * d;
    }
    terms.axis_distance.push_back(Rational(root_up(square)) + exact(header_->placement_error));
  }
  for (const geometry::VertexCluster& cluster : terms.clusters) {
    Rational largest = 0;
    for (const int v : cluster.members) largest = std::max(largest, terms.axis_distance[static_cast<std::size_t>(v)]);
    terms.cluster_axis_distance.push_back(largest);
  }
  terms.usable = true;
  return terms;
}

// proof: proofs/two-ball-cover.md#revolution-vertex-bound
std::optional<Rational> VertexRouteCheck::bound(std::size_t p, const SelfPairRecord& from,
                                                const SelfPairRecord& to,
                                                const Eigen::Isometry3d& X_WL_from,
                                                const Eigen::Isometry3d& X_WL_to,
                                                const std::vector<Eigen::Vector3d>& placed_from,
                                                const std::vector<Eigen::Vector3d>& placed_to,
                                                const Rational& increment) {
  if (!applies(p) || !from.separated || !to.separated) return std::nullopt;
  const int b = cell_->self_pairs()[p].second;
  const CheckedHull& hull = cell_->hulls()[static_cast<std::size_t>(b)];
  if (placed_from.size() != hull.raw_L.size() || placed_to.size() != hull.raw_L.size()) return std::nullopt;
  const HullTerms& hull_terms = terms(b);
  if (!hull_terms.usable) return std::nullopt;
  const WitnessSide side_from(from.witness), side_to(to.witness);
  if (!side_from.usable() || !side_to.usable()) return std::nullopt;
  // A cluster's least e at one end: the plane's side at its placed centre less its radius (the
  // lemma's e_k(v) >= (n.x - o_b)/|n| for any x within eps of T v, and T c is within eps of the
  // placed centre); 0 at least, as at every vertex.
  const auto cluster_excess = [&](const WitnessSide& side, const Eigen::Isometry3d& X_WL,
                                  const geometry::VertexCluster& cluster) {
    const Eigen::Vector3d center_W = X_WL * cluster.center_L;
    const Rational value = side.beyond(center_W) - exact(cluster.radius_up);
    return value > 0 ? value : Rational(0);
  };
  std::vector<std::pair<Rational, std::size_t>> order;
  for (std::size_t i = 0; i < hull_terms.clusters.size(); ++i) {
    const geometry::VertexCluster& cluster = hull_terms.clusters[i];
    const Rational least = std::min(cluster_excess(side_from, X_WL_from, cluster),
                                    cluster_excess(side_to, X_WL_to, cluster));
    order.emplace_back(increment * hull_terms.cluster_axis_distance[i] - least, i);
  }
  std::sort(order.begin(), order.end(), [](const auto& x, const auto& y) { return x.first > y.first; });
  Rational best = 0;
  for (const auto& [cluster_bound, i] : order) {
    if (!(cluster_bound > best)) break;  // no vertex of this or any later cluster charges more
    for (const int v : hull_terms.clusters[i].members) {
      const auto vertex = static_cast<std::size_t>(v);
      const Rational excess_from = side_from.beyond(placed_from[vertex]);
      const Rational excess_to = side_to.beyond(placed_to[vertex]);
      if (excess_from < 0 || excess_to < 0) return std::nullopt;  // the witness does not hold
      const Rational charged = increment * hull_terms.axis_distance[vertex] - std::min(excess_from, excess_to);
      if (charged > best) best = charged;
    }
  }
  return best;
}

}  // namespace grpvss::certify
