#pragma once
/// \file
/// \brief Checks of a TriangleMesh before it becomes convex pieces: hard input errors
/// (validate_mesh) and the combinatorial structure the decomposition modes depend on
/// (mesh_topology): vertices welded by exact coordinates, edge use, connected groups.

#include <array>
#include <optional>
#include <string>
#include <vector>

#include <Eigen/Core>

#include "grpvss/model/triangle_mesh.hpp"

namespace grpvss::geometry {

/// \brief Throws grpvss::InputError(mesh.source, 0, expected, found) naming the vertex or
/// triangle index for: no triangles; a vertex index outside 0..N-1; a NaN or infinite
/// coordinate; |coordinate| > 1e6 model units (a unit or scale mistake); a `triangle_part`
/// list that does not give every triangle a valid part (when part_names is non-empty).
/// Everything else (open, non-manifold, degenerate, flat) is handled by the modes.
void validate_mesh(const TriangleMesh& mesh);

/// \brief One edge, for messages: the triangle it was first seen in and the edge's two
/// input vertex indices.
struct MeshEdgeExample {
  int triangle = -1;
  int from = -1;
  int to = -1;
};

/// \brief Combinatorics of a validated mesh after welding vertices with identical
/// coordinates (STL files repeat every vertex per triangle).
///
/// An edge is an unordered pair of welded vertices; it is *used* once by every
/// non-degenerate triangle having it as a side. Degenerate triangles (zero area) bound
/// nothing and are left out of the edge counts (proofs/shape-containment.md#solid); they
/// still join groups and are covered like every triangle.
struct MeshTopology {
  /// weld[v]: welded id of input vertex v; welded_points[id]: its coordinates.
  std::vector<int> weld;
  std::vector<Eigen::Vector3d> welded_points;
  /// first_input[id]: the smallest input vertex index welded into id (for messages).
  std::vector<int> first_input;
  /// The mesh's triangles in welded ids (same order as TriangleMesh::triangles).
  std::vector<std::array<int, 3>> triangles;
  /// degenerate[t]: triangle t repeats a welded vertex or its corners are exactly collinear.
  std::vector<char> degenerate;
  int degenerate_count = 0;
  /// Edges used an odd number of times (the mesh is not closed), by exactly one triangle
  /// (open), by more than two (non-manifold), twice in the same direction (misoriented).
  int odd_edges = 0, open_edges = 0, nonmanifold_edges = 0, misoriented_edges = 0;
  std::optional<MeshEdgeExample> first_open_edge, first_nonmanifold_edge, first_misoriented_edge;
  /// Input vertices used by no triangle (ignored by every mode).
  int unused_vertices = 0;

  /// Every edge used an even number of times: the triangles form a closed surface (a
  /// mod-2 cycle) and bound a solid (proofs/shape-containment.md#solid).
  bool closed() const { return odd_edges == 0; }
  /// Every edge used exactly twice, in opposite directions.
  bool closed_and_oriented() const {
    return open_edges == 0 && nonmanifold_edges == 0 && misoriented_edges == 0 && odd_edges == 0;
  }
};

/// \brief Welds, classifies every edge and marks degenerate triangles (exact tests).
/// Precondition: validate_mesh(mesh) passed.
MeshTopology mesh_topology(const TriangleMesh& mesh);

/// \brief Triangle groups: the connected components of the given triangles (indices into
/// the mesh), two triangles being connected when they share a welded vertex — and, when
/// \p by_part is set and the mesh has named parts, belong to the same part. Each group lists
/// triangle indices in increasing order; groups are ordered by their first triangle.
std::vector<std::vector<int>> connected_triangle_groups(const TriangleMesh& mesh,
                                                        const MeshTopology& topology,
                                                        const std::vector<int>& triangles,
                                                        bool by_part);

/// \brief True iff every edge is used an even number of times by the group's triangles.
bool group_is_closed(const TriangleMesh& mesh, const MeshTopology& topology,
                     const std::vector<int>& group);

/// \brief Why the group's triangles are not a closed, consistently oriented, edge- and
/// vertex-manifold surface without degenerate triangles (what the `exact` mode needs),
/// or nullopt when they are. The text names a triangle or vertex (input indices).
std::optional<std::string> oriented_manifold_problem(const TriangleMesh& mesh,
                                                     const MeshTopology& topology,
                                                     const std::vector<int>& group);

}  // namespace grpvss::geometry
