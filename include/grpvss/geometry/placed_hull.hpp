#pragma once
/// \file
/// \brief A convex hull given in its link frame under a rigid placement, for queries that
/// visit only the placed points they need instead of placing every vertex first.

#include <cstddef>
#include <vector>

#include <Eigen/Core>
#include <Eigen/Geometry>

#include "grpvss/geometry/hull_skeleton.hpp"

namespace grpvss::geometry {

/// \brief The placed points \f$\mathrm{fl}(\hat X_{WL} v_i)\f$ of a link-frame hull, computed
/// on demand.
///
/// Preconditions the certificates rest on (proofs/fast-path.md#placed-separation):
/// `vertices_L` are the vertices (extreme points) of an exact convex hull and `skeleton` is
/// that hull's edge graph in the same numbering (exact/polytope_skeleton.hpp,
/// `vertex_skeleton`); `max_abs_L` is at least every |coordinate| of `vertices_L`.
struct PlacedHull {
  const std::vector<Eigen::Vector3d>* vertices_L = nullptr;
  const HullSkeleton* skeleton = nullptr;
  Eigen::Isometry3d X_WL = Eigen::Isometry3d::Identity();
  double max_abs_L = 0.0;

  /// Vertex i placed as kinematics::place_points places it.
  Eigen::Vector3d point_W(int i) const { return X_WL * (*vertices_L)[static_cast<std::size_t>(i)]; }
};

/// \brief Vertex count from which the probes climb a hull's template instead of placing every
/// vertex: below it placing is cheaper than the climb and the rounding-mode switches (the
/// thesis's 16-vertex hulls and their 40-60-vertex offsets ran ~25% slower on templates;
/// docs/performance.md#placed-templates).
constexpr std::size_t kTemplateClimbMinVertices = 128;

/// \brief Largest |coordinate| of \p points (exact: a maximum of absolute values), 0 if empty.
double max_abs_coordinate(const std::vector<Eigen::Vector3d>& points);

}  // namespace grpvss::geometry
