#include "grpvss/io/urdf_file.hpp"

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <limits>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "grpvss/common/input_error.hpp"
#include "grpvss/kinematics/urdf_chain.hpp"
#include "support/text_files.hpp"

namespace grpvss::io {
namespace {

const std::string kUrdfRobotsDir = std::string(GRPVSS_SOURCE_DIR) + "/../shared/robots/";
constexpr double kInfinity = std::numeric_limits<double>::infinity();

UrdfReadOptions robot_options(const std::string& package_directory, const std::string& tip = "") {
  UrdfReadOptions options;
  options.package_paths = {package_directory};
  options.use_ros_package_path = false;
  options.tip = tip;
  return options;
}

UrdfReadResult read_ur5e() {
  return read_urdf_file(kUrdfRobotsDir + "ur5e/ur5e.urdf", robot_options(kUrdfRobotsDir + "ur5e"));
}

UrdfReadResult read_panda(double finger = -1.0) {
  UrdfReadOptions options = robot_options(kUrdfRobotsDir + "franka_panda", "panda_hand_tcp");
  if (finger >= 0) options.side_joint_values["panda_finger_joint1"] = finger;
  return read_urdf_file(kUrdfRobotsDir + "franka_panda/panda.urdf", options);
}

std::vector<std::string> joint_names(const RobotDescription& d) {
  std::vector<std::string> names;
  for (const ChainJointDescription& j : d.joints) names.push_back(j.name);
  return names;
}

TEST(UrdfFile, Ur5eIsSixRevoluteJointsFromBaseLinkToTool0WithTheFilesLimits) {
  const RobotDescription d = read_ur5e().description;
  EXPECT_EQ(d.name, "ur5e_robot");
  EXPECT_EQ(d.root_link, "base_link");
  EXPECT_EQ(d.tip_link, "tool0");  // the only leaf reached through a movable joint
  EXPECT_EQ(joint_names(d), (std::vector<std::string>{"shoulder_pan_joint", "shoulder_lift_joint",
                                                       "elbow_joint", "wrist_1_joint",
                                                       "wrist_2_joint", "wrist_3_joint"}));
  for (const ChainJointDescription& j : d.joints) {
    const double limit = j.name == "elbow_joint" ? 3.141592653589793 : 6.283185307179586;
    EXPECT_EQ(j.type, JointType::kRevolute);
    EXPECT_FALSE(j.continuous);
    EXPECT_EQ(j.minimum, -limit) << j.name;
    EXPECT_EQ(j.maximum, limit) << j.name;
    EXPECT_EQ(j.velocity, 3.141592653589793);
    EXPECT_EQ(j.acceleration, kDefaultUrdfAcceleration);
    EXPECT_EQ(j.home, 0.0);
    EXPECT_EQ(j.axis, Eigen::Vector3d(0, 0, 1));
  }
  EXPECT_EQ(d.joints[3].line, 308);  // wrist_1_joint
  EXPECT_TRUE(d.side_joints.empty());
}

TEST(UrdfFile, Ur5eBaseFrameIsCarriedByBaseLinkTurnedHalfAroundZ) {
  const RobotDescription d = read_ur5e().description;
  ASSERT_EQ(d.links.size(), 7u);
  EXPECT_EQ(d.links[0].frame, "base_link");
  EXPECT_EQ(d.links[0].urdf_links, (std::vector<std::string>{"base_link", "base_link_inertia", "base"}));
  // base_link-base_fixed_joint: rpy 0 0 3.141592653589793; cos/sin residues are stored exactly.
  const auto base = kinematics::compose_frame_path(d.links[0].frame_paths[2]);
  EXPECT_EQ(base.X().matrix(), Eigen::Vector4d(-1, -1, 1, 1).asDiagonal().toDenseMatrix());
  EXPECT_EQ(d.links[0].frame_paths[2].size(), 1u);
  EXPECT_EQ(d.links[0].frame_paths[2][0].joint, "base_link-base_fixed_joint");
  EXPECT_EQ(d.links[6].frame, "tool0");
  EXPECT_EQ(d.links[6].urdf_links, (std::vector<std::string>{"wrist_3_link", "flange", "tool0"}));
  // shoulder_pan_joint hangs from base_link_inertia: its fixed joint is merged into X_PJ.
  const FramePath& pan = d.joints[0].parent_to_joint;
  ASSERT_EQ(pan.size(), 2u);
  EXPECT_EQ(pan[0].joint, "base_link-base_link_inertia");
  EXPECT_EQ(pan[1].joint, "shoulder_pan_joint");
  EXPECT_EQ(pan[1].origin.xyz, Eigen::Vector3d(0, 0, 0.1625));
  // Last joint: tool0 sits behind two fixed joints.
  ASSERT_EQ(d.last_child_to_tip.size(), 2u);
  EXPECT_EQ(d.last_child_to_tip[0].joint, "wrist_3-flange");
  EXPECT_EQ(d.last_child_to_tip[1].joint, "flange-tool0");
}

TEST(UrdfFile, Ur5eCollisionMeshesAreResolvedThroughThePackagePathAndReadExactly) {
  const RobotDescription d = read_ur5e().description;
  const std::vector<std::size_t> vertices{212, 702, 998, 534, 597, 677, 73};
  const std::vector<std::string> owners{"base_link_inertia", "shoulder_link", "upper_arm_link",
                                        "forearm_link", "wrist_1_link", "wrist_2_link", "wrist_3_link"};
  for (std::size_t i = 0; i < d.links.size(); ++i) {
    ASSERT_EQ(d.links[i].collisions.size(), 1u);
    const CollisionDescription& c = d.links[i].collisions[0];
    EXPECT_EQ(c.link, owners[i]);
    EXPECT_EQ(c.shape, CollisionShape::kMesh);
    EXPECT_EQ(c.mesh.vertices.size(), vertices[i]);
    EXPECT_EQ(c.mesh_vertex_error, 0.0);  // float32 values, no scale: nothing rounded
    const std::string folder = std::filesystem::path(kUrdfRobotsDir + "ur5e/ur_description/meshes/ur5e/collision/").lexically_normal().string();
    EXPECT_EQ(c.mesh_file.rfind(folder, 0), 0u) << c.mesh_file;
  }
  EXPECT_EQ(d.links[0].collisions[0].line, 128);
  // wrist_3_link's mesh is placed in the tool0 frame: up through both fixed joints, then origin.
  const FramePath& path = d.links[6].collisions[0].link_to_collision;
  ASSERT_EQ(path.size(), 3u);
  EXPECT_EQ(path[0].kind, FrameStep::Kind::kInverseOrigin);
  EXPECT_EQ(path[0].joint, "flange-tool0");
  EXPECT_EQ(path[1].joint, "wrist_3-flange");
  EXPECT_EQ(path[2].kind, FrameStep::Kind::kOrigin);
  EXPECT_EQ(path[2].origin.xyz, Eigen::Vector3d(0, 0, -0.0989));
  EXPECT_EQ(path[2].origin.rpy, Eigen::Vector3d(1.5707963267948966, 0, 0));
}

TEST(UrdfFile, PandaHasSevenJointsTheFilesLimitsAndTheHandOnTheLastLink) {
  const UrdfReadResult result = read_panda();
  const RobotDescription& d = result.description;
  EXPECT_EQ(d.root_link, "panda_link0");
  EXPECT_EQ(d.tip_link, "panda_hand_tcp");
  ASSERT_EQ(d.joint_count(), 7);
  const std::vector<double> lower{-2.8973, -1.7628, -2.8973, -3.0718, -2.8973, -0.0175, -2.8973};
  const std::vector<double> upper{2.8973, 1.7628, 2.8973, -0.0698, 2.8973, 3.7525, 2.8973};
  const std::vector<double> velocity{2.175, 2.175, 2.175, 2.175, 2.61, 2.61, 2.61};
  for (std::size_t i = 0; i < 7; ++i) {
    EXPECT_EQ(d.joints[i].name, "panda_joint" + std::to_string(i + 1));
    EXPECT_EQ(d.joints[i].minimum, lower[i]);
    EXPECT_EQ(d.joints[i].maximum, upper[i]);
    EXPECT_EQ(d.joints[i].velocity, velocity[i]);
  }
  EXPECT_EQ(d.joints[3].home, -0.0698);  // 0 clamped into [-3.0718, -0.0698]
  EXPECT_EQ(d.joints[5].home, 0.0);
  EXPECT_EQ(d.links[7].frame, "panda_hand_tcp");
  EXPECT_EQ(d.links[7].urdf_links,
            (std::vector<std::string>{"panda_link7", "panda_link7_sc", "panda_link8", "panda_hand",
                                      "panda_hand_sc", "panda_hand_tcp", "panda_leftfinger",
                                      "panda_rightfinger"}));
  EXPECT_EQ(d.links[7].collisions.size(), 1u + 6 + 1 + 6 + 4 + 4);
  EXPECT_EQ(d.links[5].collisions.size(), 1u + 6);  // panda_link5 + its _sc capsule pieces
  EXPECT_EQ(d.links[5].collisions[1].shape, CollisionShape::kCylinder);
  EXPECT_EQ(d.links[5].collisions[1].radius, 0.09);
  EXPECT_EQ(d.links[5].collisions[1].length, 0.1);
  EXPECT_EQ(d.links[5].collisions[2].shape, CollisionShape::kSphere);
  ASSERT_EQ(d.side_joints.size(), 2u);
  EXPECT_EQ(d.side_joints[0].name, "panda_finger_joint1");
  EXPECT_EQ(d.side_joints[0].type, JointType::kPrismatic);
  EXPECT_EQ(d.side_joints[0].value, 0.0);
  EXPECT_EQ(d.side_joints[0].carried_by, 7);
  EXPECT_EQ(d.side_joints[1].name, "panda_finger_joint2");
  EXPECT_EQ(d.side_joints[1].mimics, "panda_finger_joint1");
  EXPECT_EQ(d.side_joints[1].value, 0.0);
  EXPECT_TRUE(result.warnings.empty());
}

// The eight corners of a box centred at `centre` with half extents `half`, sorted.
std::vector<Eigen::Vector3d> sorted(std::vector<Eigen::Vector3d> points) {
  std::sort(points.begin(), points.end(), [](const Eigen::Vector3d& a, const Eigen::Vector3d& b) {
    return std::lexicographical_compare(a.data(), a.data() + 3, b.data(), b.data() + 3);
  });
  return points;
}

std::vector<Eigen::Vector3d> box(const Eigen::Vector3d& centre, const Eigen::Vector3d& half) {
  std::vector<Eigen::Vector3d> corners;
  for (int k = 0; k < 8; ++k) {
    corners.push_back(centre + Eigen::Vector3d((k & 1) ? half.x() : -half.x(),
                                               (k & 2) ? half.y() : -half.y(),
                                               (k & 4) ? half.z() : -half.z()));
  }
  return sorted(corners);
}

// The screw-mount boxes (collision 0 of each finger), in the panda_hand_tcp frame: the finger
// joint origin is 0.0584 above the hand, the tcp 0.1034; the left finger slides +y by v, the
// right one (its mimic) -y by v.
void expect_screw_mounts_at(double v) {
  const RobotDescription d = read_panda(v).description;
  EXPECT_EQ(d.side_joints[0].value, v);
  EXPECT_EQ(d.side_joints[1].value, v);
  const Eigen::Vector3d half(0.011, 0.0075, 0.010);
  const double z = 0.0584 + 0.011 - 0.1034;
  for (const auto& [finger_name, sign] :
       {std::pair<std::string, double>{"panda_leftfinger", 1.0},
        std::pair<std::string, double>{"panda_rightfinger", -1.0}}) {
    const std::string& finger = finger_name;  // a lambda cannot capture a structured binding
    const auto it = std::find_if(d.links[7].collisions.begin(), d.links[7].collisions.end(),
                                 [&](const CollisionDescription& c) { return c.link == finger && c.index == 0; });
    ASSERT_NE(it, d.links[7].collisions.end());
    EXPECT_EQ(it->shape, CollisionShape::kBox);
    const kinematics::BoundedPoints placed = kinematics::collision_points_in_link_frame(*it);
    EXPECT_LT(placed.error, 1e-14);
    const auto expected = box(Eigen::Vector3d(0, sign * (0.0185 + v), z), half);
    const auto actual = sorted(placed.points);
    for (std::size_t k = 0; k < 8; ++k) {
      EXPECT_LT((actual[k] - expected[k]).norm(), 1e-15) << finger << " corner " << k << " at " << v;
    }
  }
}

TEST(UrdfFile, PandaFingerBoxesAreClosedByDefaultAndFollowASetValueWithTheMimic) {
  expect_screw_mounts_at(0.0);
  expect_screw_mounts_at(0.03);
}

TEST(UrdfFile, PandaArmOnlyEndsAtLink8) {
  const RobotDescription d =
      read_urdf_file(kUrdfRobotsDir + "franka_panda/panda_arm_only.urdf",
                     robot_options(kUrdfRobotsDir + "franka_panda", "panda_link8"))
          .description;
  EXPECT_EQ(d.joint_count(), 7);
  EXPECT_EQ(d.links[7].frame, "panda_link8");
  EXPECT_EQ(d.links[7].urdf_links, (std::vector<std::string>{"panda_link7", "panda_link7_sc", "panda_link8"}));
  ASSERT_EQ(d.last_child_to_tip.size(), 1u);
  EXPECT_EQ(d.last_child_to_tip[0].origin.xyz, Eigen::Vector3d(0, 0, 0.107));
  EXPECT_TRUE(d.side_joints.empty());
}

// ---- synthetic robots ----------------------------------------------------------------------

std::string joint(const std::string& name, const std::string& type, const std::string& parent,
                  const std::string& child, const std::string& extra = "") {
  return "<joint name=\"" + name + "\" type=\"" + type + "\"><parent link=\"" + parent +
         "\"/><child link=\"" + child + "\"/>" + extra + "</joint>\n";
}

const std::string kLimit = "<limit lower=\"-1\" upper=\"1\" effort=\"1\" velocity=\"2\"/>";

std::string robot(const std::string& body) { return "<robot name=\"r\">\n" + body + "</robot>\n"; }

// base -j1(revolute)-> a -j2(prismatic)-> b
std::string two_joint_body(const std::string& j1_extra = kLimit, const std::string& j2_type = "prismatic") {
  return "<link name=\"base\"/>\n<link name=\"a\"/>\n<link name=\"b\"/>\n" +
         joint("j1", "revolute", "base", "a", j1_extra) +
         joint("j2", j2_type, "a", "b", "<axis xyz=\"1 0 0\"/>" + kLimit);
}

void expect_urdf_error(const std::string& text, const UrdfReadOptions& options, int line,
                  const std::string& message) {
  try {
    (void)parse_urdf(text, "robot.urdf", options);
    ADD_FAILURE() << "no InputError; expected " << message;
  } catch (const InputError& error) {
    EXPECT_EQ(error.file(), "robot.urdf");
    EXPECT_EQ(error.line(), line);
    EXPECT_EQ(std::string(error.what()), message);
  }
}

UrdfReadOptions no_packages() {
  UrdfReadOptions options;
  options.use_ros_package_path = false;
  return options;
}

TEST(UrdfFile, ASyntheticChainHasItsJointsLimitsAndAccelerations) {
  UrdfReadOptions options = no_packages();
  options.accelerations["j2"] = 0.5;
  const RobotDescription d = parse_urdf(robot(two_joint_body()), "robot.urdf", options).description;
  EXPECT_EQ(d.tip_link, "b");
  ASSERT_EQ(d.joint_count(), 2);
  EXPECT_EQ(d.joints[0].type, JointType::kRevolute);
  EXPECT_EQ(d.joints[0].axis, Eigen::Vector3d(1, 0, 0));  // URDF's default axis
  EXPECT_EQ(d.joints[1].type, JointType::kPrismatic);
  EXPECT_EQ(d.joints[0].acceleration, kDefaultUrdfAcceleration);
  EXPECT_EQ(d.joints[1].acceleration, 0.5);
  EXPECT_EQ(d.joints[1].velocity, 2.0);
  EXPECT_EQ(d.joints[1].line, 6);
}

TEST(UrdfFile, ContinuousJointsAreUnlimited) {
  const std::string text = robot("<link name=\"base\"/><link name=\"a\"/>\n" +
                                 joint("spin", "continuous", "base", "a", "<axis xyz=\"0 0 1\"/>"));
  const RobotDescription d = parse_urdf(text, "robot.urdf", no_packages()).description;
  ASSERT_EQ(d.joint_count(), 1);
  EXPECT_TRUE(d.joints[0].continuous);
  EXPECT_EQ(d.joints[0].minimum, -kInfinity);
  EXPECT_EQ(d.joints[0].maximum, kInfinity);
  EXPECT_EQ(d.joints[0].velocity, kInfinity);
  EXPECT_EQ(d.joints[0].home, 0.0);
}

TEST(UrdfFile, EqualLimitsAreReadWithAWarning) {
  const std::string text = robot("<link name=\"base\"/><link name=\"a\"/>\n" +
                                 joint("stuck", "revolute", "base", "a",
                                       "<limit lower=\"0.5\" upper=\"0.5\" effort=\"1\" velocity=\"1\"/>"));
  const UrdfReadResult result = parse_urdf(text, "robot.urdf", no_packages());
  ASSERT_EQ(result.warnings.size(), 1u);
  EXPECT_EQ(result.warnings[0].line, 3);
  EXPECT_EQ(result.warnings[0].text, "joint 'stuck' has equal lower and upper limits: it cannot move");
  EXPECT_EQ(result.description.joints[0].home, 0.5);
}

TEST(UrdfFile, MalformedXmlNamesTheLine) {
  expect_urdf_error("<robot name=\"r\">\n<link name=\"a\">\n</robot>\n", no_packages(), 2,
               "robot.urdf:2: expected well-formed XML, found Error=XML_ERROR_MISMATCHED_ELEMENT "
               "ErrorID=14 (0xe) Line number=2: XMLElement name=link");
}

TEST(UrdfFile, ARootOtherThanRobotIsAnError) {
  expect_urdf_error("<model name=\"r\"/>\n", no_packages(), 1,
               "robot.urdf:1: expected a <robot> root element, found <model>");
}

TEST(UrdfFile, UrdfdomsOwnErrorsAreReported) {
  expect_urdf_error(robot(two_joint_body("")), no_packages(), 0,
               "robot.urdf:0: expected a URDF urdfdom accepts, found Joint [j1] is of type "
               "REVOLUTE but it does not specify limits");
}

TEST(UrdfFile, AJointToAMissingLinkIsAnError) {
  const std::string text = robot("<link name=\"base\"/>\n" + joint("j1", "revolute", "base", "ghost", kLimit));
  expect_urdf_error(text, no_packages(), 0,
               "robot.urdf:0: expected a URDF urdfdom accepts, found Failed to build tree: child "
               "link [ghost] of joint [j1] not found");
}

TEST(UrdfFile, FloatingAndPlanarJointsOnTheChainAreErrors) {
  for (const std::string type : {"floating", "planar"}) {
    expect_urdf_error(robot(two_joint_body(kLimit, type)), no_packages(), 6,
                 "robot.urdf:6: expected revolute, continuous, prismatic or fixed joints on the "
                 "chain from 'base' to 'b', found joint 'j2' of type " + type);
  }
}

TEST(UrdfFile, AZeroAxisIsAnError) {
  expect_urdf_error(robot(two_joint_body("<axis xyz=\"0 0 0\"/>" + kLimit)), no_packages(), 5,
               "robot.urdf:5: expected a nonzero <axis xyz> for joint 'j1', each component 0 or "
               "of magnitude within [1e-300, 1e9], found 0 0 0");
}

TEST(UrdfFile, AnAmbiguousTipListsTheLeavesAndAnUnknownTipIsNamed) {
  const std::string text = robot("<link name=\"base\"/><link name=\"a\"/><link name=\"b\"/><link name=\"c\"/>\n" +
                                 joint("j1", "revolute", "base", "a", kLimit) +
                                 joint("j2", "revolute", "a", "b", kLimit) +
                                 joint("j3", "revolute", "a", "c", kLimit));
  expect_urdf_error(text, no_packages(), 0,
               "robot.urdf:0: expected one leaf link reached through movable joints, or a named "
               "tip, found leaves 'b', 'c'");
  UrdfReadOptions options = no_packages();
  options.tip = "d";
  expect_urdf_error(text, options, 0, "robot.urdf:0: expected a tip that is a link of the URDF, found no link 'd'");
  options.tip = "c";
  const RobotDescription d = parse_urdf(text, "robot.urdf", options).description;
  EXPECT_EQ(joint_names(d), (std::vector<std::string>{"j1", "j3"}));
  ASSERT_EQ(d.side_joints.size(), 1u);
  EXPECT_EQ(d.side_joints[0].name, "j2");
  EXPECT_EQ(d.side_joints[0].carried_by, 1);
}

TEST(UrdfFile, NoMovableJointIsAnError) {
  const std::string text = robot("<link name=\"base\"/><link name=\"a\"/>\n" + joint("f", "fixed", "base", "a"));
  expect_urdf_error(text, no_packages(), 0,
               "robot.urdf:0: expected a leaf link reached from the root through a movable joint, found none");
  UrdfReadOptions options = no_packages();
  options.tip = "a";
  expect_urdf_error(text, options, 0,
               "robot.urdf:0: expected a movable joint between the root 'base' and the tip 'a', found none");
}

TEST(UrdfFile, AMimicJointOnTheChainIsAnError) {
  expect_urdf_error(robot(two_joint_body(kLimit + "<mimic joint=\"j2\"/>")), no_packages(), 5,
               "robot.urdf:5: expected chain joints without <mimic> (a mimic joint on the chain "
               "is not supported: choose a tip before it), found joint 'j1' mimics 'j2'");
}

// base -j1-> a; a -s1(prismatic, side)-> s; a -s2(mimic of s1, side)-> t; a -j2-> tip
std::string side_body(const std::string& mimic) {
  return "<link name=\"base\"/><link name=\"a\"/><link name=\"s\"/><link name=\"t\"/><link name=\"tip\"/>\n" +
         joint("j1", "revolute", "base", "a", kLimit) +
         joint("s1", "prismatic", "a", "s", "<limit lower=\"0\" upper=\"0.5\" effort=\"1\" velocity=\"1\"/>") +
         joint("s2", "prismatic", "a", "t", "<limit lower=\"0\" upper=\"2\" effort=\"1\" velocity=\"1\"/>" + mimic) +
         joint("j2", "revolute", "a", "tip", kLimit);
}

TEST(UrdfFile, SideJointValuesAreCheckedAgainstLimitsAndNames) {
  UrdfReadOptions options = no_packages();
  options.tip = "tip";
  options.side_joint_values["s1"] = 0.75;
  expect_urdf_error(robot(side_body("")), options, 4,
               "robot.urdf:4: expected a value within [0, 0.5] for joint 's1', found 0.75");
  options.side_joint_values = {{"nope", 0.0}};
  expect_urdf_error(robot(side_body("")), options, 0,
               "robot.urdf:0: expected a movable side-branch joint to set a value for, found no such joint 'nope'");
  options.side_joint_values = {{"j2", 0.0}};
  expect_urdf_error(robot(side_body("")), options, 6,
               "robot.urdf:6: expected a side-branch joint to set a value for, found joint 'j2', which is on the chain");
  options.side_joint_values = {{"s2", 0.1}};
  expect_urdf_error(robot(side_body("<mimic joint=\"s1\"/>")), options, 5,
               "robot.urdf:5: expected a value for the master joint 's1' rather than for its mimic, found a value for joint 's2'");
}

TEST(UrdfFile, MimicSideJointsFollowTheirMasterAndMimicErrorsAreNamed) {
  UrdfReadOptions options = no_packages();
  options.tip = "tip";
  options.side_joint_values["s1"] = 0.25;
  const RobotDescription d =
      parse_urdf(robot(side_body("<mimic joint=\"s1\" multiplier=\"3\" offset=\"0.5\"/>")), "robot.urdf", options)
          .description;
  ASSERT_EQ(d.side_joints.size(), 2u);
  EXPECT_EQ(d.side_joints[1].value, 1.25);
  EXPECT_GT(d.side_joints[1].value_error, 0.0);
  EXPECT_LT(d.side_joints[1].value_error, 1e-15);
  expect_urdf_error(robot(side_body("<mimic joint=\"j1\"/>")), options, 5,
               "robot.urdf:5: expected side-branch joints that mimic side-branch joints (a mimic "
               "of a chain joint is not supported), found joint 's2' mimics chain joint 'j1'");
  expect_urdf_error(robot(side_body("<mimic joint=\"ghost\"/>")), options, 5,
               "robot.urdf:5: expected a movable master joint for <mimic>, found joint 's2' mimics 'ghost'");
  options.side_joint_values["s1"] = 0.5;
  expect_urdf_error(robot(side_body("<mimic joint=\"s1\" multiplier=\"5\" offset=\"0.5\"/>")), options, 5,
               "robot.urdf:5: expected a value within [0, 2] for joint 's2', found 3");
}

TEST(UrdfFile, AccelerationsMustNameChainJointsAndBePositive) {
  UrdfReadOptions options = no_packages();
  options.tip = "tip";
  options.accelerations["s1"] = 1.0;
  expect_urdf_error(robot(side_body("")), options, 4,
               "robot.urdf:4: expected a chain joint to set an acceleration for, found joint 's1', not on the chain");
  options.accelerations = {{"j1", -1.0}};
  expect_urdf_error(robot(side_body("")), options, 3,
               "robot.urdf:3: expected a positive, finite acceleration for joint 'j1', found -1");
}

TEST(UrdfFile, ALinkWithTwoParentsOrAJointCycleIsAnError) {
  const std::string two_parents = robot("<link name=\"base\"/><link name=\"a\"/><link name=\"b\"/>\n" +
                                        joint("j1", "revolute", "base", "a", kLimit) +
                                        joint("j2", "revolute", "base", "b", kLimit) +
                                        joint("j3", "revolute", "a", "b", kLimit));
  expect_urdf_error(two_parents, no_packages(), 5,
               "robot.urdf:5: expected each link to be the child of at most one joint, found link "
               "'b' is the child of joint 'j2' and of joint 'j3'");
  const std::string cycle = robot("<link name=\"base\"/><link name=\"a\"/><link name=\"b\"/>\n" +
                                  joint("j1", "revolute", "a", "b", kLimit) +
                                  joint("j2", "revolute", "b", "a", kLimit));
  expect_urdf_error(cycle, no_packages(), 4,
               "robot.urdf:4: expected joints that form a tree, found a cycle of joints through link 'a'");
}

TEST(UrdfFile, OutOfRangeNumbersAndBadLimitsAreNamed) {
  expect_urdf_error(robot(two_joint_body("<origin xyz=\"0 0 1e10\"/>" + kLimit)), no_packages(), 5,
               "robot.urdf:5: expected <origin xyz> of joint 'j1', each 0 or of magnitude within "
               "[1e-300, 1e9], found 0 0 10000000000");
  expect_urdf_error(robot(two_joint_body("<origin rpy=\"0 0 1e-305\"/>" + kLimit)), no_packages(), 5,
               "robot.urdf:5: expected <origin rpy> of joint 'j1' as three numbers, each 0 or of "
               "magnitude within [1e-300, 1e9], found \"0 0 1e-305\"");
  expect_urdf_error(robot(two_joint_body("<limit lower=\"1\" upper=\"-1\" effort=\"1\" velocity=\"1\"/>")),
               no_packages(), 5,
               "robot.urdf:5: expected limits lower <= upper for joint 'j1', each 0 or of "
               "magnitude within [1e-300, 1e9], found lower 1, upper -1");
}

TEST(UrdfFile, CollisionShapesAreCheckedAndNamed) {
  const std::string text = robot(
      "<link name=\"base\"><collision name=\"plate\"><geometry><box size=\"1 0 1\"/></geometry>"
      "</collision></link>\n<link name=\"a\"/>\n" + joint("j1", "revolute", "base", "a", kLimit));
  expect_urdf_error(text, no_packages(), 2,
               "robot.urdf:2: expected a positive box size in <collision> 0 of link 'base' (at "
               "most 1e9), found 0");
}

// ---- meshes and package paths -----------------------------------------------------------------

void write_tetrahedron(const std::string& path, double size) {
  std::filesystem::create_directories(std::filesystem::path(path).parent_path());
  std::ofstream out(path);
  const std::string s = std::to_string(size);
  out << "solid t\n";
  const char* faces[4][3] = {{"0 0 0", "S 0 0", "0 S 0"}, {"0 0 0", "0 0 S", "S 0 0"},
                             {"0 0 0", "0 S 0", "0 0 S"}, {"S 0 0", "0 0 S", "0 S 0"}};
  for (const auto& face : faces) {
    out << "facet normal 0 0 0\nouter loop\n";
    for (const char* vertex : face) {
      std::string v(vertex);
      for (std::size_t k; (k = v.find('S')) != std::string::npos;) v.replace(k, 1, s);
      out << "vertex " << v << "\n";
    }
    out << "endloop\nendfacet\n";
  }
  out << "endsolid t\n";
}

std::string mesh_robot(const std::string& uri) {
  return robot("<link name=\"base\"><collision><geometry><mesh filename=\"" + uri +
               "\"/></geometry></collision></link>\n<link name=\"a\"/>\n" +
               joint("j1", "revolute", "base", "a", kLimit));
}

// The largest coordinate of the (only) mesh: tells the test tetrahedra apart.
double mesh_size(const UrdfReadResult& result) {
  double size = 0.0;
  for (const Eigen::Vector3d& v : result.description.links[0].collisions[0].mesh.vertices) {
    size = std::max(size, v.cwiseAbs().maxCoeff());
  }
  return size;
}

class UrdfPackagePath : public ::testing::Test {
 protected:
  void SetUp() override {
    root_ = test::make_temporary_directory("urdf-packages");
    for (const auto& [dir, size] : {std::pair<std::string, double>{"A", 1}, {"B", 2}, {"C", 4}}) {
      write_tetrahedron(root_ + "/" + dir + "/pkg/m.stl", size);
    }
    write_tetrahedron(root_ + "/robot/meshes/r.stl", 8);
    previous_ = std::getenv("ROS_PACKAGE_PATH") ? std::getenv("ROS_PACKAGE_PATH") : "";
    setenv("ROS_PACKAGE_PATH", (root_ + "/C").c_str(), 1);
  }
  void TearDown() override {
    setenv("ROS_PACKAGE_PATH", previous_.c_str(), 1);
    std::filesystem::remove_all(root_);
  }
  UrdfReadResult read(const std::string& uri, const std::vector<std::string>& directories, bool ros) {
    UrdfReadOptions options;
    for (const std::string& d : directories) options.package_paths.push_back(root_ + "/" + d);
    options.use_ros_package_path = ros;
    std::ofstream(root_ + "/robot/robot.urdf") << mesh_robot(uri);
    return read_urdf_file(root_ + "/robot/robot.urdf", options);
  }
  std::string root_;
  std::string previous_;
};

TEST_F(UrdfPackagePath, PackageDirectoriesAreSearchedInOrderThenRosPackagePath) {
  // The tetrahedra differ in size: 1 in A, 2 in B, 4 in C (ROS_PACKAGE_PATH).
  EXPECT_EQ(mesh_size(read("package://pkg/m.stl", {"A", "B"}, true)), 1.0);
  EXPECT_EQ(mesh_size(read("package://pkg/m.stl", {"B", "A"}, true)), 2.0);
  EXPECT_EQ(mesh_size(read("package://pkg/m.stl", {}, true)), 4.0);
  EXPECT_EQ(mesh_size(read("package://pkg/m.stl", {"A/pkg"}, true)), 1.0);  // a package folder itself
  const auto result = read("package://pkg/m.stl", {"B"}, true);
  EXPECT_EQ(result.description.links[0].collisions[0].mesh_file, root_ + "/B/pkg/m.stl");
}

TEST_F(UrdfPackagePath, RelativeAndFilePathsAreTakenAgainstTheUrdfFolder) {
  EXPECT_EQ(mesh_size(read("meshes/r.stl", {}, false)), 8.0);
  EXPECT_EQ(mesh_size(read("file://" + root_ + "/A/pkg/m.stl", {}, false)), 1.0);
}

TEST_F(UrdfPackagePath, UnresolvedMeshesNameTheCollisionAndWhatWasTried) {
  try {
    read("package://pkg/m.stl", {}, false);
    ADD_FAILURE() << "no error";
  } catch (const InputError& error) {
    EXPECT_EQ(error.line(), 2);
    EXPECT_EQ(error.expected(), "mesh 'package://pkg/m.stl' of <collision> 0 of link 'base' to resolve to a file");
    EXPECT_EQ(error.found(), "no package directories (--package-path, package_paths, ROS_PACKAGE_PATH)");
  }
  try {
    read("package://other/m.stl", {"A"}, false);
    ADD_FAILURE() << "no error";
  } catch (const InputError& error) {
    EXPECT_EQ(error.found(), "no file among '" + root_ + "/A/other/m.stl'");
  }
  try {
    read("meshes/missing.stl", {}, false);
    ADD_FAILURE() << "no error";
  } catch (const InputError& error) {
    EXPECT_EQ(error.found(), "no file among '" + root_ + "/robot/meshes/missing.stl'");
  }
}

}  // namespace
}  // namespace grpvss::io
