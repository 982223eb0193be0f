#pragma once
/// \file
/// \brief A convex hull as the thesis stores it: the list of its points, in some frame.
///
/// Only the convex hull of the points matters (the thesis's Figure 7 vertex order is kept for
/// drawing the wireframe, never for geometry). The thesis uses 16 points per hull; GRPVSS
/// accepts any number >= 4 that spans 3-D.

#include <string>
#include <vector>

#include <Eigen/Core>

namespace grpvss {

/// \brief The points of one convex hull, in the frame named by the owner (link frame L for
/// robot hulls, world frame W for obstacles).
struct HullPoints {
  std::vector<Eigen::Vector3d> points;
  /// 1-based line in the input file where the hull's first point stands (for messages).
  int source_line = 0;
  /// The URDF link whose `<collision>` it is (robot hulls of URDF robots); empty otherwise.
  std::string name;
};

}  // namespace grpvss
