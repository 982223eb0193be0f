// The independent FK check of URDF robots: every collision vertex of the UR5e and the Panda,
// placed by make_chain(description) + forward_kinematics + place_hull_points, against forward
// kinematics written in the test from the URDF's own rules (support/urdf_reference.hpp: tinyxml2,
// decimal strings, long double or 50 digits), at random configurations within the limits.
#include <algorithm>
#include <cstdio>
#include <random>
#include <string>
#include <vector>

#include <boost/multiprecision/cpp_bin_float.hpp>
#include <gtest/gtest.h>

#include "grpvss/io/urdf_file.hpp"
#include "grpvss/kinematics/fk_error_bound.hpp"
#include "grpvss/kinematics/forward_kinematics.hpp"
#include "grpvss/kinematics/urdf_chain.hpp"
#include "support/data_paths.hpp"
#include "support/urdf_reference.hpp"

namespace grpvss::kinematics {
namespace {

using Float50 = boost::multiprecision::cpp_bin_float_50;

using grpvss::test::kSharedRobots;

struct UrdfCase {
  std::string urdf;
  std::string package_directory;
  std::string tip;
};

UrdfCase ur5e_urdf_case() { return {kSharedRobots + "ur5e/ur5e.urdf", kSharedRobots + "ur5e", ""}; }
UrdfCase panda() { return {kSharedRobots + "franka_panda/panda.urdf", kSharedRobots + "franka_panda", "panda_hand_tcp"}; }
UrdfCase panda_arm() {
  return {kSharedRobots + "franka_panda/panda_arm_only.urdf", kSharedRobots + "franka_panda", "panda_link8"};
}

RobotDescription read_urdf_case(const UrdfCase& robot, double finger) {
  io::UrdfReadOptions options;
  options.tip = robot.tip;
  options.package_paths = {robot.package_directory};
  options.use_ros_package_path = false;
  if (robot.tip == "panda_hand_tcp") options.side_joint_values["panda_finger_joint1"] = finger;
  return io::read_urdf_file(robot.urdf, options).description;
}

// Collision-frame points of any collision: the mesh's vertices, the box's corners, six points
// on the axes of a cylinder or sphere (their frame is what the chain places).
BoundedPoints frame_points(const CollisionDescription& c) {
  if (c.shape == CollisionShape::kMesh || c.shape == CollisionShape::kBox) return collision_frame_points(c);
  const double h = c.shape == CollisionShape::kCylinder ? c.length / 2 : c.radius;
  return {{{c.radius, 0, 0}, {-c.radius, 0, 0}, {0, c.radius, 0}, {0, -c.radius, 0}, {0, 0, h}, {0, 0, -h}}, 0.0};
}

// What Workspace and place_hull_points need: N joints and N+1 links whose hulls are the
// link-frame points of every collision (DH parameters unused).
struct PlacedRobot {
  RobotModel model;
  std::vector<std::vector<const CollisionDescription*>> collisions;  // [link][hull]
  std::vector<std::vector<BoundedPoints>> points_C;                   // [link][hull]
  std::vector<std::vector<double>> link_errors;                       // [link][hull]
};

PlacedRobot placed_robot(const RobotDescription& d) {
  PlacedRobot robot;
  for (const ChainJointDescription& j : d.joints) {
    Joint joint;
    joint.type = j.type;
    joint.minimum = j.minimum;
    joint.maximum = j.maximum;
    robot.model.joints.push_back(joint);
  }
  for (const ChainLinkDescription& l : d.links) {
    Link link;
    robot.collisions.emplace_back();
    robot.points_C.emplace_back();
    robot.link_errors.emplace_back();
    for (const CollisionDescription& c : l.collisions) {
      const BoundedPoints points_C = frame_points(c);
      const BoundedPoints points_L = place_in_link_frame(c, points_C);
      link.hulls.push_back({points_L.points, c.line});
      robot.collisions.back().push_back(&c);
      robot.points_C.back().push_back(points_C);
      robot.link_errors.back().push_back(points_L.error);
    }
    robot.model.links.push_back(link);
  }
  return robot;
}

double max_abs_coordinate(const RobotModel& model) {
  double c = 0.0;
  for (const Link& link : model.links) {
    for (const HullPoints& hull : link.hulls) {
      for (const Eigen::Vector3d& p : hull.points) c = std::max(c, p.cwiseAbs().maxCoeff());
    }
  }
  return c;
}

template <typename S>
std::map<std::string, S> reference_values(const test::ReferenceUrdf& urdf, const RobotDescription& d,
                                          const Eigen::VectorXd& q) {
  std::map<std::string, S> set;
  for (std::size_t i = 0; i < d.joints.size(); ++i) set[d.joints[i].name] = S(q[static_cast<Eigen::Index>(i)]);
  for (const SideJointDescription& side : d.side_joints) {
    if (side.mimics.empty()) set[side.name] = S(side.value);
  }
  return test::joint_values<S>(urdf, set);
}

// World pose of collision c's frame by the URDF rules.
template <typename S>
test::Pose<S> reference_collision_pose(const test::ReferenceUrdf& urdf, const CollisionDescription& c,
                                       const std::map<std::string, S>& values) {
  const test::ReferenceCollision& rc = urdf.collisions.at(c.link).at(static_cast<std::size_t>(c.index));
  return (test::link_pose<S>(urdf, c.link, values) * test::origin_pose<S>(rc.xyz, rc.rpy)).eval();
}

Eigen::VectorXd random_q(const RobotDescription& d, std::mt19937_64& generator) {
  Eigen::VectorXd q(d.joint_count());
  for (int i = 0; i < d.joint_count(); ++i) {
    const ChainJointDescription& j = d.joints[static_cast<std::size_t>(i)];
    q[i] = std::uniform_real_distribution<double>(j.minimum, j.maximum)(generator);
  }
  return q;
}

// Largest |placed vertex - reference vertex| over every collision vertex at `configurations`
// random configurations.
double worst_long_double_difference(const UrdfCase& robot, double finger, int configurations,
                                    std::uint64_t seed, std::size_t& vertices_checked) {
  const RobotDescription d = read_urdf_case(robot, finger);
  const test::ReferenceUrdf urdf = test::read_reference_urdf(robot.urdf);
  const KinematicChain chain = make_chain(d);
  const PlacedRobot placed = placed_robot(d);
  Workspace ws(placed.model);
  std::mt19937_64 generator(seed);
  double worst = 0.0;
  for (int trial = 0; trial < configurations; ++trial) {
    const Eigen::VectorXd q = random_q(d, generator);
    forward_kinematics(chain, q, ws);
    place_hull_points(placed.model, ws);
    const auto values = reference_values<long double>(urdf, d, q);
    for (std::size_t i = 0; i < placed.collisions.size(); ++i) {
      for (std::size_t h = 0; h < placed.collisions[i].size(); ++h) {
        const test::Pose<long double> X = reference_collision_pose<long double>(urdf, *placed.collisions[i][h], values);
        const auto& points_C = placed.points_C[i][h].points;
        for (std::size_t k = 0; k < points_C.size(); ++k) {
          const Eigen::Matrix<long double, 4, 1> p(points_C[k].x(), points_C[k].y(), points_C[k].z(), 1.0L);
          const Eigen::Matrix<long double, 4, 1> reference = X * p;
          const Eigen::Vector3d& mine = ws.hull_points_W[i][h][k];
          long double squared = 0;
          for (int r = 0; r < 3; ++r) squared += (mine[r] - reference[r]) * (mine[r] - reference[r]);
          worst = std::max(worst, static_cast<double>(std::sqrt(squared)));
          ++vertices_checked;
        }
      }
    }
  }
  return worst;
}

TEST(UrdfForwardKinematics, Ur5eEveryCollisionVertexWithin1e12OfTheUrdfRulesAt1000Configurations) {
  std::size_t checked = 0;
  const double worst = worst_long_double_difference(ur5e_urdf_case(), 0.0, 1000, 11, checked);
  std::printf("UR5e: %zu vertex placements, worst difference %.3e m\n", checked, worst);
  EXPECT_EQ(checked, 1000u * (212 + 702 + 998 + 534 + 597 + 677 + 73));
  EXPECT_LE(worst, 1e-12);
  EXPECT_GT(worst, 0.0);  // the comparison sees the double arithmetic
}

TEST(UrdfForwardKinematics, PandaWithHandEveryCollisionVertexWithin1e12At1000Configurations) {
  // 5 finger openings (the right finger follows by <mimic>) x 200 configurations.
  double worst = 0.0;
  std::size_t checked = 0;
  for (int k = 0; k < 5; ++k) {
    worst = std::max(worst, worst_long_double_difference(panda(), 0.01 * k, 200, 20 + k, checked));
  }
  std::printf("Panda + hand: %zu placements, worst difference %.3e m\n", checked, worst);
  EXPECT_LE(worst, 1e-12);
  EXPECT_GT(worst, 0.0);
}

TEST(UrdfForwardKinematics, PandaArmOnlyEveryCollisionVertexWithin1e12At1000Configurations) {
  std::size_t checked = 0;
  const double worst = worst_long_double_difference(panda_arm(), 0.0, 1000, 31, checked);
  std::printf("Panda arm only: %zu placements, worst difference %.3e m\n", checked, worst);
  EXPECT_LE(worst, 1e-12);
  EXPECT_GT(worst, 0.0);
}

// proof: proofs/urdf-frames.md#collision-points with proofs/fk-rounding.md#fk-rounding: every
// world vertex is within forward_kinematics_error_bound(chain, c) + its hull's link-frame error
// of the exact real-number robot of the URDF's decimals (50-digit reference).
void check_certified_bound(const UrdfCase& robot, double finger, int configurations, std::uint64_t seed) {
  const RobotDescription d = read_urdf_case(robot, finger);
  const test::ReferenceUrdf urdf = test::read_reference_urdf(robot.urdf);
  const KinematicChain chain = make_chain(d);
  const PlacedRobot placed = placed_robot(d);
  const double fk_bound = forward_kinematics_error_bound(chain, max_abs_coordinate(placed.model));
  Workspace ws(placed.model);
  std::mt19937_64 generator(seed);
  double worst_ratio = 0.0;
  for (int trial = 0; trial < configurations; ++trial) {
    const Eigen::VectorXd q = random_q(d, generator);
    forward_kinematics(chain, q, ws);
    place_hull_points(placed.model, ws);
    const auto values = reference_values<Float50>(urdf, d, q);
    for (std::size_t i = 0; i < placed.collisions.size(); ++i) {
      for (std::size_t h = 0; h < placed.collisions[i].size(); ++h) {
        const CollisionDescription& c = *placed.collisions[i][h];
        if (c.shape != CollisionShape::kMesh) continue;  // mesh vertices are exact doubles
        const test::Pose<Float50> X = reference_collision_pose<Float50>(urdf, c, values);
        const double bound = fk_bound + placed.link_errors[i][h];
        for (std::size_t k = 0; k < placed.points_C[i][h].points.size(); ++k) {
          const Eigen::Vector3d& p_C = placed.points_C[i][h].points[k];
          Float50 squared = 0;
          for (int r = 0; r < 3; ++r) {
            Float50 exact = X(r, 3);
            for (int col = 0; col < 3; ++col) exact += X(r, col) * Float50(p_C[col]);
            const Float50 difference = Float50(ws.hull_points_W[i][h][k][r]) - exact;
            squared += difference * difference;
          }
          const double error = static_cast<double>(sqrt(squared));
          ASSERT_LE(error, bound) << c.link << " collision " << c.index;
          worst_ratio = std::max(worst_ratio, error / bound);
        }
      }
    }
  }
  std::printf("%s: FK bound %.3e m, worst error / (FK bound + link bound) = %.3e\n",
              d.name.c_str(), fk_bound, worst_ratio);
  EXPECT_GT(worst_ratio, 0.0);
}

TEST(UrdfForwardKinematics, WorldVerticesAreWithinTheCertifiedBoundOfThe50DigitUrdfRobot) {
  check_certified_bound(ur5e_urdf_case(), 0.0, 25, 41);
  check_certified_bound(panda(), 0.03, 25, 42);
  check_certified_bound(panda_arm(), 0.0, 25, 43);
}

}  // namespace
}  // namespace grpvss::kinematics
