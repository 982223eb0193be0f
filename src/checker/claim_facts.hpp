#pragma once
// What the checked steps and transitions established about the whole path: the facts the
// certificate's claim is judged against (claim_check.hpp).

#include <optional>

#include <Eigen/Core>

namespace grpvss::certify {

struct ClaimFacts {
  bool all_transitions_certified = true;
  /// Some hull keeps g < Delta over some transition (proofs/two-ball-cover.md#lemma-tolerance-along-motion):
  /// with the claim `motion`, a reason for WITHIN_TOLERANCE besides interference.
  bool any_tolerance_shortfall = false;
  bool any_expanded_interference = false;
  bool any_raw_collision = false;
  /// The steps cover the whole path (every segment from parameter 0 to its end).
  bool coverage_complete = true;
  /// The configuration of the last step numbered collision_step (re-decided by the claim check).
  std::optional<Eigen::VectorXd> collision_step_q;
};

}  // namespace grpvss::certify
