// The claim `motion`'s step decision (transition_judge.hpp held_to_tolerance): every hull whose
// expanded hull is clear at both ends is held to g >= Delta, i.e. to
// max(r_k + r_k1 - 2 Delta, max(r_k, r_k1) - Delta) (proofs/two-ball-cover.md#lemma-tolerance-along-motion).
#include <gtest/gtest.h>

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

}  // namespace
}  // namespace grpvss::certify
