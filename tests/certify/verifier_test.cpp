// End-to-end behaviour of the verifier and the certificate checker on small constructed
// cells whose answers are known by construction (docs/verification.md).
#include "grpvss/certify/verifier.hpp"

#include <cmath>
#include <limits>
#include <string>

#include <fmt/core.h>
#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "grpvss/checker/certificate_checker.hpp"
#include "grpvss/io/environment_file.hpp"
#include "grpvss/io/path_file.hpp"
#include "grpvss/io/robot_file.hpp"
#include "grpvss/motion/kinematics_adapter.hpp"

namespace grpvss::certify {
namespace {

// One revolute joint about the world z axis; frame 1 sits at radius 10 on the arm, and the
// link's box reaches from the axis (x = -10) to radius 30 (x = +20): a tool sticking out 20
// beyond the link-frame origin, the case the thesis's tip-only rule cannot see.
const char* kSweepingArm = R"(1
0
0.0,0.0,10.0,0.0,-180.0,180.0,60.,60.
0
1.0
1
HULL 8
-10,-0.5,-0.5
20,-0.5,-0.5
20,0.5,-0.5
-10,0.5,-0.5
-10,-0.5,0.5
20,-0.5,0.5
20,0.5,0.5
-10,0.5,0.5
)";

const char* kTurn120Degrees = "1\n1\n120.,30.\n";

// A box in the world: radial extent [r0, r1] along direction `angle_deg`, tangential
// half-width `half_width`, z in [-1, 1].
std::string radial_box_environment(double angle_deg, double r0, double r1, double half_width,
                                   double smallest_thickness) {
  const double angle = angle_deg * M_PI / 180.0;
  const double ux = std::cos(angle), uy = std::sin(angle);
  const double vx = -uy, vy = ux;
  std::string text = fmt::format("90.\n{}\n1\nHULL 8\n", smallest_thickness);
  for (double r : {r0, r1}) {
    for (double t : {-half_width, half_width}) {
      for (double z : {-1.0, 1.0}) {
        text += fmt::format("{:.12f},{:.12f},{}\n", r * ux + t * vx, r * uy + t * vy, z);
      }
    }
  }
  return text;
}

struct Cell {
  RobotModel robot;
  Environment environment;
  PathProgram program;
  motion::KinematicsAccess kinematics;
};

Cell make_cell(const std::string& robot_text, const std::string& environment_text,
               const std::string& path_text) {
  Cell cell;
  cell.robot = io::parse_robot_file(robot_text, "robot.txt");
  cell.environment = io::parse_environment_file(environment_text, "environment.txt");
  cell.program = io::parse_path_file(path_text, "path.txt", cell.robot);
  cell.kinematics = motion::make_kinematics_access(
      cell.robot, motion::select_ik({kinematics::IkMethod::kNumeric, {}}, cell.robot, "robot.txt"));
  return cell;
}

VerificationRun run(const Cell& cell, double tolerance, ResolutionMode mode) {
  SetupRequest options;
  options.tolerance = tolerance;
  options.mode = mode;
  return verify(cell.robot, cell.environment, cell.program, cell.kinematics,
                resolve_setup(options));
}

CheckReport check(const Cell& cell, const Certificate& certificate) {
  return check_certificate(cell.robot, cell.environment, cell.program, cell.kinematics, certificate);
}

TEST(Verifier, ObstacleOnTheSweepIsACollisionWithTheCollidingConfiguration) {
  // A 2-wide box across the sweep at 60 degrees, radius 12..18.
  const Cell cell = make_cell(kSweepingArm, radial_box_environment(60, 12, 18, 1.0, 2.0),
                              kTurn120Degrees);
  const VerificationRun result = run(cell, 0.5, ResolutionMode::kCertified);
  EXPECT_EQ(result.result.verdict, Verdict::kCollision);
  ASSERT_TRUE(result.result.collision_step.has_value());
  const StepRecord& colliding = result.result.steps.at(*result.result.collision_step - 1);
  EXPECT_TRUE(colliding.unexpanded_collides);
  // The arm's box (half-width 0.5) overlaps the obstacle (half-width 1) within 60 +- ~7 deg.
  EXPECT_NEAR(colliding.q[0] * 180.0 / M_PI, 60.0, 8.0);
  EXPECT_FALSE(colliding.interference_points.empty());
  const CheckReport report = check(cell, result.certificate);
  EXPECT_TRUE(report.accepted) << (report.failures.empty() ? "" : report.failures.front());
  EXPECT_EQ(report.claim, Verdict::kCollision);
}

TEST(Verifier, ThesisRuleStepsOverAThinPlateThatCertifiedModeCatches) {
  // A plate 0.2 thick at 60 degrees, radius 25..35: only the tool (radius 20..30) reaches it.
  // The link-frame origin (radius 10) is far from it, so the thesis rule's Dmin term allows
  // a step that jumps across it (proofs/thesis-rule.md#ce1-ibm7545-tool: an off-axis tool).
  const Cell cell = make_cell(kSweepingArm, radial_box_environment(60, 25, 35, 0.1, 0.2),
                              kTurn120Degrees);
  const VerificationRun thesis = run(cell, 0.1, ResolutionMode::kThesis);
  EXPECT_EQ(thesis.result.verdict, Verdict::kClear) << "the thesis rule should miss this plate";
  for (const StepRecord& step : thesis.result.steps) EXPECT_FALSE(step.expanded_interferes);
  const VerificationRun certified = run(cell, 0.1, ResolutionMode::kCertified);
  EXPECT_EQ(certified.result.verdict, Verdict::kCollision);
}

TEST(Verifier, NearMissInsideTheToleranceIsWithinToleranceWithItsClearance) {
  // A box just beyond the tool tip: radius 30.3..31.3 at 60 degrees. The tool's corner
  // reaches radius sqrt(30^2 + 0.5^2) = 30.00417, so the true clearance is ~0.2958 < 0.5.
  const Cell cell = make_cell(kSweepingArm, radial_box_environment(60, 30.3, 31.3, 0.5, 1.0),
                              kTurn120Degrees);
  const VerificationRun result = run(cell, 0.5, ResolutionMode::kCertified);
  EXPECT_EQ(result.result.verdict, Verdict::kWithinTolerance);
  bool any_refinement = false;
  for (const StepRecord& step : result.result.steps) any_refinement |= step.refinement;
  EXPECT_TRUE(any_refinement);
  const LinkClearanceSummary& link1 = result.result.link_clearances.at(1);
  EXPECT_GT(link1.min_clearance, 0.0);
  // Sampled steps: the smallest certified clearance lies between the true minimum over the
  // motion (0.2958) shrunk by the offset's looseness, and the face-to-face gap 0.3.
  EXPECT_LE(link1.min_clearance, 0.3);
  EXPECT_GT(link1.min_clearance, 0.25);
  const CheckReport report = check(cell, result.certificate);
  EXPECT_TRUE(report.accepted) << (report.failures.empty() ? "" : report.failures.front());
}

class ClearCell : public ::testing::Test {
 protected:
  void SetUp() override {
    // Outside the sweep by 1.5: radius 31.5..36 (several steps, each certified).
    cell_ = make_cell(kSweepingArm, radial_box_environment(60, 31.5, 36, 1.0, 2.0), kTurn120Degrees);
    run_ = run(cell_, 0.5, ResolutionMode::kCertified);
    document_ = certificate_to_json(run_.certificate);
  }
  bool accepted(const nlohmann::json& document) {
    return check(cell_, certificate_from_json(document, "cert.json")).accepted;
  }
  Cell cell_;
  VerificationRun run_;
  nlohmann::json document_;
};

TEST_F(ClearCell, IsCertifiedClearAndTheCheckerAcceptsTheCertificate) {
  EXPECT_EQ(run_.result.verdict, Verdict::kClear);
  EXPECT_TRUE(accepted(document_));
  // The certificate round-trips through JSON unchanged.
  EXPECT_EQ(certificate_to_json(certificate_from_json(document_, "cert.json")), document_);
}

TEST_F(ClearCell, CheckerRejectsAChangedConfiguration) {
  auto& q = document_["segments"][0]["steps"][1]["q"][0];
  q = q.get<double>() + 1e-9;
  EXPECT_FALSE(accepted(document_));
}

TEST_F(ClearCell, CheckerRejectsAnInflatedRadius) {
  auto& radius = document_["segments"][0]["steps"][1]["hulls"][0]["radius"];
  radius = radius.get<double>() * 1.01;
  EXPECT_FALSE(accepted(document_));
}

TEST_F(ClearCell, CheckerRejectsARemovedStep) {
  auto& steps = document_["segments"][0]["steps"];
  ASSERT_GE(steps.size(), 3u);
  steps.erase(1);
  EXPECT_FALSE(accepted(document_));
}

TEST_F(ClearCell, CheckerRejectsACleanClaimOnASegmentCutToItsStart) {
  // A segment reduced to its start step is accepted only as a stopped path (ERROR); a CLEAR
  // claim over it must fail because the motion is no longer covered.
  auto& steps = document_["segments"][0]["steps"];
  ASSERT_GE(steps.size(), 2u);
  steps.erase(steps.begin() + 1, steps.end());
  const CheckReport report = check(cell_, certificate_from_json(document_, "cert.json"));
  EXPECT_FALSE(report.accepted);
  ASSERT_FALSE(report.failures.empty());
  EXPECT_NE(report.failures.back().find("do not cover the whole path"), std::string::npos)
      << report.failures.back();
}

// More than 16 obstacles: the probe uses the broadphase, and the certificate accounts for the
// obstacles it dismissed by the broadphase margin alone (no evidence record). The checker
// decides the box gaps exactly (certificate_checker.cpp, boxes_farther_than).
TEST(CheckerBroadphase, FarObstaclesWithoutEvidenceAreAcceptedANearOneIsNot) {
  std::string text = radial_box_environment(60, 31.5, 36, 1.0, 2.0);
  const std::string header = "90.\n2\n1\n";
  ASSERT_EQ(text.rfind(header, 0), 0u);
  std::string boxes = text.substr(header.size());
  for (int k = 0; k < 20; ++k) {
    const std::string far = radial_box_environment(18.0 * k, 120.0, 122.0, 1.0, 2.0);
    boxes += far.substr(header.size());
  }
  const Cell cell = make_cell(kSweepingArm, "90.\n2\n21\n" + boxes, kTurn120Degrees);
  ASSERT_EQ(cell.environment.obstacles.size(), 21u);
  const VerificationRun result = run(cell, 0.5, ResolutionMode::kCertified);
  ASSERT_EQ(result.result.verdict, Verdict::kClear);
  EXPECT_TRUE(check(cell, result.certificate).accepted);
  // The far boxes carry no evidence in the certificate: the margin accounts for them.
  const HullRecord& record = result.certificate.segments.at(0).steps.at(0).hulls.at(0);
  EXPECT_LT(record.evidence.size(), 21u);
  EXPECT_TRUE(std::isfinite(record.broadphase_margin));
  // At the step nearest the box its evidence proves less than the margin; dropping that
  // evidence leaves the box to the margin, which it is not beyond.
  const auto& steps = result.certificate.segments.at(0).steps;
  std::size_t nearest = steps.size();
  double smallest = std::numeric_limits<double>::infinity();
  for (std::size_t k = 0; k < steps.size(); ++k) {
    for (const EvidenceRecord& evidence : steps[k].hulls.at(0).evidence) {
      if (evidence.obstacle == 0 && evidence.separated && evidence.lower_bound < smallest) {
        smallest = evidence.lower_bound;
        nearest = k;
      }
    }
  }
  ASSERT_LT(nearest, steps.size());
  ASSERT_LT(smallest, steps[nearest].hulls.at(0).broadphase_margin);
  nlohmann::json document = certificate_to_json(result.certificate);
  document["segments"][0]["steps"][nearest]["hulls"][0]["evidence"] = nlohmann::json::array();
  const CheckReport tampered = check(cell, certificate_from_json(document, "cert.json"));
  EXPECT_FALSE(tampered.accepted);
  bool named = false;
  for (const std::string& failure : tampered.failures) {
    named |= failure.find("obstacle 0: no evidence and not beyond the broadphase margin") !=
             std::string::npos;
  }
  EXPECT_TRUE(named);
}

TEST_F(ClearCell, CheckerRejectsAWeakenedWitness) {
  // Moving the slab's obstacle side into the obstacle breaks n.b >= offset_b.
  for (auto& step : document_["segments"][0]["steps"]) {
    for (auto& hull : step["hulls"]) {
      for (auto& evidence : hull["evidence"]) {
        if (evidence["separated"].get<bool>()) {
          evidence["offset_b"] = evidence["offset_b"].get<double>() + 100.0;
          EXPECT_FALSE(accepted(document_));
          return;
        }
      }
    }
  }
  FAIL() << "no witness found";
}

TEST_F(ClearCell, CheckerRejectsALoweredMotionBound) {
  auto& bounds = document_["segments"][0]["steps"][0]["to_next"]["hull_motion_bounds"];
  for (auto& bound : bounds) bound = bound.get<double>() * 0.5;
  EXPECT_FALSE(accepted(document_));
}

TEST_F(ClearCell, CheckerRejectsAStrongerClaim) {
  // Claiming COLLISION for a clear path must fail: the named step touches nothing.
  document_["claim"] = "COLLISION";
  document_["collision_step"] = 1;
  EXPECT_FALSE(accepted(document_));
}

}  // namespace
}  // namespace grpvss::certify

namespace grpvss::certify {
namespace {

TEST(Verifier, EmptyEnvironmentIsClearWithFiniteRadiiTheCheckerAccepts) {
  const Cell cell = make_cell(kSweepingArm, "90.\n1.\n0\n", kTurn120Degrees);
  const VerificationRun result = run(cell, 0.5, ResolutionMode::kCertified);
  EXPECT_EQ(result.result.verdict, Verdict::kClear);
  const nlohmann::json document = certificate_to_json(result.certificate);
  // Every radius is a finite number (JSON has no infinity): the probe's cap.
  for (const auto& step : document["segments"][0]["steps"]) {
    for (const auto& hull : step["hulls"]) ASSERT_TRUE(hull["radius"].is_number());
  }
  const CheckReport report = check(cell, certificate_from_json(document, "cert.json"));
  EXPECT_TRUE(report.accepted) << (report.failures.empty() ? "" : report.failures.front());
}

}  // namespace
}  // namespace grpvss::certify
