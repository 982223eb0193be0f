// Soundness of the certified verifier against a brute-force oracle written independently of
// it (tests/support/motion_oracle.hpp): random robots, cells and PTP paths with fixed seeds.
// Property (must hold for every case): certified mode never says CLEAR where the oracle finds
// a real contact, a reported COLLISION step really collides, and every certificate is
// accepted by check_certificate. Statistics (thesis-mode misses, certified false alarms) are
// printed and recorded in docs/soundness-oracle.md.
//
// Normal run: kDefaultCases cases. Long run: GRPVSS_LONG_ORACLE=1 (kLongCases cases; also
// GRPVSS_ORACLE_CASES=<n> for any count).
#include <cmath>
#include <cstdlib>
#include <iostream>
#include <random>
#include <string>

#include <Eigen/Geometry>
#include <fmt/core.h>
#include <gtest/gtest.h>

#include "grpvss/certify/certificate_checker.hpp"
#include "grpvss/certify/verifier.hpp"
#include "grpvss/io/environment_file.hpp"
#include "grpvss/io/path_file.hpp"
#include "grpvss/io/robot_file.hpp"
#include "grpvss/motion/kinematics_adapter.hpp"
#include "support/kinematics_reference.hpp"
#include "support/motion_oracle.hpp"
#include "support/random_shapes.hpp"  // random_rotation

