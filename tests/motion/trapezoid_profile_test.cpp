#include "grpvss/motion/trapezoid_profile.hpp"

#include <cmath>
#include <random>

#include <gtest/gtest.h>

namespace grpvss::motion {
namespace {

constexpr double kDeg = M_PI / 180.0;

// Thesis A.3, segment 1: home (0,0,0,0) to (61.16 deg, 79.90 deg, 2.45 in, 171.06 deg) with the
// IBM 7545 speeds 3,3,0.3,3 and acc/dec 2/1.8, 2/1.8, 0.7/0.6, 2/1.8 (deg or in per s^2).
TEST(TrapezoidProfile, ReproducesTheThesisFirstSteps) {
  const double finish[4] = {61.16, 79.90, 2.45, 171.06};
  const double speed[4] = {3, 3, 0.3, 3};
  const double acc[4] = {2, 2, 0.7, 2};
  const double dec[4] = {1.8, 1.8, 0.6, 1.8};
  const double times[4] = {1.025, 2.503, 3.5, 4.483};
  const double expected[4][4] = {{1.05, 1.05, 0.24, 1.05},
                                 {5.26, 5.26, 0.69, 5.26},
                                 {8.25, 8.25, 0.99, 8.25},
                                 {11.20, 11.20, 1.28, 11.20}};
  for (int j = 0; j < 4; ++j) {
    // Revolute joints are planned in radians, as the library does, and printed in degrees.
    const double unit = j == 2 ? 1.0 : kDeg;
    const auto profile =
        TrapezoidProfile::plan(0.0, finish[j] * unit, speed[j] * unit, acc[j] * unit, dec[j] * unit);
    for (int k = 0; k < 4; ++k) {
      EXPECT_NEAR(profile.at(times[k]).position / unit, expected[k][j], 0.01)
          << "joint " << j + 1 << " t=" << times[k];
    }
    EXPECT_DOUBLE_EQ(profile.at(profile.duration()).position, finish[j] * unit);
  }
}

TEST(TrapezoidProfile, TrapezoidPhaseTimesFollowEq14) {
  // 50 deg at 3 deg/s, a=2, d=1.8: t1 = 1.5, ramps cover 2.25 + 2.5 = 4.75, cruise 45.25/3.
  const auto p = TrapezoidProfile::plan(0.0, 50.0, 3.0, 2.0, 1.8);
  EXPECT_FALSE(p.is_triangle());
  EXPECT_DOUBLE_EQ(p.peak_speed(), 3.0);
  EXPECT_NEAR(p.duration(), 1.5 + 45.25 / 3.0 + 3.0 / 1.8, 1e-12);
}

TEST(TrapezoidProfile, ShortMoveIsATriangleWithTheThesisPeak) {
  // D = 1 < 3^2/2 (1/2 + 1/1.8): v = sqrt(2 / (1/2 + 1/1.8)).
  const auto p = TrapezoidProfile::plan(5.0, 4.0, 3.0, 2.0, 1.8);
  const double v = std::sqrt(2.0 / (0.5 + 1.0 / 1.8));
  EXPECT_TRUE(p.is_triangle());
  EXPECT_NEAR(p.peak_speed(), v, 1e-12);
  EXPECT_NEAR(p.duration(), v / 2.0 + v / 1.8, 1e-12);
  EXPECT_NEAR(p.at(v / 2.0).velocity, -v, 1e-12);  // moving down: negative velocity
  EXPECT_NEAR(p.at(v / 2.0).position, 5.0 - v * v / 4.0, 1e-12);
  EXPECT_DOUBLE_EQ(p.at(10.0).position, 4.0);
}

TEST(TrapezoidProfile, ZeroIncrementHasZeroDuration) {
  const auto p = TrapezoidProfile::plan(0.7, 0.7, 3.0, 2.0, 1.8);
  EXPECT_EQ(p.duration(), 0.0);
  EXPECT_EQ(p.at(1.0).position, 0.7);
  EXPECT_EQ(p.at(1.0).velocity, 0.0);
}

TEST(TrapezoidProfile, RejectsNonPositiveLimits) {
  EXPECT_THROW(TrapezoidProfile::plan(0, 1, 0.0, 1, 1), std::invalid_argument);
  EXPECT_THROW(TrapezoidProfile::plan(0, 1, 1, -1, 1), std::invalid_argument);
  EXPECT_THROW(TrapezoidProfile::plan(0, 1, 1, 1, NAN), std::invalid_argument);
}

// Property test against an independent reference: integrate the acceleration the profile
// reports (midpoint rule, exact for piecewise-constant acceleration away from the breaks) and
// compare with the reported velocity and position; check |v| <= v_m, monotone progress.
TEST(TrapezoidProfile, RandomProfilesAreContinuousMonotoneAndWithinLimits) {
  std::mt19937 rng(20261121);
  std::uniform_real_distribution<double> pos(-5.0, 5.0), lim(0.2, 4.0);
  for (int trial = 0; trial < 200; ++trial) {
    const double q_s = pos(rng), q_f = pos(rng), v_m = lim(rng), a_m = lim(rng), d_m = lim(rng);
    const auto p = TrapezoidProfile::plan(q_s, q_f, v_m, a_m, d_m);
    const double sign = q_f >= q_s ? 1.0 : -1.0;
    const int n = 20000;
    const double dt = p.duration() / n;
    double q = q_s, v = 0.0, previous = q_s;
    for (int i = 0; i < n; ++i) {
      const double t = (i + 0.5) * dt;
      const double acc = p.acceleration(t);
      ASSERT_TRUE(acc == 0.0 || std::abs(acc) == a_m || std::abs(acc) == d_m);
      q += v * dt + 0.5 * acc * dt * dt;
      v += acc * dt;
      const JointState s = p.at((i + 1) * dt);
      ASSERT_LE(std::abs(s.velocity), v_m * (1 + 1e-12));
      ASSERT_GE(sign * (s.position - previous), -1e-12);  // monotone progress
      previous = s.position;
    }
    // Each of the (at most 3) phase breaks inside a step costs at most (a_m + d_m) dt.
    const double slack = 3.0 * (a_m + d_m) * dt;
    EXPECT_NEAR(v, 0.0, slack);
    EXPECT_NEAR(q, q_f, slack * p.duration());
    EXPECT_NEAR(p.at(0.37 * p.duration()).position - q_s,
                sign * std::abs(p.at(0.37 * p.duration()).position - q_s), 1e-12);
  }
}

}  // namespace
}  // namespace grpvss::motion
