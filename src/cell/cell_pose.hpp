#pragma once
/// \file
/// \brief A cell file's pose as bounded rigid factors (proofs/rigid-product bounds), in model
/// units, with the bound on what the unit conversion rounds
/// (proofs/cell-geometry.md#lemma-geometry-error).

#include <string>
#include <vector>

#include "grpvss/kinematics/rigid_product_bound.hpp"
#include "grpvss/model/cell_description.hpp"

namespace grpvss::cell {

/// \brief X = Trans(xyz * scale) R, R from rpy (URDF's Rot_z Rot_y Rot_x) or a quaternion.
struct ScaledPose {
  std::vector<kinematics::BoundedFactor> factors;          ///< X, left to right
  std::vector<kinematics::BoundedFactor> inverse_factors;  ///< X^-1, left to right
  /// Bound on |stored translation - exact translation| added by the scaling (0 when scale
  /// is 1: the translation is then the double nearest to the file's decimals, as in URDF).
  double translation_error = 0.0;
  bool identity = true;  ///< no translation, no rotation

  kinematics::BoundedProduct product() const;
  kinematics::BoundedProduct inverse_product() const;
};

/// \brief The pose in model units (`scale` model units per cell unit).
ScaledPose scaled_pose(const CellPose& pose, double scale);

/// \brief R of a quaternion (w, x, y, z), nonzero, as written, with an exact a-posteriori
/// bound on |R^ - R|_2 for the exact rotation of the quaternion's decimals.
/// proof: proofs/cell-geometry.md#lemma-quaternion-rotation
kinematics::BoundedFactor quaternion_rotation(const Eigen::Vector4d& wxyz);

/// Bound on the rounding of x * scale for every listed coordinate: 2^-50 |x|_1 per point
/// (the factor's rounding and the product's), 0 when scale is exactly 1.
double scaling_error(double largest_l1_norm, double scale);

/// Largest |p|_1 over the points.
double largest_l1_norm(const std::vector<Eigen::Vector3d>& points);

}  // namespace grpvss::cell
