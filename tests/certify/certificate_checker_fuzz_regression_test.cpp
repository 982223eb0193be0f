// Regressions found while fuzzing the certificate checker (fuzz/certificate_checker_fuzzer.cpp,
// docs/reliability.md): hostile certificates for the IBM 7545 and the one-segment path
// fuzz/inputs/tiny-path.txt must be rejected with a reason, never read out of bounds. Both
// reproducers were written by hand from a code review and crash the unfixed fuzz target.
#include <filesystem>
#include <string>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "grpvss/evidence/certificate.hpp"
#include "grpvss/checker/certificate_checker.hpp"
#include "grpvss/io/environment_file.hpp"
#include "grpvss/io/path_file.hpp"
#include "grpvss/io/robot_file.hpp"
#include "grpvss/motion/kinematics_adapter.hpp"
#include "support/text_files.hpp"

namespace {

const std::string kRoot = GRPVSS_SOURCE_DIR;

grpvss::certify::CheckReport check(const std::string& reproducer) {
  const grpvss::RobotModel robot = grpvss::io::read_robot_file(kRoot + "/data/ibm7545/robot.txt");
  const grpvss::Environment environment =
      grpvss::io::read_environment_file(kRoot + "/data/ibm7545/environment.txt");
  const grpvss::PathProgram program =
      grpvss::io::read_path_file(kRoot + "/fuzz/inputs/tiny-path.txt", robot);
  const auto kinematics = grpvss::motion::make_kinematics_access(
      robot, grpvss::motion::select_ik({}, robot, "robot.txt"));
  const auto certificate = grpvss::certify::certificate_from_json(
      nlohmann::json::parse(grpvss::test::read_text_file(
          kRoot + "/tests/regressions/certificate_checker/" + reproducer)),
      reproducer);
  return grpvss::certify::check_certificate(robot, environment, program, kinematics, certificate);
}

bool has_failure(const grpvss::certify::CheckReport& report, const std::string& text) {
  for (const std::string& failure : report.failures) {
    if (failure.find(text) != std::string::npos) return true;
  }
  return false;
}

TEST(CertificateCheckerFuzzRegression, ShortJointVectorIsRejectedNotReadPastItsEnd) {
  // Step 0's q has 2 of 4 joints; the transition to step 1 used to index q[2] and q[3].
  const auto report = check("joint-vector-too-short.json");
  EXPECT_FALSE(report.accepted);
  EXPECT_TRUE(has_failure(report, "segment 1 step 0: wrong joint count"));
  EXPECT_TRUE(has_failure(report, "claim CLEAR, but some transition is not certified"));
}

TEST(CertificateCheckerFuzzRegression, CollisionClaimAtAnEmptyJointVectorIsRejected) {
  // Step 1's q is empty and the claim names it as the collision.
  const auto report = check("collision-claim-at-empty-joint-vector.json");
  EXPECT_FALSE(report.accepted);
  EXPECT_EQ(report.claim, grpvss::certify::Verdict::kCollision);
  EXPECT_TRUE(has_failure(report, "segment 1 step 1: wrong joint count"));
  EXPECT_TRUE(
      has_failure(report, "claim COLLISION, but the robot at the named step touches no obstacle"));
}

}  // namespace
