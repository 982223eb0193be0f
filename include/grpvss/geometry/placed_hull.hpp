#pragma once
/// \file
/// \brief A convex hull given in its link frame under a rigid placement, for queries that
/// visit only the placed points they need instead of placing every vertex first.

#include <cstddef>
#include <vector>

#include <Eigen/Core>
#include <Eigen/Geometry>

#include "grpvss/geometry/directed_rounding.hpp"
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

/// \brief An enclosure of \f$m = \hat R^T n\f$ for a placement's rotation \f$\hat R\f$ (in
/// real arithmetic): `lower` = RD of each component, and m_k - lower_k <= spread for every k,
/// with spread >= the sum of the components' enclosure widths (so |m - lower|_2 <= spread too).
struct RotatedNormal {
  Eigen::Vector3d lower;
  double spread = 0.0;
};

/// \brief RotatedNormal of `n` under `X` (each component a rounded dot product of a column of
/// R with n). Needs an active UpwardRoundingScope. proof: proofs/fast-path.md#placed-separation
/// (step 1)
inline RotatedNormal rotated_normal(const Eigen::Isometry3d& X, const Eigen::Vector3d& n) {
  namespace r = rounding;
  const auto& M = X.matrix();
  RotatedNormal m;
  for (int k = 0; k < 3; ++k) {
    const double column[3] = {M(0, k), M(1, k), M(2, k)};
    m.lower[k] = r::dot_down(column, n.data());
    m.spread = r::add_up(m.spread, r::sub_up(r::dot_up(column, n.data()), m.lower[k]));
  }
  return m;
}

/// \brief Largest |coordinate| of \p points (exact: a maximum of absolute values), 0 if empty.
double max_abs_coordinate(const std::vector<Eigen::Vector3d>& points);

}  // namespace grpvss::geometry
