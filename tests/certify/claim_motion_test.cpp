// The claim `motion` (docs/verification.md#claim, proofs/two-ball-cover.md#lemma-tolerance-along-motion):
// CLEAR only where every transition keeps g >= Delta, the verifier's verdicts and the checker's
// exact decision on the IBM 7545 Table 3 PTP past a post 0.62 in. (near miss) and 0.45 in.
// (within tolerance) below the quill's path, at the tolerance 0.5.
#include <algorithm>
#include <string>

#include <gtest/gtest.h>

#include <nlohmann/json.hpp>

#include "grpvss/checker/certificate_checker.hpp"
#include "grpvss/common/input_error.hpp"
#include "grpvss/certify/verifier.hpp"
#include "support/ibm7545_run.hpp"

namespace grpvss::certify {
namespace {

using test::kIbm7545Tolerance;

double smallest_motion_clearance(const VerificationResult& result) {
  double smallest = 1e300;
  for (const LinkClearanceSummary& link : result.link_clearances) {
    if (link.min_motion_clearance) smallest = std::min(smallest, *link.min_motion_clearance);
  }
  return smallest;
}

CheckReport check_ibm7545_certificate(const test::Ibm7545Run& cell, const Certificate& certificate) {
  return check_certificate(cell.robot, cell.environment, cell.program, cell.kinematics,
                           certificate);
}

// 0.62 in. > 0.5: the claim `motion` is met, every transition keeps g >= Delta; the claim is
// recorded and the checker accepts it, deciding g >= Delta.
TEST(ClaimMotion, TheNearMissIsClearAlongTheMotion) {
  const test::Ibm7545Run cell =
      test::verify_ibm7545("bench-environment-near-miss.txt", test::kTable3PtpPath);
  const VerificationResult& result = cell.run.result;
  ASSERT_EQ(result.verdict, Verdict::kClear);
  EXPECT_EQ(result.claim, ClearClaim::kMotion);
  EXPECT_FALSE(result.tolerance_shortfall.has_value());
  EXPECT_GE(smallest_motion_clearance(result), kIbm7545Tolerance);
  EXPECT_EQ(cell.run.certificate.clear_claim, ClearClaim::kMotion);
  const CheckReport report = check_ibm7545_certificate(cell, cell.run.certificate);
  EXPECT_TRUE(report.accepted) << (report.failures.empty() ? "" : report.failures.front());
  EXPECT_EQ(report.clear_claim, ClearClaim::kMotion);
  for (const CheckedMotionClearance& link : report.motion_clearances) {
    if (link.link > 0) EXPECT_GE(link.lower_bound, kIbm7545Tolerance) << "link " << link.link;
  }
}

// 0.45 in. < 0.5: CLEAR with the claim `steps` (the expanded quill clears the post at every
// step, the nominal one along the motion; 11 steps); with the claim `motion` the steps aiming
// at g >= Delta close in on the pass and find the expanded quill interfering there:
// WITHIN_TOLERANCE (56 steps), which the checker accepts.
TEST(ClaimMotion, ThePassBelowTheToleranceIsWithinTolerance) {
  const test::Ibm7545Run steps = test::verify_ibm7545(
      "bench-environment-within-tolerance.txt", test::kTable3PtpPath, ClearClaim::kSteps);
  ASSERT_EQ(steps.run.result.verdict, Verdict::kClear);
  EXPECT_EQ(steps.run.result.steps.size(), 11u);
  EXPECT_LT(smallest_motion_clearance(steps.run.result), kIbm7545Tolerance);
  EXPECT_FALSE(steps.run.result.tolerance_shortfall.has_value());

  const test::Ibm7545Run motion =
      test::verify_ibm7545("bench-environment-within-tolerance.txt", test::kTable3PtpPath);
  const VerificationResult& result = motion.run.result;
  ASSERT_EQ(result.verdict, Verdict::kWithinTolerance);
  EXPECT_EQ(result.steps.size(), 56u);
  ASSERT_FALSE(result.interference_episodes.empty());
  EXPECT_EQ(result.interference_episodes.front().link, 4);
  EXPECT_EQ(result.interference_episodes.front().obstacle, 0);
  EXPECT_FALSE(result.interference_episodes.front().first_collision_step.has_value());
  EXPECT_FALSE(result.tolerance_shortfall.has_value());  // the interference says it already
  EXPECT_EQ(motion.run.certificate.claim, Verdict::kWithinTolerance);
  EXPECT_TRUE(check_ibm7545_certificate(motion, motion.run.certificate).accepted);
}

// Where the steps cannot shrink towards g >= Delta (a certified step floor of 1/4 of the
// segment here) a transition meeting only the nominal rule is accepted on it: the near miss
// (CLEAR with either claim at the usual floor) is WITHIN_TOLERANCE with the shortfall named
// (the quill, link 4, past the post, obstacle 0), never UNDECIDED; its certificate claims
// WITHIN_TOLERANCE and is accepted.
TEST(ClaimMotion, ATransitionMeetingOnlyTheNominalRuleIsAShortfall) {
  test::Ibm7545Run cell =
      test::verify_ibm7545("bench-environment-near-miss.txt", test::kTable3PtpPath);
  SetupRequest request;
  request.tolerance = kIbm7545Tolerance;
  request.limits.certify_floor_fraction = 0.25;
  cell.setup = resolve_setup(request);
  cell.run = verify(cell.robot, cell.environment, cell.program, cell.kinematics, cell.setup);
  const VerificationResult& result = cell.run.result;
  ASSERT_EQ(result.verdict, Verdict::kWithinTolerance);
  EXPECT_TRUE(result.interference_episodes.empty());
  ASSERT_TRUE(result.tolerance_shortfall.has_value());
  EXPECT_EQ(result.tolerance_shortfall->link, 4);
  EXPECT_EQ(result.tolerance_shortfall->obstacle, 0);
  EXPECT_LT(result.tolerance_shortfall->motion_clearance, kIbm7545Tolerance);
  EXPECT_GE(result.tolerance_shortfall->step, 1);
  EXPECT_TRUE(check_ibm7545_certificate(cell, cell.run.certificate).accepted);
}

// A CLEAR certificate made with the claim `steps` whose claim is relabelled `motion` is
// rejected: some transition keeps g < Delta; the failure names the steps, the quill and the post.
TEST(ClaimMotion, TheCheckerRejectsACertificateWhoseTransitionsKeepLessThanDelta) {
  const test::Ibm7545Run steps = test::verify_ibm7545(
      "bench-environment-within-tolerance.txt", test::kTable3PtpPath, ClearClaim::kSteps);
  ASSERT_EQ(steps.run.certificate.claim, Verdict::kClear);
  EXPECT_TRUE(check_ibm7545_certificate(steps, steps.run.certificate).accepted);
  Certificate relabelled = steps.run.certificate;
  relabelled.clear_claim = ClearClaim::kMotion;
  const CheckReport report = check_ibm7545_certificate(steps, relabelled);
  EXPECT_FALSE(report.accepted);
  ASSERT_FALSE(report.failures.empty());
  bool named = false;
  for (const std::string& failure : report.failures) {
    if (failure.find("below the tolerance 0.5") != std::string::npos &&
        failure.find("link 4") != std::string::npos &&
        failure.find("obstacle 0") != std::string::npos && failure.find("steps ") == 0) {
      named = true;
    }
  }
  EXPECT_TRUE(named) << report.failures.front();
}

// A certificate JSON without "clear_claim" (made before the claim existed) reads as `steps`.
TEST(ClaimMotion, ACertificateWithoutTheFieldReadsAsSteps) {
  const test::Ibm7545Run cell =
      test::verify_ibm7545("bench-environment-near-miss.txt", test::kTable3PtpPath);
  nlohmann::json document = certificate_to_json(cell.run.certificate);
  EXPECT_EQ(document.at("clear_claim"), "motion");
  EXPECT_EQ(certificate_from_json(document, "c.json").clear_claim, ClearClaim::kMotion);
  document.erase("clear_claim");
  EXPECT_EQ(certificate_from_json(document, "c.json").clear_claim, ClearClaim::kSteps);
  document["clear_claim"] = "everywhere";
  EXPECT_THROW(certificate_from_json(document, "c.json"), InputError);
}

}  // namespace
}  // namespace grpvss::certify
