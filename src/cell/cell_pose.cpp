#include "cell_pose.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

#include <gmpxx.h>

#include <Eigen/Geometry>

#include "grpvss/kinematics/urdf_chain.hpp"
#include "grpvss/common/unit_roundoff.hpp"

namespace grpvss::cell {
namespace {

using kinematics::BoundedFactor;
using kinematics::BoundedProduct;

// The smallest double s with s^2 >= value (value >= 0, exact).
double sqrt_upper(const mpq_class& value) {
  double s = std::sqrt(value.get_d());
  while (mpq_class(s) * mpq_class(s) < value) s = std::nextafter(s, std::numeric_limits<double>::infinity());
  return s;
}

// Trans(xyz) for the double nearest to each decimal: |xyz^ - xyz| <= u |xyz|_1 (as URDF
// origins, proofs/urdf-frames.md#frame-steps).
BoundedFactor translation_factor(const Eigen::Vector3d& xyz) {
  BoundedFactor factor;
  factor.X.translation() = xyz;
  factor.tau = std::nextafter(kUnitRoundoff * xyz.cwiseAbs().sum() * (1 + 4 * kUnitRoundoff),
                              std::numeric_limits<double>::infinity());
  return factor;
}

BoundedFactor inverse_rotation(const BoundedFactor& rotation) {
  BoundedFactor inverse;
  inverse.X.linear() = rotation.X.linear().transpose();  // exact; |R^T - R_exact^T| = |R - R_exact|
  inverse.delta = rotation.delta;
  return inverse;
}

}  // namespace

BoundedFactor quaternion_rotation(const Eigen::Vector4d& wxyz) {
  Eigen::Quaterniond q(wxyz[0], wxyz[1], wxyz[2], wxyz[3]);
  q.normalize();
  BoundedFactor factor;
  factor.X.linear() = q.toRotationMatrix();
  // R(q) = M(q) / |q|^2 with quadratic M: exact in rationals for the stored doubles.
  const mpq_class w(wxyz[0]), x(wxyz[1]), y(wxyz[2]), z(wxyz[3]);
  const mpq_class n = w * w + x * x + y * y + z * z;
  const mpq_class M[3][3] = {
      {w * w + x * x - y * y - z * z, 2 * (x * y - w * z), 2 * (x * z + w * y)},
      {2 * (x * y + w * z), w * w - x * x + y * y - z * z, 2 * (y * z - w * x)},
      {2 * (x * z - w * y), 2 * (y * z + w * x), w * w - x * x - y * y + z * z}};
  mpq_class frobenius_squared = 0;
  for (int r = 0; r < 3; ++r) {
    for (int c = 0; c < 3; ++c) {
      const mpq_class difference = mpq_class(factor.X.linear()(r, c)) - M[r][c] / n;
      frobenius_squared += difference * difference;
    }
  }
  // |R^ - R(q^)|_2 <= |.|_F (decided exactly), plus |R(q^) - R(q)|_2 <= 4u for the decimals q.
  // proof: proofs/cell-geometry.md#lemma-quaternion-rotation
  const double stored_error = sqrt_upper(frobenius_squared);
  factor.delta = std::nextafter(stored_error + 4 * kUnitRoundoff * (1 + 4 * kUnitRoundoff),
                                std::numeric_limits<double>::infinity());
  return factor;
}

double scaling_error(double largest_l1, double scale) {
  if (scale == 1.0) return 0.0;
  // |fl(x * s^) - x s| <= |x s| (2u + u^2) per coordinate with s^ = s (1 + u): below 2^-51
  // relative; summed over three coordinates and doubled for strictness: 2^-50 |p|_1 * s.
  // proof: proofs/cell-geometry.md#lemma-geometry-error
  return std::ldexp(largest_l1 * std::abs(scale), -49);
}

double largest_l1_norm(const std::vector<Eigen::Vector3d>& points) {
  double largest = 0.0;
  for (const Eigen::Vector3d& p : points) largest = std::max(largest, p.cwiseAbs().sum());
  return largest;
}

BoundedProduct ScaledPose::product() const {
  BoundedProduct X;
  for (const BoundedFactor& factor : factors) X.multiply(factor);
  return X;
}

BoundedProduct ScaledPose::inverse_product() const {
  BoundedProduct X;
  for (const BoundedFactor& factor : inverse_factors) X.multiply(factor);
  return X;
}

ScaledPose scaled_pose(const CellPose& pose, double scale) {
  ScaledPose scaled;
  scaled.identity = pose.is_identity();
  const Eigen::Vector3d xyz = pose.xyz * scale;
  scaled.translation_error = scaling_error(pose.xyz.cwiseAbs().sum(), scale);
  if (pose.quaternion) {
    const BoundedFactor rotation = quaternion_rotation(*pose.quaternion);
    scaled.factors = {translation_factor(xyz), rotation};
    scaled.inverse_factors = {inverse_rotation(rotation), translation_factor(-xyz)};
    return scaled;
  }
  FrameStep step;
  step.kind = FrameStep::Kind::kOrigin;
  step.origin.xyz = xyz;
  step.origin.rpy = pose.rpy;
  scaled.factors = kinematics::step_factors(step);
  step.kind = FrameStep::Kind::kInverseOrigin;
  scaled.inverse_factors = kinematics::step_factors(step);
  return scaled;
}

}  // namespace grpvss::cell
