// The claim `motion`'s step decision (transition_judge.hpp held_to_tolerance): every hull whose
// expanded hull is clear at both ends is held to g >= Delta, i.e. to
// max(r_k + r_k1 - 2 Delta, max(r_k, r_k1) - Delta) (proofs/two-ball-cover.md#lemma-tolerance-along-motion).
#include <utility>
#include <vector>

#include <gtest/gtest.h>

#include "certify/lemma_reference.hpp"
#include "certify/transition_judge.hpp"

namespace grpvss::certify {
namespace {

ProbeResult probe(std::vector<double> radii, std::vector<bool> interferes) {
  ProbeResult result;
  for (std::size_t i = 0; i < radii.size(); ++i) {
    HullState hull;
    hull.radius = radii[i];
    hull.expanded_interferes = interferes[i];
    result.hulls.push_back(hull);
  }
  return result;
}

TransitionRecord nominal(std::vector<double> bounds, std::vector<double> allowances) {
  TransitionRecord record;
  record.certified = true;
  record.hull_motion_bounds = std::move(bounds);
  record.hull_allowances = std::move(allowances);
  record.governing.assign(record.hull_motion_bounds.size(), GoverningTerm::kClearance);
  return record;
}

TEST(HeldToTolerance, BalancedAndOneSidedAllowances) {
  // Delta 0.5. Hull 0: r = 1, 1.5: balanced 1.5, one-sided 1.0 -> 1.5; bound 1.5 holds.
  // Hull 1: r = 3, 0.75: balanced 2.75, one-sided 2.5 -> 2.75; bound 2.875 fails.
  // Hull 2: r = 5, 0.25: balanced 4.25, one-sided 4.5 -> 4.5; bound 4.5 holds (g = 0.5 exactly:
  // the one-sided branch, the point leaves the obstacle behind).
  const ProbeResult from = probe({1.0, 3.0, 5.0}, {false, false, false});
  const ProbeResult to = probe({1.5, 0.75, 0.25}, {false, false, false});
  const TransitionRecord held =
      held_to_tolerance(nominal({1.5, 2.875, 4.5}, {2.5, 3.75, 5.25}), from, to, 0.5);
  EXPECT_EQ(held.hull_allowances, (std::vector<double>{1.5, 2.75, 4.5}));
  EXPECT_FALSE(held.certified);
  const TransitionRecord met =
      held_to_tolerance(nominal({1.5, 2.75, 4.5}, {2.5, 3.75, 5.25}), from, to, 0.5);
  EXPECT_TRUE(met.certified);
}

TEST(HeldToTolerance, AnInterferingHullKeepsTheNominalAllowance) {
  const ProbeResult from = probe({0.25}, {true});
  const ProbeResult to = probe({0.5}, {false});
  const TransitionRecord held = held_to_tolerance(nominal({0.625}, {0.75}), from, to, 0.5);
  EXPECT_EQ(held.hull_allowances, (std::vector<double>{0.75}));
  EXPECT_TRUE(held.certified);
}

TEST(HeldToTolerance, ANominallyUncertifiedTransitionStaysUncertified) {
  const ProbeResult from = probe({10.0}, {false});
  const ProbeResult to = probe({10.0}, {false});
  TransitionRecord record = nominal({0.1}, {20.0});
  record.certified = false;  // e.g. a self pair failed
  EXPECT_FALSE(held_to_tolerance(record, from, to, 0.5).certified);
}

// Self pairs (proofs/two-ball-cover.md#corollary-self-tolerance-along-motion): the relative
// bound is held to max(d_k + d_k1 - 2 Delta, max(d_k, d_k1) - Delta), whatever the hulls do.
// Delta 0.5. Pair 0: d = 1, 1.5 -> 1.5 (balanced); bound 1.5 holds (g = 0.5 exactly). Pair 1:
// d = 5, 0.25 -> 4.5 (one-sided); bound 4.5 holds. Pair 2: d = 0.75, 0.75 -> 0.5; bound 0.625
// (below the nominal 1.5: the hulls never meet) fails: they may come within 0.4375 < Delta.
TEST(HeldToTolerance, SelfPairsAreHeldToAGapOfDelta) {
  ProbeResult from = probe({10.0}, {false});
  ProbeResult to = probe({10.0}, {false});
  const std::vector<std::pair<double, double>> distances{{1.0, 1.5}, {5.0, 0.25}, {0.75, 0.75}};
  for (const auto& [d_k, d_k1] : distances) {
    SelfPairEvidence at_k, at_k1;
    at_k.distance = d_k;
    at_k1.distance = d_k1;
    from.self_pairs.push_back(at_k);
    to.self_pairs.push_back(at_k1);
  }
  TransitionRecord record = nominal({0.1}, {20.0});
  record.self_pair_motion_bounds = {1.5, 4.5, 0.625};
  record.self_pair_allowances = {2.5, 5.25, 1.5};
  const TransitionRecord held = held_to_tolerance(record, from, to, 0.5);
  EXPECT_EQ(held.self_pair_allowances, (std::vector<double>{1.5, 4.5, 0.5}));
  EXPECT_EQ(held.hull_allowances, (std::vector<double>{19.0}));
  EXPECT_FALSE(held.certified);
  record.self_pair_motion_bounds[2] = 0.5;  // g = (1.5 - 0.5) / 2 = 0.5 = Delta
  EXPECT_TRUE(held_to_tolerance(record, from, to, 0.5).certified);
}

// The allowance is rounded down: with the doubles 0.1, 0.2 and Delta 0.05, plain double
// arithmetic gives 0.1 + 0.2 - 0.1 = 0.20000000000000004, above the exact value (decided in
// rationals); the held allowance is at most the exact value and within 1e-16 of it.
TEST(HeldToTolerance, TheHeldAllowanceIsRoundedDown) {
  using lemma_ref::Q;
  const Q exact_allowance = Q(0.1) + Q(0.2) - 2 * Q(0.05);
  EXPECT_GT(Q(0.1 + 0.2 - 2 * 0.05), exact_allowance);
  const double allowance = held_allowance_down(0.1, 0.2, 0.05);
  EXPECT_LE(Q(allowance), exact_allowance);
  EXPECT_GT(Q(allowance), exact_allowance - Q(1e-16));
}

}  // namespace
}  // namespace grpvss::certify
