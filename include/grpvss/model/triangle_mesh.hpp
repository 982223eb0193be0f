#pragma once
/// \file
/// \brief A triangle mesh as a CAD or robot-description file gives it (STL, DAE, OBJ), before
/// any convex hull or decomposition: the input of geometry/'s certified shape builders.

#include <array>
#include <string>
#include <vector>

#include <Eigen/Core>

namespace grpvss {

/// \brief Vertices and triangles in the mesh's own frame, in the model's length unit (the
/// reader has applied the file's unit and any `scale`).
struct TriangleMesh {
  std::vector<Eigen::Vector3d> vertices;
  /// Vertex indices of each triangle, counter-clockwise seen from outside when the file is
  /// consistently oriented (not assumed by any certified step).
  std::vector<std::array<int, 3>> triangles;
  /// Named parts the file declares (OBJ objects/groups, DAE nodes); empty when it has none.
  std::vector<std::string> part_names;
  /// triangle_part[t]: index into part_names of triangle t (empty when part_names is).
  std::vector<int> triangle_part;
  /// The file it came from, for messages.
  std::string source;
};

}  // namespace grpvss
