// The certified march's proposals (include/grpvss/certify/step_proposal.hpp): slack ratios and
// the PTP proposal from motion bounds, on hand-made numbers.
#include "certify/step_proposal.hpp"

#include <cmath>
#include <limits>

#include <gtest/gtest.h>

namespace grpvss::certify {
namespace {

TransitionRecord transition(std::vector<double> bounds, std::vector<double> allowances) {
  TransitionRecord record;
  record.hull_motion_bounds = std::move(bounds);
  record.hull_allowances = std::move(allowances);
  return record;
}

TEST(StepProposal, TransitionSlackIsTheSmallestAllowanceOverBound) {
  EXPECT_DOUBLE_EQ(transition_slack(transition({2.0, 0.0, 1.0}, {3.0, 5.0, 0.5})), 0.5);
  EXPECT_DOUBLE_EQ(transition_slack(transition({2.0, 1.0}, {3.0, 5.0})), 1.5);
  EXPECT_EQ(transition_slack(transition({0.0, 0.0}, {0.0, 1.0})),
            std::numeric_limits<double>::infinity());
}

// Loose: a ratio (allowance - held margin) / bound at least kLooseFactor (1.5) times the
// smallest, or no motion at all; not a pair on its revolution route. The floor keeps the next
// transition passing with kLooseRoom (1.5) times the bound: margin + 1.5 bound - clearance.
TEST(StepProposal, LooseTermsHaveOneAndAHalfTimesTheLimitingRoomAndAFloorThatKeepsItPassing) {
  ASSERT_EQ(kLooseFactor, 1.5);
  ASSERT_EQ(kLooseRoom, 1.5);
  constexpr double kNot = std::numeric_limits<double>::infinity();
  // Hull ratios 1.5, 2.25 (exactly 1.5 x 1.5), 2.2, and one that does not move; pair ratios
  // 3, 1.4 (the smallest: 1.5 x 1.4 = 2.1 is the line) and 5 (on its revolution route).
  TransitionRecord record = transition({2.0, 2.0, 1.0, 0.0}, {3.0, 4.5, 2.2, 0.0});
  record.self_pair_motion_bounds = {1.0, 5.0, 1.0};
  record.self_pair_allowances = {3.0, 7.0, 5.0};
  record.self_pair_by_revolution = {0, 0, 1};
  const std::vector<double> radii{1.0, 2.5, 1.0, 0.25};
  const std::vector<double> distances{2.0, 3.0, 4.0};
  LooseTerms loose;
  loose_terms(record, 0.0, radii, distances, loose);
  EXPECT_EQ(loose.hull_floors, (std::vector<double>{kNot, 1.5 * 2.0 - 2.5, 1.5 * 1.0 - 1.0, -0.25}));
  EXPECT_EQ(loose.pair_floors, (std::vector<double>{1.5 * 1.0 - 2.0, kNot, kNot}));
  // Held to the tolerance (margin 1): ratios 1, 1.75, 1.2, -; 2, 1.2, 4: the line is 1.5.
  loose_terms(record, 1.0, radii, distances, loose);
  EXPECT_EQ(loose.hull_floors, (std::vector<double>{kNot, 1.0 + 1.5 * 2.0 - 2.5, kNot, 1.0 - 0.25}));
  EXPECT_EQ(loose.pair_floors, (std::vector<double>{1.0 + 1.5 * 1.0 - 2.0, kNot, kNot}));
  // A limit with no room left (ratio <= 0) gives no scale: only what did not move is loose.
  loose_terms(transition({1.0, 2.0, 0.0}, {0.5, 40.0, 0.0}), 1.0, {0.25, 20.0, 3.0}, {}, loose);
  EXPECT_EQ(loose.hull_floors, (std::vector<double>{kNot, kNot, 1.0 - 3.0}));
  EXPECT_TRUE(loose.pair_floors.empty());
}

// Next to a collision only the hulls their clearances do not cover are held to 2 Delta.
TEST(StepProposal, BasicResolutionHoldsOnlyUncoveredHullsToTwoDelta) {
  // Hull 0 in contact (allowance 0) moves 0.8 <= 2 Delta = 1; hull 1 moves 4, far beyond
  // 2 Delta, but its clearances allow 6: the rule holds (ratio min(1/0.8, 6/4) = 1.25).
  EXPECT_DOUBLE_EQ(basic_resolution_slack(transition({0.8, 4.0}, {0.0, 6.0}), 1.0), 1.25);
  // The contact hull moving 1.6 breaks it.
  EXPECT_DOUBLE_EQ(basic_resolution_slack(transition({1.6, 4.0}, {0.0, 6.0}), 1.0), 0.625);
  // A covered hull that moves beyond its allowance and beyond 2 Delta breaks it too.
  EXPECT_DOUBLE_EQ(basic_resolution_slack(transition({0.5, 8.0}, {0.0, 6.0}), 1.0), 0.75);
}

// One revolute joint moving linearly, q(t) = t, hull axis radius R = 2: M_h = 2 t.
double propose(const std::vector<ProposalHull>& hulls, bool has_trend, double previous_step,
               double max_step) {
  const Eigen::VectorXd q_now = Eigen::VectorXd::Zero(1);
  const auto joints_at = [](double t) { return Eigen::VectorXd::Constant(1, t); };
  return predicted_ptp_step(joints_at, q_now, max_step, std::vector<double>(hulls.size(), 2.0),
                            hulls, has_trend, previous_step);
}

// Bisection from below with 10 halvings of max_step: within max_step / 1024 under the answer.
void expect_from_below(double proposed, double exact, double max_step) {
  EXPECT_LE(proposed, exact);
  EXPECT_GT(proposed, exact - max_step / 1024.0);
}

TEST(StepProposal, WithoutTrendTheFarRadiusIsAssumedEqual) {
  // 2 t <= 0.95 (1 + 1)  =>  t <= 0.95.
  expect_from_below(propose({{1.0, false, 0.0}}, false, 1.0, 4.0), 0.95, 4.0);
}

TEST(StepProposal, ClaimMotionAimsAtTheAllowanceLessTwoDelta) {
  // Delta = 0.25, held_margin 0.5: 2 t <= 0.95 (1 + 1 - 0.5)  =>  t <= 0.7125
  // (proofs/two-ball-cover.md#lemma-tolerance-along-motion).
  ProposalHull held{1.0, false, 0.0};
  held.held_margin = 0.5;
  expect_from_below(propose({held}, false, 1.0, 4.0), 0.7125, 4.0);
}

// Two revolute joints, q(t) = (t, t), weights R = (2, 2), axis distances D = (0.5, 0.5) at q_now:
// M'_h = t min(2, 0.5) + t min(2, 0.5 + 2 t) (proofs/motion-bound.md#lemma-axis-distance-along-step).
// Within 0.95 (1 + 1) = 1.9: up to t = 0.75 it is t + 2 t^2 (1.875 at 0.75); beyond, joint 1's
// distance is capped by R = 2, so 0.5 t + 2 t <= 1.9, t = 0.76.
TEST(StepProposal, AxisDistancesGiveTheStepRadiusFormWithTheJointsAfterEachAxis) {
  const Eigen::VectorXd q_now = Eigen::VectorXd::Zero(2);
  const auto joints_at = [](double t) { return Eigen::VectorXd::Constant(2, t); };
  const std::vector<ProposalHull> hulls{{1.0, false, 0.0}};
  const double with_distances = predicted_ptp_step(joints_at, q_now, 4.0, {2.0, 2.0}, hulls, false,
                                                   1.0, {0.5, 0.5});
  expect_from_below(with_distances, 0.76, 4.0);
  // Without them, M_h = 4 t <= 1.9.
  const double without = predicted_ptp_step(joints_at, q_now, 4.0, {2.0, 2.0}, hulls, false, 1.0);
  expect_from_below(without, 1.9 / 4.0, 4.0);
}

TEST(StepProposal, AShrinkingClearanceIsExtrapolated) {
  // r_{k-1} = 1.5 one unit ago: r_far = 1 - 0.5 t, so 2 t <= 0.95 (2 - 0.5 t), t <= 1.9 / 2.475.
  expect_from_below(propose({{1.0, false, 1.5}}, true, 1.0, 4.0), 1.9 / 2.475, 4.0);
}

TEST(StepProposal, TheClearanceIsNeverAssumedToFallFasterThanTheMotion) {
  // r_{k-1} = 10: the trend says r_far = 1 - 9 t, but the hull moves only 2 t, so
  // r_far >= 1 - 2 t: 2 t <= 0.95 (2 - 2 t), t <= 1.9 / 3.9.
  expect_from_below(propose({{1.0, false, 10.0}}, true, 1.0, 4.0), 1.9 / 3.9, 4.0);
}

TEST(StepProposal, TheTightestHullGovernsAndContactOrRefiningHullsAreIgnored) {
  // Radii 3 (t <= 2.85) and 1 (t <= 0.95): the second governs.
  expect_from_below(propose({{3.0, false, 0.0}, {1.0, false, 0.0}}, false, 1.0, 4.0), 0.95, 4.0);
  // A hull in contact (radius 0) or refining next to a contact does not cut the proposal.
  EXPECT_EQ(propose({{0.0, false, 0.0}, {1.0, true, 0.0}}, false, 1.0, 4.0), 4.0);
  // When the whole allowed step fits it is returned as it is.
  EXPECT_EQ(propose({{100.0, false, 0.0}}, false, 1.0, 4.0), 4.0);
}

// A self pair with a revolution route (proofs/two-ball-cover.md#revolution-route): the pair
// passes when its own entry or its stand-in fits; the stand-in never limits the step by itself.
TEST(StepProposal, ARouteStandsInForItsPairAndNeverLimitsTheStepAlone) {
  ProposalHull pair{1.0, false, 0.0};   // alone: t <= 0.95
  ProposalHull route{3.0, false, 0.0};  // t <= 2.85
  route.alternative_only = true;
  pair.alternative = 1;
  expect_from_below(propose({pair, route}, false, 1.0, 4.0), 2.85, 4.0);
  // The tighter of the two stands: the route at radius 0.5 (t <= 0.475) does not shorten it.
  route.radius = 0.5;
  expect_from_below(propose({pair, route}, false, 1.0, 4.0), 0.95, 4.0);
  // A route with no distance (radius 0) stands in for nothing, and limits nothing.
  route.radius = 0.0;
  expect_from_below(propose({pair, route}, false, 1.0, 4.0), 0.95, 4.0);
  pair.alternative = -1;
  route.radius = 0.1;
  expect_from_below(propose({pair, route}, false, 1.0, 4.0), 0.95, 4.0);
}

}  // namespace
}  // namespace grpvss::certify

