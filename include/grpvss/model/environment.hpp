#pragma once
/// \file
/// \brief Static obstacles (convex hulls in the world frame W) and the thesis's two
/// environment constants used by its step rule (Eq. 3-3).

#include <vector>

#include "grpvss/model/hull_points.hpp"

namespace grpvss {

struct Environment {
  double smallest_angle = 0.0;      ///< theta of Eq. 3-1, RADIANS, 0 < theta < pi
  double smallest_thickness = 0.0;  ///< L of Eq. 3-2, length units
  std::vector<HullPoints> obstacles;  ///< points in the world frame W
};

}  // namespace grpvss
