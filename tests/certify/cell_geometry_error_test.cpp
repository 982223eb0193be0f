// proofs/cell-geometry.md#lemma-geometry-error: a cell whose geometry rounds (a URDF robot on
// a turned base, a rotated obstacle) gets a placement error of at least twice the FK bound
// plus both point errors, and its axis radii grow by the hull point error.
#include <filesystem>
#include <fstream>
#include <string>

#include <gtest/gtest.h>

#include "grpvss/cell/load_cell.hpp"
#include "grpvss/certify/motion_bound.hpp"
#include "grpvss/certify/robot_cell.hpp"
#include "grpvss/kinematics/fk_error_bound.hpp"

namespace {

const std::string kRobots = std::string(GRPVSS_SOURCE_DIR) + "/../shared/robots/";

grpvss::cell::LoadedCell ur5e_cell() {
  const std::filesystem::path directory =
      std::filesystem::temp_directory_path() / "grpvss-cell-geometry-error";
  std::filesystem::create_directories(directory);
  const std::string file = (directory / "cell.yaml").string();
  std::ofstream(file) << "units: m\nrobot:\n  urdf: " << kRobots << "ur5e/ur5e.urdf\n"
                      << "  package_paths: [" << kRobots << "ur5e]\n"
                      << "  base: {xyz: [0, 0, 0.8], rpy: [0, 0, 0.3]}\nobstacles:\n"
                      << "  - {name: block, box: [0.2, 0.2, 0.2], pose: {xyz: [0.6, 0.1, 1.0], "
                         "rpy: [0.1, 0.2, 0.3]}}\n";
  grpvss::cell::LoadedCell cell = grpvss::cell::load_cell(file);
  std::filesystem::remove_all(directory);
  return cell;
}

TEST(CellGeometryError, PlacementErrorCoversTheGeometryErrors) {
  const grpvss::cell::LoadedCell cell = ur5e_cell();
  ASSERT_GT(cell.robot.hull_point_error, 0.0);
  ASSERT_GT(cell.environment.point_error, 0.0);
  EXPECT_EQ(cell.environment.names, std::vector<std::string>{"block"});
  grpvss::certify::CellSettings settings;
  settings.tolerance = 0.005;
  const grpvss::certify::RobotCell robot_cell(cell.robot, cell.environment, settings);
  const double largest = grpvss::certify::largest_link_coordinate(robot_cell.hulls());
  const double fk = grpvss::kinematics::forward_kinematics_error_bound(robot_cell.chain(), largest);
  EXPECT_GE(robot_cell.placement_error(),
            2 * (fk + cell.robot.hull_point_error + cell.environment.point_error));
  // Without the geometry errors the bound would be smaller: they are really added.
  EXPECT_GT(robot_cell.placement_error(), 2 * fk * (1 + 1e-9));
}

TEST(CellGeometryError, AxisRadiiGrowByTheHullPointError) {
  grpvss::cell::LoadedCell cell = ur5e_cell();
  const grpvss::certify::HullRadiusTable with_error(cell.robot);
  const double error = cell.robot.hull_point_error;
  cell.robot.hull_point_error = 0.0;
  const grpvss::certify::HullRadiusTable without_error(cell.robot);
  for (int link = 1; link < with_error.link_count(); ++link) {
    for (int hull = 0; hull < with_error.hull_count(link); ++hull) {
      for (int joint = 1; joint <= link; ++joint) {
        EXPECT_GE(with_error.radius(link, hull, joint),
                  without_error.radius(link, hull, joint) + error * (1 - 1e-9))
            << "link " << link << " joint " << joint;
      }
    }
  }
}

}  // namespace
