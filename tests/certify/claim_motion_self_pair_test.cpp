// The claim `motion` for self pairs (proofs/two-ball-cover.md#corollary-self-tolerance-along-motion,
// docs/verification.md#claim): the Panda of ../shared/robots (tests/data/cells/panda-self.yaml,
// tolerance 0.005 m) folding its hand towards its upper arm and stopping just short of touching
// (tests/data/cells/panda-grazing-fold.txt: elbow to -146 degrees, wrist to 36 degrees; -147 /
// 37 already touches, tests/certify/panda_self_collision_test.cpp). The hand's capsule passes
// closer than the tolerance to the upper arm's: WITHIN_TOLERANCE with the claim `motion`,
// naming both links; CLEAR with the claim `steps` (the nominal hulls never meet); both
// certificates accepted, and the `steps` certificate relabelled `motion` rejected.
#include <algorithm>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "grpvss/cell/load_cell.hpp"
#include "grpvss/certify/verifier.hpp"
#include "grpvss/checker/certificate_checker.hpp"
#include "grpvss/io/path_file.hpp"
#include "grpvss/motion/kinematics_adapter.hpp"
#include "support/panda_self_run.hpp"
#include "support/urdf_cell_oracle.hpp"

namespace grpvss::certify {
namespace {

using test::PandaSelfRun;

// As `grpvss verify --cell panda-self.yaml --path panda-grazing-fold.txt --claim <claim>`.
PandaSelfRun run_grazing_fold(ClearClaim claim) {
  return test::run_panda_self("panda-grazing-fold.txt", claim);
}

CheckReport check_self_pair_certificate(const PandaSelfRun& r, const Certificate& certificate) {
  return test::check_panda_self(r, certificate);
}

std::string first_failure(const CheckReport& report) {
  return report.failures.empty() ? "" : report.failures.front();
}

TEST(ClaimMotionSelfPair, TheHandPassingWithinTheToleranceOfTheUpperArmIsWithinTolerance) {
  const PandaSelfRun r = run_grazing_fold(ClearClaim::kMotion);
  const VerificationResult& result = r.verified.result;
  ASSERT_EQ(result.verdict, Verdict::kWithinTolerance);
  EXPECT_TRUE(result.self_collision_episodes.empty());  // the hulls never meet
  EXPECT_TRUE(result.interference_episodes.empty());    // nor does the expanded robot the table
  ASSERT_TRUE(result.tolerance_shortfall.has_value());
  const ToleranceShortfall& shortfall = *result.tolerance_shortfall;
  EXPECT_EQ(link_label(r.cell.robot, shortfall.link), "panda_link2");
  EXPECT_EQ(link_label(r.cell.robot, shortfall.other_link), "panda_hand_tcp");
  EXPECT_EQ(shortfall.obstacle, -1);
  EXPECT_LT(shortfall.motion_clearance, r.cell.tolerance);
  EXPECT_GT(shortfall.motion_clearance, 0.0);
  EXPECT_EQ(shortfall.step, 30);
  EXPECT_EQ(result.steps.size(), 42u);  // 12 with the claim `steps`: the steps close in on the fold
  // The certificate: the hand / upper arm hulls are proven separated at every step, and their
  // proven distance falls below the tolerance (to 0.0035 m) on the way.
  const std::vector<SelfCollisionPair>& pairs = r.cell.robot.self_collision_pairs;
  double closest = 1.0;
  for (const SegmentCertificate& segment : r.verified.certificate.segments) {
    for (const StepCertificate& step : segment.steps) {
      ASSERT_EQ(step.self_pairs.size(), pairs.size());
      for (std::size_t p = 0; p < pairs.size(); ++p) {
        if (self_pair_label(r.cell.robot, pairs[p]) != "panda_hand_sc / panda_link2_sc") continue;
        EXPECT_TRUE(step.self_pairs[p].separated) << "step " << step.step;
        closest = std::min(closest, step.self_pairs[p].lower_bound);
      }
    }
  }
  EXPECT_GT(closest, 0.0035);
  EXPECT_LT(closest, r.cell.tolerance);
  EXPECT_EQ(r.verified.certificate.claim, Verdict::kWithinTolerance);
  const CheckReport report = check_self_pair_certificate(r, r.verified.certificate);
  EXPECT_TRUE(report.accepted) << first_failure(report);
  EXPECT_EQ(report.claim, Verdict::kWithinTolerance);
  // The oracle's own FK and exact LP: the last configuration touches nothing.
  const test::UrdfCellOracle oracle(r.cell);
  EXPECT_FALSE(oracle.check(result.steps.back().q).contact);
}

TEST(ClaimMotionSelfPair, WithTheClaimStepsTheGrazingFoldIsClear) {
  const PandaSelfRun r = run_grazing_fold(ClearClaim::kSteps);
  const VerificationResult& result = r.verified.result;
  ASSERT_EQ(result.verdict, Verdict::kClear);
  EXPECT_FALSE(result.tolerance_shortfall.has_value());
  EXPECT_EQ(result.steps.size(), 12u);
  const CheckReport report = check_self_pair_certificate(r, r.verified.certificate);
  EXPECT_TRUE(report.accepted) << first_failure(report);
  EXPECT_EQ(report.claim, Verdict::kClear);
}

// The `steps` certificate relabelled `motion`: a CLEAR certificate whose self pair keeps less
// than the tolerance along the motion is rejected, the failure naming the steps and the pair.
TEST(ClaimMotionSelfPair, TheCheckerRejectsAClearMotionCertificateWhosePairKeepsLessThanDelta) {
  const PandaSelfRun r = run_grazing_fold(ClearClaim::kSteps);
  ASSERT_EQ(r.verified.certificate.claim, Verdict::kClear);
  Certificate relabelled = r.verified.certificate;
  relabelled.clear_claim = ClearClaim::kMotion;
  const CheckReport report = check_self_pair_certificate(r, relabelled);
  EXPECT_FALSE(report.accepted);
  ASSERT_FALSE(report.failures.empty());
  int self_pair_failures = 0;
  for (const std::string& failure : report.failures) {
    if (failure.find("self pair panda_hand_sc / panda_link2_sc: the gap kept along the motion") !=
            std::string::npos &&
        failure.find("is below the tolerance 0.005") != std::string::npos &&
        failure.find("steps ") != std::string::npos) {
      ++self_pair_failures;
    }
  }
  EXPECT_GE(self_pair_failures, 1) << first_failure(report);
}

}  // namespace
}  // namespace grpvss::certify
