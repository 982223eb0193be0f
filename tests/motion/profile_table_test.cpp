#include "grpvss/motion/profile_table.hpp"

#include <cmath>
#include <string>

#include <gtest/gtest.h>

#include "grpvss/common/input_error.hpp"
#include "grpvss/io/profile_table_file.hpp"
#include "grpvss/motion/ptp_motion.hpp"
#include "motion/cartesian_robot.hpp"

namespace grpvss::motion {
namespace {

// The reader (io/) validates, the motion stage evaluates.
ProfileTable parse_table(std::string_view text, std::string file_name) {
  return ProfileTable(io::parse_profile_table(text, std::move(file_name)));
}
ProfileTable read_table(const std::string& path) {
  return ProfileTable(io::read_profile_table_file(path));
}

// Smoothstep s(t) = 3 t^2 - 2 t^3 on [0, 1] s, ds/dt = 6 t - 6 t^2: a cubic, so the Hermite
// interpolant of its samples is exact everywhere (an independent reference).
std::string smoothstep_table(int joints) {
  std::string text = "# smoothstep for every joint\njoints " + std::to_string(joints) + "\n";
  for (double t : {0.0, 0.25, 0.5, 1.0}) {
    text += std::to_string(t);
    for (int j = 0; j < joints; ++j)
      text += ", " + std::to_string(3 * t * t - 2 * t * t * t) + ", " + std::to_string(6 * t - 6 * t * t);
    text += "\n";
  }
  return text;
}

TEST(ProfileTable, HermiteInterpolationReproducesACubic) {
  const ProfileTable table = parse_table(smoothstep_table(2), "table.txt");
  EXPECT_EQ(table.joint_count(), 2);
  EXPECT_EQ(table.header_line(), 2);
  EXPECT_EQ(table.duration(1), 1.0);
  for (double t : {0.1, 0.3, 0.62, 0.875}) {
    EXPECT_NEAR(table.progress(0, t).position, 3 * t * t - 2 * t * t * t, 1e-12);
    EXPECT_NEAR(table.progress(1, t).velocity, 6 * t - 6 * t * t, 1e-12);
  }
  EXPECT_EQ(table.progress(0, -1.0).position, 0.0);
  EXPECT_EQ(table.progress(0, 2.0).position, 1.0);
}

TEST(ProfileTable, JointDurationIsWhenItsProgressFirstReachesOne) {
  const ProfileTable table = parse_table(
      "joints 2\n0 0 0 0 0\n1 1 0 0.5 0.5\n2 1 0 1 0\n", "t.txt");
  EXPECT_EQ(table.duration(0), 1.0);
  EXPECT_EQ(table.duration(1), 2.0);
  // Monotone progress on a dense grid (Fritsch-Carlson checked by the reader).
  double previous = 0.0;
  for (int i = 0; i <= 2000; ++i) {
    const double s = table.progress(1, i * 0.001).position;
    ASSERT_GE(s, previous);
    previous = s;
  }
}

TEST(ProfileTable, AppliedToAMoveScalesProgressByTheIncrement) {
  auto table = std::make_shared<const ProfileTable>(parse_table(smoothstep_table(4), "t"));
  const RobotModel robot = testing::cartesian_robot();
  Eigen::VectorXd q_s(4), q_f(4), v(4);
  q_s << 1, 2, 3, 0;
  q_f << -1, 2, 4, 1;
  v << 1, 1, 1, 1;
  const PtpMotion motion = PtpMotion::plan(robot, q_s, q_f, v, PtpTiming::kIndependent, table);
  EXPECT_EQ(motion.duration(), 1.0);
  EXPECT_EQ(motion.joints()[1].duration(), 0.0);  // zero increment does not move
  const double t = 0.4, s = 3 * t * t - 2 * t * t * t;
  EXPECT_NEAR(motion.joints_at(t)[0], 1 - 2 * s, 1e-12);
  EXPECT_NEAR(motion.velocities_at(t)[2], 6 * t - 6 * t * t, 1e-12);
  EXPECT_EQ(motion.joints_at(1.0), q_f);
}

TEST(ProfileTable, SynchronizedTimingStretchesShorterColumns) {
  // Example table: joints 1, 2, 4 last 8 s, joint 3 lasts 6 s (smoothstep s(u), u = t / 6).
  auto table = std::make_shared<const ProfileTable>(
      read_table(std::string(GRPVSS_SOURCE_DIR) + "/data/motion/example-table.txt"));
  const RobotModel robot = testing::cartesian_robot();
  const Eigen::VectorXd q_s = Eigen::VectorXd::Zero(4), q_f = Eigen::VectorXd::Constant(4, 2.0);
  const PtpMotion free = PtpMotion::plan(robot, q_s, q_f, q_f, PtpTiming::kIndependent, table);
  const PtpMotion sync = PtpMotion::plan(robot, q_s, q_f, q_f, PtpTiming::kSynchronized, table);
  EXPECT_EQ(free.joints()[2].duration(), 6.0);
  EXPECT_EQ(sync.joints()[2].duration(), 8.0);
  // Stretched by k = 6/8: at t = 4 s joint 3 is where the table has it at 3 s (s = 0.5),
  // moving k times slower (ds/dt = 0.25 / s at 3 s in the table).
  EXPECT_NEAR(sync.joints_at(4.0)[2], 1.0, 1e-12);
  EXPECT_NEAR(sync.velocities_at(4.0)[2], 2.0 * 0.25 * 0.75, 1e-12);
  EXPECT_NEAR(free.joints_at(3.0)[2], 1.0, 1e-12);
}

TEST(ProfileTable, JointCountMustMatchTheRobot) {
  auto table = std::make_shared<const ProfileTable>(parse_table(smoothstep_table(3), "t3.txt"));
  const RobotModel robot = testing::cartesian_robot();
  const Eigen::VectorXd q = Eigen::VectorXd::Zero(4), v = Eigen::VectorXd::Ones(4);
  try {
    PtpMotion::plan(robot, q, q, v, PtpTiming::kIndependent, table);
    FAIL() << "expected InputError";
  } catch (const InputError& error) {
    EXPECT_EQ(error.file(), "t3.txt");
    EXPECT_EQ(error.line(), 2);
    EXPECT_EQ(error.expected(), "'joints 4' (the robot's joint count)");
  }
}

struct BadTable {
  const char* text;
  int line;
  const char* expected_fragment;
};

TEST(ProfileTable, RejectsMalformedTablesWithFileAndLine) {
  const BadTable cases[] = {
      {"0 0 0\n1 1 0\n", 1, "joints N"},
      {"joints 1\n", 2, "at least two rows"},
      {"joints 1\n0 0 0\n1 1\n", 3, "a row"},
      {"joints 1\n0.5 0 0\n1 1 0\n", 2, "first row at time 0"},
      {"joints 1\n0 0.1 0\n1 1 0\n", 2, "s_1 = 0 in the first row"},
      {"joints 1\n0 0 0\n1 0.5 0\n1 1 0\n", 4, "a time greater than 1"},
      {"joints 1\n0 0 0\n1 0.6 0\n2 0.5 0\n3 1 0\n", 4, "non-decreasing progress s_1"},
      {"joints 1\n0 0 0\n1 1.5 0\n", 3, "progress s_1 in [0, 1]"},
      {"joints 1\n0 0 -1\n1 1 0\n", 2, "ds_1/dt >= 0"},
      {"joints 1\n0 0 0\n1 0.9 0\n", 3, "s_1 = 1 in the last row"},
      {"joints 1\n0 0 5\n1 1 0\n", 3, "Fritsch-Carlson"},
      {"joints 1\n0 0 0\n1 0 0.1\n2 1 0\n", 3, "Fritsch-Carlson"},
      {"joints 1\n0 0 0\n1 nan 0\n", 3, "a finite number"},
  };
  for (const BadTable& bad : cases) {
    try {
      parse_table(bad.text, "bad.txt");
      ADD_FAILURE() << "accepted: " << bad.text;
    } catch (const InputError& error) {
      EXPECT_EQ(error.file(), "bad.txt") << bad.text;
      EXPECT_EQ(error.line(), bad.line) << bad.text << " -> " << error.what();
      EXPECT_NE(error.expected().find(bad.expected_fragment), std::string::npos)
          << bad.text << " -> " << error.what();
    }
  }
}

TEST(ProfileTable, MissingFileIsAnInputErrorAtLineZero) {
  try {
    read_table("/nonexistent/table.txt");
    FAIL();
  } catch (const InputError& error) {
    EXPECT_EQ(error.line(), 0);
  }
}

TEST(ProfileTable, ShippedExampleParses) {
  const ProfileTable table =
      read_table(std::string(GRPVSS_SOURCE_DIR) + "/data/motion/example-table.txt");
  EXPECT_EQ(table.joint_count(), 4);
  for (int j = 0; j < 4; ++j) EXPECT_GT(table.duration(j), 0.0);
}

}  // namespace
}  // namespace grpvss::motion
