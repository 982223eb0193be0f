// The Panda of ../shared/robots folding its hand into its arm (tests/data/cells/panda-self.yaml,
// which keeps the Panda's self pairs): elbow (joint 4) from -135 to -165 degrees and wrist
// (joint 6) from 90 to 60 degrees bring the hand's capsule into the upper arm's, a COLLISION
// naming both links at the exact first step, with the certificate accepted; the same fold
// stopped short (-145 / 35 degrees; -147 / 37 already touches) is CLEAR and accepted. The
// independent oracle (support/urdf_cell_oracle.hpp: own FK, exact LP) confirms the named step
// is a self-contact and the step before is not.
#include <string>

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

// As `grpvss verify --cell panda-self.yaml --path <path>`.
PandaSelfRun run_panda_path(const std::string& path) { return test::run_panda_self(path); }

CheckReport check_panda_certificate(const PandaSelfRun& r) { return test::check_panda_self(r, r.verified.certificate); }

TEST(PandaSelfCollision, FoldingTheHandIntoTheUpperArmIsACollisionNamingBothLinks) {
  const PandaSelfRun r = run_panda_path("panda-fold.txt");
  ASSERT_FALSE(r.cell.robot.self_collision_pairs.empty());
  const VerificationResult& result = r.verified.result;
  EXPECT_EQ(result.verdict, Verdict::kCollision);
  ASSERT_TRUE(result.collision_step.has_value());
  // 19 steps (26 before the claim `motion` held self pairs to a gap of Delta: the steps close in
  // on the fold until they give up aiming at g >= Delta; 50 before the step's axis distances).
  EXPECT_EQ(*result.collision_step, 19);
  ASSERT_FALSE(result.self_collision_episodes.empty());
  const SelfCollisionEpisode& first = result.self_collision_episodes.front();
  EXPECT_EQ(self_pair_label(r.cell.robot, first.pair), "panda_hand_sc / panda_link2_sc");
  EXPECT_EQ(link_label(r.cell.robot, first.pair.link_b), "panda_hand_tcp");  // the hand rides link 7
  EXPECT_EQ(first.pair.link_b, 7);
  EXPECT_EQ(link_label(r.cell.robot, first.pair.link_a), "panda_link2");
  EXPECT_EQ(first.first_step, 19);
  EXPECT_TRUE(result.interference_episodes.empty());  // the table is never touched
  const CheckReport report = check_panda_certificate(r);
  EXPECT_TRUE(report.accepted) << (report.failures.empty() ? "" : report.failures.front());
  EXPECT_EQ(report.claim, Verdict::kCollision);
  // The oracle's own FK and exact LP: the named step is a self-contact, the step before is not.
  const test::UrdfCellOracle oracle(r.cell);
  const auto named = static_cast<std::size_t>(*result.collision_step);  // steps[k - 1] is step k
  ASSERT_EQ(result.steps.at(named - 1).index, *result.collision_step);
  const test::UrdfOracleContact at = oracle.check(result.steps.at(named - 1).q);
  EXPECT_TRUE(at.contact && at.self);
  EXPECT_FALSE(oracle.check(result.steps.at(named - 2).q).contact);
}

TEST(PandaSelfCollision, TheFoldStoppedShortIsClearAndItsCertificateIsAccepted) {
  const PandaSelfRun r = run_panda_path("panda-near-fold.txt");
  EXPECT_EQ(r.verified.result.verdict, Verdict::kClear);
  EXPECT_TRUE(r.verified.result.self_collision_episodes.empty());
  const CheckReport report = check_panda_certificate(r);
  EXPECT_TRUE(report.accepted) << (report.failures.empty() ? "" : report.failures.front());
  EXPECT_EQ(report.claim, Verdict::kClear);
}

}  // namespace
}  // namespace grpvss::certify
