// The YAML path (docs/input-formats.md#yaml-path): joint targets and absolute end-effector
// poses with declared units, in the world or the robot's base frame; every defect named with
// the file and line. The robot is the IBM 7545 (joints R, R, P, R), placed in a model in mm.
#include <cmath>
#include <string>

#include <Eigen/Geometry>
#include <gtest/gtest.h>

#include "grpvss/io/path_file.hpp"
#include "grpvss/io/robot_file.hpp"
#include "support/input_error_expectations.hpp"

namespace grpvss::io {
namespace {

using grpvss::testing::expect_input_error;

const RobotModel& ibm7545_robot() {
  static const RobotModel robot =
      read_robot_file(std::string(GRPVSS_SOURCE_DIR) + "/data/ibm7545/robot.txt");
  return robot;
}

const double kPiFromAcos = std::acos(-1.0);

PathPlacement in_millimetres(const Eigen::Isometry3d& X_WR = Eigen::Isometry3d::Identity()) {
  return PathPlacement{LengthUnit::kMillimetre, X_WR};
}

PathProgram parse_yaml_text(const std::string& text, const PathPlacement& placement = in_millimetres()) {
  return parse_path_file(text, "p.yaml", ibm7545_robot(), placement);
}

// The rotation of a target (axis-angle as stored) as a matrix.
Eigen::Matrix3d rotation_of(const WorldTarget& target) {
  return Eigen::AngleAxisd(target.angle, target.axis_W.normalized()).toRotationMatrix();
}

TEST(YamlPath, JointTargetsAndSpeedsAreConvertedFromTheDeclaredUnits) {
  const PathProgram program = parse_yaml_text(
      "units: {length: m, angle: deg}\n"
      "segments:\n"
      "  - ptp: {joints: [90, -45, 0.25, 180], speed: [30, 60, 0.5, 90]}\n"
      "  - ptp: {joints: [0, 0, 0, 0], speed: 45}\n");
  ASSERT_EQ(program.segments.size(), 2u);
  const auto& first = std::get<PtpJointSegment>(program.segments[0].spec);
  EXPECT_EQ(program.segments[0].source_line, 3);
  EXPECT_EQ(first.target, Eigen::Vector4d(kPiFromAcos / 2, -kPiFromAcos / 4, 250.0, kPiFromAcos));
  EXPECT_EQ(first.velocity, Eigen::Vector4d(kPiFromAcos / 6, kPiFromAcos / 3, 500.0, kPiFromAcos / 2));
  const auto& second = std::get<PtpJointSegment>(program.segments[1].spec);
  EXPECT_EQ(second.velocity, Eigen::Vector4d(kPiFromAcos / 4, kPiFromAcos / 4, 45000.0, kPiFromAcos / 4));
}

TEST(YamlPath, RpyQuaternionAndAxisAngleGiveTheSameAbsoluteOrientation) {
  // Rot_z(90°) Rot_y(0) Rot_x(180°) = the half turn about (1, 1, 0)/√2.
  const PathProgram program = parse_yaml_text(
      "units: {length: mm, angle: deg}\n"
      "segments:\n"
      "  - lin: {pose: {xyz: [400, 100, 300], rpy: [180, 0, 90]}}\n"
      "  - lin: {pose: {xyz: [400, 100, 300], quaternion: {w: 0, x: 0.7071067811865476, y: 0.7071067811865476, z: 0}}}\n"
      "  - lin: {pose: {xyz: [400, 100, 300], axis_angle: [1, 1, 0, 180]}}\n"
      "  - lin: {pose: {xyz: [400, 100, 300]}}\n");
  Eigen::Matrix3d expected;
  expected << 0, 1, 0, 1, 0, 0, 0, 0, -1;
  for (int s = 0; s < 3; ++s) {
    const WorldTarget& target = std::get<CpLineSegment>(program.segments[s].spec).target;
    EXPECT_TRUE(target.orientation_is_absolute) << s;
    EXPECT_EQ(target.position_W, Eigen::Vector3d(400, 100, 300)) << s;
    EXPECT_LT((rotation_of(target) - expected).norm(), 1e-15) << s << "\n" << rotation_of(target);
  }
  const WorldTarget& kept = std::get<CpLineSegment>(program.segments[3].spec).target;
  EXPECT_FALSE(kept.orientation_is_absolute);
  EXPECT_EQ(kept.angle, 0.0);
}

TEST(YamlPath, BaseFramePosesArePlacedThroughTheRobotsBase) {
  Eigen::Isometry3d X_WR = Eigen::Isometry3d::Identity();
  X_WR.translate(Eigen::Vector3d(100, 0, 800));
  X_WR.rotate(Eigen::AngleAxisd(kPiFromAcos / 2, Eigen::Vector3d::UnitZ()));
  const PathProgram program = parse_yaml_text(
      "units: {length: m, angle: rad}\n"
      "segments:\n"
      "  - ptp: {pose: {xyz: [0.5, 0, 0.25], axis_angle: [0, 0, 1, 0.5], frame: base}, speed: 1}\n",
      in_millimetres(X_WR));
  const WorldTarget& target = std::get<PtpWorldSegment>(program.segments[0].spec).target;
  EXPECT_LT((target.position_W - Eigen::Vector3d(100, 500, 1050)).norm(), 1e-12);
  EXPECT_TRUE(target.orientation_is_absolute);
  EXPECT_LT((rotation_of(target) -
             Eigen::AngleAxisd(kPiFromAcos / 2 + 0.5, Eigen::Vector3d::UnitZ()).toRotationMatrix()).norm(),
            1e-15);
}

TEST(YamlPath, DefectsAreNamedWithFileLineAndExpectation) {
  const std::string units = "units: {length: mm, angle: deg}\n";
  expect_input_error([] { parse_yaml_text("segments: []\n"); }, "p.yaml", 1,
                     "p.yaml:1: expected the path: the key 'units', found a mapping without it");
  expect_input_error([] { parse_yaml_text("units: {length: mm, angle: grad}\nsegments: []\n"); }, "p.yaml", 1,
                     "p.yaml:1: expected units.angle: deg or rad, found 'grad'");
  expect_input_error([&] { parse_yaml_text(units + "segments: []\n"); }, "p.yaml", 2,
                     "p.yaml:2: expected segments: a list of at least one segment, found a list of 0 entries");
  expect_input_error([&] { parse_yaml_text(units + "segments:\n  - ptp: {joints: [1, 2, 3], speed: 1}\n"); },
                     "p.yaml", 3,
                     "p.yaml:3: expected segment 1 ptp.joints: a list of 4 numbers (one per joint), found a list of 3 entries");
  expect_input_error(
      [&] { parse_yaml_text(units + "segments:\n  - lin: {pose: {xyz: [1, 2, 3], rpy: [0, 0, 0], axis_angle: [0, 0, 1, 5]}}\n"); },
      "p.yaml", 3,
      "p.yaml:3: expected segment 1 lin.pose: at most one of rpy, quaternion and axis_angle, found a mapping");
  expect_input_error(
      [&] { parse_yaml_text(units + "segments:\n  - lin: {pose: {xyz: [1, 2, 3], frame: tool}}\n"); }, "p.yaml", 3,
      "p.yaml:3: expected segment 1 lin.pose.frame: world or base, found 'tool'");
  expect_input_error(
      [&] { parse_yaml_text(units + "segments:\n  - ptp: {pose: {xyz: [1, 2, 3]}, speed: 0}\n"); }, "p.yaml", 3,
      "p.yaml:3: expected segment 1 ptp.speed: a number > 0, found '0'");
  expect_input_error(
      [&] { parse_yaml_text(units + "segments:\n  - lin: {pose: {xyz: [1, 2, 3], quaternion: {w: 1, x: 1, y: 0, z: 0}}}\n"); },
      "p.yaml", 3,
      "p.yaml:3: expected segment 1 lin.pose.quaternion: a unit quaternion (norm 1 within 1e-6), norm 1.4142135623730951, found a mapping");
  expect_input_error(
      [&] { parse_path_file(units + "segments:\n  - lin: {pose: {xyz: [1, 2, 3]}}\n", "p.yaml", ibm7545_robot(), {}); },
      "p.yaml", 1,
      "p.yaml:1: expected units.length: a robot with a declared length unit (a cell); thesis robot files take the thesis path format, found 'mm'");
  expect_input_error([&] { parse_yaml_text(units + "segments:\n  - {ptp: {joints: [1, 2, 3, 4], speed: 1}, lin: {pose: {xyz: [1, 2, 3]}}}\n"); },
                     "p.yaml", 3, "p.yaml:3: expected segment 1: exactly one of ptp and lin, found a mapping");
  expect_input_error([&] { parse_yaml_text("units: [\n"); }, "p.yaml", 2,
                     "p.yaml:2: expected well-formed YAML, found end of sequence flow not found");
}

TEST(YamlPath, OnlyYamlNamesAreReadAsYaml) {
  EXPECT_TRUE(is_yaml_path_file_name("a/b.yaml"));
  EXPECT_TRUE(is_yaml_path_file_name("B.YML"));
  EXPECT_FALSE(is_yaml_path_file_name("path.txt"));
  EXPECT_FALSE(is_yaml_path_file_name("yaml"));
}

}  // namespace
}  // namespace grpvss::io
