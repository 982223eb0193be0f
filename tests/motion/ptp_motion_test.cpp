#include "grpvss/motion/ptp_motion.hpp"

#include <cmath>
#include <random>

#include <gtest/gtest.h>

#include "motion/cartesian_robot.hpp"

namespace grpvss::motion {
namespace {

Eigen::VectorXd vec(std::initializer_list<double> values) {
  Eigen::VectorXd v(static_cast<Eigen::Index>(values.size()));
  Eigen::Index i = 0;
  for (double x : values) v[i++] = x;
  return v;
}

TEST(PtpMotion, IndependentJointsStopOnTheirOwn) {
  const RobotModel robot = testing::cartesian_robot();
  const Eigen::VectorXd q_s = vec({0, 0, 0, 0}), q_f = vec({5, -1, 0, 2}), v = vec({1, 1, 1, 1});
  const PtpMotion motion = PtpMotion::plan(robot, q_s, q_f, v, PtpTiming::kIndependent);
  double longest = 0.0;
  for (int j = 0; j < 4; ++j) {
    const auto reference = TrapezoidProfile::plan(q_s[j], q_f[j], v[j], robot.joints[j].acceleration,
                                                  robot.joints[j].deceleration);
    EXPECT_DOUBLE_EQ(motion.joints()[j].duration(), reference.duration());
    EXPECT_DOUBLE_EQ(motion.joints_at(0.7 * reference.duration())[j],
                     reference.at(0.7 * reference.duration()).position);
    longest = std::max(longest, reference.duration());
  }
  EXPECT_EQ(motion.joints()[2].duration(), 0.0);  // zero increment
  EXPECT_DOUBLE_EQ(motion.duration(), longest);
  EXPECT_EQ(motion.joints_at(longest), q_f);
}

// The synchronised law of a trapezoid joint equals the trapezoid planned with k v_m,
// k^2 a_m, k^2 d_m (k = T_j / T): an independent construction of the same motion.
TEST(PtpMotion, SynchronizedJointsArriveTogetherWithScaledLimits) {
  const RobotModel robot = testing::cartesian_robot();
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> pos(-3.0, 3.0), speed(0.3, 2.0);
  for (int trial = 0; trial < 50; ++trial) {
    const Eigen::VectorXd q_s = vec({pos(rng), pos(rng), pos(rng), pos(rng) / 2});
    const Eigen::VectorXd q_f = vec({pos(rng), pos(rng), pos(rng), pos(rng) / 2});
    const Eigen::VectorXd v = vec({speed(rng), speed(rng), speed(rng), speed(rng)});
    const PtpMotion sync = PtpMotion::plan(robot, q_s, q_f, v, PtpTiming::kSynchronized);
    const PtpMotion free = PtpMotion::plan(robot, q_s, q_f, v, PtpTiming::kIndependent);
    const double T = sync.duration();
    EXPECT_DOUBLE_EQ(T, free.duration());
    for (int j = 0; j < 4; ++j) {
      const Joint& joint = robot.joints[j];
      EXPECT_DOUBLE_EQ(sync.joints()[j].duration(), T);
      const double k = free.joints()[j].duration() / T;
      const auto reference = TrapezoidProfile::plan(q_s[j], q_f[j], k * v[j], k * k * joint.acceleration,
                                                    k * k * joint.deceleration);
      EXPECT_NEAR(reference.duration(), T, 1e-9 * T);
      for (double u : {0.0, 0.1, 0.33, 0.5, 0.71, 0.9, 0.999}) {
        const JointState s = sync.joints()[j].at(u * T);
        EXPECT_NEAR(s.position, reference.at(u * T).position, 1e-9);
        EXPECT_NEAR(s.velocity, reference.at(u * T).velocity, 1e-9);
        EXPECT_LE(std::abs(s.velocity), v[j] * (1 + 1e-12));
      }
      // Every joint is still moving just before T (they arrive together) and is there at T.
      EXPECT_GT(std::abs(sync.velocities_at(0.999 * T)[j]), 0.0);
      EXPECT_EQ(sync.joints_at(T)[j], q_f[j]);
      // Acceleration bounds by finite differences of the velocity.
      const double h = T / 4000;
      for (int i = 0; i + 1 < 4000; ++i) {
        const double dv = sync.joints()[j].at((i + 1) * h).velocity - sync.joints()[j].at(i * h).velocity;
        ASSERT_LE(std::abs(dv) / h, std::max(joint.acceleration, joint.deceleration) * (1 + 1e-9));
      }
    }
  }
}

TEST(PtpMotion, RejectsVectorsOfTheWrongSize) {
  const RobotModel robot = testing::cartesian_robot();
  EXPECT_THROW(PtpMotion::plan(robot, vec({0, 0, 0}), vec({1, 1, 1, 1}), vec({1, 1, 1, 1}),
                               PtpTiming::kIndependent),
               std::invalid_argument);
}

}  // namespace
}  // namespace grpvss::motion
