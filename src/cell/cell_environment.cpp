#include "cell_environment.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <map>
#include <stdexcept>
#include <string>
#include <tuple>

#include <fmt/format.h>

#include "cell_pose.hpp"
#include "grpvss/common/input_error.hpp"
#include "grpvss/exact/circumscribed_shapes.hpp"
#include "grpvss/exact/mesh_decomposition.hpp"
#include "grpvss/io/environment_file.hpp"
#include "grpvss/io/mesh_file.hpp"
#include "grpvss/kinematics/urdf_chain.hpp"
#include "grpvss/common/unit_roundoff.hpp"

namespace grpvss::cell {
namespace {

using kinematics::BoundedPoints;

// The convex pieces of one obstacle in its own frame, model units, each with its error, and
// what the shape's reading warned about (text without the obstacle's name).
struct ShapePieces {
  std::vector<BoundedPoints> pieces;
  std::vector<io::InputWarning> warnings;
};

// Box, cylinder, sphere: polytopes that contain the shape of the (scaled) stored sizes; the
// sizes are the doubles nearest to the decimals (relative u), scaled (2^-51 more).
ShapePieces primitive_pieces(const CellObstacle& obstacle, double scale) {
  BoundedPoints points;
  double extent = 0.0;
  if (obstacle.shape == CellObstacle::Shape::kBox) {
    points.points = geometry::circumscribed_box(obstacle.box_size * scale);
    extent = (obstacle.box_size * scale).cwiseAbs().sum() / 2;
  } else if (obstacle.shape == CellObstacle::Shape::kCylinder) {
    points.points = geometry::circumscribed_cylinder(obstacle.radius * scale, obstacle.length * scale);
    extent = (obstacle.radius + obstacle.length / 2) * scale;
  } else {
    points.points = geometry::circumscribed_sphere(obstacle.radius * scale);
    extent = obstacle.radius * scale;
  }
  // proof: proofs/cell-geometry.md#lemma-geometry-error (decimal and scaling rounding)
  points.error = 4 * kUnitRoundoff * extent + scaling_error(extent, scale);
  return {{points}};
}

geometry::DecomposeMode decompose_mode(MeshDecomposition mode) {
  switch (mode) {
    case MeshDecomposition::kParts: return geometry::DecomposeMode::kParts;
    case MeshDecomposition::kExact: return geometry::DecomposeMode::kExact;
    case MeshDecomposition::kHull: break;
  }
  return geometry::DecomposeMode::kHull;
}

ShapePieces mesh_pieces(const CellObstacle& obstacle, double scale) {
  io::MeshReadOptions read_options;
  read_options.scale = obstacle.scale * scale;
  read_options.scale_is_exact = obstacle.scale_is_exact && scale == 1.0;
  const io::MeshFile mesh = io::read_mesh_file(obstacle.file, read_options);
  geometry::DecompositionOptions options;
  options.mode = decompose_mode(obstacle.decompose);
  const geometry::ConvexPieces convex = geometry::decompose_mesh(mesh.mesh, options);
  ShapePieces pieces;
  for (const geometry::ShapeWarning& warning : convex.warnings) {
    pieces.warnings.push_back({warning.file, warning.line, warning.text});
  }
  if (obstacle.decompose == MeshDecomposition::kHull && convex.volume_ratio) {
    pieces.warnings.push_back({obstacle.file, 0,
                               fmt::format("decompose: hull covers {:.3g} times the mesh's volume "
                                           "(parts or exact cover less)",
                                           *convex.volume_ratio)});
  }
  for (const std::vector<Eigen::Vector3d>& piece : convex.pieces) {
    // The product of two scale factors rounds once more than the reader accounts for.
    const double extra = scaling_error(largest_l1_norm(piece), 2.0);
    pieces.pieces.push_back({piece, mesh.vertex_error + (scale == 1.0 ? 0.0 : extra)});
  }
  return pieces;
}

ShapePieces environment_pieces(const CellObstacle& obstacle, double scale) {
  const Environment environment = io::read_environment_file(obstacle.file);
  ShapePieces pieces;
  for (const HullPoints& hull : environment.obstacles) {
    BoundedPoints points;
    for (const Eigen::Vector3d& p : hull.points) points.points.push_back(p * scale);
    points.error = scaling_error(largest_l1_norm(hull.points), scale);
    pieces.pieces.push_back(std::move(points));
  }
  return pieces;
}

ShapePieces obstacle_pieces(const CellObstacle& obstacle, double scale) {
  switch (obstacle.shape) {
    case CellObstacle::Shape::kMesh: return mesh_pieces(obstacle, scale);
    case CellObstacle::Shape::kThesisEnvironment: return environment_pieces(obstacle, scale);
    default: return primitive_pieces(obstacle, scale);
  }
}

// Primitive shapes reject sizes beyond their limits with std::invalid_argument.
ShapePieces checked_obstacle_pieces(const CellObstacle& obstacle, double scale,
                                    const std::string& cell_file) {
  try {
    return obstacle_pieces(obstacle, scale);
  } catch (const std::invalid_argument& error) {
    throw InputError(cell_file, obstacle.line, "a shape the exact stage accepts",
                     obstacle.name + ": " + error.what());
  }
}

// Everything obstacle_pieces() reads of an obstacle: two obstacles with equal keys have equal
// pieces and warnings (the pose is applied afterwards).
using ShapeKey = std::tuple<int, std::string, std::array<double, 3>, std::array<double, 3>,
                            double, double, bool, int>;

ShapeKey shape_key(const CellObstacle& obstacle) {
  const auto triple = [](const Eigen::Vector3d& v) { return std::array<double, 3>{v.x(), v.y(), v.z()}; };
  return {static_cast<int>(obstacle.shape), obstacle.file, triple(obstacle.box_size),
          triple(obstacle.scale), obstacle.radius, obstacle.length, obstacle.scale_is_exact,
          static_cast<int>(obstacle.decompose)};
}

bool finite_sizes(const CellObstacle& obstacle) {
  return obstacle.box_size.allFinite() && obstacle.scale.allFinite() &&
         std::isfinite(obstacle.radius) && std::isfinite(obstacle.length);
}

// The pieces of each distinct shape, built once per cell: a cell places the same mesh (a
// fixture, a bin) or the same post many times, and reading, decomposing and the exact checks
// of circumscribed shapes are the cost of loading it.
class ShapePiecesOnce {
 public:
  ShapePiecesOnce(double scale, const std::string& cell_file) : scale_(scale), cell_file_(cell_file) {}
  const ShapePieces& of(const CellObstacle& obstacle) {
    // A size that is not finite would compare equal to any key: built (and refused) unkept.
    if (!finite_sizes(obstacle)) {
      unkept_ = checked_obstacle_pieces(obstacle, scale_, cell_file_);
      return unkept_;
    }
    auto [at, inserted] = built_.try_emplace(shape_key(obstacle));
    if (inserted) at->second = checked_obstacle_pieces(obstacle, scale_, cell_file_);
    return at->second;
  }

