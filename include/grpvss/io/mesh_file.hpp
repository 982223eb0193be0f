#pragma once
/// \file
/// \brief Reader of triangle-mesh files (binary and ASCII STL, COLLADA .dae, Wavefront .obj)
/// through assimp. Format notes, units and messages: docs/urdf.md#meshes.
///
/// Vertices are the file's float32 values converted exactly to double; the file's node
/// transforms (COLLADA nodes, its `<unit meter>`) and `scale` are applied in double, and the
/// rounding of that arithmetic is bounded (MeshFile::vertex_error,
/// proof: proofs/urdf-frames.md#mesh-vertices).

#include <string>

#include <Eigen/Core>

#include "grpvss/model/triangle_mesh.hpp"

namespace grpvss::io {

/// \brief How to read a mesh.
struct MeshReadOptions {
  /// Per-axis scale applied to every vertex after the file's own transforms (URDF
  /// `<mesh scale>`). Every component must be finite and nonzero.
  Eigen::Vector3d scale = Eigen::Vector3d::Ones();
  /// True when `scale` holds exactly the intended numbers; false when it is the double nearest
  /// to a decimal (then a relative error of 2^-53 per component is included in vertex_error).
  bool scale_is_exact = true;
  /// COLLADA `<up_axis>`: false (default) keeps the file's coordinates as they are, as rviz,
  /// Gazebo and MoveIt do for robot meshes; true turns the file's up axis onto +z.
  /// The `<unit meter>` is always applied.
  bool apply_collada_up_axis = false;
};

/// \brief A mesh as read, with the bound on its arithmetic.
struct MeshFile {
  TriangleMesh mesh;  ///< vertices deduplicated by exact position; every triangle kept
  /// Bound on |vertex - exact vertex| (Euclidean, in the mesh's unit after scaling) for every
  /// vertex; the exact vertex is the real-number value of scale * (file transforms) * (the
  /// float32 coordinates). 0 when there is nothing to round (no transform, exact scale).
  double vertex_error = 0.0;
};

/// Largest accepted mesh: vertices and triangles (each).
inline constexpr std::size_t kMaxMeshElements = std::size_t{20} * 1000 * 1000;

/// \brief Reads a mesh file (`.stl`, `.dae`, `.obj`, any case).
/// \throws InputError(path, 0, expected, found) when the file is missing, not a regular file,
/// too large, of another type, unreadable for assimp, holds no triangle, or has a coordinate
/// or transform entry that is not finite (or a non-affine COLLADA node transform).
MeshFile read_mesh_file(const std::string& path, const MeshReadOptions& options = {});

}  // namespace grpvss::io
