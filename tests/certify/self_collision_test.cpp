// Self-collision (issue #19 points 6, 7, 9): proofs/two-ball-cover.md#lemma-relative-motion on
// its own (two moving point sets against an exact minimum distance), then the UR5e of
// ../shared/robots (tests/data/cells/ur5e-self.yaml): its pairs skip adjacent links and the
// SRDF's; folding the wrist into the upper arm is a COLLISION naming both links whose
// certificate the checker accepts; a clear path is CLEAR and ACCEPTED; tampering with the pair
// list or a slab is REJECTED; the SRDF's disable of the colliding pair makes the fold CLEAR; and
// an independent exact reference (CGAL, tests/support) agrees on sampled configurations; far
// pairs settled by their balls keep a slab that holds exactly.
#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <limits>
#include <random>
#include <string>
#include <vector>

#include <unistd.h>

#include <gtest/gtest.h>

#include "certify/cell_probe.hpp"
#include "certify/self_pair_probe.hpp"
#include "certify/transition_judge.hpp"
#include "grpvss/cell/load_cell.hpp"
#include "grpvss/certify/robot_cell.hpp"
#include "grpvss/certify/verifier.hpp"
#include "grpvss/checker/certificate_checker.hpp"
#include "grpvss/io/path_file.hpp"
#include "grpvss/exact/certified_query.hpp"
#include "grpvss/geometry/gjk.hpp"
#include "grpvss/geometry/separation_witness.hpp"
#include "grpvss/kinematics/forward_kinematics.hpp"
#include "grpvss/motion/kinematics_adapter.hpp"
#include "grpvss/motion/trajectory.hpp"
#include "support/data_paths.hpp"
#include "support/geometry_reference.hpp"
#include "support/ur5e_self_run.hpp"

namespace grpvss::certify {
namespace {

// ---- the lemma ---------------------------------------------------------------------------

using Points = std::vector<Eigen::Vector3d>;

double min_distance(const Points& a, const Points& b) {
  double best = std::numeric_limits<double>::infinity();
  for (const auto& p : a) {
    for (const auto& q : b) best = std::min(best, (p - q).norm());
  }
  return best;
}

// A rigid motion of a point set: rotation about z by angle(t) and a translation along a
// polyline; every point's path is sampled densely so that its length is measured.
struct RigidMotion {
  Eigen::Vector3d axis_point;
  double angle_total = 0.0;
  std::vector<Eigen::Vector3d> polyline;  ///< translation waypoints, equally timed

