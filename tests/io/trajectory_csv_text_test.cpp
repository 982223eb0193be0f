// io::render_trajectory_csv: the canonical CSV of a trajectory given as numbers (the Python
// module's arrays): the exact text, and that io::parse_trajectory_csv reads back every double
// bit for bit (shortest round-trip decimals), velocities included.
#include <cmath>
#include <string>

#include <gtest/gtest.h>

#include "grpvss/io/trajectory_csv_text.hpp"
#include "grpvss/io/trajectory_file.hpp"

namespace {

grpvss::JointTrajectory two_joints(bool with_velocities) {
  grpvss::JointTrajectory trajectory;
  trajectory.joint_names = {"a", "b"};
  trajectory.times = {0.0, 0.1, 2.5};
  trajectory.positions = {Eigen::Vector2d(0.0, -1.5708), Eigen::Vector2d(1.0 / 3.0, 1e-5),
                          Eigen::Vector2d(-2.0, 3.141592653589793)};
  if (with_velocities) {
    trajectory.velocities = {Eigen::Vector2d(0.0, 0.0), Eigen::Vector2d(0.5, -0.25),
                             Eigen::Vector2d(0.0, 0.0)};
  }
  return trajectory;
}

TEST(TrajectoryCsvText, WritesTheHeaderAndShortestRoundTripNumbers) {
  EXPECT_EQ(grpvss::io::render_trajectory_csv(two_joints(false)),
            "time,a,b\n"
            "0,0,-1.5708\n"
            "0.1,0.3333333333333333,1e-05\n"
            "2.5,-2,3.141592653589793\n");
  EXPECT_EQ(grpvss::io::render_trajectory_csv(two_joints(true)),
            "time,a,b,a.vel,b.vel\n"
            "0,0,-1.5708,0,0\n"
            "0.1,0.3333333333333333,1e-05,0.5,-0.25\n"
            "2.5,-2,3.141592653589793,0,0\n");
}

TEST(TrajectoryCsvText, TheReaderReadsBackEveryNumberExactlyAndNamesTheLines) {
  for (const bool with_velocities : {false, true}) {
    const grpvss::JointTrajectory original = two_joints(with_velocities);
    const grpvss::JointTrajectory read = grpvss::io::parse_trajectory_csv(
        grpvss::io::render_trajectory_csv(original), "arrays.csv");
    EXPECT_EQ(read.joint_names, original.joint_names);
    EXPECT_EQ(read.times, original.times);
    ASSERT_EQ(read.positions.size(), 3u);
    for (std::size_t k = 0; k < 3; ++k) {
      EXPECT_EQ(read.positions[k], original.positions[k]) << k;
      if (with_velocities) EXPECT_EQ(read.velocities[k], original.velocities[k]) << k;
    }
    EXPECT_EQ(read.has_velocities(), with_velocities);
    EXPECT_EQ(read.joint_names_line, 1);
    EXPECT_EQ(read.source_lines, (std::vector<int>{2, 3, 4}));
  }
}

}  // namespace
