// The clearance along the motion (proofs/two-ball-cover.md#corollary-motion-clearance): its
// rounded evaluation, and the verifier's numbers against exact distances of the motion.
#include "certify/motion_clearance.hpp"

#include <cmath>
#include <random>
#include <string>

#include <boost/multiprecision/cpp_int.hpp>
#include <gtest/gtest.h>

#include "grpvss/checker/certificate_checker.hpp"
#include "grpvss/certify/verifier.hpp"
#include "grpvss/motion/kinematics_adapter.hpp"
#include "grpvss/motion/trajectory.hpp"
#include "support/geometry_reference.hpp"
#include "support/ibm7545_run.hpp"
#include "support/oracle_cases.hpp"
#include "support/kinematics_reference.hpp"

namespace grpvss::certify {
namespace {

using Rational = boost::multiprecision::cpp_rational;

// A bounding ball of a point set: its centroid and the largest distance to it.
std::pair<Eigen::Vector3d, double> bounding_ball(const testing::Points& points) {
  Eigen::Vector3d centre = Eigen::Vector3d::Zero();
  for (const auto& p : points) centre += p;
  centre /= static_cast<double>(points.size());
  double radius = 0.0;
  for (const auto& p : points) radius = std::max(radius, (p - centre).norm());
  return {centre, radius};
}

Rational exact_motion_clearance(double r_k, double r_k1, double bound) {
  const Rational a(r_k), b(r_k1), m(bound);
  const Rational balanced = (a + b - m) / 2;
  const Rational one_sided = (a > b ? a : b) - m;
  return balanced > one_sided ? balanced : one_sided;
}

TEST(MotionClearance, HandNumbers) {
  EXPECT_EQ(motion_clearance_lower_bound(1.0, 1.0, 2.0), 0.0);   // the 2-Delta step: nothing left
  EXPECT_EQ(motion_clearance_lower_bound(2.0, 2.0, 1.0), 1.5);   // balanced
  EXPECT_EQ(motion_clearance_lower_bound(5.0, 0.0, 1.0), 4.0);   // one-sided
  EXPECT_EQ(motion_clearance_lower_bound(0.1, 0.2, 1.0), -0.35000000000000003);  // uncovered
}

// Never above the exact value, and at most a few ulps below it.
TEST(MotionClearance, RoundedDownAndTight) {
  std::mt19937_64 rng(4341);
  std::uniform_real_distribution<double> radius(0.0, 50.0);
  std::uniform_real_distribution<double> bound(0.0, 60.0);
  for (int k = 0; k < 20000; ++k) {
    const double r_k = radius(rng), r_k1 = radius(rng), m = bound(rng);
    const double g = motion_clearance_lower_bound(r_k, r_k1, m);
    const Rational exact = exact_motion_clearance(r_k, r_k1, m);
    ASSERT_LE(Rational(g), exact) << r_k << " " << r_k1 << " " << m;
    ASSERT_GE(Rational(g), exact - Rational(1e-13)) << r_k << " " << r_k1 << " " << m;
  }
}

// The Table 3 PTP with the post below the quill's path: for every transition and link, the
// distance of the link's hulls to every obstacle at 24 configurations of the motion (bounding
// balls where they settle it, else exact) is at least the reported motion clearance (less
// 1e-9 for the test's own float placement, test reference kinematics).
TEST(MotionClearance, TheVerifiersBoundsHoldAlongTheNearMissMotion) {
  for (const char* environment_file :
       {"bench-environment-near-miss.txt", "bench-environment-within-tolerance.txt"}) {
    // Claim `steps`: the quill passes 0.45 in. above the post of the second cell, below the
    // tolerance 0.5, which only the claim `motion` refuses as CLEAR (claim_motion_test.cpp).
    const test::Ibm7545Run cell = test::verify_ibm7545(environment_file, test::kTable3PtpPath,
                                                       ClearClaim::kSteps);
    const RobotModel& robot = cell.robot;
    const Environment& environment = cell.environment;
    const VerificationRun& run = cell.run;
    ASSERT_EQ(run.result.verdict, Verdict::kClear) << environment_file;
    const motion::Trajectory trajectory = motion::Trajectory::plan(
        robot, cell.program, cell.kinematics, cell.setup.run.motion);
    const motion::PtpMotion& ptp = *trajectory.segments().at(0).ptp;
    double previous_time = 0.0;
    int checked = 0;
    double quill_bound = 0.0;
    for (const StepRecord& step : run.result.steps) {
      for (int link = 1; link <= robot.joint_count(); ++link) {
        const double g = step.links[link].motion_clearance.value();
        if (link == 4) quill_bound = step.index == 1 ? g : std::min(quill_bound, g);
        if (!(g > 0.0)) continue;
        for (int k = 0; k <= 23; ++k) {
          const double t = previous_time + (step.segment_parameter - previous_time) * k / 23.0;
          const Eigen::Matrix4d X_WL = test::reference_link_pose<double>(robot, ptp.joints_at(t), link);
          for (const HullPoints& hull : robot.links[link].hulls) {
            testing::Points placed;
            for (const auto& p : hull.points) placed.push_back((X_WL * p.homogeneous()).head<3>());
            const auto [centre, radius] = bounding_ball(placed);
            for (const HullPoints& obstacle : environment.obstacles) {
              const double lower = std::max(0.0, g - 1e-9);
              // Balls far apart settle it (with a margin far above rounding); the rest exactly.
              const auto [obstacle_centre, obstacle_radius] = bounding_ball(obstacle.points);
              if ((centre - obstacle_centre).norm() - radius - obstacle_radius > lower + 1e-6) {
                ++checked;
                continue;
              }
              ASSERT_TRUE(testing::reference_distance_squared_at_least(placed, obstacle.points,
                                                                    lower * lower))
                  << environment_file << " step " << step.index << " link " << link << " t " << t;
              ++checked;
            }
          }
        }
      }
      previous_time = step.segment_parameter;
    }
    EXPECT_GT(checked, 500);
    // The quill passes 0.62 / 0.45 in. above the post: its bound is positive and below that.
    EXPECT_GT(quill_bound, 0.0);
    EXPECT_LT(quill_bound, 0.62);
    const LinkClearanceSummary& quill = run.result.link_clearances.at(4);
    EXPECT_EQ(quill.min_motion_clearance, quill_bound);
  }
}

// The checker derives the same clearances along the motion on its own (exact radii, exact
// motion bounds): never below the verifier's, which use the recorded, rounded-up bounds, and
// equal to them up to that rounding. A certificate with one radius inflated is rejected and
// proves no clearance.
TEST(MotionClearance, TheCheckerDerivesTheVerifiersClearancesExactly) {
  // Claim `steps`: the quill's 0.0435 (the claim `motion` holds it to 0.5, claim_motion_test.cpp).
  const test::Ibm7545Run cell = test::verify_ibm7545("bench-environment-near-miss.txt",
                                                     test::kTable3PtpPath, ClearClaim::kSteps);
  const RobotModel& robot = cell.robot;
  const Environment& environment = cell.environment;
  const PathProgram& program = cell.program;
  const motion::KinematicsAccess& kinematics = cell.kinematics;
  const VerificationRun& run = cell.run;
  ASSERT_EQ(run.result.verdict, Verdict::kClear);
  const CheckReport report = check_certificate(robot, environment, program, kinematics, run.certificate);
  ASSERT_TRUE(report.accepted);
  ASSERT_EQ(report.motion_clearances.size(), robot.links.size());
  for (const CheckedMotionClearance& checked : report.motion_clearances) {
    const LinkClearanceSummary& reported = run.result.link_clearances.at(checked.link);
    ASSERT_TRUE(reported.min_motion_clearance.has_value()) << "link " << checked.link;
    EXPECT_GE(checked.lower_bound, *reported.min_motion_clearance) << "link " << checked.link;
    EXPECT_LE(checked.lower_bound, *reported.min_motion_clearance + 1e-9) << "link " << checked.link;
  }
  EXPECT_GT(report.motion_clearances.at(4).lower_bound, 0.0435);  // the quill, 0.62 in. above
  EXPECT_LT(report.motion_clearances.at(4).lower_bound, 0.0436);

  Certificate tampered = run.certificate;
  HullRecord& quill = tampered.segments.at(0).steps.at(3).hulls.back();
  ASSERT_EQ(quill.link, 4);
  quill.radius += 0.25;
  const CheckReport rejected = check_certificate(robot, environment, program, kinematics, tampered);
  EXPECT_FALSE(rejected.accepted);
  EXPECT_TRUE(rejected.motion_clearances.empty());
}

// The random PTP cells of the oracle (tests/support/oracle_cases.cpp: hulls sticking out of
// the skeleton, obstacles near the path, several segments): every reported clearance along the
// motion holds at 5 configurations of its transition, by exact distances (Release only: label
// heavy, tests/ctest_properties.cmake).
TEST(MotionClearance, TheVerifiersBoundsHoldOnTheOracleCells) {
  int checked_exactly = 0, transitions = 0;
  for (std::uint64_t seed = 1; seed <= 12; ++seed) {
    const test::OracleCase c = test::random_ptp_case(seed);
    const motion::KinematicsAccess kinematics =
        motion::make_kinematics_access(c.robot, motion::select_ik(c.ik, c.robot, "random"));
    SetupRequest options;
    options.tolerance = c.tolerance;
    options.limits.max_probes = 20000;
    const VerificationRun run =
        verify(c.robot, c.environment, c.program, kinematics, resolve_setup(options));
    const motion::Trajectory trajectory =
        motion::Trajectory::plan(c.robot, c.program, kinematics, options.motion);
    const StepRecord* previous = &*run.result.start;
    for (const StepRecord& step : run.result.steps) {
      const motion::SegmentTrajectory& segment = trajectory.segments().at(step.segment - 1);
      ASSERT_TRUE(segment.ptp.has_value());
      const double from = previous->segment == step.segment ? previous->segment_parameter : 0.0;
      previous = &step;
      ++transitions;
      for (int link = 1; link <= c.robot.joint_count(); ++link) {
        const double g = step.links[link].motion_clearance.value();
        if (!(g > 0.0)) continue;
        const double lower = std::max(0.0, g - 1e-9);
        for (int k = 0; k <= 4; ++k) {
          const double s = from + (step.segment_parameter - from) * k / 4.0;
          const Eigen::Matrix4d X_WL =
              test::reference_link_pose<double>(c.robot, segment.ptp->joints_at(s), link);
          for (const HullPoints& hull : c.robot.links[link].hulls) {
            testing::Points placed;
            for (const auto& p : hull.points) placed.push_back((X_WL * p.homogeneous()).head<3>());
            const auto [centre, radius] = bounding_ball(placed);
            for (const HullPoints& obstacle : c.environment.obstacles) {
              const auto [obstacle_centre, obstacle_radius] = bounding_ball(obstacle.points);
              if ((centre - obstacle_centre).norm() - radius - obstacle_radius > lower + 1e-6) continue;
              ASSERT_TRUE(testing::reference_distance_squared_at_least(placed, obstacle.points,
                                                                       lower * lower))
                  << "seed " << seed << " step " << step.index << " link " << link << " s " << s;
              ++checked_exactly;
            }
          }
        }
      }
    }
  }
  EXPECT_GT(transitions, 50);
  EXPECT_GT(checked_exactly, 100);  // near pairs, decided by the exact distance
}

}  // namespace
}  // namespace grpvss::certify
