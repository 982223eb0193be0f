#pragma once
// Terms of the step rule far from limiting the step: where the probe may skip GJK.

#include <vector>

namespace grpvss::certify {

/// Which terms of the step rule the march's last transition left far from limiting the step
/// (step_proposal.hpp, loose_terms). The probe may prove their clearance on the kept witness
/// normal alone, without GJK: a proven slab is evidence like any other (the checker decides it
/// on every placed vertex), only a little below the closest one, so at most the step length
/// changes, never a claim.
struct LooseTerms {
  std::vector<char> hulls;  ///< [hull], RobotCell::hulls() order; empty: none
  std::vector<char> pairs;  ///< [self pair], RobotCell::self_pairs() order; empty: none
};

/// A loose term's kept normal is taken when its bound is at least this fraction of the bound
/// the normal was found with (by GJK); below it the normal is stale and GJK runs again.
constexpr double kLooseKeep = 0.75;

}  // namespace grpvss::certify
