#include "grpvss/kinematics/fk_error_bound.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>

#include "grpvss/common/unit_roundoff.hpp"

namespace grpvss::kinematics {
namespace {

// One factor T_k = (R_k, t_k) of the left-to-right product: bounds on the stored rotation's
// error (spectral norm), on the stored translation's error, and on the stored translation's norm.
struct Factor {
  double delta;
  double tau;
  double lambda;
};

double l1_norm(const Eigen::Vector3d& t) { return t.cwiseAbs().sum(); }  // >= Euclidean norm

// The chain's state bounds after k factors: r >= |R^_k - R_k|_2, e >= |t^_k - t_k|,
// T >= |t^_k|. proof: proofs/fk-rounding.md#fk-rounding (recursion (R), (E), (T)).
struct State {
  double r = 0.0;
  double e = 0.0;
  double T = 0.0;

  void multiply(const Factor& f) {
    const double g = gamma(4);
    const double rounding = g * (std::sqrt(3.0) * (1 + r) * f.lambda + T);
    const double e_next = e + r * f.lambda + f.tau + rounding;
    const double T_next = (1 + r) * f.lambda + T + rounding;
    // (1 + r)(1 + delta)(1 + 3g) - 1 expanded: only sums of non-negative terms, so evaluating
    // it in double loses no relative accuracy (no cancellation against the 1).
    const double h = 3 * g;
    r = r + f.delta + h + r * f.delta + r * h + f.delta * h + r * f.delta * h;
    e = e_next;
    T = T_next;
  }

  // Bound for p^_W = fl(R^ p_L + t^) with |p_L|_2 <= p_norm, (P).
  double point_bound(double p_norm) const {
    return r * p_norm + e + gamma(4) * (std::sqrt(3.0) * (1 + r) * p_norm + T);
  }
};

}  // namespace

double forward_kinematics_error_bound(const KinematicChain& chain, double max_abs_coordinate) {
  if (!(max_abs_coordinate >= 0) || !std::isfinite(max_abs_coordinate)) {
    throw std::invalid_argument("forward_kinematics_error_bound: max_abs_coordinate must be finite and >= 0");
  }
  // proof: proofs/fk-rounding.md#trig-rounding (sin/cos within 2 ulp -> entries within 4u)
  const double revolute_delta = std::sqrt(2.0) * 4 * kUnitRoundoff;
  const double p_norm = std::sqrt(3.0) * max_abs_coordinate;
  State state;
  double bound = state.point_bound(p_norm);  // link 0: X_W0 = identity
  for (const ChainJoint& joint : chain.joints) {
    state.multiply({joint.X_PJ_error.rotation, joint.X_PJ_error.translation,
                    l1_norm(joint.X_PJ.translation())});
    if (joint.type == JointType::kRevolute) {
      state.multiply({revolute_delta, 0.0, 0.0});
    } else {
      state.multiply({0.0, 0.0, std::max(std::abs(joint.minimum), std::abs(joint.maximum))});
    }
    state.multiply({joint.X_JC_error.rotation, joint.X_JC_error.translation,
                    l1_norm(joint.X_JC.translation())});
    bound = std::max(bound, state.point_bound(p_norm));
  }
  // Evaluating this recursion in double perturbs it by a relative O(100 u); doubling is a
  // generous cover for that. proof: proofs/fk-rounding.md#evaluating-the-bound
  return 2 * bound;
}

}  // namespace grpvss::kinematics
