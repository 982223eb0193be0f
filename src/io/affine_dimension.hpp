#pragma once
/// \file
/// \brief The exact dimension of the affine hull of a point set, used to reject hulls whose
/// points are all coincident, collinear or coplanar (they have no interior).

#include <vector>

#include <Eigen/Core>

namespace grpvss::io {

/// \brief Dimension of the affine hull of `points`: -1 (no points), 0 (all coincident),
/// 1 (collinear), 2 (coplanar) or 3.
///
/// Decided EXACTLY: every coordinate is an integer multiple of one power of two
/// \f$2^{e}\f$ (the smallest exponent among the coordinates), so after scaling by
/// \f$2^{-e}\f$ the cross products and orientation determinants are evaluated in
/// boost::multiprecision::cpp_int without any rounding.
int affine_dimension(const std::vector<Eigen::Vector3d>& points);

/// \brief True iff affine_dimension(points) == 3, i.e. the convex hull has positive volume.
inline bool spans_3d(const std::vector<Eigen::Vector3d>& points) {
  return affine_dimension(points) == 3;
}

}  // namespace grpvss::io
