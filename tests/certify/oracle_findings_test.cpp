// Findings of the oracle soundness runs (docs/soundness-oracle.md#findings), kept as
// regression tests with the exact random case that exposed them. The first three were checker
// rejections of a certificate the verifier wrote (never a CLEAR claim), fixed in
// src/certify/certificate_checker.cpp: a segment with only its start step is checked and
// marked uncovered; a collision at step 0 is re-decided at the robot's home configuration. The
// last was a CLEAR on a CP line with an unreachable stretch between samples (a missed error 5,
// not a collision), fixed in src/certify/verifier.cpp.
#include <variant>

#include <gtest/gtest.h>

#include "grpvss/checker/certificate_checker.hpp"
#include "grpvss/certify/verifier.hpp"
#include "grpvss/motion/cp_line.hpp"
#include "grpvss/motion/kinematics_adapter.hpp"
#include "grpvss/motion/trajectory.hpp"
#include "support/motion_oracle.hpp"
#include "support/oracle_cases.hpp"

namespace grpvss::certify {
namespace {

// One oracle case verified in certified mode, with the kinematics its certificate needs.
struct CaseRun {
  test::OracleCase c;
  motion::KinematicsAccess kinematics;
  VerificationRun run;
  CheckReport check() const {
    return check_certificate(c.robot, c.environment, c.program, kinematics, run.certificate);
  }
};

CaseRun verify_case(test::OracleCase c) {
  CaseRun result{std::move(c), {}, {}};
  result.kinematics = motion::make_kinematics_access(
      result.c.robot, motion::select_ik(result.c.ik, result.c.robot, "random"));
  SetupRequest options;
  options.tolerance = result.c.tolerance;
  result.run = verify(result.c.robot, result.c.environment, result.c.program, result.kinematics,
                      resolve_setup(options));
  return result;
}

// Found by the long run (fixed): the long oracle run's SCARA case 408 (seed
// 0xc0de0198, Delta = 1.148) stops with error 7 (IK joint jump) at the FIRST step of CP
// segment 3. The verdict ERROR is right, but the certificate written for the run is rejected
// by check_certificate: "segment 3: fewer than two steps" (the unsimulated segment is written
// with a single step). Not a soundness bug (nothing is claimed CLEAR), but every certificate
// must be accepted. The CI shard case 95 (seed 0xc0de005f: COLLISION in segment 1, then error 7
// at the first step of CP segment 2) shows the same rejection for a COLLISION certificate.
TEST(OracleFindings, CpSegmentStoppedAtItsFirstStepStillGivesAnAcceptedCertificate) {
  const CaseRun verified = verify_case(test::random_scara_cp_case(0xc0de0198ULL));
  const VerificationRun& run = verified.run;
  ASSERT_EQ(run.result.verdict, Verdict::kError);
  ASSERT_EQ(run.result.errors.size(), 1u);
  EXPECT_EQ(run.result.errors.front().code, kErrorCpJointJump);
  EXPECT_EQ(run.result.errors.front().segment, 3);
  const CheckReport report = verified.check();
  EXPECT_EQ(report.claim, Verdict::kError);
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
  const CaseRun verified = verify_case(c);
  const VerificationRun& run = verified.run;
  EXPECT_EQ(run.result.verdict, Verdict::kCollision);
  const CheckReport report = verified.check();
  EXPECT_EQ(report.claim, Verdict::kCollision);
  EXPECT_TRUE(report.accepted) << (report.failures.empty() ? "" : report.failures.front());
}

// Found by the long run (fixed): long-run SCARA case 1945 (seed 0xc0de0799,
// Delta = 0.022): the robot collides at its home configuration (step 0; the oracle confirms)
// and the first CP line stops with error 5 before any step. Verdict COLLISION at step 0 is
// right, but check_certificate rejects the certificate: "claim COLLISION, but the robot at the
// named step touches no obstacle".
TEST(OracleFindings, CollisionAtTheStartBeforeAnErrorGivesAnAcceptedCertificate) {
  const test::OracleCase c = test::random_scara_cp_case(0xc0de0799ULL);
  Eigen::VectorXd home(c.robot.joint_count());
  for (int j = 0; j < c.robot.joint_count(); ++j) home[j] = c.robot.joints[j].home;
  ASSERT_TRUE(test::MotionOracle(c.robot, c.environment).check(home).contact);
  const CaseRun verified = verify_case(c);
  const VerificationRun& run = verified.run;
  ASSERT_EQ(run.result.verdict, Verdict::kCollision);
  EXPECT_EQ(run.result.collision_step, 0);
  ASSERT_EQ(run.result.errors.size(), 1u);
  EXPECT_EQ(run.result.errors.front().code, 5);
  const CheckReport report = verified.check();
  EXPECT_EQ(report.claim, Verdict::kCollision);
  EXPECT_TRUE(report.accepted) << (report.failures.empty() ? "" : report.failures.front());
}

// Found by the long run (fixed in the seventh session): case 1199 (seed 0xc0de04af) was CLEAR
// on a CP line the oracle could not follow. Segment 2 starts with joint 2 exactly at its upper
// limit (the PTP before it was clamped there) and the commanded line needs it beyond the limit
// for its first 0.05-0.24 in. (Delta 0.127): the IK samples of the trajectory (every 0.5 in.)
// and of the verifier's steps (about 1.6 in.) all succeed, the unreachable stretch lies between
// them. A CP step that starts with a joint at its limit now probes the line just ahead (Delta/64,
// Delta/8): error 5 at the segment's first step.
TEST(OracleFindings, AnUnreachableStretchNextToAJointLimitIsErrorFive) {
  const CaseRun verified = verify_case(test::random_scara_cp_case(0xc0de04afULL));
  const test::OracleCase& c = verified.c;
  const VerificationRun& run = verified.run;
  ASSERT_EQ(run.result.verdict, Verdict::kError);
  ASSERT_EQ(run.result.errors.size(), 1u);
  const PathError& error = run.result.errors.front();
  EXPECT_EQ(error.code, 5);
  EXPECT_EQ(error.segment, 2);
  // Reported at the segment's start: the last step recorded is the first segment's end.
  int last_step_of_segment_one = -1;
  for (const StepRecord& step : run.result.steps) {
    if (step.segment == 1) last_step_of_segment_one = step.index;
  }
  EXPECT_EQ(error.step, last_step_of_segment_one);
  // The line itself: IK within the limits fails just after the start and succeeds from 0.24 in.
  const motion::Trajectory trajectory = motion::Trajectory::plan(c.robot, c.program, verified.kinematics, {});
  ASSERT_TRUE(trajectory.errors().empty());  // the 0.5 in. samples all succeed
  const motion::SegmentTrajectory& line = trajectory.segments().at(1);
  ASSERT_EQ(line.kind, motion::SegmentKind::kCpLine);
  for (const double s : {0.0049, 0.049}) {
    EXPECT_FALSE(motion::solve_within_limits(c.robot, verified.kinematics, line.cp->pose_at(s), line.q_start)) << s;
  }
  EXPECT_TRUE(motion::solve_within_limits(c.robot, verified.kinematics, line.cp->pose_at(0.24), line.q_start));
  const CheckReport report = verified.check();
  EXPECT_EQ(report.claim, Verdict::kError);
  EXPECT_TRUE(report.accepted) << (report.failures.empty() ? "" : report.failures.front());
}

}  // namespace
}  // namespace grpvss::certify