 private:
  double scale_;
  const std::string& cell_file_;
  std::map<ShapeKey, ShapePieces> built_;
  ShapePieces unkept_;
};

void use_thesis_constants(const CellDescription& cell, Environment& environment) {
  if (cell.thesis_constants) {
    environment.smallest_angle = cell.thesis_constants->smallest_angle;
    environment.smallest_thickness = cell.thesis_constants->smallest_thickness;
    return;
  }
  for (const CellObstacle& obstacle : cell.obstacles) {
    if (obstacle.shape != CellObstacle::Shape::kThesisEnvironment) continue;
    const Environment thesis = io::read_environment_file(obstacle.file);
    environment.smallest_angle = thesis.smallest_angle;
    environment.smallest_thickness = thesis.smallest_thickness;
    return;
  }
}

}  // namespace

Environment load_cell_environment(const CellDescription& cell, double scale,
                                  std::vector<io::InputWarning>& warnings) {
  Environment environment;
  ShapePiecesOnce shapes(scale, cell.source);
  for (const CellObstacle& obstacle : cell.obstacles) {
    const ShapePieces& pieces = shapes.of(obstacle);
    for (const io::InputWarning& warning : pieces.warnings) {
      warnings.push_back({warning.file, warning.line, obstacle.name + ": " + warning.text});
    }
    const ScaledPose pose = scaled_pose(obstacle.pose, scale);
    const kinematics::BoundedProduct X_WO = pose.product();
    for (const BoundedPoints& piece : pieces.pieces) {
      const BoundedPoints placed = kinematics::transform_points(X_WO, piece);
      HullPoints hull;
      hull.points = placed.points;
      hull.source_line = obstacle.line;
      environment.obstacles.push_back(std::move(hull));
      environment.names.push_back(obstacle.name);
      environment.point_error =
          std::max(environment.point_error, placed.error + pose.translation_error);
    }
  }
  use_thesis_constants(cell, environment);
  return environment;
}

}  // namespace grpvss::cell
