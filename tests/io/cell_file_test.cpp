#include "grpvss/io/cell_file.hpp"

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "grpvss/common/input_error.hpp"
#include "grpvss/io/length_unit.hpp"
#include "support/data_paths.hpp"
#include "support/input_error_expectations.hpp"

namespace grpvss::io {
namespace {

using grpvss::test::kSourceDir;
const std::string kCells = kSourceDir + "/tests/data/cells";

std::string normal(const std::string& path) {
  return std::filesystem::path(path).lexically_normal().string();
}

// A cell of the structure alone (files are not checked), with one robot line and `rest`.
std::string cell_with(const std::string& rest, const std::string& units = "m") {
  return "units: " + units + "\nrobot: {thesis: robot.txt}\n" + rest;
}

CellReadResult parse_cell_yaml(const std::string& text) { return parse_cell(text, "cell.yaml", false); }

void expect_cell_error(const std::string& text, int line, const std::string& message) {
  SCOPED_TRACE(text);
  testing::expect_input_error([&] { parse_cell_yaml(text); }, "cell.yaml", line, "cell.yaml:" + std::to_string(line) + ": " + message);
}

TEST(CellFile, ThesisCellWithBoxesIsReadToTheLastField) {
  const CellReadResult result = read_cell_file(kCells + "/thesis-boxes.yaml");
  const CellDescription& cell = result.cell;
  EXPECT_TRUE(result.warnings.empty());
  EXPECT_EQ(cell.source, kCells + "/thesis-boxes.yaml");
  EXPECT_EQ(cell.units, LengthUnit::kInch);
  EXPECT_EQ(cell.units_line, 2);
  EXPECT_EQ(cell.metres_per_unit, 0.0254);
  EXPECT_FALSE(cell.metres_per_unit_is_exact);

  const CellRobot& robot = cell.robot;
  EXPECT_EQ(robot.line, 4);
  EXPECT_EQ(robot.source, CellRobot::Source::kThesis);
  EXPECT_EQ(robot.file, normal(kSourceDir + "/data/ibm7545/robot.txt"));
  EXPECT_TRUE(robot.package_paths.empty());
  EXPECT_EQ(robot.srdf, "");
  EXPECT_EQ(robot.tip, "");
  EXPECT_EQ(robot.base.xyz, Eigen::Vector3d(0, 0, 2.5));
  EXPECT_EQ(robot.base.rpy, Eigen::Vector3d(0, 0, 1.5));
  EXPECT_FALSE(robot.base.quaternion.has_value());
  EXPECT_EQ(robot.base.line, 5);
  EXPECT_EQ(robot.tool.xyz, Eigen::Vector3d(0, 0, 0.75));
  EXPECT_EQ(robot.tool.rpy, Eigen::Vector3d::Zero());
  EXPECT_EQ(robot.tool.line, 6);
  ASSERT_TRUE(robot.home.has_value());
  EXPECT_EQ(*robot.home, (std::vector<double>{0, 0.5, -0.5, 0}));
  EXPECT_EQ(robot.home_line, 7);
  EXPECT_EQ(robot.default_acceleration, 4.0);
  EXPECT_TRUE(robot.accelerations.empty());

  ASSERT_EQ(cell.obstacles.size(), 5u);
  const CellObstacle& table = cell.obstacles[0];
  EXPECT_EQ(table.name, "table");
  EXPECT_EQ(table.shape, CellObstacle::Shape::kBox);
  EXPECT_EQ(table.box_size, Eigen::Vector3d(40, 30, 1.5));
  EXPECT_EQ(table.pose.xyz, Eigen::Vector3d(10, 0, -0.75));
  EXPECT_TRUE(table.pose.rpy.isZero(0.0));
  EXPECT_EQ(table.line, 10);
  const CellObstacle& feeder = cell.obstacles[1];
  EXPECT_EQ(feeder.name, "feeder");
  EXPECT_EQ(feeder.shape, CellObstacle::Shape::kBox);
  EXPECT_EQ(feeder.box_size, Eigen::Vector3d(6, 4, 8));
  EXPECT_EQ(feeder.pose.xyz, Eigen::Vector3d(15, 15, 4));
  ASSERT_TRUE(feeder.pose.quaternion.has_value());
  EXPECT_EQ(*feeder.pose.quaternion, Eigen::Vector4d(1, 0, 0, 0));
  EXPECT_EQ(feeder.pose.line, 14);
  EXPECT_FALSE(feeder.pose.is_identity());  // a translation
  EXPECT_EQ(feeder.line, 11);
  const CellObstacle& post = cell.obstacles[2];
  EXPECT_EQ(post.shape, CellObstacle::Shape::kCylinder);
  EXPECT_EQ(post.radius, 1.0);
  EXPECT_EQ(post.length, 12.0);
  EXPECT_EQ(post.pose.xyz, Eigen::Vector3d(-12, 8, 6));
  EXPECT_EQ(post.line, 16);
  const CellObstacle& lamp = cell.obstacles[3];
  EXPECT_EQ(lamp.shape, CellObstacle::Shape::kSphere);
  EXPECT_EQ(lamp.radius, 2.5);
  EXPECT_EQ(lamp.pose.xyz, Eigen::Vector3d(0, -14, 20));
  const CellObstacle& old_cell = cell.obstacles[4];
  EXPECT_EQ(old_cell.name, "thesis_cell");
  EXPECT_EQ(old_cell.shape, CellObstacle::Shape::kThesisEnvironment);
  EXPECT_EQ(old_cell.file, normal(kSourceDir + "/data/ibm7545/environment.txt"));
  EXPECT_TRUE(old_cell.pose.is_identity());
  EXPECT_EQ(old_cell.line, 18);

  ASSERT_EQ(cell.allowed_contacts.size(), 2u);
  EXPECT_EQ(cell.allowed_contacts[0].first, "link0");
  EXPECT_EQ(cell.allowed_contacts[0].second, "table");
  EXPECT_EQ(cell.allowed_contacts[0].line, 20);
  EXPECT_EQ(cell.allowed_contacts[1].first, "link3");
  EXPECT_EQ(cell.allowed_contacts[1].second, "feeder");
  EXPECT_EQ(cell.allowed_contacts[1].line, 21);
  EXPECT_EQ(cell.tolerance, 0.25);
  EXPECT_EQ(cell.tolerance_line, 22);
  EXPECT_EQ(cell.motion.cp_speed, 10.0);
  EXPECT_EQ(cell.motion.cp_spacing, 0.5);
  ASSERT_TRUE(cell.thesis_constants.has_value());
  EXPECT_EQ(cell.thesis_constants->smallest_angle, 0.5);
  EXPECT_EQ(cell.thesis_constants->smallest_thickness, 1.0);
  EXPECT_EQ(cell.thesis_constants->line, 24);
}

TEST(CellFile, UrdfCellWithMeshIsReadToTheLastField) {
  const std::string robots = kSourceDir + "/../shared/robots/ur5e";
  const CellReadResult result = read_cell_file(kCells + "/ur5e-fixture.yaml");
  const CellDescription& cell = result.cell;
  EXPECT_TRUE(result.warnings.empty());
  EXPECT_EQ(cell.units, LengthUnit::kMetre);
  EXPECT_EQ(cell.metres_per_unit, 1.0);
  EXPECT_TRUE(cell.metres_per_unit_is_exact);

  const CellRobot& robot = cell.robot;
  EXPECT_EQ(robot.source, CellRobot::Source::kUrdf);
  EXPECT_EQ(robot.file, normal(robots + "/ur5e.urdf"));
  EXPECT_EQ(robot.package_paths, std::vector<std::string>{normal(robots)});
  EXPECT_EQ(robot.srdf, normal(kCells + "/ur5e-cell.srdf"));
  EXPECT_EQ(robot.tip, "tool0");
  EXPECT_EQ(robot.base.xyz, Eigen::Vector3d(0, 0, 0.8));
  EXPECT_TRUE(robot.base.rpy.isZero(0.0));
  EXPECT_EQ(robot.tool.xyz, Eigen::Vector3d(0, 0, 0.15));
  ASSERT_TRUE(robot.tool.quaternion.has_value());
  EXPECT_EQ(*robot.tool.quaternion, Eigen::Vector4d(0.5, 0.5, 0.5, 0.5));
  EXPECT_EQ(*robot.home, (std::vector<double>{0, -1.5708, 1.5708, 0, 0, 0}));
  EXPECT_EQ(robot.default_acceleration, 5.0);
  ASSERT_EQ(robot.accelerations.size(), 1u);
  EXPECT_EQ(robot.accelerations[0].joint, "shoulder_pan_joint");
  EXPECT_EQ(robot.accelerations[0].value, 2.5);
  EXPECT_EQ(robot.accelerations[0].line, 12);

  ASSERT_EQ(cell.obstacles.size(), 2u);
  EXPECT_EQ(cell.obstacles[0].box_size, Eigen::Vector3d(1.2, 0.8, 0.05));
  EXPECT_EQ(cell.obstacles[0].pose.xyz, Eigen::Vector3d(0.5, 0, 0.775));
  const CellObstacle& bracket = cell.obstacles[1];
  EXPECT_EQ(bracket.name, "bracket");
  EXPECT_EQ(bracket.shape, CellObstacle::Shape::kMesh);
  EXPECT_EQ(bracket.file, normal(kCells + "/l-bracket.stl"));
  EXPECT_EQ(bracket.mesh_units, LengthUnit::kMillimetre);
  EXPECT_EQ(bracket.scale, Eigen::Vector3d::Constant(0.001));  // mm -> m, the nearest double
  EXPECT_FALSE(bracket.scale_is_exact);
  EXPECT_EQ(bracket.decompose, MeshDecomposition::kParts);
  EXPECT_EQ(bracket.pose.xyz, Eigen::Vector3d(0.4, 0.2, 0.8));
  EXPECT_EQ(bracket.pose.rpy, Eigen::Vector3d(0, 0, 3.14159));
  EXPECT_EQ(bracket.line, 15);

  ASSERT_EQ(cell.allowed_contacts.size(), 1u);
  EXPECT_EQ(cell.allowed_contacts[0].first, "base_link_inertia");
  EXPECT_EQ(cell.allowed_contacts[0].second, "table");
  EXPECT_EQ(cell.tolerance, 0.005);
  EXPECT_EQ(cell.motion.cp_speed, 0.25);
  EXPECT_EQ(cell.motion.cp_spacing, 0.01);
  EXPECT_FALSE(cell.thesis_constants.has_value());
}

TEST(CellFile, DefaultsOfAMinimalCell) {
  const CellDescription cell = parse_cell_yaml("units: mm\nrobot: {urdf: r.urdf}\n").cell;
  EXPECT_EQ(cell.units, LengthUnit::kMillimetre);
  EXPECT_EQ(cell.metres_per_unit, 0.001);
  EXPECT_FALSE(cell.metres_per_unit_is_exact);
  EXPECT_EQ(cell.robot.file, "r.urdf");  // the file name has no folder: as written
  EXPECT_TRUE(cell.robot.base.is_identity());
  EXPECT_TRUE(cell.robot.tool.is_identity());
  EXPECT_FALSE(cell.robot.home.has_value());
  EXPECT_FALSE(cell.robot.default_acceleration.has_value());
  EXPECT_TRUE(cell.obstacles.empty());
  EXPECT_TRUE(cell.allowed_contacts.empty());
  EXPECT_FALSE(cell.tolerance.has_value());
  EXPECT_FALSE(cell.motion.cp_speed.has_value());
  EXPECT_FALSE(cell.motion.cp_spacing.has_value());
}

TEST(CellFile, UnitFactorsAreTheNearestDoublesToTheExactRatios) {
  // Reference: Python's Fraction -> float (correctly rounded) of 1/1000, 254/10000, ...
  EXPECT_EQ(length_unit_factor(LengthUnit::kMillimetre, LengthUnit::kMetre), 0.001);
  EXPECT_EQ(length_unit_factor(LengthUnit::kInch, LengthUnit::kMetre), 0.0254);
  EXPECT_EQ(length_unit_factor(LengthUnit::kMetre, LengthUnit::kInch), 39.37007874015748);
  EXPECT_EQ(length_unit_factor(LengthUnit::kMillimetre, LengthUnit::kInch), 0.03937007874015748);
  EXPECT_EQ(length_unit_factor(LengthUnit::kInch, LengthUnit::kMillimetre), 25.4);
  EXPECT_EQ(length_unit_factor(LengthUnit::kMetre, LengthUnit::kMillimetre), 1000.0);
  EXPECT_TRUE(length_unit_factor_is_exact(LengthUnit::kMetre, LengthUnit::kMillimetre));
  EXPECT_TRUE(length_unit_factor_is_exact(LengthUnit::kInch, LengthUnit::kInch));
  EXPECT_FALSE(length_unit_factor_is_exact(LengthUnit::kMillimetre, LengthUnit::kMetre));
  EXPECT_FALSE(length_unit_factor_is_exact(LengthUnit::kInch, LengthUnit::kMillimetre));
  // 0.001 is not 1/1000: 1000 * 0.001 rounds back to 1 but the factor itself is inexact.
  EXPECT_NE(std::fma(1000.0, 0.001, -1.0), 0.0);
  EXPECT_EQ(std::fma(1000.0, 1000.0, -1e6), 0.0);
}

// scale and units of a mesh obstacle, in a cell of `cell_units`.
CellObstacle mesh_with(const std::string& keys, const std::string& cell_units) {
  const CellDescription cell = parse_cell_yaml(cell_with("obstacles:\n  - {name: m, mesh: m.stl" + keys + "}\n", cell_units)).cell;
  return cell.obstacles.at(0);
}

TEST(CellFile, MeshUnitsBecomeAScaleIntoTheCellsUnit) {
  struct Case {
    std::string mesh_units, cell_units;
    double scale;
    bool exact;
  };
  const Case cases[] = {{"mm", "m", 0.001, false},   {"m", "mm", 1000.0, true},
                        {"in", "mm", 25.4, false},   {"in", "m", 0.0254, false},
                        {"mm", "in", 0.03937007874015748, false}, {"mm", "mm", 1.0, true}};
  for (const Case& c : cases) {
    SCOPED_TRACE(c.mesh_units + " in " + c.cell_units);
    const CellObstacle mesh = mesh_with(", units: " + c.mesh_units, c.cell_units);
    EXPECT_EQ(mesh.scale, Eigen::Vector3d::Constant(c.scale));
    EXPECT_EQ(mesh.scale_is_exact, c.exact);
    EXPECT_EQ(mesh.mesh_units, length_unit_from_name(c.mesh_units));
  }
}

TEST(CellFile, ScaleIsExactOnlyForDecimalsThatAreDoubles) {
  struct Case {
    std::string scale;
    Eigen::Vector3d value;
    bool exact;
  };
  const Case cases[] = {{"2", Eigen::Vector3d::Constant(2), true},
                        {"0.5", Eigen::Vector3d::Constant(0.5), true},
                        {"0.125", Eigen::Vector3d::Constant(0.125), true},
                        {"0.001", Eigen::Vector3d::Constant(0.001), false},
                        {"0.1", Eigen::Vector3d::Constant(0.1), false},
                        {"1e-3", Eigen::Vector3d::Constant(0.001), false},  // exponents: not claimed
                        {"[1, 0.25, 4]", Eigen::Vector3d(1, 0.25, 4), true},
                        {"[1, 0.2, 4]", Eigen::Vector3d(1, 0.2, 4), false}};
  for (const Case& c : cases) {
    SCOPED_TRACE(c.scale);
    const CellObstacle mesh = mesh_with(", scale: " + c.scale, "m");
    EXPECT_EQ(mesh.scale, c.value);
    EXPECT_EQ(mesh.scale_is_exact, c.exact);
    EXPECT_FALSE(mesh.mesh_units.has_value());
  }
  // Checked against exact rational arithmetic: 0.125 = 1/8 and 0.1 != 1/10 as doubles.
  EXPECT_EQ(0.125 * 8.0, 1.0);
  EXPECT_NE(std::fma(0.1, 10.0, -1.0), 0.0);
}

TEST(CellFile, ObstaclesOfAnImplausibleSizeWarnAboutTheUnit) {
  const CellReadResult big = parse_cell_yaml(cell_with(
      "obstacles:\n"
      "  - {name: table, box: [2000, 800, 50], pose: {xyz: [500, 0, 775]}}\n"  // 4
      "  - {name: post, cylinder: {radius: 0.05, length: 0.6}}\n"));
  ASSERT_EQ(big.warnings.size(), 1u);
  EXPECT_EQ(big.warnings[0].file, "cell.yaml");
  EXPECT_EQ(big.warnings[0].line, 4);
  EXPECT_EQ(big.warnings[0].text,
            "obstacle 'table': a size of 2000 m (2000 m) is more than a robot cell's 100 m: are the "
            "numbers in another unit than `units: m`?");

  const CellReadResult small = parse_cell_yaml(cell_with(
      "obstacles:\n  - {name: table, box: [1.2, 0.8, 0.05], pose: {xyz: [0.5, 0, 0.775]}}\n", "mm"));
  ASSERT_EQ(small.warnings.size(), 1u);
  EXPECT_EQ(small.warnings[0].line, 1);  // the units line
  EXPECT_EQ(small.warnings[0].text,
            "the largest length of the cell, 1.2 mm (0.0012 m), is less than a robot "
            "cell's 0.05 m: are the numbers in another unit than `units: mm`?");

  const CellReadResult base = parse_cell_yaml("units: mm\nrobot: {thesis: r.txt, base: {xyz: [0, 0, 200000]}}\n");
  ASSERT_EQ(base.warnings.size(), 1u);
  EXPECT_EQ(base.warnings[0].line, 2);
  EXPECT_EQ(base.warnings[0].text,
            "robot.base: a position of 200000 mm (200 m) is more than a robot cell's 100 m: are the "
            "numbers in another unit than `units: mm`?");
}

TEST(CellFile, PlausibleSizesDoNotWarn) {
  // 100 m exactly and 0.05 m exactly are plausible; a cell of meshes only has no sizes.
  EXPECT_TRUE(parse_cell_yaml(cell_with("obstacles:\n  - {name: a, box: [100, 1, 1]}\n")).warnings.empty());
  EXPECT_TRUE(parse_cell_yaml(cell_with("obstacles:\n  - {name: a, box: [50, 10, 10]}\n", "mm")).warnings.empty());
  EXPECT_TRUE(parse_cell_yaml(cell_with("obstacles:\n  - {name: a, mesh: a.stl}\n", "mm")).warnings.empty());
}

TEST(CellFile, AContactListedTwiceWarnsAndIsKeptOnce) {
  const CellReadResult result = parse_cell_yaml(cell_with(
      "obstacles: [{name: table, box: [1, 1, 1]}]\n"
      "allowed_contacts:\n  - [link0, table]\n  - [table, link0]\n"));
  ASSERT_EQ(result.cell.allowed_contacts.size(), 1u);
  ASSERT_EQ(result.warnings.size(), 1u);
  EXPECT_EQ(result.warnings[0].line, 6);
  EXPECT_EQ(result.warnings[0].text, "allowed contact table / link0 is listed twice");
}


TEST(CellFile, SelfCollisionIsOnByDefaultAndTakesTrueOrFalseOnly) {
  EXPECT_TRUE(parse_cell_yaml("units: m\nrobot: {thesis: r.txt}\n").cell.self_collision);
  EXPECT_FALSE(parse_cell_yaml("units: m\nrobot: {thesis: r.txt}\nself_collision: false\n").cell.self_collision);
  expect_cell_error("units: m\nrobot: {thesis: r.txt}\nself_collision: no\n", 3,
               "expected self_collision: true or false, found 'no'");
}

TEST(CellFile, StructureErrorsNameTheLineAndWhatWasExpected) {
  expect_cell_error("units: m\nrobot: {thesis: r.txt}\nobstacle: []\n", 3,
               "expected the cell: a key among units, robot, obstacles, allowed_contacts, tolerance, "
               "motion, thesis_constants, self_collision (did you mean 'obstacles'?), found 'obstacle'");
  expect_cell_error("units: m\nrobot:\n  urdf: r.urdf\n  pacakge_paths: [a]\n", 4,
               "expected robot: a key among urdf, thesis, package_paths, srdf, tip, base, tool, home, "
               "acceleration (did you mean 'package_paths'?), found 'pacakge_paths'");
  expect_cell_error("units: m\nrobot: {thesis: r.txt}\nunits: mm\n", 3,
               "expected the cell: each key once (a second 'units'), found 'units'");
  expect_cell_error("robot: {thesis: r.txt}\n", 1,
               "expected the cell: the key 'units', found a mapping without it");
  expect_cell_error("units: m\n", 1, "expected the cell: the key 'robot', found a mapping without it");
  expect_cell_error("- units\n", 1,
               "expected the cell: a mapping with keys units, robot, obstacles, allowed_contacts, "
               "tolerance, motion, thesis_constants, self_collision, found a list of 1 entry");
  expect_cell_error("", 0, "expected one YAML document (the cell), found none");
  expect_cell_error("~\n", 1,
               "expected the cell: a mapping with keys units, robot, obstacles, allowed_contacts, "
               "tolerance, motion, thesis_constants, self_collision, found nothing");
  expect_cell_error("units: m\nrobot: {thesis: r.txt}\n---\nunits: m\n", 3,
               "expected one YAML document (the cell), found a second document");
  // YAML::LoadAll never returns on this text (each call succeeds without consuming the comma).
  expect_cell_error(",nobot", 1, "expected one YAML document (the cell), found a second document");
}

TEST(CellFile, YamlSyntaxErrorsNameTheirLine) {
  expect_cell_error("units: m\nrobot: {thesis: r.txt\n", 3,
               "expected well-formed YAML, found end of map flow not found");
  expect_cell_error("units: m\nrobot:\n  thesis: r.txt\n tip: [\n", 4,
               "expected well-formed YAML, found end of map not found");
}

TEST(CellFile, UnitErrorsListTheUnits) {
  expect_cell_error("units: metres\nrobot: {thesis: r.txt}\n", 1,
               "expected units: one of m, mm, in (did you mean 'm'?), found 'metres'");
  expect_cell_error("units: cm\nrobot: {thesis: r.txt}\n", 1,
               "expected units: one of m, mm, in, found 'cm'");  // no suggestion: cm is not m
  expect_cell_error("units: [m]\nrobot: {thesis: r.txt}\n", 1,
               "expected units: a non-empty name of at most 256 printable characters, found a list of 1 entry");
  expect_cell_error(cell_with("obstacles:\n  - {name: a, mesh: a.stl, units: feet}\n"), 4,
               "expected units: one of m, mm, in, found 'feet'");
}

TEST(CellFile, RobotErrors) {
  expect_cell_error("units: m\nrobot: {tip: tool0}\n", 2,
               "expected robot: the key 'urdf' or 'thesis' (the robot file), found a mapping without either");
  expect_cell_error("units: m\nrobot:\n  urdf: r.urdf\n  thesis: r.txt\n", 4,
               "expected robot: either urdf or thesis, not both, found 'thesis'");
  expect_cell_error("units: m\nrobot:\n  thesis: r.txt\n  srdf: r.srdf\n", 4,
               "expected robot: 'srdf' only with a urdf robot (a thesis robot file has none), found 'srdf'");
  expect_cell_error("units: m\nrobot:\n  thesis: r.txt\n  home: [0, 1, x]\n", 4,
               "expected robot.home[2]: a finite number, 0 or 1e-300 <= |x| <= 1e9, found 'x'");
  expect_cell_error("units: m\nrobot:\n  thesis: r.txt\n  home: []\n", 4,
               "expected robot.home: a list of 1 to 64 numbers, found a list of 0 entries");
  expect_cell_error("units: m\nrobot:\n  thesis: r.txt\n  acceleration: {default: 0}\n", 4,
               "expected robot.acceleration.default: a number > 0, found '0'");
  expect_cell_error("units: m\nrobot:\n  thesis: r.txt\n  acceleration:\n    j1: 1\n    j1: 2\n", 6,
               "expected robot.acceleration: each joint once ('j1' is also on line 5), found 'j1'");
  expect_cell_error("units: m\nrobot:\n  thesis: r.txt\n  base: {xyz: [0, 0]}\n", 4,
               "expected robot.base.xyz: a list of 3 numbers [x, y, z], found a list of 2 entries");
  expect_cell_error("units: m\nrobot:\n  thesis: r.txt\n  base: {xyz: [0, 0, 1], rpy: [0, 0, 1], quaternion: {w: 1, x: 0, y: 0, z: 0}}\n",
               4, "expected robot.base: either rpy or quaternion, not both, found a mapping");
  expect_cell_error("units: m\nrobot:\n  thesis: r.txt\n  tool:\n    quaternion: {w: 0, x: 0, y: 0, z: 0}\n", 5,
               "expected robot.tool.quaternion: a nonzero quaternion {w, x, y, z}, found a mapping");
  expect_cell_error("units: m\nrobot:\n  thesis: r.txt\n  tool:\n    quaternion: {w: 1, x: 0, y: 0}\n", 5,
               "expected robot.tool.quaternion: the key 'z', found a mapping without it");
}

TEST(CellFile, NumbersMustBeFiniteAndInRange) {
  const std::string expected = "a finite number, 0 or 1e-300 <= |x| <= 1e9";
  for (const std::string text : {".inf", "nan", "inf", "1e10", "1e-320", "0x10", "1,5", "true", "1_000"}) {
    SCOPED_TRACE(text);
    expect_cell_error(cell_with("tolerance: " + text + "\n"), 3,
                 "expected tolerance: " + expected + ", found '" + text + "'");
  }
  expect_cell_error(cell_with("tolerance: ''\n"), 3, "expected tolerance: " + expected + ", found ''");
  expect_cell_error(cell_with("tolerance: -0.1\n"), 3, "expected tolerance: a number > 0, found '-0.1'");
  EXPECT_EQ(parse_cell_yaml(cell_with("tolerance: +1e-3\n")).cell.tolerance, 0.001);
}

TEST(CellFile, ObstacleErrors) {
  expect_cell_error(cell_with("obstacles:\n  - {box: [1, 1, 1]}\n"), 4,
               "expected obstacles[0]: the key 'name', found a mapping without it");
  expect_cell_error(cell_with("obstacles:\n  - {name: a, pose: {xyz: [0, 0, 0]}}\n"), 4,
               "expected obstacle 'a': one shape key among box, cylinder, sphere, mesh, thesis_environment, found none");
  expect_cell_error(cell_with("obstacles:\n  - name: a\n    box: [1, 1, 1]\n    sphere: {radius: 1}\n"), 6,
               "expected obstacle 'a': one shape (it already is a box), found 'sphere'");
  expect_cell_error(cell_with("obstacles:\n  - {name: a, box: [1, 0, 1]}\n"), 4,
               "expected obstacle 'a'.box[1]: a number > 0, found '0'");
  expect_cell_error(cell_with("obstacles:\n  - {name: a, box: [1, -2, 1]}\n"), 4,
               "expected obstacle 'a'.box[1]: a number > 0, found '-2'");
  expect_cell_error(cell_with("obstacles:\n  - {name: a, box: 1}\n"), 4,
               "expected obstacle 'a'.box: a list of 3 sizes [x, y, z], found '1'");
  expect_cell_error(cell_with("obstacles:\n  - name: a\n    cylinder: {radius: 1, lenght: 2}\n"), 5,
               "expected obstacle 'a'.cylinder: a key among radius, length (did you mean 'length'?), found 'lenght'");
  expect_cell_error(cell_with("obstacles:\n  - name: a\n    sphere:\n      radius: -1\n"), 6,
               "expected obstacle 'a'.sphere.radius: a number > 0, found '-1'");
  expect_cell_error(cell_with("obstacles:\n  - {name: a, box: [1, 1, 1], scale: 2}\n"), 4,
               "expected obstacle 'a': 'scale' only with a mesh, found 'scale'");
  expect_cell_error(cell_with("obstacles:\n  - {name: a, thesis_environment: e.txt, pose: {xyz: [0, 0, 1]}}\n"), 4,
               "expected obstacle 'a': no pose with thesis_environment (its hulls are in world "
               "coordinates), found 'pose'");
  expect_cell_error(cell_with("obstacles:\n  - {name: a, mesh: a.stl, scale: 2, units: mm}\n"), 4,
               "expected obstacle 'a': either scale or units, not both, found 'units'");
  expect_cell_error(cell_with("obstacles:\n  - {name: a, mesh: a.stl, scale: [1, 2]}\n"), 4,
               "expected obstacle 'a'.scale: a number > 0 or a list of 3, found a list of 2 entries");
  expect_cell_error(cell_with("obstacles:\n  - {name: a, mesh: a.stl, decompose: convex}\n"), 4,
               "expected obstacle 'a'.decompose: one of hull, parts, exact, found 'convex'");
  expect_cell_error(cell_with("obstacles:\n  - {name: '', box: [1, 1, 1]}\n"), 4,
               "expected obstacles[0].name: a non-empty name of at most 256 printable characters, found ''");
  expect_cell_error(cell_with("obstacles: {name: a}\n"), 3,
               "expected obstacles: a list of at most 100000 obstacles, found a mapping");
}

TEST(CellFile, ObstacleNamesAreUnique) {
  expect_cell_error(cell_with("obstacles:\n"
                         "  - {name: table, box: [1, 1, 1]}\n"      // 4
                         "  - {name: post, sphere: {radius: 1}}\n"  // 5
                         "  - {name: table, sphere: {radius: 1}}\n"),  // 6
               6, "expected obstacle names: each name once ('table' is also the obstacle on line 4), found 'table'");
}

TEST(CellFile, AllowedContactErrors) {
  const std::string obstacles = "obstacles: [{name: table, box: [1, 1, 1]}, {name: post, box: [1, 1, 1]}]\n";
  expect_cell_error(cell_with(obstacles + "allowed_contacts:\n  - {link: link0, obstacle: tabel}\n"), 5,
               "expected allowed_contacts[0].obstacle: the name of one of the cell's obstacles (did you "
               "mean 'table'?), found 'tabel'");
  expect_cell_error(cell_with(obstacles + "allowed_contacts:\n  - [table, post]\n"), 5,
               "expected allowed_contacts[0]: at least one robot link (obstacles never move against each "
               "other), found a list of 2 entries");
  expect_cell_error(cell_with(obstacles + "allowed_contacts:\n  - [link0]\n"), 5,
               "expected allowed_contacts[0]: a pair [NAME, NAME] of link or obstacle names, or {link: L, "
               "obstacle: O}, found a list of 1 entry");
  expect_cell_error(cell_with(obstacles + "allowed_contacts:\n  - [link0, link0]\n"), 5,
               "expected allowed_contacts[0]: two different names (a part always touches itself), found a "
               "list of 2 entries");
  // Link names are checked when the robot is loaded: a pair of unknown names is read.
  EXPECT_EQ(parse_cell_yaml(cell_with(obstacles + "allowed_contacts: [[link0, link1]]\n")).cell.allowed_contacts.size(), 1u);
}

TEST(CellFile, OtherSectionErrors) {
  expect_cell_error(cell_with("motion: {cp_speed: 1, spacing: 2}\n"), 3,
               "expected motion: a key among cp_speed, cp_spacing, found 'spacing'");
  expect_cell_error(cell_with("motion: {cp_spacing: 0}\n"), 3, "expected motion.cp_spacing: a number > 0, found '0'");
  expect_cell_error(cell_with("thesis_constants: {smallest_angle: 4, smallest_thickness: 1}\n"), 3,
               "expected thesis_constants.smallest_angle: an angle in radians, 0 < angle < pi, found '4'");
  expect_cell_error(cell_with("thesis_constants: {smallest_angle: 1}\n"), 3,
               "expected thesis_constants: the key 'smallest_thickness', found a mapping without it");
}

TEST(CellFile, ReferencedFilesMustExist) {
  const std::string name = kCells + "/inline.yaml";
  testing::expect_input_error(
      [&] { parse_cell("units: m\nrobot: {thesis: missing.txt}\n", name); }, name, 2,
      name + ":2: expected robot.thesis: an existing file (a path relative to the cell file's folder, "
             "file:// or package://), found 'missing.txt' (tried: " + kCells + "/missing.txt)");
  testing::expect_input_error(
      [&] {
        parse_cell("units: m\nrobot: {thesis: ../../../data/ibm7545/robot.txt}\n"
                   "obstacles:\n  - {name: f, mesh: cad/f.stl}\n", name);
      },
      name, 4,
      name + ":4: expected obstacle 'f'.mesh: an existing file (a path relative to the cell file's "
             "folder, file:// or package://), found 'cad/f.stl' (tried: " + kCells + "/cad/f.stl)");
  testing::expect_input_error(
      [&] { parse_cell("units: m\nrobot: {urdf: r.urdf, package_paths: [nowhere]}\n", name); }, name, 2,
      name + ":2: expected robot.package_paths[0]: an existing directory (looked at " + kCells +
          "/nowhere), found 'nowhere'");
  testing::expect_input_error([&] { read_cell_file(kCells + "/absent.yaml"); }, kCells + "/absent.yaml", 0,
                              kCells + "/absent.yaml:0: expected a readable file, found No such file or directory");
}

TEST(CellFile, SizeLimitsAreEnforcedBeforeReading) {
  const std::string huge(kMaxCellFileBytes + 1, '#');
  expect_cell_error(huge, 0, "expected a cell file of at most 16777216 bytes, found 16777217 bytes");
  std::string many = cell_with("obstacles: [");
  for (std::size_t i = 0; i <= kMaxCellEntries; ++i) many += "0,";
  many += "0]\n";
  expect_cell_error(many, 3, "expected obstacles: a list of at most 100000 obstacles, found a list of 100002 entries");
}

TEST(CellFile, EveryPrefixOfASampleIsReadOrRejectedWithAnInputError) {
  const std::string text = testing::source_file_text("tests/data/cells/thesis-boxes.yaml");
  // Any other exception escaping fails the test; a rejected prefix names a line it has.
  for (std::size_t length = 0; length < text.size(); ++length) {
    const std::string prefix = text.substr(0, length);
    const int lines = 1 + static_cast<int>(std::count(prefix.begin(), prefix.end(), '\n'));
    try {
      parse_cell(prefix, kCells + "/thesis-boxes.yaml", false);
    } catch (const InputError& error) {
      EXPECT_LE(error.line(), lines) << "prefix of " << length << " bytes: " << error.what();
    }
  }
  EXPECT_EQ(parse_cell(text, kCells + "/thesis-boxes.yaml", false).cell.obstacles.size(), 5u);
}

}  // namespace
}  // namespace grpvss::io
