#include "transition_judge.hpp"

#include <algorithm>
#include <limits>

#include "joint_linear_motion_bound.hpp"
#include "vertex_route.hpp"
#include "grpvss/geometry/directed_rounding.hpp"

namespace grpvss::certify {
namespace {

// The hull's motion bound over the transition: the joint-sum bound M_h, or on a joint-linear
// step the smaller chord bound when joints undo each other's sweep (a roll joint keeping the
// tool's orientation on a CP line moves the hull far less than the sum of their sweeps).
// proof: proofs/motion-bound.md#lemma-motion-bound, proofs/motion-bound.md#lemma-joint-linear-chord
double hull_motion_bound(const RobotCell& cell, const LinkHull& hull, const ProbeResult& from,
                         const ProbeResult& to, const Eigen::VectorXd& dq, bool joint_linear) {
  double bound = cell.radii().hull_motion_bound(hull.link, hull.hull, dq);
  if (joint_linear && bound > 0.0) {
    bound = std::min(bound, joint_linear_motion_bound(cell.radii(), hull.link, hull.hull,
                                                      hull.raw_L, from.q, from.X_WL[hull.link],
                                                      to.q, to.X_WL[hull.link],
                                                      cell.placement_error()));
  }
  return bound;
}

GoverningTerm governing_term(const HullState& from, const HullState& to, double allowance,
                             double two_delta, bool cut_by_segment_end) {
  if (from.expanded_interferes || to.expanded_interferes) return GoverningTerm::kRawClearance;
  if (allowance <= two_delta * (1.0 + 1e-9)) return GoverningTerm::kTolerance;
  if (cut_by_segment_end) return GoverningTerm::kSegmentEnd;
  return GoverningTerm::kClearance;
}

}  // namespace

// Both hulls move: their relative motion bound (rounded up) must stay below d_k + d_{k+1}
// (rounded down). It is the smaller of M_a + M_b and the bound of hull b in link a's frame,
// where only joints a+1..b move it (the arm swinging both about joint 1 moves neither relative
// to the other). proof: proofs/two-ball-cover.md#lemma-relative-motion,
// proofs/two-ball-cover.md#relative-frame
double self_pair_motion_bound(const RobotCell& cell, const SelfPairHulls& pair,
                              const TransitionRecord& record, const Eigen::VectorXd& dq,
                              const StepAxisDistances* axis) {
  namespace r = geometry::rounding;
  const LinkHull& a = cell.hulls()[static_cast<std::size_t>(pair.a)];
  const LinkHull& b = cell.hulls()[static_cast<std::size_t>(pair.b)];
  const double both = r::nearest_mode_add_up(record.hull_motion_bounds[static_cast<std::size_t>(pair.a)],
                                             record.hull_motion_bounds[static_cast<std::size_t>(pair.b)]);
  // Scratch kept per thread: a judge evaluates 15-450 pairs per trial.
  thread_local Eigen::VectorXd relative;
  relative = dq;
  relative.head(a.link).setZero();  // joints 1..a move link a's frame, not b within it
  double bound = std::min(both, cell.radii().hull_motion_bound(b.link, b.hull, relative));
  if (axis != nullptr && bound > 0.0) {
    // Distances from the axes a+1..b are the same seen from link a's frame.
    // proof: proofs/motion-bound.md#lemma-axis-distance-along-step
    thread_local Eigen::VectorXd relative_up;
    relative_up = axis->increments_up;
    relative_up.head(a.link).setZero();
    bound = std::min(bound, axis->radii->motion_bound(pair.b, relative_up, axis->from, axis->to));
  }
  return bound;
}

// The revolution route: hull a lies in a solid of revolution about joint a+1's axis, which that joint turns
// into itself, so in the frame of joint a+1 only joints a+2..b move hull b relative to it.
// proof: proofs/two-ball-cover.md#revolution-route
double revolution_motion_bound(const RobotCell& cell, const SelfPairHulls& pair,
                               const Eigen::VectorXd& dq, const StepAxisDistances* axis) {
  const LinkHull& a = cell.hulls()[static_cast<std::size_t>(pair.a)];
  const LinkHull& b = cell.hulls()[static_cast<std::size_t>(pair.b)];
  const Eigen::Index frozen = std::min<Eigen::Index>(a.link + 1, dq.size());
  thread_local Eigen::VectorXd relative;
  relative = dq;
  relative.head(frozen).setZero();
  double bound = cell.radii().hull_motion_bound(b.link, b.hull, relative);
  if (axis != nullptr && bound > 0.0) {
    thread_local Eigen::VectorXd relative_up;
    relative_up = axis->increments_up;
    relative_up.head(frozen).setZero();
    bound = std::min(bound, axis->radii->motion_bound(pair.b, relative_up, axis->from, axis->to));
  }
  return bound;
}

// The route's M_v from both ends' vertex terms (+inf when either end proves no route distance).
// proof: proofs/two-ball-cover.md#revolution-vertex-bound
double vertex_route_motion_bound(const RobotCell& cell, std::size_t pair, const ProbeResult& from,
                                 const ProbeResult& to, const StepAxisDistances& axis) {
  VertexRouteEnd* at_from = vertex_route_end(*axis.radii, pair, from);
  VertexRouteEnd* at_to = at_from != nullptr ? vertex_route_end(*axis.radii, pair, to) : nullptr;
  if (at_to == nullptr) return std::numeric_limits<double>::infinity();
  const int joint = cell.hulls()[static_cast<std::size_t>(cell.self_pairs()[pair].b)].link;
  return vertex_route_bound(*axis.radii, *at_from, *at_to, axis.increments_up[joint - 1]);
}

namespace {

// allowance / bound, +inf for a bound of 0 with a positive allowance.
double route_ratio(double bound, double allowance) {
  if (!(allowance > 0.0)) return 0.0;
  return bound > 0.0 ? allowance / bound : std::numeric_limits<double>::infinity();
}

}  // namespace

bool by_revolution(const TransitionRecord& record, std::size_t pair) {
  return pair < record.self_pair_by_revolution.size() && record.self_pair_by_revolution[pair] != 0;
}

double route_distance(const SelfPairEvidence& evidence, bool revolution) {
  return revolution ? evidence.revolution_distance : evidence.distance;
}

void judge_self_pairs(const RobotCell& cell, const ProbeResult& from, const ProbeResult& to,
                      const Eigen::VectorXd& dq, TransitionRecord& record,
                      const StepAxisDistances* axis) {
  const std::vector<SelfPairHulls>& pairs = cell.self_pairs();
  std::vector<int> routes;  // sized at the first pair with a revolution route
  record.self_pair_motion_bounds.reserve(pairs.size());
  record.self_pair_allowances.reserve(pairs.size());
  for (std::size_t p = 0; p < pairs.size(); ++p) {
    const auto a = static_cast<std::size_t>(pairs[p].a);
    const auto b = static_cast<std::size_t>(pairs[p].b);
    double bound = self_pair_motion_bound(cell, pairs[p], record, dq, axis);
    double allowance = allowance_down(from.self_pairs[p].distance, to.self_pairs[p].distance);
    if (cell.hulls()[a].revolution_L) {
      // Either route proves the pair; the step keeps the one with more room.
      routes.resize(pairs.size(), 0);
      double revolution_bound = revolution_motion_bound(cell, pairs[p], dq, axis);
      if (axis != nullptr && revolution_bound > 0.0 && has_vertex_route(cell, pairs[p])) {
        revolution_bound = std::min(revolution_bound, vertex_route_motion_bound(cell, p, from, to, *axis));
      }
      const double revolution_allowance = allowance_down(from.self_pairs[p].revolution_distance,
                                                         to.self_pairs[p].revolution_distance);
      if (route_ratio(revolution_bound, revolution_allowance) > route_ratio(bound, allowance)) {
        bound = revolution_bound;
        allowance = revolution_allowance;
        routes[p] = 1;
      }
    }
    if (!(bound < allowance)) {
      record.certified = false;
      record.governing[a] = record.governing[b] = GoverningTerm::kUncertified;
    }
    record.self_pair_motion_bounds.push_back(bound);
    record.self_pair_allowances.push_back(allowance);
  }
  if (!routes.empty()) record.self_pair_by_revolution = std::move(routes);
}

double allowance_down(double radius_k, double radius_k1) {
  namespace r = geometry::rounding;
  r::UpwardRoundingScope upward;
  return r::add_down(radius_k, radius_k1);
}

// proof: proofs/two-ball-cover.md#corollary-step
TransitionRecord judge_transition(const RobotCell& cell, const ProbeResult& from,
                                  const ProbeResult& to, bool cut_by_segment_end,
                                  bool joint_linear, const Eigen::VectorXd& joint_variation,
                                  const StepAxisRadii* step_radii) {
  TransitionRecord record;
  record.certified = true;
  // proof: proofs/joint-variation.md#theorem-variation-motion-bound
  const Eigen::VectorXd dq = joint_variation.size() > 0 ? joint_variation : Eigen::VectorXd(to.q - from.q);
  const double two_delta = 2.0 * cell.tolerance();
  // proof: proofs/motion-bound.md#lemma-axis-distance-along-step
  StepAxisDistances axis;
  if (step_radii != nullptr) {
    axis.radii = step_radii;
    std::vector<double> scratch;
    axis.from = step_radii->kept_or_computed(from, scratch);
    axis.to = step_radii->kept_or_computed(to, scratch);
    axis.increments_up = increments_up(from.q, to.q, joint_variation);
  }
  record.hull_motion_bounds.reserve(cell.hulls().size());
  record.hull_allowances.reserve(cell.hulls().size());
  record.governing.reserve(cell.hulls().size());
  for (std::size_t i = 0; i < cell.hulls().size(); ++i) {
    double bound = hull_motion_bound(cell, cell.hulls()[i], from, to, dq, joint_linear);
    if (step_radii != nullptr && bound > 0.0) {
      bound = std::min(bound, step_radii->motion_bound(static_cast<int>(i), axis.increments_up,
                                                       axis.from, axis.to));
    }
    const double allowance = allowance_down(from.hulls[i].radius, to.hulls[i].radius);
    GoverningTerm governing =
        governing_term(from.hulls[i], to.hulls[i], allowance, two_delta, cut_by_segment_end);
    if (!(bound <= allowance)) {
      record.certified = false;
      governing = GoverningTerm::kUncertified;
    }
    record.hull_motion_bounds.push_back(bound);
    record.hull_allowances.push_back(allowance);
    record.governing.push_back(governing);
  }
  // The pairs' relative bounds take the same increments (or variations) as the hulls'.
  judge_self_pairs(cell, from, to, dq, record, step_radii != nullptr ? &axis : nullptr);
  return record;
}

// g >= Delta holds when M <= r_k + r_{k+1} - 2 Delta or M <= max(r_k, r_{k+1}) - Delta; each
// rounded down, so that "bound <= allowance" in double implies it exactly.
// proof: proofs/two-ball-cover.md#lemma-tolerance-along-motion
double held_allowance_down(double radius_k, double radius_k1, double tolerance) {
  namespace r = geometry::rounding;
  const double balanced = r::nearest_mode_sub_down(r::nearest_mode_add_down(radius_k, radius_k1),
                                                   2.0 * tolerance);
  const double one_sided = r::nearest_mode_sub_down(std::max(radius_k, radius_k1), tolerance);
  return std::max(balanced, one_sided);
}

// Hulls against the obstacles, and self pairs (their distances d_k, d_{k+1} and relative bound)
// to a gap of Delta. proof: proofs/two-ball-cover.md#lemma-tolerance-along-motion,
// proofs/two-ball-cover.md#corollary-self-tolerance-along-motion
TransitionRecord held_to_tolerance(const TransitionRecord& nominal, const ProbeResult& from,
                                   const ProbeResult& to, double tolerance) {
  TransitionRecord held = nominal;
  for (std::size_t i = 0; i < held.hull_allowances.size(); ++i) {
    if (from.hulls[i].expanded_interferes || to.hulls[i].expanded_interferes) continue;
    held.hull_allowances[i] =
        held_allowance_down(from.hulls[i].radius, to.hulls[i].radius, tolerance);
    if (!(held.hull_motion_bounds[i] <= held.hull_allowances[i])) held.certified = false;
  }
  for (std::size_t p = 0; p < held.self_pair_allowances.size(); ++p) {
    const bool revolution = by_revolution(held, p);
    held.self_pair_allowances[p] = held_allowance_down(route_distance(from.self_pairs[p], revolution),
                                                       route_distance(to.self_pairs[p], revolution),
                                                       tolerance);
    if (!(held.self_pair_motion_bounds[p] <= held.self_pair_allowances[p])) held.certified = false;
  }
  return held;
}

TransitionRecord beside_collisions(const TransitionRecord& transition, const ProbeResult& from,
                                   const ProbeResult& to) {
  TransitionRecord beside = transition;
  for (std::size_t i = 0; i < beside.hull_allowances.size(); ++i) {
    if (from.hulls[i].raw_collides || to.hulls[i].raw_collides) {
      beside.hull_allowances[i] = allowance_down(from.hulls[i].radius_beside_collisions,
                                                 to.hulls[i].radius_beside_collisions);
    }
  }
  // A self pair in contact at an end is not held either.
  for (std::size_t p = 0; p < beside.self_pair_allowances.size(); ++p) {
    if (from.self_pairs[p].contact || to.self_pairs[p].contact) {
      beside.self_pair_allowances[p] = std::numeric_limits<double>::infinity();
    }
  }
  return beside;
}

}  // namespace grpvss::certify
