// The brute-force oracle's own parts (tests/support/motion_oracle.hpp, exact_hull_lp.hpp)
// checked against independent references: the exact LP against the library's exact SAT
// classification (two different exact methods must agree), the oracle's per-configuration
// decision (float pre-filter + LP) against the SAT on every pair, and its sampling guarantee
// against the reference FK.
#include <random>
#include <vector>

#include <Eigen/Geometry>
#include <gtest/gtest.h>

#include "grpvss/exact/exact_contact.hpp"
#include "support/exact_hull_lp.hpp"
#include "support/kinematics_reference.hpp"
#include "support/motion_oracle.hpp"
#include "support/oracle_cases.hpp"
#include "support/random_shapes.hpp"

namespace grpvss::test {
namespace {

std::vector<Eigen::Vector3d> integer_box(const Eigen::Vector3d& lo, const Eigen::Vector3d& hi) {
  std::vector<Eigen::Vector3d> points;
  for (int k = 0; k < 8; ++k) {
    points.emplace_back(k & 1 ? hi.x() : lo.x(), k & 2 ? hi.y() : lo.y(), k & 4 ? hi.z() : lo.z());
  }
  return points;
}

TEST(ExactHullLp, TouchingAndBarelySeparatedAxisBoxes) {
  const auto a = integer_box({0, 0, 0}, {1, 1, 1});
  // Sharing a face, an edge, a vertex: touching counts as intersecting (closed sets).
  EXPECT_TRUE(hulls_intersect_exact_lp(a, integer_box({1, 0, 0}, {2, 1, 1})));
  EXPECT_TRUE(hulls_intersect_exact_lp(a, integer_box({1, 1, 0}, {2, 2, 1})));
  EXPECT_TRUE(hulls_intersect_exact_lp(a, integer_box({1, 1, 1}, {2, 2, 2})));
  // Contained, overlapping.
  EXPECT_TRUE(hulls_intersect_exact_lp(a, integer_box({0.25, 0.25, 0.25}, {0.5, 0.5, 0.5})));
  EXPECT_TRUE(hulls_intersect_exact_lp(a, integer_box({0.5, 0.5, 0.5}, {2, 2, 2})));
  // One ulp-scale gap (2^-50) beyond the shared face, edge, vertex: separated.
  const double g = std::ldexp(1.0, -50);
  EXPECT_FALSE(hulls_intersect_exact_lp(a, integer_box({1 + g, 0, 0}, {2, 1, 1})));
  EXPECT_FALSE(hulls_intersect_exact_lp(a, integer_box({1 + g, 1, 0}, {2, 2, 1})));
  EXPECT_FALSE(hulls_intersect_exact_lp(a, integer_box({1, 1, 1 + g}, {2, 2, 2})));
  // Degenerate sets are fine for an LP: a point on a face, a segment through a vertex (x + y = 2).
  EXPECT_TRUE(hulls_intersect_exact_lp(a, {Eigen::Vector3d(1, 0.5, 0.5)}));
  EXPECT_FALSE(hulls_intersect_exact_lp(a, {Eigen::Vector3d(1 + g, 0.5, 0.5)}));
  EXPECT_TRUE(hulls_intersect_exact_lp(a, {Eigen::Vector3d(2, 0, 0.5), Eigen::Vector3d(0, 2, 0.5)}));
  EXPECT_FALSE(hulls_intersect_exact_lp(a, {Eigen::Vector3d(2 + g, 0, 0.5), Eigen::Vector3d(0, 2 + g, 0.5)}));
}

TEST(ExactHullLp, AgreesWithTheExactSatClassificationOnRandomRotatedBoxes) {
  std::mt19937_64 rng(0x1b0c5);
  std::uniform_real_distribution<double> size(0.2, 2.0);
  std::uniform_real_distribution<double> offset(-3.0, 3.0);
  int intersecting = 0;
  for (int trial = 0; trial < 400; ++trial) {
    auto make = [&](const Eigen::Vector3d& center) {
      const Eigen::Matrix3d rotation = random_rotation(rng);
      const Eigen::Vector3d half(size(rng), size(rng), size(rng));
      std::vector<Eigen::Vector3d> points;
      for (int k = 0; k < 8; ++k) {
        points.push_back(center + rotation * Eigen::Vector3d(k & 1 ? half.x() : -half.x(),
                                                             k & 2 ? half.y() : -half.y(),
                                                             k & 4 ? half.z() : -half.z()));
      }
      return points;
    };
    const auto a = make(Eigen::Vector3d::Zero());
    const auto b = make(Eigen::Vector3d(offset(rng), offset(rng), offset(rng)));
    const bool sat = geometry::classify_exact(a, b) != geometry::Contact::kSeparated;
    EXPECT_EQ(hulls_intersect_exact_lp(a, b), sat) << "trial " << trial;
    intersecting += sat;
  }
  // Both outcomes are exercised.
  EXPECT_GT(intersecting, 50);
  EXPECT_LT(intersecting, 350);
}

TEST(MotionOracle, ContactDecisionAgreesWithTheExactSatOnEveryPair) {
  int contacts = 0;
  int configurations = 0;
  for (std::uint64_t seed : {0x5eed0000ULL, 0x5eed0003ULL, 0xc0de0001ULL, 0xc0de0002ULL}) {
    const OracleCase c = (seed >> 16) == 0x5eed ? random_ptp_case(seed) : random_scara_cp_case(seed);
    const MotionOracle oracle(c.robot, c.environment);
    std::mt19937_64 rng(seed);
    for (int trial = 0; trial < 60; ++trial) {
      Eigen::VectorXd q(c.robot.joint_count());
      for (int j = 0; j < c.robot.joint_count(); ++j) {
        q[j] = std::uniform_real_distribution<double>(c.robot.joints[j].minimum, c.robot.joints[j].maximum)(rng);
      }
      bool sat_contact = false;
      for (int link = 0; link <= c.robot.joint_count(); ++link) {
        const Eigen::Matrix4d X_WL = reference_link_pose<double>(c.robot, q, link);
        for (const HullPoints& hull : c.robot.links[link].hulls) {
          std::vector<Eigen::Vector3d> placed;
          for (const auto& p : hull.points) placed.push_back(X_WL.topLeftCorner<3, 3>() * p + X_WL.topRightCorner<3, 1>());
          for (const HullPoints& obstacle : c.environment.obstacles) {
            sat_contact |= geometry::classify_exact(placed, obstacle.points) != geometry::Contact::kSeparated;
          }
        }
      }
      EXPECT_EQ(oracle.check(q).contact, sat_contact) << "seed " << seed << " trial " << trial;
      contacts += sat_contact;
      ++configurations;
    }
  }
  EXPECT_GT(contacts, 5);
  EXPECT_LT(contacts, configurations - 5);
}

TEST(MotionOracle, SamplesKeepEveryHullPointWithinTheSpacing) {
  // The oracle's sampling guarantee, checked against the reference FK: a joint increment dq
  // moves no hull vertex farther than motion_bound(dq).
  const OracleCase c = random_ptp_case(0x5eed0000ULL);
  const MotionOracle oracle(c.robot, c.environment);
  std::mt19937_64 rng(7);
  std::uniform_real_distribution<double> step(-0.05, 0.05);
  for (int trial = 0; trial < 200; ++trial) {
    Eigen::VectorXd q0(c.robot.joint_count()), dq(c.robot.joint_count());
    for (int j = 0; j < c.robot.joint_count(); ++j) {
      q0[j] = std::uniform_real_distribution<double>(c.robot.joints[j].minimum, c.robot.joints[j].maximum)(rng);
      dq[j] = step(rng);
    }
    const double bound = oracle.motion_bound(dq);
    for (int link = 0; link <= c.robot.joint_count(); ++link) {
      const Eigen::Matrix4d X0 = reference_link_pose<double>(c.robot, q0, link);
      const Eigen::Matrix4d X1 = reference_link_pose<double>(c.robot, q0 + dq, link);
      for (const HullPoints& hull : c.robot.links[link].hulls) {
        for (const auto& p_L : hull.points) {
          const Eigen::Vector4d p(p_L.x(), p_L.y(), p_L.z(), 1.0);
          EXPECT_LE(((X1 - X0) * p).norm(), bound * (1.0 + 1e-9) + 1e-12);
        }
      }
    }
  }
}

TEST(MotionOracle, JointLinearSamplingFindsTheCollidingConfigurationBetweenFarSamples) {
  // A joint-linear piece whose end points are clear but whose middle collides: the sampled
  // path must report it (the oracle's sampling, not only its end points).
  std::mt19937_64 rng(11);
  int found = 0;
  for (std::uint64_t seed = 0x5eed0000ULL; seed < 0x5eed0000ULL + 40 && found < 3; ++seed) {
    const OracleCase c = random_ptp_case(seed);
    const MotionOracle oracle(c.robot, c.environment);
    for (int trial = 0; trial < 400; ++trial) {
      Eigen::VectorXd q_mid(c.robot.joint_count()), dq(c.robot.joint_count());
      for (int j = 0; j < c.robot.joint_count(); ++j) {
        const Joint& joint = c.robot.joints[j];
        q_mid[j] = std::uniform_real_distribution<double>(joint.minimum, joint.maximum)(rng);
        dq[j] = std::uniform_real_distribution<double>(-0.3, 0.3)(rng) * (joint.maximum - joint.minimum);
      }
      const Eigen::VectorXd q0 = q_mid - dq, q1 = q_mid + dq;
      if (!oracle.check(q_mid).contact || oracle.check(q0).contact || oracle.check(q1).contact) continue;
      const OraclePathResult result = oracle.sample_joint_linear({q0, q1}, 0.05, 3);
      EXPECT_TRUE(result.first_contact.contact) << "seed " << seed << " trial " << trial;
      EXPECT_EQ(result.contact_segment, 3);
      EXPECT_TRUE(oracle.check(result.contact_q).contact);
      EXPECT_GT(result.samples, 2);
      ++found;
      break;
    }
  }
  EXPECT_EQ(found, 3);
}

}  // namespace
}  // namespace grpvss::test
