// CellProbe::add_interference_points, which the verifier uses for accepted steps, adds exactly
// the points a probe with points finds: same pairs, same exact points, same order.
#include "grpvss/certify/cell_probe.hpp"

#include <random>
#include <string>

#include <gtest/gtest.h>

#include "grpvss/io/environment_file.hpp"
#include "grpvss/io/robot_file.hpp"
#include "support/random_configurations.hpp"

namespace grpvss::certify {
namespace {

std::string data(const std::string& name) {
  return std::string(GRPVSS_SOURCE_DIR) + "/data/ibm7545/" + name;
}

void expect_same_points(const std::vector<InterferencePoint>& expected,
                        const std::vector<InterferencePoint>& actual, int configuration) {
  ASSERT_EQ(expected.size(), actual.size()) << "configuration " << configuration;
  for (std::size_t i = 0; i < expected.size(); ++i) {
    EXPECT_EQ(expected[i].link, actual[i].link);
    EXPECT_EQ(expected[i].hull, actual[i].hull);
    EXPECT_EQ(expected[i].obstacle, actual[i].obstacle);
    EXPECT_EQ(expected[i].kind, actual[i].kind);
    EXPECT_EQ(expected[i].p_W, actual[i].p_W) << "configuration " << configuration << " point " << i;
  }
}

TEST(CellProbe, AddedInterferencePointsAreThoseOfAProbeWithPoints) {
  const RobotModel robot = io::read_robot_file(data("robot.txt"));
  std::mt19937_64 rng(7545);
  int with_points = 0;
  for (const char* environment_file : {"environment.txt", "bench-environment.txt"}) {
    const Environment environment = io::read_environment_file(data(environment_file));
    CellOptions options;
    options.tolerance = 0.5;
    const RobotCell cell(robot, environment, options);
    CellProbe reference(cell);
    CellProbe added(cell);
    ProbeResult full, trial;
    for (int k = 0; k < 300; ++k) {
      const Eigen::VectorXd q = test::random_configuration(robot, rng);
      reference.probe(q, /*with_points=*/true, full);
      added.probe(q, /*with_points=*/false, trial);
      ASSERT_TRUE(trial.interference_points.empty());
      added.add_interference_points(trial);
      expect_same_points(full.interference_points, trial.interference_points, k);
      with_points += full.interference_points.empty() ? 0 : 1;
    }
  }
  EXPECT_GT(with_points, 20);  // the property is exercised, not vacuous
}

}  // namespace
}  // namespace grpvss::certify
