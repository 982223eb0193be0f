// Findings of the oracle soundness runs (docs/soundness-oracle.md#findings), kept as
// regression tests with the exact random case that exposed them. Each was a checker rejection
// of a certificate the verifier wrote (never a CLEAR claim), fixed in
// src/certify/certificate_checker.cpp: a segment with only its start step is checked and
// marked uncovered; a collision at step 0 is re-decided at the robot's home configuration.
#include <variant>

#include <gtest/gtest.h>

#include "grpvss/certify/certificate_checker.hpp"
#include "grpvss/certify/verifier.hpp"
#include "grpvss/motion/kinematics_adapter.hpp"
#include "support/motion_oracle.hpp"
#include "support/oracle_cases.hpp"

namespace grpvss::certify {
namespace {

// Found by the long run (fixed): the long oracle run's SCARA case 408 (seed
// 0xc0de0198, Delta = 1.148) stops with error 7 (IK joint jump) at the FIRST step of CP
// segment 3. The verdict ERROR is right, but the certificate written for the run is rejected
// by check_certificate: "segment 3: fewer than two steps" (the unsimulated segment is written
// with a single step). Not a soundness bug (nothing is claimed CLEAR), but every certificate
// must be accepted. The CI shard case 95 (seed 0xc0de005f: COLLISION in segment 1, then error 7
// at the first step of CP segment 2) shows the same rejection for a COLLISION certificate.
TEST(OracleFindings, CpSegmentStoppedAtItsFirstStepStillGivesAnAcceptedCertificate) {
  const test::OracleCase c = test::random_scara_cp_case(0xc0de0198ULL);
  const auto kinematics = motion::make_kinematics_access(c.robot, motion::select_ik(c.ik, c.robot, "random"));
  VerifyOptions options;
  options.tolerance = c.tolerance;
  const VerificationRun run = verify(c.robot, c.environment, c.program, kinematics, options);
  ASSERT_EQ(run.result.verdict, Verdict::kError);
  ASSERT_EQ(run.result.errors.size(), 1u);
  EXPECT_EQ(run.result.errors.front().code, kErrorCpJointJump);
  EXPECT_EQ(run.result.errors.front().segment, 3);
  const CheckReport report = check_certificate(c.robot, c.environment, c.program, kinematics, run.certificate);
  EXPECT_EQ(report.claim, "ERROR");
  EXPECT_TRUE(report.accepted) << (report.failures.empty() ? "" : report.failures.front());
}

// Found by the long run (fixed): long-run PTP case 1289 (seed 0x5eed0509) has a
// second PTP segment whose target is where the first one ended (both clamped to the joint
// limits): zero motion. The verifier simulates it without a step, the certificate holds the
// segment with fewer than two steps and check_certificate rejects the COLLISION certificate
// ("segment 2: fewer than two steps"). Same in case 1267 (seed 0x5eed04f3, WITHIN_TOLERANCE).
TEST(OracleFindings, ZeroMotionPtpSegmentStillGivesAnAcceptedCertificate) {
  const test::OracleCase c = test::random_ptp_case(0x5eed0509ULL);
  ASSERT_EQ(c.program.segments.size(), 2u);
  const auto& first = std::get<PtpJointSegment>(c.program.segments[0].spec);
  const auto& second = std::get<PtpJointSegment>(c.program.segments[1].spec);
  ASSERT_EQ(first.target, second.target);  // the second segment does not move
  const auto kinematics = motion::make_kinematics_access(c.robot, motion::select_ik(c.ik, c.robot, "random"));
  VerifyOptions options;
  options.tolerance = c.tolerance;
  const VerificationRun run = verify(c.robot, c.environment, c.program, kinematics, options);
  EXPECT_EQ(run.result.verdict, Verdict::kCollision);
  const CheckReport report = check_certificate(c.robot, c.environment, c.program, kinematics, run.certificate);
  EXPECT_EQ(report.claim, "COLLISION");
  EXPECT_TRUE(report.accepted) << (report.failures.empty() ? "" : report.failures.front());
}

// Found by the long run (fixed): long-run SCARA case 1945 (seed 0xc0de0799,
// Delta = 0.022): the robot collides at its home configuration (step 0; the oracle confirms)
// and the first CP line stops with error 5 before any step. Verdict COLLISION at step 0 is
// right, but check_certificate rejects the certificate: "claim COLLISION, but the robot at the
// named step touches no obstacle".
TEST(OracleFindings, CollisionAtTheStartBeforeAnErrorGivesAnAcceptedCertificate) {
  const test::OracleCase c = test::random_scara_cp_case(0xc0de0799ULL);
  const auto kinematics = motion::make_kinematics_access(c.robot, motion::select_ik(c.ik, c.robot, "random"));
  Eigen::VectorXd home(c.robot.joint_count());
  for (int j = 0; j < c.robot.joint_count(); ++j) home[j] = c.robot.joints[j].home;
  ASSERT_TRUE(test::MotionOracle(c.robot, c.environment).check(home).contact);
  VerifyOptions options;
  options.tolerance = c.tolerance;
  const VerificationRun run = verify(c.robot, c.environment, c.program, kinematics, options);
  ASSERT_EQ(run.result.verdict, Verdict::kCollision);
  EXPECT_EQ(run.result.collision_step, 0);
  ASSERT_EQ(run.result.errors.size(), 1u);
  EXPECT_EQ(run.result.errors.front().code, 5);
  const CheckReport report = check_certificate(c.robot, c.environment, c.program, kinematics, run.certificate);
  EXPECT_EQ(report.claim, "COLLISION");
  EXPECT_TRUE(report.accepted) << (report.failures.empty() ? "" : report.failures.front());
}

}  // namespace
}  // namespace grpvss::certify
