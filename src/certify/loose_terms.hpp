#pragma once
// Terms of the step rule far from limiting the step: where the probe may skip GJK.

#include <vector>

namespace grpvss::certify {

/// Which terms of the step rule the march's last transition left far from limiting the step
/// (step_proposal.hpp, loose_terms), and how small a clearance each may be left with. The probe
/// may prove their clearance on the kept witness normal alone, without GJK: a proven slab is
/// evidence like any other (the checker decides it on every placed vertex), only a little
/// below the closest one, so at most the step length changes, never a claim.
struct LooseTerms {
  /// [hull], RobotCell::hulls() order: the smallest radius (HullState::radius) a kept normal
  /// may leave the hull with; +inf: not loose. Empty: none is.
  std::vector<double> hull_floors;
  /// [self pair], RobotCell::self_pairs() order: the same for the pair's distance
  /// (SelfPairEvidence::distance).
  std::vector<double> pair_floors;
};

/// A loose term's kept normal is taken when its bound is at least this fraction of the bound
/// the normal was found with (by GJK); below it the normal is stale and GJK runs again.
constexpr double kLooseKeep = 0.75;

}  // namespace grpvss::certify
