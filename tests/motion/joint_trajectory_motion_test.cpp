#include "grpvss/motion/joint_trajectory_motion.hpp"

#include <cfenv>
#include <cmath>
#include <limits>
#include <stdexcept>

#include <gtest/gtest.h>

#include "grpvss/io/trajectory_file.hpp"
#include "grpvss/motion/exact_joint_variation.hpp"

namespace grpvss::motion {
namespace {

JointTrajectory overshoot_sample() {
  return io::read_trajectory_file(std::string(GRPVSS_SOURCE_DIR) + "/data/trajectories/overshoot.json");
}

constexpr int kElbow = 2;

TEST(JointTrajectoryMotion, LinearInterpolationBetweenWaypoints) {
  const JointTrajectoryMotion motion(
      io::parse_trajectory_csv("time,a,b\n0.5,1,-2\n1.5,3,-2\n2.5,2,0\n", "l.csv"));
  EXPECT_EQ(motion.interpolation(), JointInterpolation::kLinear);
  EXPECT_EQ(motion.piece_count(), 2);
  EXPECT_EQ(motion.start_time(), 0.5);
  EXPECT_EQ(motion.end_time(), 2.5);
  EXPECT_EQ(motion.piece_breaks(), (std::vector<double>{0.5, 1.5, 2.5}));
  EXPECT_EQ(motion.piece_at(0.5), 0);
  EXPECT_EQ(motion.piece_at(1.5), 1);  // a waypoint starts the later piece
  EXPECT_EQ(motion.piece_at(2.5), 1);  // the end belongs to the last piece
  EXPECT_EQ(motion.q_at(1.0), Eigen::Vector2d(2, -2));
  EXPECT_EQ(motion.q_at(2.0), Eigen::Vector2d(2.5, -1));
  EXPECT_EQ(motion.q_at(1.5), Eigen::Vector2d(3, -2));
  EXPECT_EQ(motion.qdot_at(1.0), Eigen::Vector2d(2, 0));
  EXPECT_EQ(motion.qdot_at(1.5), Eigen::Vector2d(-1, 2));  // right-hand slope at a waypoint
  EXPECT_EQ(motion.qdot_at(2.5), Eigen::Vector2d(-1, 2));  // left-hand slope at the end
}

TEST(JointTrajectoryMotion, HermitePieceHasTheWaypointValuesAndSlopes) {
  // p 0 -> 1, v 0 -> 1.5 over h = 1: q = 1.5 s^2 - 0.5 s^3, q' = 3 s - 1.5 s^2 (by hand).
  const JointTrajectoryMotion motion(io::parse_trajectory_csv(
      "time,a,a.vel\n2,0,0\n3,1,1.5\n", "h.csv"));
  EXPECT_EQ(motion.interpolation(), JointInterpolation::kCubicHermite);
  EXPECT_EQ(motion.q_at(2)[0], 0.0);
  EXPECT_EQ(motion.q_at(3)[0], 1.0);
  EXPECT_EQ(motion.qdot_at(2)[0], 0.0);
  EXPECT_EQ(motion.qdot_at(3)[0], 1.5);
  EXPECT_DOUBLE_EQ(motion.q_at(2.5)[0], 0.3125);
  EXPECT_DOUBLE_EQ(motion.qdot_at(2.5)[0], 1.125);
  EXPECT_DOUBLE_EQ(motion.q_at(2.25)[0], 1.5 * 0.0625 - 0.5 * 0.015625);
  EXPECT_DOUBLE_EQ(motion.qdot_at(2.75)[0], 3 * 0.75 - 1.5 * 0.5625);
  EXPECT_EQ(exact_q_at(motion, 2.5)[0], mpq_class(5, 16));
}

TEST(JointTrajectoryMotion, TheJsonSampleOvershootsItsSecondWaypointByTwoNinths) {
  // Elbow: 2 (v 1.5) -> 2 (v 0) over [1.5, 2.5] s: q = 2 + 1.5 s - 3 s^2 + 1.5 s^3,
  // q' = 1.5 (1 - s)(1 - 3 s): maximum 2 + 2/9 at s = 1/3.
  const JointTrajectoryMotion motion(overshoot_sample());
  const double peak_time = 1.5 + 1.0 / 3.0;
  EXPECT_NEAR(motion.q_at(peak_time)[kElbow], 2.0 + 2.0 / 9.0, 1e-14);
  EXPECT_NEAR(motion.qdot_at(peak_time)[kElbow], 0.0, 1e-14);
  EXPECT_EQ(exact_q_at(motion, 2.0)[kElbow], mpq_class(35, 16));  // s = 1/2: 2 + 3/16
  EXPECT_EQ(motion.q_at(2.5)[kElbow], 2.0);
  for (double t = 1.5 + 1e-3; t < 2.49; t += 1e-3) {
    ASSERT_GT(motion.q_at(t)[kElbow], 2.0) << t;  // above both waypoints all along the piece
  }
}

TEST(JointTrajectoryMotion, EnclosuresContainTheExactValues) {
  const JointTrajectoryMotion motion(overshoot_sample());
  for (double t = 0.5; t <= 2.5; t += 0.0137) {
    const JointIntervals box = motion.q_enclosure_at(t);
    const std::vector<mpq_class> exact = exact_q_at(motion, t);
    for (int j = 0; j < motion.joint_count(); ++j) {
      ASSERT_LE(mpq_class(box.lower[j]), exact[j]) << t;
      ASSERT_GE(mpq_class(box.upper[j]), exact[j]) << t;
      ASSERT_LE(box.upper[j] - box.lower[j], 1e-14) << t;
      ASSERT_LE(box.lower[j], motion.q_at(t)[j] + 1e-15);
    }
  }
  const JointIntervals at_waypoint = motion.q_enclosure_at(1.5);
  EXPECT_EQ(at_waypoint.lower, motion.trajectory().positions[1]);
  EXPECT_EQ(at_waypoint.upper, motion.trajectory().positions[1]);
}

TEST(JointTrajectoryMotion, OneWaypointIsAMotionThatStays) {
  const JointTrajectoryMotion motion(io::parse_trajectory_csv("time,a\n3,0.5\n", "one.csv"));
  EXPECT_EQ(motion.piece_count(), 0);
  EXPECT_EQ(motion.piece_at(3), -1);
  EXPECT_EQ(motion.q_at(3)[0], 0.5);
  EXPECT_EQ(motion.qdot_at(3)[0], 0.0);
  EXPECT_EQ(motion.variation_bound(3, 3)[0], 0.0);
  EXPECT_EQ(exact_variation_bound(motion, 3, 3)[0], 0);
}

TEST(JointTrajectoryMotion, RejectsTimesOutsideTheTrajectory) {
  const JointTrajectoryMotion motion(overshoot_sample());
  EXPECT_THROW(motion.q_at(0.4), std::out_of_range);
  EXPECT_THROW(motion.q_at(2.5000001), std::out_of_range);
  EXPECT_THROW(motion.q_at(std::nan("")), std::out_of_range);
  EXPECT_THROW(motion.variation_bound(0.4, 1.0), std::out_of_range);
  EXPECT_THROW(motion.variation_bound(2.0, 1.0), std::invalid_argument);
  EXPECT_THROW(exact_variation_bound(motion, 2.0, 1.0), std::invalid_argument);
  EXPECT_THROW(exact_q_at(motion, 3.0), std::out_of_range);
}

TEST(JointTrajectoryMotion, RefusesToEvaluateEnclosuresInAnotherRoundingMode) {
  const JointTrajectoryMotion motion(overshoot_sample());
  std::fesetround(FE_UPWARD);
  EXPECT_THROW(motion.variation_bound(1.0, 2.0), std::logic_error);
  EXPECT_THROW(motion.q_enclosure_at(1.0), std::logic_error);
  std::fesetround(FE_TONEAREST);
  EXPECT_NO_THROW(motion.variation_bound(1.0, 2.0));
}

TEST(JointTrajectoryMotion, RejectsTrajectoriesThatBreakTheInvariants) {
  const JointTrajectory good = overshoot_sample();
  JointTrajectory unsorted = good;
  unsorted.times[2] = unsorted.times[1];
  EXPECT_THROW(JointTrajectoryMotion{unsorted}, std::invalid_argument);
  JointTrajectory negative = good;
  negative.times[0] = -1;
  EXPECT_THROW(JointTrajectoryMotion{negative}, std::invalid_argument);
  JointTrajectory short_vector = good;
  short_vector.positions[1].conservativeResize(5);
  EXPECT_THROW(JointTrajectoryMotion{short_vector}, std::invalid_argument);
  JointTrajectory not_finite = good;
  not_finite.velocities[1][0] = std::numeric_limits<double>::infinity();
  EXPECT_THROW(JointTrajectoryMotion{not_finite}, std::invalid_argument);
  JointTrajectory huge = good;
  huge.positions[0][3] = 2e9;
  EXPECT_THROW(JointTrajectoryMotion{huge}, std::invalid_argument);
  JointTrajectory missing_velocities = good;
  missing_velocities.velocities.pop_back();
  EXPECT_THROW(JointTrajectoryMotion{missing_velocities}, std::invalid_argument);
  JointTrajectory empty = good;
  empty.times.clear();
  empty.positions.clear();
  empty.velocities.clear();
  EXPECT_THROW(JointTrajectoryMotion{empty}, std::invalid_argument);
}

}  // namespace
}  // namespace grpvss::motion