  Eigen::Vector3d translation(double t) const {
    const double x = t * static_cast<double>(polyline.size() - 1);
    const auto i = std::min(static_cast<std::size_t>(x), polyline.size() - 2);
    return polyline[i] + (x - static_cast<double>(i)) * (polyline[i + 1] - polyline[i]);
  }
  Points at(const Points& body, double t) const {
    const Eigen::AngleAxisd rotation(angle_total * t, Eigen::Vector3d::UnitZ());
    Points out;
    for (const auto& p : body) out.push_back(rotation * (p - axis_point) + axis_point + translation(t));
    return out;
  }
};

constexpr int kSamples = 400;

// Longest sampled path of any point of `body` (a lower bound of the true length, converging).
double longest_path(const RigidMotion& motion, const Points& body) {
  double longest = 0.0;
  for (std::size_t v = 0; v < body.size(); ++v) {
    double length = 0.0;
    Eigen::Vector3d previous = motion.at({body[v]}, 0.0)[0];
    for (int k = 1; k <= 4 * kSamples; ++k) {
      const Eigen::Vector3d now = motion.at({body[v]}, k / (4.0 * kSamples))[0];
      length += (now - previous).norm();
      previous = now;
    }
    longest = std::max(longest, length);
  }
  return longest;
}

TEST(RelativeMotionLemma, TwoMovingSetsKeepHalfTheSlackBetweenTheSteps) {
  std::mt19937 rng(19);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  int covered = 0;
  for (int trial = 0; trial < 200; ++trial) {
    Points a, b;
    for (int i = 0; i < 6; ++i) a.push_back({u(rng), u(rng), u(rng)});
    for (int i = 0; i < 6; ++i) b.push_back(Eigen::Vector3d(u(rng), u(rng), u(rng)) + Eigen::Vector3d(4, 0, 0));
    RigidMotion ma{{0, 0, 0}, 2.0 * u(rng), {}}, mb{{4, 0, 0}, 2.0 * u(rng), {}};
    for (int w = 0; w < 3; ++w) {
      ma.polyline.push_back(Eigen::Vector3d(u(rng), u(rng), u(rng)));
      mb.polyline.push_back(Eigen::Vector3d(u(rng), u(rng), u(rng)));
    }
    const double d0 = min_distance(ma.at(a, 0.0), mb.at(b, 0.0));
    const double d1 = min_distance(ma.at(a, 1.0), mb.at(b, 1.0));
    // The sampled lengths are slightly short of the true ones: inflate them.
    const double M_a = longest_path(ma, a) * (1 + 1e-4);
    const double M_b = longest_path(mb, b) * (1 + 1e-4);
    const double kept = 0.5 * (d0 + d1 - M_a - M_b);
    if (!(kept > 0.0)) continue;  // the lemma says nothing
    ++covered;
    for (int k = 0; k <= kSamples; ++k) {
      const double t = static_cast<double>(k) / kSamples;
      EXPECT_GE(min_distance(ma.at(a, t), mb.at(b, t)), kept - 1e-12) << "trial " << trial << " t " << t;
    }
  }
  EXPECT_GE(covered, 40);  // enough trials where the inequality holds to test the statement
}

TEST(RelativeMotionLemma, EqualityLetsThePointsMeetSoTheRuleIsStrict) {
  // a goes from 0 to 3 and back (M_a = 6), b stays at 3 (M_b = 0): d_k = d_k+1 = 3, and
  // M_a + M_b = d_k + d_k+1 exactly; at t = 1/2 they meet.
  const RigidMotion ma{{0, 0, 0}, 0.0, {{0, 0, 0}, {3, 0, 0}, {0, 0, 0}}};
  const RigidMotion mb{{0, 0, 0}, 0.0, {{0, 0, 0}, {0, 0, 0}}};
  const Points a{{0, 0, 0}}, b{{3, 0, 0}};
  EXPECT_EQ(min_distance(ma.at(a, 0.0), mb.at(b, 0.0)), 3.0);
  EXPECT_EQ(min_distance(ma.at(a, 1.0), mb.at(b, 1.0)), 3.0);
  EXPECT_NEAR(longest_path(ma, a), 6.0, 1e-9);
  EXPECT_EQ(min_distance(ma.at(a, 0.5), mb.at(b, 0.5)), 0.0);
  // Half way less: they keep exactly half the slack, (3 + 3 - 4) / 2 = 1.
  const RigidMotion shorter{{0, 0, 0}, 0.0, {{0, 0, 0}, {2, 0, 0}, {0, 0, 0}}};
  EXPECT_EQ(min_distance(shorter.at(a, 0.5), mb.at(b, 0.5)), 1.0);
}

TEST(RelativeMotionLemma, TheExactDistanceBoundSubtractsTwicePlacementErrorRoundedDown) {
  EXPECT_EQ(exact_distance_lower_bound(1.0, 0.25), 0.5);
  EXPECT_EQ(exact_distance_lower_bound(0.5, 0.25), 0.0);  // not above 2 eps: nothing proven
  EXPECT_EQ(exact_distance_lower_bound(0.1, 0.25), 0.0);
  // 0.3 - 2e-17 rounds to 0.3 in nearest mode; rounded down it must be below 0.3.
  const double d = exact_distance_lower_bound(0.3, 1e-17);
  EXPECT_LT(d, 0.3);
  EXPECT_EQ(d, std::nextafter(0.3, 0.0));
}

// ---- the UR5e ------------------------------------------------------------------------------

using grpvss::test::kTestCells;

using test::has_failure;
using test::Ur5eSelfInputs;

Ur5eSelfInputs load(const std::string& cell_file, const std::string& path_file) {
  return test::load_ur5e_self(cell_file, path_file);
}

VerificationRun verify_ur5e(const Ur5eSelfInputs& run) { return test::verify_ur5e_self(run); }

CheckReport check_ur5e_self_certificate(const Ur5eSelfInputs& run, const Certificate& certificate) {
  return test::check_ur5e_self(run, certificate);
}

int hull_count(const RobotModel& robot, int link) {
  return static_cast<int>(robot.links[static_cast<std::size_t>(link)].hulls.size());
}

TEST(SelfCollision, PairsAreEveryHullPairTwoChainLinksApartAndAdjacentLinksAreListed) {
  const cell::LoadedCell cell = cell::load_cell(kTestCells + "ur5e-self.yaml");
  const RobotModel& robot = cell.robot;
  ASSERT_EQ(robot.links.size(), 7u);
  int expected = 0;
  for (int a = 0; a < 7; ++a) {
    for (int b = a + 2; b < 7; ++b) expected += hull_count(robot, a) * hull_count(robot, b);
  }
  EXPECT_EQ(static_cast<int>(robot.self_collision_pairs.size()), expected);
  EXPECT_TRUE(std::is_sorted(robot.self_collision_pairs.begin(), robot.self_collision_pairs.end()));
  for (const SelfCollisionPair& pair : robot.self_collision_pairs) {
    EXPECT_GE(pair.link_b - pair.link_a, 2);
  }
  ASSERT_FALSE(robot.unverified_link_pairs.empty());
  EXPECT_EQ(robot.unverified_link_pairs.front().first, "base_link_inertia");
  EXPECT_EQ(robot.unverified_link_pairs.front().second, "shoulder_link");
  EXPECT_EQ(robot.unverified_link_pairs.front().reason, "adjacent");
}

TEST(SelfCollision, TheSrdfAndAllowedContactsRemoveTheirPairsAndListThem) {
  const cell::LoadedCell with_srdf = cell::load_cell(kTestCells + "ur5e-self-srdf.yaml");
  const cell::LoadedCell plain = cell::load_cell(kTestCells + "ur5e-self.yaml");
  const RobotModel& robot = with_srdf.robot;
  // wrist_2_link / upper_arm_link (SRDF) and wrist_3_link / upper_arm_link (allowed_contacts).
  EXPECT_EQ(robot.self_collision_pairs.size(), plain.robot.self_collision_pairs.size() - 2);
  for (const SelfCollisionPair& pair : robot.self_collision_pairs) {
    const std::string label = self_pair_label(robot, pair);
    EXPECT_NE(label, "wrist_2_link / upper_arm_link");
    EXPECT_NE(label, "wrist_3_link / upper_arm_link");
  }
  const auto listed = [&](const std::string& first, const std::string& second,
                          const std::string& reason) {
    return std::any_of(robot.unverified_link_pairs.begin(), robot.unverified_link_pairs.end(),
                       [&](const UnverifiedLinkPair& p) {
                         return p.first == first && p.second == second && p.reason == reason;
                       });
  };
  EXPECT_TRUE(listed("upper_arm_link", "wrist_2_link", "SRDF (Never)"));
  EXPECT_TRUE(listed("upper_arm_link", "wrist_3_link", "allowed_contacts"));
  const cell::LoadedCell off = cell::load_cell(kTestCells + "ur5e-self-off.yaml");
  EXPECT_TRUE(off.robot.self_collision_pairs.empty());
  EXPECT_TRUE(off.robot.unverified_link_pairs.empty());
}

TEST(SelfCollision, FoldingTheWristIntoTheUpperArmIsACollisionNamingBothLinks) {
  const Ur5eSelfInputs run = load("ur5e-self.yaml", "ur5e-fold.txt");
  const VerificationRun verified = verify_ur5e(run);
  EXPECT_EQ(verified.result.verdict, Verdict::kCollision);
  ASSERT_TRUE(verified.result.collision_step.has_value());
  ASSERT_FALSE(verified.result.self_collision_episodes.empty());
  const SelfCollisionEpisode& first = verified.result.self_collision_episodes.front();
  EXPECT_EQ(self_pair_label(run.cell.robot, first.pair), "wrist_2_link / upper_arm_link");
  EXPECT_EQ(first.first_step, *verified.result.collision_step);
  EXPECT_TRUE(verified.result.interference_episodes.empty());  // the table is never touched
  // The checker re-decides the contact exactly and accepts the COLLISION claim.
  const CheckReport report = check_ur5e_self_certificate(run, verified.certificate);
  EXPECT_TRUE(report.accepted) << (report.failures.empty() ? "" : report.failures.front());
}

TEST(SelfCollision, AClearPathIsCertifiedAgainstItselfAndTheCheckerAcceptsIt) {
  const Ur5eSelfInputs run = load("ur5e-self.yaml", "ur5e-clear.txt");
  const VerificationRun verified = verify_ur5e(run);
  EXPECT_EQ(verified.result.verdict, Verdict::kClear);
  const Certificate& certificate = verified.certificate;
  EXPECT_EQ(certificate.self_collision_pairs, run.cell.robot.self_collision_pairs);
  for (const SegmentCertificate& segment : certificate.segments) {
    for (const StepCertificate& step : segment.steps) {
      ASSERT_EQ(step.self_pairs.size(), certificate.self_collision_pairs.size());
      for (const SelfPairRecord& pair : step.self_pairs) EXPECT_TRUE(pair.separated);
    }
  }
  const CheckReport report = check_ur5e_self_certificate(run, certificate);
  EXPECT_TRUE(report.accepted) << (report.failures.empty() ? "" : report.failures.front());
}

TEST(SelfCollision, ACertificateWithAnotherPairListOrAFalseSlabIsRejected) {
  const Ur5eSelfInputs run = load("ur5e-self.yaml", "ur5e-clear.txt");
  const Certificate certificate = verify_ur5e(run).certificate;
  ASSERT_TRUE(check_ur5e_self_certificate(run, certificate).accepted);

  Certificate fewer_pairs = certificate;
  fewer_pairs.self_collision_pairs.pop_back();
  const CheckReport fewer = check_ur5e_self_certificate(run, fewer_pairs);
  EXPECT_FALSE(fewer.accepted);
  EXPECT_TRUE(has_failure(fewer, "the certificate's self-collision pairs differ from the inputs'"));

  // A slab claiming more distance than it proves (its lower bound doubled).
  Certificate inflated = certificate;
  SelfPairRecord& slab = inflated.segments.front().steps.front().self_pairs.front();
  slab.lower_bound = 2.0 * slab.lower_bound + 0.01;
  const CheckReport false_slab = check_ur5e_self_certificate(run, inflated);
  EXPECT_FALSE(false_slab.accepted);
  EXPECT_TRUE(has_failure(false_slab, "the separation witness does not hold"));

  // Without its self-pair records a step proves no self-collision distance at all.
  Certificate stripped = certificate;
  stripped.segments.front().steps.back().self_pairs.clear();
  const CheckReport missing = check_ur5e_self_certificate(run, stripped);
  EXPECT_FALSE(missing.accepted);
  EXPECT_TRUE(has_failure(missing, "expected a self-pair record for each of the"));
}

TEST(SelfCollision, DisablingTheCollidingPairInTheSrdfMakesTheFoldClear) {
  const Ur5eSelfInputs run = load("ur5e-self-srdf.yaml", "ur5e-fold.txt");
  const VerificationRun verified = verify_ur5e(run);
  EXPECT_EQ(verified.result.verdict, Verdict::kClear);
  EXPECT_TRUE(verified.result.self_collision_episodes.empty());
  EXPECT_TRUE(check_ur5e_self_certificate(run, verified.certificate).accepted);
}

// The placed raw hulls of a configuration, by RobotCell hull index.
std::vector<Points> placed_pair_hulls(const RobotCell& cell, const Eigen::VectorXd& q) {
  kinematics::Workspace workspace(cell.robot());
  kinematics::forward_kinematics(cell.chain(), q, workspace);
  std::vector<Points> placed(cell.hulls().size());
  for (std::size_t i = 0; i < cell.hulls().size(); ++i) {
    kinematics::place_points(workspace.X_WL[static_cast<std::size_t>(cell.hulls()[i].link)],
                             cell.hulls()[i].raw_L, placed[i]);
  }
  return placed;
}

// Independent: CGAL's exact contact (tests/support/geometry_reference) on every self pair.
bool reference_self_contact(const RobotCell& cell, const Eigen::VectorXd& q) {
  const std::vector<Points> placed = placed_pair_hulls(cell, q);
  for (const SelfPairHulls& pair : cell.self_pairs()) {
    if (grpvss::testing::reference_contact(placed[static_cast<std::size_t>(pair.a)],
                                placed[static_cast<std::size_t>(pair.b)]) !=
        geometry::Contact::kSeparated) {
      return true;
    }
  }
  return false;
}

// proofs/two-ball-cover.md#relative-frame: hull b seen from link a's frame moves by joints
// a+1..b only, and no farther than M_b|a; turning the arm about joint 1 alone moves no pair of
// links 1..6 relative to each other.
TEST(RelativeMotionLemma, InLinkAsFrameHullBTravelsAtMostItsBoundOverTheJointsBetween) {
  const cell::LoadedCell loaded = test::load_test_cell("ur5e-self.yaml");
  const RobotCell cell = test::certified_cell(loaded);
  std::mt19937 rng(3);
  std::uniform_real_distribution<double> u(-1.0, 1.0);
  kinematics::Workspace workspace(cell.robot());
  for (int trial = 0; trial < 6; ++trial) {
    Eigen::VectorXd q0(6), q1(6);
    for (int j = 0; j < 6; ++j) {
      q0[j] = 2.0 * u(rng);
      q1[j] = q0[j] + 0.5 * u(rng);
    }
    for (const SelfPairHulls& pair : cell.self_pairs()) {
      const LinkHull& a = cell.hulls()[static_cast<std::size_t>(pair.a)];
      const LinkHull& b = cell.hulls()[static_cast<std::size_t>(pair.b)];
      Eigen::VectorXd relative = q1 - q0;
      relative.head(a.link).setZero();
      const double bound = cell.radii().hull_motion_bound(b.link, b.hull, relative);
      // Every vertex's sampled path in link a's frame (joint-linear motion).
      double longest = 0.0;
      for (const Eigen::Vector3d& v : b.raw_L) {
        double length = 0.0;
        Eigen::Vector3d previous;
        for (int k = 0; k <= 100; ++k) {
          kinematics::forward_kinematics(cell.chain(), q0 + (q1 - q0) * (k / 100.0), workspace);
          const Eigen::Vector3d p_A = workspace.X_WL[static_cast<std::size_t>(a.link)].inverse() *
                                      (workspace.X_WL[static_cast<std::size_t>(b.link)] * v);
          if (k > 0) length += (p_A - previous).norm();
          previous = p_A;
        }
        longest = std::max(longest, length);
      }
      EXPECT_LE(longest, bound * (1 + 1e-9) + 1e-12) << "trial " << trial;
      if (a.link >= 1) {
        // Joint 1 alone: hull b does not move in link a's frame.
        Eigen::VectorXd joint_one = Eigen::VectorXd::Zero(6);
        joint_one[0] = 1.0;
        joint_one.head(a.link).setZero();
        // (0 rounded upward: a few subnormal ulps)
        EXPECT_LT(cell.radii().hull_motion_bound(b.link, b.hull, joint_one), 1e-300);
      }
    }
  }
}

TEST(SelfCollision, TheStepRuleHoldsEachPairToItsRelativeBound) {
  const cell::LoadedCell loaded = test::load_test_cell("ur5e-self.yaml");
  const RobotCell cell = test::certified_cell(loaded);
  CellProbe probe(cell);
  ProbeResult from, to;
  Eigen::VectorXd q(6);
  q << 0, -1.5708, 1.5708, 0, 0, 0;
  probe.probe(q, false, from);
  q[0] += 0.5;  // joint 1 only
  probe.probe(q, false, to);
  const TransitionRecord record = judge_transition(cell, from, to, false, false);
  ASSERT_EQ(record.self_pair_motion_bounds.size(), cell.self_pairs().size());
  for (std::size_t p = 0; p < cell.self_pairs().size(); ++p) {
    const LinkHull& a = cell.hulls()[static_cast<std::size_t>(cell.self_pairs()[p].a)];
    const LinkHull& b = cell.hulls()[static_cast<std::size_t>(cell.self_pairs()[p].b)];
    if (a.link >= 1) {
      EXPECT_LT(record.self_pair_motion_bounds[p], 1e-300);  // 0, rounded upward
      EXPECT_FALSE(by_revolution(record, p));
      EXPECT_EQ(record.self_pair_allowances[p],
                allowance_down(from.self_pairs[p].distance, to.self_pairs[p].distance));
    } else {
      // The base is round about joint 1: its solid of revolution is turned into itself, so
      // joint 1 alone moves no hull relative to it (the revolution route's bound is 0), while
      // b's bound in the base frame is its world bound M_b > 0.
      ASSERT_TRUE(a.revolution_L.has_value());
      EXPECT_TRUE(by_revolution(record, p));
      EXPECT_LT(record.self_pair_motion_bounds[p], 1e-300);
      EXPECT_GT(record.hull_motion_bounds[static_cast<std::size_t>(cell.self_pairs()[p].b)], 0.0);
      EXPECT_EQ(record.self_pair_allowances[p],
                allowance_down(from.self_pairs[p].revolution_distance,
                               to.self_pairs[p].revolution_distance));
      // Below the exact distance of the placed hulls (it may exceed d: a pair settled by its
      // balls' slab gets the solid's tighter support on that normal).
      EXPECT_GT(from.self_pairs[p].revolution_distance, 0.0);
      const std::vector<Points> placed = placed_pair_hulls(cell, from.q);
      const double exact_distance = std::sqrt(geometry::exact_distance_squared_lower(
          placed[static_cast<std::size_t>(cell.self_pairs()[p].a)],
          placed[static_cast<std::size_t>(cell.self_pairs()[p].b)]));
      EXPECT_LE(from.self_pairs[p].revolution_distance, exact_distance + 1e-12);
    }
    EXPECT_GE(b.link - a.link, 2);
  }
}

// On a trajectory piece the joints may go out and back within one step: the pairs' relative
// bounds take the joints' variation, as the hulls' do, never the ends' difference (which is 0
// here). proof: proofs/joint-variation.md#theorem-variation-motion-bound
TEST(SelfCollision, TheRelativeBoundTakesTheJointVariationOfATrajectoryPiece) {
  const cell::LoadedCell loaded = test::load_test_cell("ur5e-self.yaml");
  const RobotCell cell = test::certified_cell(loaded);
  CellProbe probe(cell);
  ProbeResult at;
  Eigen::VectorXd q(6);
  q << 0, -1.5708, 1.5708, 0, 0, 0;
  probe.probe(q, false, at);
  const Eigen::VectorXd variation = Eigen::VectorXd::Constant(6, 0.1);
  const TransitionRecord record = judge_transition(cell, at, at, false, false, variation);
  ASSERT_EQ(record.self_pair_motion_bounds.size(), cell.self_pairs().size());
  for (std::size_t p = 0; p < cell.self_pairs().size(); ++p) {
    const SelfPairHulls& pair = cell.self_pairs()[p];
    const LinkHull& a = cell.hulls()[static_cast<std::size_t>(pair.a)];
    const LinkHull& b = cell.hulls()[static_cast<std::size_t>(pair.b)];
    // Joints a+2..b move hull b even about a's solid of revolution: a positive bound either way.
    Eigen::VectorXd beyond = variation;
    beyond.head(a.link + 1).setZero();
    const double least = cell.radii().hull_motion_bound(b.link, b.hull, beyond);
    EXPECT_GT(least, 0.0) << "pair " << p;
    EXPECT_GE(record.self_pair_motion_bounds[p], std::min(least, record.hull_motion_bounds[static_cast<std::size_t>(pair.a)] +
                                                                     record.hull_motion_bounds[static_cast<std::size_t>(pair.b)]))
        << "pair " << p;
  }
}

// A pair whose placed balls are far enough apart is settled by their slab, without GJK or a
// vertex scan (self_pair_probe.hpp): the slab holds exactly on the placed hulls, its distance
// never exceeds the closest witness's nor the reference distance, and it is kept only at or
// above the sum of the two hulls' radii passed in; empty radii give every pair its closest
// witness, bit for bit as before the shortcut.
TEST(SelfCollision, FarPairsAreSettledByTheirBallsAndTheSlabHoldsOnThePlacedHulls) {
  const cell::LoadedCell loaded = test::load_test_cell("ur5e-self.yaml");
  const RobotCell cell = test::certified_cell(loaded);
  const std::size_t hulls = cell.hulls().size();
  kinematics::Workspace workspace(cell.robot());
  Eigen::VectorXd q(6);
  q << 0.3, -1.2, 1.1, -0.4, 1.57, 0.2;
  kinematics::forward_kinematics(cell.chain(), q, workspace);
  const std::vector<Points> placed = placed_pair_hulls(cell, q);
  std::vector<SelfPairEvidence> closest, by_balls, unreached;
  SelfPairProbe closest_probe(cell), ball_probe(cell), unreached_probe(cell);
  closest_probe.probe(workspace.X_WL, {}, closest);
  const double radius = 0.01;  // every hull: a pair needs 2 cm between its balls
  ball_probe.probe(workspace.X_WL, std::vector<double>(hulls, radius), by_balls);
  unreached_probe.probe(workspace.X_WL, std::vector<double>(hulls, 1e9), unreached);
  int settled = 0, closer_look = 0;
  for (std::size_t p = 0; p < cell.self_pairs().size(); ++p) {
    const auto& a = placed[static_cast<std::size_t>(cell.self_pairs()[p].a)];
    const auto& b = placed[static_cast<std::size_t>(cell.self_pairs()[p].b)];
    ASSERT_TRUE(closest[p].separated) << "pair " << p;
    ASSERT_TRUE(by_balls[p].separated) << "pair " << p;
    EXPECT_EQ(unreached[p].lower_bound, closest[p].lower_bound) << "pair " << p;
    EXPECT_EQ(unreached[p].witness.normal, closest[p].witness.normal) << "pair " << p;
    EXPECT_TRUE(geometry::check_witness_exactly(a, b, by_balls[p].witness, by_balls[p].lower_bound))
        << "pair " << p;
    EXPECT_LE(by_balls[p].distance, closest[p].distance) << "pair " << p;
    EXPECT_LT(by_balls[p].lower_bound, grpvss::testing::reference_distance(a, b)) << "pair " << p;
    if (by_balls[p].lower_bound != closest[p].lower_bound) {
      ++settled;
      EXPECT_GE(by_balls[p].distance, 2 * radius) << "pair " << p;
    } else {
      ++closer_look;
    }
  }
  EXPECT_GE(settled, 3);
  EXPECT_GE(closer_look, 1);  // base / upper arm: ~1 cm apart, closer than the threshold
}

// The UR5e alone (no obstacle: only self-collision can stop a path), base at the origin.
cell::LoadedCell free_ur5e(const std::filesystem::path& directory) {
  const std::string robots = std::string(GRPVSS_SOURCE_DIR) + "/../shared/robots/";
  const std::string file = (directory / "free.yaml").string();
  std::ofstream(file) << "units: m\nrobot:\n  urdf: " << robots << "ur5e/ur5e.urdf\n"
                      << "  package_paths: [" << robots << "ur5e]\n  tip: tool0\n"
                      << "  home: [0, -1.5708, 1.5708, 0, 0, 0]\ntolerance: 0.005\n";
  return cell::load_cell(file);
}

// Double GJK can claim an overlap on two CAD hulls ~6 mm apart (a nearly flat simplex of their
// many coplanar vertices: found on a benchmark path, where the exact SAT over every edge pair
// of base_link_inertia and upper_arm_link then cost ~0.1 s a query). certified_pair_query
// tries the caller's warm normal (the pair's last witness) before the exact fallback: the
// answer is a certified slab that holds exactly and stays below the reference distance.
TEST(SelfCollision, TheWarmNormalSettlesAPairDoubleGjkCallsOverlapping) {
  const std::filesystem::path directory = std::filesystem::temp_directory_path() /
                                          ("grpvss-self-warm-" + std::to_string(::getpid()));
  std::filesystem::create_directories(directory);
  const cell::LoadedCell loaded = free_ur5e(directory);
  std::filesystem::remove_all(directory);
  CellSettings settings;
  settings.tolerance = loaded.tolerance;
  const RobotCell cell(loaded.robot, loaded.environment, settings);
  Eigen::VectorXd q(6);
  q << 0.9772725874971312, 0.83967636208827023, 1.2511440378415255, -0.69245001152371943,
      0.088747194030848603, -1.051461583708666;
  const Eigen::Vector3d warm(-0.0036158021299844967, 0.0044345373303059307, 0.0012508983572103276);
  const std::vector<Points> placed = placed_pair_hulls(cell, q);
  const auto& base = placed[0];
  const auto& upper_arm = placed[2];
  ASSERT_EQ(cell.robot().links[static_cast<std::size_t>(cell.hulls()[2].link)].name,
            "upper_arm_link");
  const geometry::GjkResult proposed =
      geometry::gjk(base, upper_arm, &warm, &cell.raw_skeleton(0), 0, &cell.raw_skeleton(2), 0);
  RecordProperty("gjk_status", static_cast<int>(proposed.status));
  const double reference = grpvss::testing::reference_distance(base, upper_arm);
  EXPECT_NEAR(reference, 0.0059, 0.0005);
  for (const Eigen::Vector3d* warm_start : {&warm, static_cast<const Eigen::Vector3d*>(nullptr)}) {
    const geometry::CertifiedPairResult result = geometry::certified_pair_query(
        base, upper_arm, warm_start, &cell.raw_skeleton(0), nullptr, &cell.raw_skeleton(2), nullptr);
    ASSERT_EQ(result.contact, geometry::Contact::kSeparated);
    ASSERT_TRUE(result.witness.has_value());
    EXPECT_TRUE(geometry::check_witness_exactly(base, upper_arm, *result.witness,
                                                result.clearance_lower_bound));
    EXPECT_LE(result.clearance_lower_bound, reference);
    EXPECT_GT(result.clearance_lower_bound, 0.9 * reference);
    if (warm_start != nullptr && proposed.status != geometry::GjkStatus::kSeparated) {
      EXPECT_EQ(result.decided_by, geometry::DecidedBy::kIntervalFilter);
    }
  }
  EXPECT_EQ(proposed.status, geometry::GjkStatus::kOverlapping);
}

TEST(SelfCollision, AnExactReferenceAgreesOnRandomUr5ePaths) {
  const std::filesystem::path directory =
      std::filesystem::temp_directory_path() / ("grpvss-self-oracle-" + std::to_string(::getpid()));
  std::filesystem::create_directories(directory);
  const cell::LoadedCell loaded = free_ur5e(directory);
  ASSERT_TRUE(loaded.environment.obstacles.empty());
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> angle(-170.0, 170.0);
  int collisions = 0, clear = 0;
  for (int trial = 0; trial < 5; ++trial) {
    const std::string path = (directory / ("p" + std::to_string(trial) + ".txt")).string();
    {
      std::ofstream out(path);
      out << "1\n1\n";
      for (int j = 0; j < 6; ++j) out << angle(rng) << ",30.\n";
    }
    Ur5eSelfInputs run{loaded, io::read_path_file(path, loaded.robot), {}};
    run.kinematics =
        motion::make_kinematics_access(run.cell.robot, motion::select_ik({}, run.cell.robot, "ur5e"));
    const VerificationRun verified = verify_ur5e(run);
    SetupRequest request;
    request.tolerance = run.cell.tolerance;
    const RobotCell cell(run.cell.robot, run.cell.environment, resolve_setup(request).cell);
    const VerificationResult& result = verified.result;
    if (!result.self_collision_episodes.empty()) {
      // The step the verifier names is a self-contact for the reference too.
      ++collisions;
      const int step = result.self_collision_episodes.front().first_step;
      const Eigen::VectorXd q =
          step == 0 ? result.start->q : result.steps[static_cast<std::size_t>(step - 1)].q;
      EXPECT_TRUE(reference_self_contact(cell, q)) << "trial " << trial << " step " << step;
    } else if (result.verdict == Verdict::kClear) {
      // Dense samples of the planned motion: never a self-contact for the reference.
      ++clear;
      motion::MotionModel model;
      const motion::Trajectory trajectory =
          motion::Trajectory::plan(run.cell.robot, run.program, run.kinematics, model);
      for (int k = 0; k <= 20; ++k) {
        const auto q = trajectory.joints_at(trajectory.duration() * k / 20.0);
        ASSERT_TRUE(q.has_value());
        EXPECT_FALSE(reference_self_contact(cell, *q)) << "trial " << trial << " sample " << k;
      }
    }
    EXPECT_TRUE(check_ur5e_self_certificate(run, verified.certificate).accepted) << "trial " << trial;
  }
  std::filesystem::remove_all(directory);
  RecordProperty("self_collisions", collisions);
  RecordProperty("clear", clear);
  EXPECT_GE(collisions + clear, 3);
}

}  // namespace
}  // namespace grpvss::certify
