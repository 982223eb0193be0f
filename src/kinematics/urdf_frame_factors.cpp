// The stored factors of URDF frame steps and their error bounds (proofs/urdf-frames.md).
#include <cmath>
#include <limits>
#include <stdexcept>

#include "grpvss/kinematics/urdf_chain.hpp"

#include "grpvss/common/unit_roundoff.hpp"

namespace grpvss::kinematics {
namespace {

// Rotation by `angle` about coordinate axis `axis` (0 x, 1 y, 2 z), built entry by entry from
// libm cos/sin. When the angle is the double nearest to a decimal (angle_is_rounded), the
// exact angle is within gamma_1 |angle| of it. Entries of magnitude <= 3u are stored as 0.
// proof: proofs/urdf-frames.md#planar-factors (Lemma 0 of fk-rounding.md with a rounded angle)
BoundedFactor planar_rotation(int axis, double angle, bool angle_is_rounded, double angle_error) {
  BoundedFactor factor;
  if (angle == 0.0 && angle_error == 0.0) return factor;  // exact identity
  const auto without_residue = [](double x) { return std::abs(x) <= 3 * kUnitRoundoff ? 0.0 : x; };
  const double c = without_residue(std::cos(angle));
  const double s = without_residue(std::sin(angle));
  const int i = (axis + 1) % 3;
  const int j = (axis + 2) % 3;
  Eigen::Matrix3d R = Eigen::Matrix3d::Identity();
  R(i, i) = c;
  R(i, j) = -s;
  R(j, i) = s;
  R(j, j) = c;
  factor.X.linear() = R;
  const double sigma = 4 * kUnitRoundoff + (angle_is_rounded ? gamma(1) * std::abs(angle) : 0.0);
  factor.delta = std::sqrt(2.0) * sigma + angle_error;
  return factor;
}

// Trans(t) where every nonzero component of t is the double nearest to a decimal:
// |t^ - t| <= gamma_1 |t^|_2 <= gamma_1 |t^|_1. proof: proofs/urdf-frames.md#decimal-inputs
BoundedFactor decimal_translation(const Eigen::Vector3d& t) {
  BoundedFactor factor;
  factor.X.translation() = t;
  factor.tau = gamma(1) * t.cwiseAbs().sum();
  return factor;
}

BoundedFactor linear_factor(const Eigen::Matrix3d& R, double error) {
  BoundedFactor factor;
  factor.X.linear() = R;
  factor.delta = error;
  return factor;
}

void push_unless_identity(std::vector<BoundedFactor>& factors, const BoundedFactor& factor) {
  if (factor.X.matrix() == Eigen::Matrix4d::Identity() && factor.delta == 0.0 && factor.tau == 0.0) {
    return;
  }
  factors.push_back(factor);
}

// Origin: Trans(xyz) Rot_z(yaw) Rot_y(pitch) Rot_x(roll).
void origin_factors(const UrdfOrigin& origin, std::vector<BoundedFactor>& factors) {
  push_unless_identity(factors, decimal_translation(origin.xyz));
  push_unless_identity(factors, planar_rotation(2, origin.rpy.z(), true, 0.0));
  push_unless_identity(factors, planar_rotation(1, origin.rpy.y(), true, 0.0));
  push_unless_identity(factors, planar_rotation(0, origin.rpy.x(), true, 0.0));
}

// Origin^-1: Rot_x(-roll) Rot_y(-pitch) Rot_z(-yaw) Trans(-xyz) (negation is exact).
void inverse_origin_factors(const UrdfOrigin& origin, std::vector<BoundedFactor>& factors) {
  push_unless_identity(factors, planar_rotation(0, -origin.rpy.x(), true, 0.0));
  push_unless_identity(factors, planar_rotation(1, -origin.rpy.y(), true, 0.0));
  push_unless_identity(factors, planar_rotation(2, -origin.rpy.z(), true, 0.0));
  push_unless_identity(factors, decimal_translation(-origin.xyz));
}

// Rot(axis, v) = R_a Rot_z(v) R_a^T; Trans(v axis/|axis|) = R_a Trans_z(v) R_a^T.
void motion_factors(const FrameStep& step, std::vector<BoundedFactor>& factors) {
  const AxisFrame frame = axis_frame(step.axis);
  push_unless_identity(factors, linear_factor(frame.R, frame.error));
  if (step.kind == FrameStep::Kind::kRotation) {
    push_unless_identity(factors, planar_rotation(2, step.value, false, step.value_error));
  } else {
    BoundedFactor slide;
    slide.X.translation() = Eigen::Vector3d(0.0, 0.0, step.value);
    slide.tau = step.value_error;
    push_unless_identity(factors, slide);
  }
  push_unless_identity(factors, linear_factor(frame.R.transpose(), frame.error));
}

// Unit vector along `axis`: scaled by a power of two so its largest component lies in [1, 2),
// then divided by its norm. proof: proofs/urdf-frames.md#axis-frame (nu)
Eigen::Vector3d unit_axis(const Eigen::Vector3d& axis) {
  const int exponent = std::ilogb(axis.cwiseAbs().maxCoeff());
  Eigen::Vector3d x;
  for (int i = 0; i < 3; ++i) x[i] = std::ldexp(axis[i], -exponent);
  const double norm = std::sqrt(x[0] * x[0] + x[1] * x[1] + x[2] * x[2]);
  return x / norm;
}

// Duff et al., "Building an orthonormal basis, revisited" (JCGT 2017): columns b1, b2, n with
// b1 x b2 = n for a unit n; exact for n = +-e_i.
Eigen::Matrix3d basis_with_z(const Eigen::Vector3d& n) {
  const double sign = std::copysign(1.0, n.z());
  const double a = -1.0 / (sign + n.z());
  const double b = n.x() * n.y() * a;
  Eigen::Matrix3d R;
  R.col(0) = Eigen::Vector3d(1.0 + sign * n.x() * n.x() * a, sign * b, -sign * n.x());
  R.col(1) = Eigen::Vector3d(b, sign + n.y() * n.y() * a, -n.y());
  R.col(2) = n;
  return R;
}

// eta >= |R^T R - I|_2, from the computed residual and Higham's inner-product bound, doubled
// for its own evaluation. proof: proofs/urdf-frames.md#axis-frame
double orthogonality_defect(const Eigen::Matrix3d& R) {
  const Eigen::Matrix3d residual = R.transpose() * R - Eigen::Matrix3d::Identity();
  const Eigen::Matrix3d products = R.cwiseAbs().transpose() * R.cwiseAbs();
  double sum = 0.0;
  for (int i = 0; i < 3; ++i) {
    for (int j = 0; j < 3; ++j) {
      const double entry =
          std::abs(residual(i, j)) + gamma(4) * (products(i, j) + (i == j ? 1.0 : 0.0));
      sum += entry * entry;
    }
  }
  return 2 * std::sqrt(sum);
}

}  // namespace

AxisFrame axis_frame(const Eigen::Vector3d& axis) {
  if (!axis.allFinite() || axis == Eigen::Vector3d::Zero()) {
    throw std::invalid_argument("axis_frame: the axis must be finite and nonzero");
  }
  AxisFrame frame;
  const int zeros = (axis.x() == 0.0) + (axis.y() == 0.0) + (axis.z() == 0.0);
  if (zeros == 2) {
    // n = +-e_i exactly, whatever the decimal's rounding; the basis is exact.
    Eigen::Vector3d n = Eigen::Vector3d::Zero();
    for (int i = 0; i < 3; ++i) n[i] = axis[i] == 0.0 ? 0.0 : std::copysign(1.0, axis[i]);
    frame.R = basis_with_z(n);
    return frame;
  }
  frame.R = basis_with_z(unit_axis(axis));
  const double eta = orthogonality_defect(frame.R);
  if (!(eta <= 0.5) || !(frame.R.determinant() > 0)) {
    throw std::logic_error("axis_frame: the basis is not a rotation");  // unreachable
  }
  // nu: 2u for the decimals' rounding, gamma_12 for the normalisation, 2^-1070 for underflow.
  const double nu = 2 * kUnitRoundoff + gamma(12) + std::ldexp(1.0, -1070);
  frame.error = 2 * eta + nu;
  return frame;
}

std::vector<BoundedFactor> step_factors(const FrameStep& step) {
  std::vector<BoundedFactor> factors;
  switch (step.kind) {
    case FrameStep::Kind::kOrigin:
      origin_factors(step.origin, factors);
      break;
    case FrameStep::Kind::kInverseOrigin:
      inverse_origin_factors(step.origin, factors);
      break;
    case FrameStep::Kind::kRotation:
    case FrameStep::Kind::kTranslation:
      motion_factors(step, factors);
      break;
  }
  return factors;
}

BoundedProduct compose_frame_path(const FramePath& path) {
  BoundedProduct product;
  for (const FrameStep& step : path) {
    for (const BoundedFactor& factor : step_factors(step)) product.multiply(factor);
  }
  return product;
}

}  // namespace grpvss::kinematics