namespace grpvss::certify {
namespace {

// A trial 1.44x over the model's deviation shrinks to 0.9 / 1.2 = 0.75 of itself; 4x and more,
// or NaN, is halved (a jump does not follow the square law).
TEST(StepProposal, CpModelRetryFollowsTheSquareLawBelowFourTimesTheModel) {
  EXPECT_DOUBLE_EQ(cp_model_retry_fraction(1.44), 0.75);
  EXPECT_DOUBLE_EQ(cp_model_retry_fraction(1.0 + 1e-12), 0.9 / std::sqrt(1.0 + 1e-12));
  EXPECT_DOUBLE_EQ(cp_model_retry_fraction(3.24), 0.5);  // 0.9 / 1.8
  EXPECT_DOUBLE_EQ(cp_model_retry_fraction(4.0), 0.5);
  EXPECT_DOUBLE_EQ(cp_model_retry_fraction(22.047), 0.5);
  EXPECT_DOUBLE_EQ(cp_model_retry_fraction(std::nan("")), 0.5);
}

// After a step that used 0.25 of the model, the next may be 0.95 / 0.5 = 1.9 times as long;
// one at the model's limit does not shrink the next proposal; a straight one is not capped.
TEST(StepProposal, CpModelCapsTheNextProposalByTheSquareLaw) {
  EXPECT_DOUBLE_EQ(cp_model_growth_cap(0.25), 1.9);
  EXPECT_DOUBLE_EQ(cp_model_growth_cap(1.0), 1.0);
  EXPECT_EQ(cp_model_growth_cap(0.0), std::numeric_limits<double>::infinity());
}

// The sample path's joint-4 wrap keeps a deviation of 22 whatever the step: the second, shorter
// failure from the same start is a jump. A smooth failure that drops fourfold is not; nor is
// a failure from another start, or after reset().
TEST(StepProposal, CpModelFailuresTellAJumpFromAStepTooLong) {
  CpModelFailures wrap;
  EXPECT_FALSE(wrap.record(5.8, 6.1, 22.0));
  EXPECT_TRUE(wrap.record(5.8, 3.0, 22.0));

  CpModelFailures quartered;
  EXPECT_FALSE(quartered.record(0.0, 8.0, 4.0));
  EXPECT_FALSE(quartered.record(0.0, 4.0, 1.1));  // 1.1 < 4 / 2: the square law holds

  CpModelFailures moved;
  EXPECT_FALSE(moved.record(0.0, 8.0, 22.0));
  EXPECT_FALSE(moved.record(2.0, 4.0, 22.0));  // another start
  moved.reset();
  EXPECT_FALSE(moved.record(2.0, 2.0, 22.0));  // forgotten
  EXPECT_FALSE(moved.record(2.0, 3.0, 22.0));  // not shorter
}

}  // namespace
}  // namespace grpvss::certify
