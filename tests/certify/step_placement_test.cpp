// Where the certified march puts its steps next to a contact: the proposals aim the trials
// (src/certify/step_proposal.cpp, PathVerifier::march_segment); the step rule decides. These
// tests pin the report's shape, not soundness (the oracle tests do that).
#include <gtest/gtest.h>

#include "support/ibm7545_run.hpp"

namespace grpvss::certify {
namespace {

// The Table 3 CP line run into a post (bench-environment-cp-line.txt), after a PTP(WCS)
// approach to its start. Approaching the contact, every proven step is allowed only the raw
// clearance left, so proven steps shrank geometrically towards the contact time: 20 steps
// with the quill moving less than 0.2 Delta each, crowded before the first collision. The
// trial after a refining step now aims at the basic resolution, and one past the contact
// finds the COLLISION.
TEST(StepPlacement, TheApproachToAContactDoesNotCreep) {
  const test::Ibm7545Run cell = test::verify_ibm7545(
      "bench-environment-cp-line.txt",
      "2\n2\n0.,20.,8.,0.,0.,1.,141.\n3.\n3.\n0.3\n3.\n3\n-20.,-5.,2.,0.,0.,1.,0.\n");
  const VerificationRun& run = cell.run;
  ASSERT_EQ(run.result.verdict, Verdict::kCollision);
  int creeping = 0, cp_steps = 0;
  for (const StepRecord& step : run.result.steps) {
    if (step.segment != 2) continue;
    ++cp_steps;
    const LinkStepRecord& quill = step.links.at(4);
    if (quill.motion_bound < 0.2 * test::kIbm7545Tolerance) ++creeping;
  }
  EXPECT_EQ(creeping, 0);
  // 51 before; 27 while the colliding pair was sampled at 2 Delta; 11 with the joint-sum
  // motion bound only (proofs/motion-bound.md#lemma-joint-linear-chord).
  EXPECT_EQ(cp_steps, 5);
  // The collision is found by the step that passes the contact.
  ASSERT_TRUE(run.result.collision_step.has_value());
  const StepRecord& first = run.result.steps.at(static_cast<std::size_t>(*run.result.collision_step - 1));
  EXPECT_EQ(first.index, *run.result.collision_step);
  EXPECT_GT(first.links.at(4).motion_bound, first.links.at(4).allowance);  // not proven: a basic step
}

// The sample path's CP line (A.1.3) turns joint 4 past its limit: the IK nearest the last
// step jumps branch (error 7). Each trial across the jump failed the CP joint-path model and was
// halved, the accepted half grew again and failed again: 15 proven steps crept up to the jump
// (all at s = 8.828) before the error. A failing step far shorter than the last accepted one
// now has the jump located by bisection on the model (IK and FK only), and the next trial
// lands just before it.
TEST(StepPlacement, AJointJumpAheadIsLocatedWithoutCreepingUpToIt) {
  // The placement of the `steps` claim's rule (the `motion` claim's steps are finer).
  const test::Ibm7545Run cell =
      test::verify_ibm7545_files("environment.txt", "path.txt", ClearClaim::kSteps);
  const VerificationRun& run = cell.run;
  ASSERT_EQ(run.result.errors.size(), 1u);
  const PathError& error = run.result.errors.front();
  EXPECT_EQ(error.code, 7);
  EXPECT_EQ(error.segment, 3);
  ASSERT_FALSE(run.result.steps.empty());
  const StepRecord& last = run.result.steps.back();
  EXPECT_EQ(error.step, last.index);
  // 43 before; 28 while colliding pairs were sampled at 2 Delta; 26 before the chord bound; 24
  // before the step's axis distances (proofs/motion-bound.md#lemma-axis-distance-along-step).
  EXPECT_EQ(last.index, 23);
  EXPECT_NEAR(last.segment_parameter, 8.8283, 1e-4);  // where joint 4 reaches its limit
  int creeping = 0;
  for (const StepRecord& step : run.result.steps) {
    if (step.segment == 3 && step.links.at(4).motion_bound < 0.2 * test::kIbm7545Tolerance) ++creeping;
  }
  EXPECT_EQ(creeping, 0);
}

// The Table 3 PTP runs the quill through the post. Inside a collision nothing is certified and
// the verdict is already COLLISION, so the colliding pair is not sampled: the step after the
// first collision lands with the quill out of the post (it was in the post at 5 steps in a
// row, at the basic resolution, before). Every other link is still held to the basic
// resolution or covered by its clearances on that step.
TEST(StepPlacement, ACollisionIsCrossedWithoutSamplingTheCollidingPair) {
  // The `steps` claim: under `motion` the approach to the post is held to the tolerance.
  const test::Ibm7545Run cell =
      test::verify_ibm7545("bench-environment.txt", test::kTable3PtpPath, ClearClaim::kSteps);
  const VerificationRun& run = cell.run;
  ASSERT_EQ(run.result.verdict, Verdict::kCollision);
  ASSERT_TRUE(run.result.collision_step.has_value());
  const int collision = *run.result.collision_step;
  int colliding_steps = 0;
  for (const StepRecord& step : run.result.steps) colliding_steps += step.unexpanded_collides;
  EXPECT_EQ(colliding_steps, 1);  // 5 before
  // 13 before; 5 before the step's axis distances, which let the last step stop a sliver short.
  EXPECT_EQ(run.result.steps.size(), 6u);
  const StepRecord& after = run.result.steps.at(static_cast<std::size_t>(collision));
  EXPECT_FALSE(after.expanded_interferes);
  const double two_delta = 2.0 * test::kIbm7545Tolerance;
  EXPECT_GT(after.links.at(4).motion_bound, 3.0 * two_delta);  // the quill crossed the post
  for (int link = 1; link < 4; ++link) {
    const LinkStepRecord& record = after.links.at(static_cast<std::size_t>(link));
    EXPECT_LE(record.motion_bound, std::max(record.allowance, two_delta)) << "link " << link;
  }
}

}  // namespace
}  // namespace grpvss::certify
