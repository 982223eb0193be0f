// proofs/motion-bound.md#lemma-general-axis-radius on real robots: the UR5e and the Panda of
// ../shared/robots, loaded through a cell (base pose included), placed at random
// configurations by the independent URDF forward kinematics of tests/support/urdf_reference
// (tinyxml2 and the URDF rules, no src/ code): every hull point's distance from every joint
// axis before its link stays within the verifier's radius, and the verifier's rounded-up
// radius is never below the checker's exact one.
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <map>
#include <random>
#include <stdexcept>
#include <string>

#include <gtest/gtest.h>

#include "checker/exact_axis_radius.hpp"
#include "grpvss/cell/load_cell.hpp"
#include "grpvss/certify/motion_bound.hpp"
#include "support/urdf_reference.hpp"

namespace {

using grpvss::RobotModel;

const std::string kSharedRobotsDir = std::string(GRPVSS_SOURCE_DIR) + "/../shared/robots/";

struct RealRobot {
  std::string urdf;
  std::string package_folder;
  std::string tip;
};

// A cell around the robot alone (one far obstacle), its base turned and raised.
grpvss::cell::LoadedCell load(const RealRobot& robot, const std::string& directory) {
  const std::string file = directory + "/cell.yaml";
  std::ofstream(file) << "units: m\nrobot:\n  urdf: " << robot.urdf << "\n  package_paths: ["
                      << robot.package_folder << "]\n  tip: " << robot.tip
                      << "\n  base: {xyz: [0.1, -0.2, 0.8], rpy: [0, 0, 0.7]}\n"
                      << "obstacles:\n  - {name: far, box: [0.1, 0.1, 0.1], pose: {xyz: [9, 9, 9]}}\n";
  return grpvss::cell::load_cell(file);
}

using Pose = grpvss::test::Pose<long double>;
using Vector = Eigen::Matrix<long double, 3, 1>;

Pose base_pose() {
  return grpvss::test::origin_pose<long double>("0.1 -0.2 0.8", "0 0 0.7");
}

// Distance of p from the line through `point` along unit `direction`.
long double axis_distance(const Vector& p, const Vector& point, const Vector& direction) {
  const Vector offset = p - point;
  return (offset - direction * direction.dot(offset)).norm();
}

const grpvss::test::ReferenceJoint& reference_joint(const grpvss::test::ReferenceUrdf& urdf,
                                                    const std::string& name) {
  for (const grpvss::test::ReferenceJoint& joint : urdf.joints) {
    if (joint.name == name) return joint;
  }
  throw std::runtime_error("no joint " + name);
}

// Worst ratio distance / radius over random in-limit configurations; fails on any excess.
double worst_ratio(const RealRobot& real, int configurations, std::uint64_t seed) {
  const std::string directory = std::filesystem::temp_directory_path() /
                                ("grpvss-axis-radius-" + std::to_string(seed));
  std::filesystem::create_directories(directory);
  const grpvss::cell::LoadedCell cell = load(real, directory);
  std::filesystem::remove_all(directory);
  const RobotModel& robot = cell.robot;
  const grpvss::certify::HullRadiusTable table(robot);
  const grpvss::test::ReferenceUrdf urdf = grpvss::test::read_reference_urdf(real.urdf);
  std::mt19937_64 generator(seed);
  double worst = 0.0;
  for (int trial = 0; trial < configurations; ++trial) {
    std::map<std::string, long double> values;
    for (const grpvss::Joint& joint : robot.joints) {
      const double low = std::max(joint.minimum, -3.2), high = std::min(joint.maximum, 3.2);
      values[joint.name] = std::uniform_real_distribution<double>(low, high)(generator);
    }
    values = grpvss::test::joint_values(urdf, values);
    for (int link = 1; link < static_cast<int>(robot.links.size()); ++link) {
      const Pose X_WL =
          base_pose() * grpvss::test::link_pose<long double>(urdf, robot.links[link].name, values);
      for (int joint = 1; joint <= link; ++joint) {
        const grpvss::test::ReferenceJoint& reference = reference_joint(urdf, robot.joints[joint - 1].name);
        const Pose X_WJ = base_pose() *
                          grpvss::test::link_pose<long double>(urdf, reference.parent, values) *
                          grpvss::test::origin_pose<long double>(reference.xyz, reference.rpy);
        const Vector axis = grpvss::test::decimal3<long double>(reference.axis);
        const Vector direction = X_WJ.block<3, 3>(0, 0) * axis / axis.norm();
        const Vector point = X_WJ.block<3, 1>(0, 3);
        for (int hull = 0; hull < static_cast<int>(robot.links[link].hulls.size()); ++hull) {
          const double radius = table.radius(link, hull, joint);
          for (const Eigen::Vector3d& p_L : robot.links[link].hulls[hull].points) {
            const Vector p_W = X_WL.block<3, 3>(0, 0) * p_L.cast<long double>() + X_WL.block<3, 1>(0, 3);
            const double distance = static_cast<double>(axis_distance(p_W, point, direction));
            EXPECT_LE(distance, radius) << robot.links[link].name << " hull " << hull << " joint " << joint;
            worst = std::max(worst, distance / radius);
          }
        }
      }
    }
  }
  return worst;
}

const RealRobot kUr5e{kSharedRobotsDir + "ur5e/ur5e.urdf", kSharedRobotsDir + "ur5e", "tool0"};
const RealRobot kPanda{kSharedRobotsDir + "franka_panda/panda_arm_only.urdf", kSharedRobotsDir + "franka_panda",
                       "panda_link8"};

TEST(GeneralAxisRadius, BoundsTheSampledAxisDistanceOfTheUr5eAndPanda) {
  const double ur5e = worst_ratio(kUr5e, 200, 7);
  const double panda = worst_ratio(kPanda, 200, 8);
  std::printf("worst sampled axis distance / radius: UR5e %.3f, Panda %.3f\n", ur5e, panda);
  // The bound is attained by no sample but is not vacuous either.
  EXPECT_GT(ur5e, 0.3);
  EXPECT_GT(panda, 0.3);
}

TEST(GeneralAxisRadius, TableIsNeverBelowTheCheckersExactRadius) {
  for (const RealRobot& real : {kUr5e, kPanda}) {
    const std::string directory = std::filesystem::temp_directory_path() / "grpvss-axis-exact";
    std::filesystem::create_directories(directory);
    const grpvss::cell::LoadedCell cell = load(real, directory);
    std::filesystem::remove_all(directory);
    const grpvss::certify::HullRadiusTable table(cell.robot);
    ASSERT_GT(cell.robot.hull_point_error, 0.0);  // the base pose and mesh placement round
    for (int link = 1; link < static_cast<int>(cell.robot.links.size()); ++link) {
      for (int hull = 0; hull < static_cast<int>(cell.robot.links[link].hulls.size()); ++hull) {
        for (int joint = 1; joint <= link; ++joint) {
          const mpq_class exact = grpvss::certify::exact_axis_radius(
              cell.robot, link, cell.robot.links[link].hulls[hull], joint);
          EXPECT_GE(mpq_class(table.radius(link, hull, joint)), exact)
              << cell.robot.links[link].name << " joint " << joint;
        }
      }
    }
  }
}

}  // namespace
