// Lengths that look like the wrong unit (docs/cell-format.md#unit-warnings): a cell is
// checked in metres against kLargestPlausibleLengthMetres and kSmallestPlausibleCellMetres.
#include <algorithm>
#include <string>

#include <fmt/core.h>

#include "cell_sections.hpp"
#include "grpvss/io/cell_file.hpp"
#include "grpvss/io/length_unit.hpp"

namespace grpvss::io {
namespace {

// The largest size of a shape (cell units); 0 for shapes whose size is in another file.
double largest_size(const CellObstacle& obstacle) {
  switch (obstacle.shape) {
    case CellObstacle::Shape::kBox: return obstacle.box_size.maxCoeff();
    case CellObstacle::Shape::kCylinder: return std::max(2.0 * obstacle.radius, obstacle.length);
    case CellObstacle::Shape::kSphere: return 2.0 * obstacle.radius;
    case CellObstacle::Shape::kMesh:
    case CellObstacle::Shape::kThesisEnvironment: return 0.0;
  }
  return 0.0;
}

bool has_size(const CellObstacle& obstacle) { return largest_size(obstacle) > 0.0; }

class UnitSizeCheck {
 public:
  UnitSizeCheck(CellYaml& yaml, const CellDescription& cell) : yaml_(yaml), cell_(cell) {}

  // One length (cell units) of the item `what` on `line`: warned about when too large.
  void length(double value, const std::string& what, int line) {
    const double metres = value * cell_.metres_per_unit;
    if (metres > largest_metres_) {
      largest_metres_ = metres;
      largest_value_ = value;
    }
    if (metres <= kLargestPlausibleLengthMetres || warned_line_ == line) return;
    warned_line_ = line;
    yaml_.warn_at(line, fmt::format("{} {} {} ({} m) is more than a robot cell's {} m: are the "
                                    "numbers in another unit than `units: {}`?",
                                    what, value, unit(), metres, kLargestPlausibleLengthMetres, unit()));
  }

  // After every length: the whole cell smaller than a robot.
  void finish(bool any_size) {
    if (!any_size || largest_metres_ >= kSmallestPlausibleCellMetres) return;
    yaml_.warn_at(cell_.units_line,
                  fmt::format("the largest length of the cell, {} {} ({} m), is less than a robot "
                              "cell's {} m: are the numbers in another unit than `units: {}`?",
                              largest_value_, unit(), largest_metres_,
                              kSmallestPlausibleCellMetres, unit()));
  }

 private:
  std::string unit() const { return std::string(length_unit_name(cell_.units)); }

  CellYaml& yaml_;
  const CellDescription& cell_;
  double largest_metres_ = 0.0;
  double largest_value_ = 0.0;  // the same length in cell units
  int warned_line_ = -1;
};

}  // namespace

void warn_about_unit_sizes(CellYaml& yaml, const CellDescription& cell) {
  UnitSizeCheck check(yaml, cell);
  const CellRobot& robot = cell.robot;
  check.length(robot.base.xyz.cwiseAbs().maxCoeff(), "robot.base: a position of", robot.base.line);
  check.length(robot.tool.xyz.cwiseAbs().maxCoeff(), "robot.tool: a position of", robot.tool.line);
  bool any_size = false;
  for (const CellObstacle& obstacle : cell.obstacles) {
    const std::string what = fmt::format("obstacle '{}'", obstacle.name);
    check.length(largest_size(obstacle), what + ": a size of", obstacle.line);
    check.length(obstacle.pose.xyz.cwiseAbs().maxCoeff(), what + ": a position of", obstacle.line);
    any_size = any_size || has_size(obstacle);
  }
  check.finish(any_size);
}

}  // namespace grpvss::io