namespace grpvss::certify {
namespace {

constexpr int kDefaultCases = 60;
constexpr int kLongCases = 1000;
constexpr double kOracleSpacingFraction = 1.0 / 20.0;  // of the tolerance

int case_count() {
  if (const char* count = std::getenv("GRPVSS_ORACLE_CASES")) return std::max(1, std::atoi(count));
  if (const char* long_run = std::getenv("GRPVSS_LONG_ORACLE"); long_run && std::string(long_run) == "1") {
    return kLongCases;
  }
  return kDefaultCases;
}

struct RandomCase {
  RobotModel robot;
  Environment environment;
  PathProgram program;
  double tolerance = 0.5;
};

double uniform(std::mt19937_64& rng, double lo, double hi) {
  return std::uniform_real_distribution<double>(lo, hi)(rng);
}

Eigen::Vector3d random_unit(std::mt19937_64& rng) {
  std::normal_distribution<double> normal(0.0, 1.0);
  Eigen::Vector3d v(normal(rng), normal(rng), normal(rng));
  return v.normalized();
}

// A box with half extents h, rotated at random, centred at c (8 points: cheap exact offsets).
std::vector<Eigen::Vector3d> random_box(std::mt19937_64& rng, const Eigen::Vector3d& c,
                                        const Eigen::Vector3d& h) {
  const Eigen::Matrix3d rotation = test::random_rotation(rng);
  std::vector<Eigen::Vector3d> points;
  for (int k = 0; k < 8; ++k) {
    const Eigen::Vector3d p_L((k & 1 ? 1 : -1) * h.x(), (k & 2 ? 1 : -1) * h.y(),
                              (k & 4 ? 1 : -1) * h.z());
    points.push_back(c + rotation * p_L);
  }
  return points;
}

// A box from the origin along a random direction u to length `length` (a tool sticking out
// beyond the frame origin), cross-section half-width w.
std::vector<Eigen::Vector3d> random_tool(std::mt19937_64& rng, double length, double w) {
  const Eigen::Matrix3d rotation = test::random_rotation(rng);
  std::vector<Eigen::Vector3d> points;
  for (int k = 0; k < 8; ++k) {
    const Eigen::Vector3d p_L(k & 1 ? length : -w, (k & 2 ? 1 : -1) * w, (k & 4 ? 1 : -1) * w);
    points.push_back(rotation * p_L);
  }
  return points;
}

// 2-5 joints, mixed revolute/prismatic, random DH; 1-2 hulls per link, the second often a
// "tool" far from the link skeleton (beyond the frame origin).
RobotModel random_robot(std::mt19937_64& rng) {
  RobotModel robot;
  robot.name = "random";
  const int joints = std::uniform_int_distribution<int>(2, 5)(rng);
  const double alphas[] = {0.0, M_PI / 2, -M_PI / 2, uniform(rng, -M_PI, M_PI)};
  for (int j = 0; j < joints; ++j) {
    Joint joint;
    joint.type = (j > 0 && uniform(rng, 0, 1) < 0.3) ? JointType::kPrismatic : JointType::kRevolute;
    joint.dh.a = uniform(rng, 0.0, 4.0);
    joint.dh.d = uniform(rng, 0.0, 3.0);
    joint.dh.alpha = alphas[std::uniform_int_distribution<int>(0, 3)(rng)];
    if (joint.type == JointType::kRevolute) {
      joint.minimum = -uniform(rng, 1.0, M_PI);
      joint.maximum = uniform(rng, 1.0, M_PI);
      joint.acceleration = uniform(rng, 1.0, 4.0);
      joint.deceleration = uniform(rng, 1.0, 4.0);
    } else {
      joint.minimum = 0.0;
      joint.maximum = uniform(rng, 1.0, 4.0);
      joint.acceleration = uniform(rng, 2.0, 6.0);
      joint.deceleration = uniform(rng, 2.0, 6.0);
    }
    joint.home = uniform(rng, joint.minimum, joint.maximum);
    robot.joints.push_back(joint);
  }
  robot.links.resize(joints + 1);
  for (int link = 1; link <= joints; ++link) {
    robot.links[link].thickness = 1.0;
    const Joint& joint = robot.joints[link - 1];
    // The link body: between the previous frame's origin (at -a along x) and this origin.
    const Eigen::Vector3d body_center(-0.5 * joint.dh.a, 0.0, 0.0);
    const Eigen::Vector3d body_half(0.5 * joint.dh.a + uniform(rng, 0.2, 0.6), uniform(rng, 0.2, 0.6),
                                    uniform(rng, 0.2, 0.6));
    robot.links[link].hulls.push_back({random_box(rng, body_center, body_half), 0});
    if (uniform(rng, 0, 1) < 0.6) {
      // A tool sticking out far beyond the frame origin.
      robot.links[link].hulls.push_back(
          {random_tool(rng, uniform(rng, 3.0, 8.0), uniform(rng, 0.1, 0.5)), 0});
    }
  }
  if (uniform(rng, 0, 1) < 0.5) {
    robot.links[0].hulls.push_back(
        {random_box(rng, Eigen::Vector3d(0, 0, -1.5), Eigen::Vector3d(1.0, 1.0, 0.5)), 0});
  }
  return robot;
}

Eigen::VectorXd random_target(std::mt19937_64& rng, const RobotModel& robot,
                              const Eigen::VectorXd& from) {
  Eigen::VectorXd target(robot.joint_count());
  for (int j = 0; j < robot.joint_count(); ++j) {
    const Joint& joint = robot.joints[j];
    const double span = joint.maximum - joint.minimum;
    target[j] = std::clamp(from[j] + uniform(rng, -0.3, 0.3) * span, joint.minimum, joint.maximum);
  }
  return target;
}

RandomCase random_case(std::uint64_t seed) {
  std::mt19937_64 rng(seed);
  RandomCase c;
  c.robot = random_robot(rng);
  c.tolerance = uniform(rng, 0.3, 1.0);
  // Path: 1-2 PTP joint segments.
  const int segments = std::uniform_int_distribution<int>(1, 2)(rng);
  Eigen::VectorXd q(c.robot.joint_count());
  for (int j = 0; j < c.robot.joint_count(); ++j) q[j] = c.robot.joints[j].home;
  std::vector<Eigen::VectorXd> visited{q};
  for (int s = 0; s < segments; ++s) {
    PtpJointSegment segment;
    segment.target = random_target(rng, c.robot, q);
    segment.velocity.resize(c.robot.joint_count());
    for (int j = 0; j < c.robot.joint_count(); ++j) {
      segment.velocity[j] =
          c.robot.joints[j].type == JointType::kRevolute ? uniform(rng, 0.3, 1.5) : uniform(rng, 0.5, 2.0);
    }
    // Configurations along the move (linear in joints: the sweep's neighbourhood).
    for (double f : {0.25, 0.5, 0.75, 1.0}) visited.push_back(q + f * (segment.target - q));
    q = segment.target;
    c.program.segments.push_back({segment, s + 2});
  }
  // Obstacles near the swept volume (at a random hull point of a configuration on the path,
  // with a random surface gap from -1 to +3 tolerances) and far away.
  const int near = std::uniform_int_distribution<int>(1, 3)(rng);
  const int far = std::uniform_int_distribution<int>(0, 2)(rng);
  double smallest_thickness = 10.0;
  std::vector<std::pair<int, int>> hull_ids;
  for (int link = 1; link <= c.robot.joint_count(); ++link) {
    for (int h = 0; h < static_cast<int>(c.robot.links[link].hulls.size()); ++h) hull_ids.push_back({link, h});
  }
  for (int k = 0; k < near; ++k) {
    const Eigen::VectorXd& q_on_path =
        visited[std::uniform_int_distribution<std::size_t>(1, visited.size() - 1)(rng)];
    const auto [link, h] = hull_ids[std::uniform_int_distribution<std::size_t>(0, hull_ids.size() - 1)(rng)];
    const auto& points_L = c.robot.links[link].hulls[h].points;
    const Eigen::Vector3d p_L = points_L[std::uniform_int_distribution<std::size_t>(0, points_L.size() - 1)(rng)];
    const Eigen::Matrix4d X_WL = test::reference_link_pose<double>(c.robot, q_on_path, link);
    const Eigen::Vector3d p_W = X_WL.topLeftCorner<3, 3>() * p_L + X_WL.topRightCorner<3, 1>();
    const Eigen::Vector3d direction = random_unit(rng);
    const double gap = uniform(rng, -0.5, 4.0) * c.tolerance;
    if (uniform(rng, 0, 1) < 0.4) {
      // A thin plate (what the thesis rule's Dmin step can jump over).
      const double thickness = uniform(rng, 0.05, 0.3);
      const Eigen::Vector3d half(uniform(rng, 1.0, 4.0), uniform(rng, 1.0, 4.0), 0.5 * thickness);
      c.environment.obstacles.push_back(
          {random_box(rng, p_W + direction * (half.norm() + gap), half), 0});
      smallest_thickness = std::min(smallest_thickness, thickness);
    } else {
      const Eigen::Vector3d half(uniform(rng, 0.3, 2.0), uniform(rng, 0.3, 2.0), uniform(rng, 0.3, 2.0));
      c.environment.obstacles.push_back(
          {random_box(rng, p_W + direction * (half.norm() + gap), half), 0});
      smallest_thickness = std::min(smallest_thickness, 2.0 * half.minCoeff());
    }
  }
  double reach = 10.0;
  for (const Joint& joint : c.robot.joints) reach += joint.dh.a + joint.dh.d + std::abs(joint.maximum);
  for (int k = 0; k < far; ++k) {
    const Eigen::Vector3d half(uniform(rng, 1.0, 4.0), uniform(rng, 1.0, 4.0), uniform(rng, 1.0, 4.0));
    c.environment.obstacles.push_back(
        {random_box(rng, random_unit(rng) * (reach + half.norm() + uniform(rng, 1.0, 20.0)), half), 0});
    smallest_thickness = std::min(smallest_thickness, 2.0 * half.minCoeff());
  }
  c.environment.smallest_angle = M_PI / 2.0;
  c.environment.smallest_thickness = smallest_thickness;
  return c;
}

VerificationRun run_mode(const RandomCase& c, const motion::KinematicsAccess& kinematics,
                         ResolutionMode mode) {
  VerifyOptions options;
  options.tolerance = c.tolerance;
  options.mode = mode;
  // Bounded time: near-touching steps can shrink without end (ERROR 9, never CLEAR).
  options.max_probes = 20000;
  return verify(c.robot, c.environment, c.program, kinematics, options);
}

struct Statistics {
  int cases = 0;
  int oracle_contact = 0;
  int oracle_clear_beyond_tolerance = 0;  // oracle: no contact and sampled min distance >= Delta
  int certified[5] = {0, 0, 0, 0, 0};     // by Verdict
  int thesis[5] = {0, 0, 0, 0, 0};
  int thesis_misses = 0;            // thesis CLEAR, oracle contact
  int certified_misses = 0;         // certified CLEAR, oracle contact (must stay 0)
  int certified_false_alarms = 0;   // non-CLEAR with oracle min distance >= Delta, or
                                    // COLLISION without oracle contact
  int certified_false_collisions = 0;
  int certificates_rejected = 0;
  long long oracle_samples = 0;
  long long oracle_exact_checks = 0;
  long long certified_steps = 0;
  long long thesis_steps = 0;
};

TEST(OracleSoundness, CertifiedModeNeverMissesAContactTheOracleFinds) {
  const int cases = case_count();
  Statistics stats;
  for (int i = 0; i < cases; ++i) {
    const std::uint64_t seed = 0x5eed0000ULL + static_cast<std::uint64_t>(i);
    SCOPED_TRACE(fmt::format("case {} (seed {:#x})", i, seed));
    const RandomCase c = random_case(seed);
    const auto kinematics =
        motion::make_kinematics_access(c.robot, motion::select_ik("numeric", c.robot, "random"));
    const test::MotionOracle oracle(c.robot, c.environment);
    const test::OraclePathResult truth =
        oracle.sample_path(c.program, kOracleSpacingFraction * c.tolerance);
    const VerificationRun certified = run_mode(c, kinematics, ResolutionMode::kCertified);
    const VerificationRun thesis = run_mode(c, kinematics, ResolutionMode::kThesis);
    const Verdict verdict = certified.result.verdict;

    ++stats.cases;
    stats.oracle_samples += truth.samples;
    stats.oracle_exact_checks += truth.exact_checks;
    stats.certified_steps += static_cast<long long>(certified.result.steps.size());
    stats.thesis_steps += static_cast<long long>(thesis.result.steps.size());
    ++stats.certified[static_cast<int>(verdict)];
    ++stats.thesis[static_cast<int>(thesis.result.verdict)];
    const bool contact = truth.first_contact.contact;
    stats.oracle_contact += contact;
    const bool clear_beyond_tolerance = !contact && truth.min_distance_estimate >= c.tolerance;
    stats.oracle_clear_beyond_tolerance += clear_beyond_tolerance;

    // The soundness property.
    if (contact) {
      EXPECT_NE(verdict, Verdict::kClear)
          << "certified CLEAR but the oracle found contact at segment " << truth.contact_segment
          << " t=" << truth.contact_time << " link " << truth.first_contact.link << " hull "
          << truth.first_contact.hull << " obstacle " << truth.first_contact.obstacle;
      stats.certified_misses += verdict == Verdict::kClear;
      stats.thesis_misses += thesis.result.verdict == Verdict::kClear;
    }
    // A reported collision is real.
    if (verdict == Verdict::kCollision) {
      ASSERT_TRUE(certified.result.collision_step.has_value());
      const int step = *certified.result.collision_step;
      const StepRecord& record =
          step == 0 ? *certified.result.start : certified.result.steps.at(step - 1);
      EXPECT_TRUE(oracle.check(record.q).contact) << "reported collision step " << step;
      stats.certified_false_collisions += !contact;
    }
    if (verdict != Verdict::kClear && verdict != Verdict::kError &&
        (clear_beyond_tolerance || (verdict == Verdict::kCollision && !contact))) {
      ++stats.certified_false_alarms;
    }
    // Every certificate is accepted by the independent checker.
    const CheckReport report = check_certificate(c.robot, c.environment, c.program, kinematics,
                                                 certified.certificate);
    EXPECT_TRUE(report.accepted) << (report.failures.empty() ? "" : report.failures.front());
    EXPECT_EQ(report.claim, to_string(verdict));
    stats.certificates_rejected += !report.accepted;
  }
  // The generator must exercise both sides of the property.
  EXPECT_GT(stats.oracle_contact, 0);
  EXPECT_GT(stats.oracle_clear_beyond_tolerance, 0);
  EXPECT_EQ(stats.certified_misses, 0);

  auto verdicts = [](const int* counts) {
    return fmt::format("CLEAR {} COLLISION {} WITHIN_TOLERANCE {} UNDECIDED {} ERROR {}", counts[0],
                       counts[1], counts[2], counts[3], counts[4]);
  };
  const int not_clear_truth = stats.cases - stats.oracle_contact;
  std::cout << fmt::format(
      "[oracle] cases {}; oracle contact {}, oracle clear by >= Delta {}; oracle samples {} "
      "(exact checks {})\n"
      "[oracle] certified: {}; steps {}; misses {}; false alarms {} ({:.1f}% of the {} cases "
      "clear by >= Delta); false collisions {}; certificates rejected {}\n"
      "[oracle] thesis: {}; steps {}; misses {} ({:.1f}% of the {} contact cases)\n",
      stats.cases, stats.oracle_contact, stats.oracle_clear_beyond_tolerance, stats.oracle_samples,
      stats.oracle_exact_checks, verdicts(stats.certified), stats.certified_steps,
      stats.certified_misses, stats.certified_false_alarms,
      100.0 * stats.certified_false_alarms / std::max(1, stats.oracle_clear_beyond_tolerance),
      stats.oracle_clear_beyond_tolerance, stats.certified_false_collisions,
      stats.certificates_rejected, verdicts(stats.thesis), stats.thesis_steps, stats.thesis_misses,
      100.0 * stats.thesis_misses / std::max(1, stats.oracle_contact), stats.oracle_contact);
  (void)not_clear_truth;
}

// One revolute joint about the world z axis; the link's box reaches from the axis (x = -10)
// to radius 30 (x = +20) while frame 1 sits at radius 10: a tool sticking out 20 beyond the
// link-frame origin. A 0.2-thick plate at 60 degrees, radius 25..35, is reached only by the
// tool; the thesis rule's steps at the frame origin jump across it.
TEST(OracleSoundness, ThinPlateTheThesisRuleMissesIsFoundByOracleAndCertifiedMode) {
  const char* robot_text = R"(1
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
  std::string environment_text = "90.\n0.2\n1\nHULL 8\n";
  const double angle = 60.0 * M_PI / 180.0;
  const Eigen::Vector2d u(std::cos(angle), std::sin(angle)), v(-std::sin(angle), std::cos(angle));
  for (double r : {25.0, 35.0}) {
    for (double t : {-0.1, 0.1}) {
      for (double z : {-1.0, 1.0}) {
        const Eigen::Vector2d p = r * u + t * v;
        environment_text += fmt::format("{:.12f},{:.12f},{}\n", p.x(), p.y(), z);
      }
    }
  }
  RandomCase c;
  c.robot = io::parse_robot_file(robot_text, "robot.txt");
  c.environment = io::parse_environment_file(environment_text, "environment.txt");
  c.program = io::parse_path_file("1\n1\n120.,30.\n", "path.txt", c.robot);
  c.tolerance = 0.1;
  const auto kinematics =
      motion::make_kinematics_access(c.robot, motion::select_ik("numeric", c.robot, "robot.txt"));
  const test::MotionOracle oracle(c.robot, c.environment);
  const test::OraclePathResult truth = oracle.sample_path(c.program, kOracleSpacingFraction * c.tolerance);
  ASSERT_TRUE(truth.first_contact.contact);
  // The tool's half-width 0.5 at radius 25 meets the plate's 0.1 near 60 degrees.
  EXPECT_NEAR(truth.contact_q[0] * 180.0 / M_PI, 60.0, 2.0);
  EXPECT_EQ(run_mode(c, kinematics, ResolutionMode::kThesis).result.verdict, Verdict::kClear);
  const VerificationRun certified = run_mode(c, kinematics, ResolutionMode::kCertified);
  EXPECT_EQ(certified.result.verdict, Verdict::kCollision);
  const CheckReport report =
      check_certificate(c.robot, c.environment, c.program, kinematics, certified.certificate);
  EXPECT_TRUE(report.accepted) << (report.failures.empty() ? "" : report.failures.front());
}

TEST(MotionOracle, SamplesKeepEveryHullPointWithinTheSpacing) {
  // The oracle's own sampling guarantee, checked against the reference FK: consecutive
  // samples of a random case move no hull vertex by more than the spacing.
  const RandomCase c = random_case(0x5eed0000ULL);
  const test::MotionOracle oracle(c.robot, c.environment);
  std::mt19937_64 rng(7);
  for (int trial = 0; trial < 200; ++trial) {
    Eigen::VectorXd q0(c.robot.joint_count()), dq(c.robot.joint_count());
    for (int j = 0; j < c.robot.joint_count(); ++j) {
      q0[j] = uniform(rng, c.robot.joints[j].minimum, c.robot.joints[j].maximum);
      dq[j] = uniform(rng, -0.05, 0.05);
    }
    const double bound = oracle.motion_bound(dq);
    for (int link = 0; link <= c.robot.joint_count(); ++link) {
      const Eigen::Matrix4d X0 = test::reference_link_pose<double>(c.robot, q0, link);
      const Eigen::Matrix4d X1 = test::reference_link_pose<double>(c.robot, q0 + dq, link);
      for (const HullPoints& hull : c.robot.links[link].hulls) {
        for (const auto& p_L : hull.points) {
          const Eigen::Vector4d p(p_L.x(), p_L.y(), p_L.z(), 1.0);
          // The straight displacement is at most the path length, which the bound covers.
          EXPECT_LE(((X1 - X0) * p).norm(), bound * (1.0 + 1e-9) + 1e-12);
        }
      }
    }
  }
}

}  // namespace
}  // namespace grpvss::certify
