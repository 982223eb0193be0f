#pragma once
/// \file
/// \brief The rounding bound of a left-to-right product of rigid transforms, each stored with
/// a known error (Lemma 1 of proofs/fk-rounding.md, as a reusable accumulator), and the product
/// itself computed in the order the lemma assumes.

#include <Eigen/Geometry>

#include "grpvss/kinematics/kinematic_chain.hpp"

namespace grpvss::kinematics {

/// \brief A stored rigid factor \f$\hat T = (\hat R, \hat t)\f$ with
/// \f$\|\hat R - R\|_2 \le\f$ delta and \f$\|\hat t - t\|_2 \le\f$ tau against the exact factor
/// \f$T = (R, t)\f$ it denotes (R exactly orthogonal).
struct BoundedFactor {
  Eigen::Isometry3d X = Eigen::Isometry3d::Identity();
  double delta = 0.0;
  double tau = 0.0;
};

/// \brief \f$\hat P_k = \mathrm{fl}(\hat P_{k-1}\hat T_k)\f$ from \f$\hat P_0 = I\f$, with the
/// bounds (R), (E), (T) of proofs/fk-rounding.md#fk-rounding on its error.
/// proof: proofs/fk-rounding.md#fk-rounding
class BoundedProduct {
 public:
  /// P <- fl(P * factor.X); the bounds follow (R), (E), (T).
  void multiply(const BoundedFactor& factor);

  const Eigen::Isometry3d& X() const { return X_; }
  /// Bound r on the spectral norm of (stored rotation - exact rotation).
  double rotation_error() const { return r_; }
  /// Bound e on |stored translation - exact translation|.
  double translation_error() const { return e_; }
  /// Bound T on |stored translation|.
  double translation_norm() const { return T_; }
  /// The bounds as a FixedTransformError, doubled to cover their evaluation in double
  /// (proof: proofs/fk-rounding.md#evaluating-the-bound).
  FixedTransformError error() const { return {2 * r_, 2 * e_}; }
  /// (P): bound on |fl(R^ p + t^) - (R p + t)| for a stored point p with |p|_2 <= p_norm,
  /// doubled for its evaluation in double.
  double point_bound(double p_norm) const;

 private:
  Eigen::Isometry3d X_ = Eigen::Isometry3d::Identity();
  double r_ = 0.0;
  double e_ = 0.0;
  double T_ = 0.0;
};

}  // namespace grpvss::kinematics
