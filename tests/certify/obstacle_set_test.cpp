// The cell's obstacles are built on first use (issue 22.5): what is built is exactly what an
// eager build gives, and a verification among far-away obstacles builds only the near ones.
#include "grpvss/certify/obstacle_set.hpp"

#include <random>
#include <set>
#include <string>
#include <thread>
#include <vector>

#include <gtest/gtest.h>

#include "certify/cell_probe.hpp"
#include "grpvss/certify/robot_cell.hpp"
#include "grpvss/io/environment_file.hpp"
#include "grpvss/io/robot_file.hpp"
#include "support/data_paths.hpp"
#include "support/random_configurations.hpp"

namespace grpvss::certify {
namespace {

using grpvss::test::ibm7545_file;

// A unit box at (x, y, 0) with a point inside it (not a vertex of its hull).
HullPoints box_with_inner_point(double x, double y) {
  HullPoints box;
  for (int corner = 0; corner < 8; ++corner) {
    box.points.emplace_back(x + (corner & 1), y + ((corner >> 1) & 1), 2.0 * ((corner >> 2) & 1));
  }
  box.points.insert(box.points.begin() + 3, Eigen::Vector3d(x + 0.5, y + 0.25, 1.0));
  return box;
}

// The sample cell's two obstacles and `far` boxes 300 to 800 inches away, as the resource
// test's many-obstacle environment.
Environment sample_with_far_boxes(int far) {
  Environment environment = io::read_environment_file(ibm7545_file("environment.txt"));
  for (int i = 0; i < far; ++i) {
    environment.obstacles.push_back(box_with_inner_point(300 + 5 * (i % 100), -250 + 5 * (i / 100)));
  }
  return environment;
}

TEST(ObstacleSet, BuildsWhatAnEagerBuildGives) {
  std::vector<HullPoints> obstacles;
  for (int i = 0; i < 5; ++i) obstacles.push_back(box_with_inner_point(3.0 * i, -1.5 * i));
  const ObstacleSet set(obstacles);
  EXPECT_EQ(set.size(), 5);
  EXPECT_EQ(set.built_count(), 0);
  for (int o = 0; o < set.size(); ++o) {
    const auto& points = obstacles[static_cast<std::size_t>(o)].points;
    const auto vertices = geometry::ConvexPolytope::from_points(points).vertices();
    EXPECT_EQ(set.vertices_W(o), vertices);  // the inner point is dropped, order kept
    EXPECT_EQ(set.vertices_W(o).size(), 8u);
    EXPECT_EQ(set.polytope_W(o).vertices(), vertices);
    EXPECT_EQ(set.polytope_W(o).faces().size(), 6u);
    const geometry::CertifiedSphere sphere = geometry::certified_sphere(vertices);
    EXPECT_EQ(set.sphere_W(o).center, sphere.center);
    EXPECT_EQ(set.sphere_W(o).radius_upper, sphere.radius_upper);
    // The box of the input points is the box of the hull's vertices.
    const geometry::Aabb box = geometry::Aabb::of_points(vertices);
    EXPECT_EQ(set.index().box(o).lo, box.lo);
    EXPECT_EQ(set.index().box(o).hi, box.hi);
    EXPECT_EQ(set.built_count(), o + 1);
  }
  EXPECT_THROW(set.vertices_W(5), std::out_of_range);
}

TEST(ObstacleSet, ThreadsSharingTheSetSeeOneBuild) {
  std::vector<HullPoints> obstacles;
  for (int i = 0; i < 200; ++i) obstacles.push_back(box_with_inner_point(2.0 * i, 0.0));
  const ObstacleSet set(obstacles);
  std::vector<const geometry::ConvexPolytope*> seen[2];
  std::vector<std::thread> threads;
  for (auto& polytopes : seen) {
    threads.emplace_back([&set, &polytopes] {
      for (int o = 0; o < set.size(); ++o) polytopes.push_back(&set.polytope_W(o));
    });
  }
  for (std::thread& thread : threads) thread.join();
  EXPECT_EQ(seen[0], seen[1]);  // the same objects: each built once
  EXPECT_EQ(set.built_count(), 200);
}

TEST(ObstacleSet, ProbesAmongFarObstaclesBuildOnlyTheNearOnes) {
  const RobotModel robot = io::read_robot_file(ibm7545_file("robot.txt"));
  const Environment environment = sample_with_far_boxes(2000);
  CellSettings settings;
  settings.tolerance = 0.5;
  const RobotCell cell(robot, environment, settings);
  ASSERT_EQ(cell.obstacles().size(), 2002);
  EXPECT_EQ(cell.obstacles().built_count(), 0);  // the broadphase alone is built up front
  std::mt19937_64 rng(22);
  std::set<int> decided;
  CellProbe probe(cell);
  for (int k = 0; k < 200; ++k) {
    ProbeResult result;
    probe.probe(test::random_configuration(robot, rng), /*with_points=*/false, result);
    for (const PairEvidence& evidence : result.evidence) decided.insert(evidence.obstacle);
  }
  // Only the sample's two obstacles are ever within reach; every obstacle built was decided.
  EXPECT_EQ(decided, (std::set<int>{0, 1}));
  EXPECT_EQ(cell.obstacles().built_count(), 2);
}

}  // namespace
}  // namespace grpvss::certify
