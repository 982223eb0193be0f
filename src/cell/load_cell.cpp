#include "grpvss/cell/load_cell.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <utility>

#include <fmt/format.h>

#include "cell_allowed_contacts.hpp"
#include "cell_environment.hpp"
#include "cell_robot.hpp"
#include "cell_self_collision.hpp"
#include "grpvss/io/cell_file.hpp"
#include "grpvss/io/length_unit.hpp"

namespace grpvss::cell {
namespace {

double largest_extent(const std::vector<HullPoints>& hulls) {
  double largest = 0.0;
  for (const HullPoints& hull : hulls) {
    for (const Eigen::Vector3d& p : hull.points) largest = std::max(largest, p.cwiseAbs().maxCoeff());
  }
  return largest;
}

// The smallest link hull's largest half-extent (0 without hulls).
std::pair<double, std::string> smallest_link(const RobotModel& robot) {
  double smallest = std::numeric_limits<double>::infinity();
  std::string name;
  for (std::size_t i = 0; i < robot.links.size(); ++i) {
    for (const HullPoints& hull : robot.links[i].hulls) {
      Eigen::Vector3d lo = hull.points.front(), hi = hull.points.front();
      for (const Eigen::Vector3d& p : hull.points) {
        lo = lo.cwiseMin(p);
        hi = hi.cwiseMax(p);
      }
      const double size = (hi - lo).maxCoeff();
      if (size < smallest) {
        smallest = size;
        name = link_label(robot, static_cast<int>(i));
      }
    }
  }
  return {std::isfinite(smallest) ? smallest : 0.0, name};
}

// docs/cell-format.md#unit-warnings: a robot 100x larger or smaller than its cell, or a
// tolerance above the smallest link, is almost always a unit mistake.
void warn_about_sizes(const LoadedCell& cell, std::vector<io::InputWarning>& warnings) {
  double robot_size = 0.0;
  for (const Link& link : cell.robot.links) robot_size = std::max(robot_size, largest_extent(link.hulls));
  for (const Joint& joint : cell.robot.joints) {
    if (joint.frames) {
      robot_size = std::max(robot_size, joint.frames->X_JC.translation().cwiseAbs().maxCoeff());
    }
  }
  const double cell_size = largest_extent(cell.environment.obstacles);
  const std::string unit(io::length_unit_name(cell.model_unit));
  if (robot_size > 0.0 && cell_size > 0.0 &&
      (robot_size > 100.0 * cell_size || cell_size > 100.0 * robot_size)) {
    warnings.push_back({cell.description.source, cell.description.units_line,
                        fmt::format("robot {} reaches {:.4g} {} but the obstacles {:.4g} {}: "
                                    "check the units of the robot and of the cell",
                                    cell.robot.name, robot_size, unit, cell_size, unit)});
  }
  const auto [link_size, link_name] = smallest_link(cell.robot);
  if (cell.tolerance > 0.0 && link_size > 0.0 && cell.tolerance > link_size) {
    warnings.push_back({cell.description.source, cell.description.tolerance_line,
                        fmt::format("tolerance {:.4g} {} is larger than {} ({:.4g} {} across): "
                                    "check its unit",
                                    cell.tolerance, unit, link_name, link_size, unit)});
  }
}

double rounded_up_tolerance(double tolerance, double scale) {
  const double converted = tolerance * scale;
  return scale == 1.0 ? converted
                      : std::nextafter(converted, std::numeric_limits<double>::infinity());
}

}  // namespace

LoadedCell load_cell(CellDescription description, std::vector<io::InputWarning> warnings,
                     const CellLoadOptions& options) {
  LoadedCell cell;
  const bool urdf = description.robot.source == CellRobot::Source::kUrdf;
  cell.model_unit = urdf ? LengthUnit::kMetre : description.units;
  cell.model_units_per_cell_unit = urdf ? description.metres_per_unit : 1.0;
  const double scale = cell.model_units_per_cell_unit;
  cell.robot = load_cell_robot(description, options, scale, warnings);
  cell.environment = load_cell_environment(description, scale, warnings);
  cell.environment.allowed_contacts =
      resolve_allowed_contacts(description, cell.robot, cell.environment, warnings);
  resolve_self_collision(description, cell.robot, warnings);
  if (description.tolerance) cell.tolerance = rounded_up_tolerance(*description.tolerance, scale);
  cell.description = std::move(description);
  warn_about_sizes(cell, warnings);
  cell.warnings = std::move(warnings);
  return cell;
}

LoadedCell load_cell(const std::string& cell_file, const CellLoadOptions& options) {
  io::CellReadResult read = io::read_cell_file(cell_file);
  return load_cell(std::move(read.cell), std::move(read.warnings), options);
}

}  // namespace grpvss::cell
