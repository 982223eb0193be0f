#include "grpvss/report/scene_json.hpp"

#include <random>
#include <set>
#include <stdexcept>

#include <Eigen/Geometry>
#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include "grpvss/io/environment_file.hpp"
#include "grpvss/io/robot_file.hpp"
#include "support/data_paths.hpp"
#include "support/kinematics_reference.hpp"

namespace grpvss::report {
namespace {

using nlohmann::json;

using grpvss::test::kIbm7545Data;

struct Ibm7545 {
  RobotModel robot = io::read_robot_file(kIbm7545Data + "robot.txt");
  Environment environment = io::read_environment_file(kIbm7545Data + "environment.txt");
};

/// Three steps at random joint values (fixed seed) plus the home configuration as start.
certify::VerificationResult result_with_steps(const RobotModel& robot) {
  certify::VerificationResult result;
  result.tolerance = 0.5;
  std::mt19937 random(20261121);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  for (int index = 1; index <= 3; ++index) {
    certify::StepRecord step;
    step.index = index;
    step.q.resize(robot.joint_count());
    for (int j = 0; j < robot.joint_count(); ++j) {
      const Joint& joint = robot.joints[static_cast<std::size_t>(j)];
      step.q[j] = joint.minimum + unit(random) * (joint.maximum - joint.minimum);
    }
    result.steps.push_back(step);
  }
  certify::StepRecord start;
  start.q.resize(robot.joint_count());
  for (int j = 0; j < robot.joint_count(); ++j) start.q[j] = robot.joints[static_cast<std::size_t>(j)].home;
  result.start = start;
  return result;
}

// The run's cell (result_with_steps() has tolerance 0.5).
certify::RobotCell cell_of(const Ibm7545& cell, geometry::OffsetShape shape) {
  return certify::RobotCell(cell.robot, cell.environment, {0.5, shape});
}

Eigen::Vector3d vec(const json& v) { return {v[0].get<double>(), v[1].get<double>(), v[2].get<double>()}; }

TEST(SceneJson, HoldsEveryHullObstacleAndStepOfTheIbm7545) {
  const Ibm7545 cell;
  const auto result = result_with_steps(cell.robot);
  const json scene =
      scene_to_json(result, cell_of(cell, geometry::OffsetShape::kRhombicuboctahedron));
  ASSERT_EQ(scene["links"].size(), cell.robot.links.size());
  std::size_t hulls = 0;
  for (std::size_t link = 0; link < cell.robot.links.size(); ++link) {
    EXPECT_EQ(scene["links"][link]["link"], static_cast<int>(link));
    EXPECT_EQ(scene["links"][link]["hulls"].size(), cell.robot.links[link].hulls.size());
    hulls += scene["links"][link]["hulls"].size();
  }
  EXPECT_EQ(hulls, 11u);  // data/ibm7545/robot.txt
  EXPECT_EQ(scene["obstacles"].size(), 2u);
  EXPECT_EQ(scene["steps"].size(), 3u);
  EXPECT_EQ(scene["expansion"]["shape"], "rhombicuboctahedron");
  EXPECT_GE(scene["expansion"]["radius"].get<double>(), 0.5);
  EXPECT_LT(scene["expansion"]["radius"].get<double>(), 0.5 + 1e-9);
}

TEST(SceneJson, HullVerticesAreInputPointsAndFacesAreClosedSurfaces) {
  const Ibm7545 cell;
  const json scene = scene_to_json(result_with_steps(cell.robot), cell_of(cell, geometry::OffsetShape::kCube));
  EXPECT_EQ(scene["expansion"]["shape"], "cube");
  const auto check_polytope = [](const json& polytope, const char* key,
                                 const std::vector<Eigen::Vector3d>& input) {
    const json& vertices = polytope[key];
    // Euler: V - E + F = 2 for a closed convex surface, every edge used by two face loops.
    EXPECT_EQ(vertices.size() - polytope["edges"].size() + polytope["faces"].size(), 2u);
    std::multiset<std::pair<int, int>> directed;
    for (const json& face : polytope["faces"]) {
      for (std::size_t k = 0; k < face.size(); ++k) {
        directed.insert({face[k].get<int>(), face[(k + 1) % face.size()].get<int>()});
      }
    }
    for (const json& edge : polytope["edges"]) {
      EXPECT_EQ(directed.count({edge[0].get<int>(), edge[1].get<int>()}), 1u);
      EXPECT_EQ(directed.count({edge[1].get<int>(), edge[0].get<int>()}), 1u);
    }
    if (input.empty()) return;
    for (const json& v : vertices) {
      bool found = false;
      for (const auto& p : input) found = found || p == vec(v);  // bit for bit
      EXPECT_TRUE(found) << v.dump();
    }
  };
  for (std::size_t link = 0; link < cell.robot.links.size(); ++link) {
    for (std::size_t h = 0; h < cell.robot.links[link].hulls.size(); ++h) {
      const json& hull = scene["links"][link]["hulls"][h];
      EXPECT_EQ(hull["hull"], static_cast<int>(h));
      check_polytope(hull, "vertices_L", cell.robot.links[link].hulls[h].points);
      check_polytope(hull["expanded"], "vertices_L", {});
    }
  }
  for (std::size_t o = 0; o < cell.environment.obstacles.size(); ++o) {
    check_polytope(scene["obstacles"][o], "vertices_W", cell.environment.obstacles[o].points);
  }
}

TEST(SceneJson, ExpandedHullContainsEveryRawVertexPushedOutByTheRadius) {
  const Ibm7545 cell;
  const json scene = scene_to_json(result_with_steps(cell.robot), cell_of(cell, geometry::OffsetShape::kRhombicuboctahedron));
  const double radius = scene["expansion"]["radius"].get<double>();
  std::mt19937 random(7);
  std::normal_distribution<double> normal;
  for (const json& link : scene["links"]) {
    for (const json& hull : link["hulls"]) {
      const json& expanded = hull["expanded"];
      std::vector<Eigen::Vector3d> ev;
      for (const json& v : expanded["vertices_L"]) ev.push_back(vec(v));
      for (const json& v : hull["vertices_L"]) {
        Eigen::Vector3d direction(normal(random), normal(random), normal(random));
        // 0.999 r: the check below is in double; the exact containment is proven elsewhere.
        const Eigen::Vector3d p = vec(v) + 0.999 * radius * direction.normalized();
        for (const json& face : expanded["faces"]) {
          const Eigen::Vector3d a = ev[face[0].get<std::size_t>()];
          const Eigen::Vector3d b = ev[face[1].get<std::size_t>()];
          const Eigen::Vector3d c = ev[face[2].get<std::size_t>()];
          const Eigen::Vector3d n = (b - a).cross(c - a).normalized();  // outward (CCW)
          EXPECT_LE(n.dot(p - a), 1e-9);
        }
      }
    }
  }
}

TEST(SceneJson, StepPosesAreRowMajorForwardKinematicsOfTheStepJointValues) {
  const Ibm7545 cell;
  const auto result = result_with_steps(cell.robot);
  const json scene =
      scene_to_json(result, cell_of(cell, geometry::OffsetShape::kCube));
  const auto expect_poses = [&](const json& poses, const Eigen::VectorXd& q) {
    ASSERT_EQ(poses.size(), cell.robot.links.size());
    for (std::size_t link = 0; link < poses.size(); ++link) {
      const Eigen::Matrix4d reference =
          test::reference_link_pose<double>(cell.robot, q, static_cast<int>(link));
      ASSERT_EQ(poses[link].size(), 16u);
      for (int r = 0; r < 4; ++r) {
        for (int c = 0; c < 4; ++c) {
          EXPECT_NEAR(poses[link][4 * r + c].get<double>(), reference(r, c), 1e-12)
              << "link " << link << " (" << r << "," << c << ")";
        }
      }
    }
  };
  for (std::size_t k = 0; k < result.steps.size(); ++k) {
    EXPECT_EQ(scene["steps"][k]["step"], result.steps[k].index);
    expect_poses(scene["steps"][k]["X_WL"], result.steps[k].q);
  }
  EXPECT_EQ(scene["start"]["step"], 0);
  expect_poses(scene["start"]["X_WL"], result.start->q);
}

TEST(SceneJson, IsDeterministicAndRejectsWrongJointCounts) {
  const Ibm7545 cell;
  auto result = result_with_steps(cell.robot);
  const auto render = [&] {
    return scene_to_json(result, cell_of(cell, geometry::OffsetShape::kCube)).dump();
  };
  EXPECT_EQ(render(), render());
  result.steps[1].q.resize(2);
  EXPECT_THROW(render(), std::logic_error);
}

}  // namespace
}  // namespace grpvss::report
