#include "grpvss/kinematics/rigid_product_bound.hpp"

#include <cmath>
#include <limits>

#include "grpvss/common/unit_roundoff.hpp"

namespace grpvss::kinematics {
namespace {

double translation_l1_norm(const Eigen::Vector3d& t) { return t.cwiseAbs().sum(); }  // >= Euclidean norm

}  // namespace

void BoundedProduct::multiply(const BoundedFactor& factor) {
  // Lemma 1 of proofs/fk-rounding.md, term by term (lambda_k = |t^_k|_1 >= |t^_k|_2).
  const double g = gamma(4);
  const double lambda = translation_l1_norm(factor.X.translation());
  const double rounding = g * (std::sqrt(3.0) * (1 + r_) * lambda + T_);
  const double e_next = e_ + r_ * lambda + factor.tau + rounding;
  const double T_next = (1 + r_) * lambda + T_ + rounding;
  // (1 + r)(1 + delta)(1 + 3g) - 1, expanded so that no step cancels against the 1.
  const double h = 3 * g;
  const double d = factor.delta;
  r_ = r_ + d + h + r_ * d + r_ * h + d * h + r_ * d * h;
  e_ = e_next;
  T_ = T_next;
  // The isometry product (R, t)(R', t') = (R R', R t' + t), the order the lemma assumes.
  X_ = X_ * factor.X;
}

double BoundedProduct::point_bound(double p_norm) const {
  return 2 * (r_ * p_norm + e_ + gamma(4) * (std::sqrt(3.0) * (1 + r_) * p_norm + T_));
}

}  // namespace grpvss::kinematics
