#include "transition_check.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include <fmt/core.h>

namespace grpvss::certify {

TransitionCheck::TransitionCheck(const CheckedCell& cell, const Certificate& header,
                                 CheckLedger& ledger, ClaimFacts& facts,
                                 MotionClearances& clearances)
    : cell_(cell),
      header_(header),
      ledger_(ledger),
      facts_(facts),
      clearances_(clearances),
      vertex_route_(cell, header),
      from_frames_(cell.robot()),
      to_frames_(cell.robot()) {}

void TransitionCheck::check(const StepCertificate& from, const StepCertificate& to,
                            const std::vector<Rational>& radius_from,
                            const std::vector<Rational>& radius_to,
                            const std::vector<std::vector<Eigen::Vector3d>>& placed_from,
                            const std::vector<std::vector<Eigen::Vector3d>>& placed_to,
                            bool joint_linear, const std::string& where,
                            const std::vector<Rational>& joint_variation) {
  const TransitionRecord& claimed = from.to_next;
  const std::vector<CheckedHull>& hulls = cell_.hulls();
  hull_bounds_.clear();
  self_pair_bounds_ = SelfPairBounds{};
  increments_.clear();
  checked_from_step_ = from.step;
  checked_to_step_ = to.step;
  // A step with the wrong joint count was already rejected by the step check; reading its q
  // here would run past the vector (found reviewing for the checker fuzz target).
  const int joints = cell_.robot().joint_count();
  if (from.q.size() != joints || to.q.size() != joints) {
    facts_.all_transitions_certified = false;
    return;
  }
  if (claimed.hull_motion_bounds.size() != hulls.size() ||
      claimed.hull_allowances.size() != hulls.size() || claimed.governing.size() != hulls.size()) {
    ledger_.fail(where + ": the transition record is incomplete");
    facts_.all_transitions_certified = false;
    return;
  }
  bool certified = true;
  hull_bounds_.assign(hulls.size(), std::nullopt);
  kinematics::forward_kinematics(cell_.chain(), from.q, from_frames_);
  kinematics::forward_kinematics(cell_.chain(), to.q, to_frames_);
  std::vector<Rational> increments(static_cast<std::size_t>(joints));
  for (int j = 0; j < joints; ++j) {
    increments[static_cast<std::size_t>(j)] =
        joint_variation.empty() ? Rational(abs(exact(to.q[j]) - exact(from.q[j])))
                                : joint_variation[static_cast<std::size_t>(j)];
  }
  for (std::size_t i = 0; i < hulls.size(); ++i) {
    const CheckedHull& hull = hulls[i];
    const std::string hull_where = where + " hull " + std::to_string(i);
    Rational bound = joint_sum_bound(hull, from, to, joint_variation);
    const Rational allowance = radius_from[i] + radius_to[i];
    ledger_.decided(3);
    const Rational recorded = exact(claimed.hull_motion_bounds[i]);
    if (!(recorded >= bound)) {
      // proof: proofs/motion-bound.md#lemma-joint-linear-chord
      ledger_.decided();
      const bool chord_holds = joint_linear && placed_from[i].size() == hull.raw_L.size() &&
                               placed_to[i].size() == hull.raw_L.size() &&
                               chord_bound_holds(hull, from, to, placed_from[i], placed_to[i],
                                                 claimed.hull_motion_bounds[i]);
      // proof: proofs/motion-bound.md#lemma-axis-distance-along-step
      if (chord_holds || recorded >= step_axis_bound(hull, increments)) {
        bound = recorded;  // proven >= every point's path length
      } else {
        ledger_.fail(hull_where + (joint_linear ? ": the recorded motion bound is below the exact "
                                                  "bound, the chord bound and the step's "
                                                  "axis-distance bound"
                                                : ": the recorded motion bound is below the exact "
                                                  "bound and the step's axis-distance bound"));
        certified = false;
      }
    }
    hull_bounds_[i] = bound;  // the exact bound, or the recorded one the chord check proved
    if (!(exact(claimed.hull_allowances[i]) <= allowance)) {
      ledger_.fail(hull_where + ": the recorded allowance exceeds r_k + r_k+1");
      certified = false;
    }
    if (!(bound <= allowance)) {
      if (claimed.certified) ledger_.fail(hull_where + ": motion bound exceeds the allowance");
      certified = false;
    }
    const Rational kept = keep_motion_clearance(hull, radius_from[i], radius_to[i], bound, to.step);
    if (kept < exact(header_.tolerance)) facts_.any_tolerance_shortfall = true;
    if (header_.claim == Verdict::kClear && header_.clear_claim == ClearClaim::kMotion) {
      hold_to_tolerance(kept, i, from, to);
    }
  }
  if (!certified) facts_.all_transitions_certified = false;
  for (const auto& [a, b] : cell_.self_pairs()) {
    const CheckedHull& hull_a = hulls[static_cast<std::size_t>(a)];
    const CheckedHull& hull_b = hulls[static_cast<std::size_t>(b)];
    // Joints 1..a move link a's frame, not b in it. proof: proofs/two-ball-cover.md#relative-frame
    self_pair_bounds_.relative.push_back(frozen_bound(hull_b, increments, hull_a.link));
    // Hull a's solid of revolution is turned into itself by joint a+1 as well.
    // proof: proofs/two-ball-cover.md#revolution-route
    self_pair_bounds_.revolution.push_back(
        hull_a.revolution_L ? std::optional<Rational>(frozen_bound(hull_b, increments, hull_a.link + 1))
                            : std::nullopt);
  }
  // M_v is decided only for the pairs whose other routes leave it needed (check_self_pair_transition).
  increments_ = std::move(increments);
}

std::optional<Rational> TransitionCheck::vertex_route_bound(
    std::size_t p, const StepCertificate& from, const StepCertificate& to,
    const std::vector<std::vector<Eigen::Vector3d>>& placed_from,
    const std::vector<std::vector<Eigen::Vector3d>>& placed_to) {
  if (from.step != checked_from_step_ || to.step != checked_to_step_) {
    throw std::logic_error("TransitionCheck::vertex_route_bound: not the last checked transition");
  }
  if (p >= cell_.self_pairs().size()) return std::nullopt;
  const int b = cell_.self_pairs()[p].second;
  const auto link = static_cast<std::size_t>(cell_.hulls()[static_cast<std::size_t>(b)].link);
  if (p >= from.self_pairs.size() || p >= to.self_pairs.size() || static_cast<std::size_t>(b) >= placed_from.size() ||
      static_cast<std::size_t>(b) >= placed_to.size() || link < 1 || link > increments_.size()) {
    return std::nullopt;
  }
  return vertex_route_.bound(p, from.self_pairs[p], to.self_pairs[p], from_frames_.X_WL[link],
                             to_frames_.X_WL[link], placed_from[static_cast<std::size_t>(b)],
                             placed_to[static_cast<std::size_t>(b)], increments_[link - 1]);
}


// The smaller of the joint-sum bound and M'_h of hull b with joints 1..frozen held still.
Rational TransitionCheck::frozen_bound(const CheckedHull& hull_b,
                                       const std::vector<Rational>& increments, int frozen) const {
  const int joints = cell_.robot().joint_count();
  std::vector<Rational> relative = increments;
  for (int j = 0; j < std::min(frozen, joints); ++j) relative[static_cast<std::size_t>(j)] = 0;
  Rational joint_sum = 0;
  for (int joint = frozen + 1; joint <= std::min(hull_b.link, joints); ++joint) {
    const Rational& increment = relative[static_cast<std::size_t>(joint - 1)];
    joint_sum += cell_.robot().joints[joint - 1].type == JointType::kRevolute
                     ? increment * hull_b.axis_radius[static_cast<std::size_t>(joint - 1)]
                     : increment;
  }
  return std::min(joint_sum, step_axis_bound(hull_b, relative));
}

// proof: proofs/motion-bound.md#lemma-motion-bound
Rational TransitionCheck::joint_sum_bound(const CheckedHull& hull, const StepCertificate& from,
                                          const StepCertificate& to,
                                          const std::vector<Rational>& joint_variation) const {
  Rational bound = 0;
  for (int joint = 1; joint <= hull.link; ++joint) {
    const Rational increment = joint_variation.empty()
                                   ? Rational(abs(exact(to.q[joint - 1]) - exact(from.q[joint - 1])))
                                   : joint_variation[static_cast<std::size_t>(joint - 1)];
    bound += cell_.robot().joints[joint - 1].type == JointType::kRevolute
                 ? increment * hull.axis_radius[joint - 1]
                 : increment;
  }
  return bound;
}

Rational TransitionCheck::step_axis_bound(const CheckedHull& hull,
                                          const std::vector<Rational>& increments) const {
  const int moving = std::min(hull.link, cell_.robot().joint_count());
  Rational tail = 0;
  Rational bound = 0;
  for (int j = moving; j >= 1; --j) {
    const Rational& increment = increments[static_cast<std::size_t>(j - 1)];
    const bool revolute = cell_.robot().joints[j - 1].type == JointType::kRevolute;
    if (revolute) {
      const Rational at_ends = std::min(axis_distance(from_frames_, hull, j),
                                        axis_distance(to_frames_, hull, j));
      const Rational near = at_ends + tail;
      bound += increment * std::min(hull.axis_radius[static_cast<std::size_t>(j - 1)], near);
      tail += increment * hull.axis_radius[static_cast<std::size_t>(j - 1)];
    } else {
      bound += increment;
      tail += increment;
    }
  }
  return bound;
}

Rational TransitionCheck::axis_distance(const kinematics::Workspace& frames,
                                        const CheckedHull& hull, int joint) const {
  const Eigen::Vector3d c = frames.X_WL[static_cast<std::size_t>(hull.link)] * hull.ball_center_L;
  const Eigen::Isometry3d& X_WJ = frames.X_WJ[static_cast<std::size_t>(joint - 1)];
  const Eigen::Vector3d o = X_WJ.translation();
  const Eigen::Vector3d z = X_WJ.linear().col(2);
  const double limit = cell_.hull_coordinate_limit();
  const double s = std::clamp(z.dot(c - o), -limit, limit);  // any |s| <= L is sound
  Rational square = 0;
  for (int k = 0; k < 3; ++k) {
    const Rational d = exact(c[k]) - exact(o[k]) - exact(s) * exact(z[k]);
    square += d * d;
  }
  return Rational(root_up(square)) + exact(header_.placement_error) + hull.ball_radius;
}

bool TransitionCheck::chord_bound_holds(const CheckedHull& hull, const StepCertificate& from,
                                        const StepCertificate& to,
                                        const std::vector<Eigen::Vector3d>& placed_from,
                                        const std::vector<Eigen::Vector3d>& placed_to,
                                        double claimed) const {
  if (!std::isfinite(claimed)) return false;
  // P_h exactly: sum_m w_m |dq_m| ([m rev] |dq_m| + 2 sum_{j<m rev} |dq_j|).
  Rational curvature = 0;
  Rational revolute_before = 0;
  for (int m = 1; m <= hull.link; ++m) {
    const Rational increment = abs(exact(to.q[m - 1]) - exact(from.q[m - 1]));
    const bool revolute = cell_.robot().joints[m - 1].type == JointType::kRevolute;
    const Rational weight = revolute ? hull.axis_radius[m - 1] : Rational(1);
    curvature += weight * increment * (2 * revolute_before + (revolute ? increment : Rational(0)));
    if (revolute) revolute_before += increment;
  }
  // Each placed point is within placement_error of its exact place (proofs/fk-rounding.md).
  const Rational chord_allowed =
      exact(claimed) - 2 * exact(header_.placement_error) - curvature / 3;
  if (chord_allowed < 0) return false;
  const Rational chord_allowed_squared = chord_allowed * chord_allowed;
  for (std::size_t v = 0; v < placed_from.size(); ++v) {
    Rational square = 0;
    for (int k = 0; k < 3; ++k) {
      const Rational d = exact(placed_to[v][k]) - exact(placed_from[v][k]);
      square += d * d;
    }
    if (square > chord_allowed_squared) return false;
  }
  return true;
}

// proof: proofs/two-ball-cover.md#corollary-motion-clearance
Rational TransitionCheck::keep_motion_clearance(const CheckedHull& hull,
                                                const Rational& radius_from,
                                                const Rational& radius_to, const Rational& bound,
                                                int to_step) {
  const Rational balanced = (radius_from + radius_to - bound) / 2;
  const Rational one_sided = std::max(radius_from, radius_to) - bound;
  const Rational kept = std::max(Rational(0), std::max(balanced, one_sided));
  auto& smallest = clearances_[static_cast<std::size_t>(hull.link)];
  if (!smallest || kept < smallest->first) smallest = std::make_pair(kept, to_step);
  return kept;
}

namespace {

// The obstacle with the smallest recorded lower bound at either end (-1: none recorded).
int nearest_recorded_obstacle(const HullRecord& from, const HullRecord& to) {
  int nearest = -1;
  double smallest = 0.0;
  for (const HullRecord* record : {&from, &to}) {
    for (const EvidenceRecord& evidence : record->evidence) {
      if (nearest < 0 || evidence.lower_bound < smallest) {
        nearest = evidence.obstacle;
        smallest = evidence.lower_bound;
      }
    }
  }
  return nearest;
}

}  // namespace

void TransitionCheck::hold_to_tolerance(const Rational& kept, std::size_t hull,
                                        const StepCertificate& from, const StepCertificate& to) {
  ledger_.decided();
  if (kept >= exact(header_.tolerance)) return;
  const CheckedHull& checked = cell_.hulls()[hull];
  const int obstacle = hull < from.hulls.size() && hull < to.hulls.size()
                           ? nearest_recorded_obstacle(from.hulls[hull], to.hulls[hull])
                           : -1;
  ledger_.fail(fmt::format(
      "steps {}-{} {} hull {} near {}: the motion clearance {:.6g} is below the tolerance {} "
      "(claim motion: robot + tolerance clear along the whole motion)",
      from.step, to.step, hull_label(cell_.robot(), checked.link, checked.hull), checked.hull,
      obstacle < 0 ? std::string("no recorded obstacle")
                   : obstacle_label(cell_.environment(), obstacle),
      kept.get_d(), header_.tolerance));
}

}  // namespace grpvss::certify
