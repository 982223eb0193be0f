#include "turn_variants.hpp"

#include <algorithm>
#include <cmath>

#include "elementary_rotations.hpp"

namespace grpvss::kinematics::detail {
namespace {

// value + 2 pi k within [minimum, maximum] (slack admitted, clamped), ascending.
std::vector<double> turns_within(double value, double minimum, double maximum) {
  std::vector<double> turns;
  const double k_low = std::ceil((minimum - kLimitSlack - value) / (2 * kPi));
  const double k_high = std::floor((maximum + kLimitSlack - value) / (2 * kPi));
  for (double k = k_low; k <= k_high; k += 1.0) {
    turns.push_back(std::clamp(value + 2 * kPi * k, minimum, maximum));
  }
  return turns;
}

}  // namespace

std::vector<Eigen::VectorXd> turn_variants(const KinematicChain& chain, const Eigen::VectorXd& q) {
  std::vector<Eigen::VectorXd> variants{q};
  for (int i = 0; i < q.size(); ++i) {
    const ChainJoint& joint = chain.joints[static_cast<std::size_t>(i)];
    const std::vector<double> turns = turns_within(q[i], joint.minimum, joint.maximum);
    std::vector<Eigen::VectorXd> widened;
    widened.reserve(variants.size() * turns.size());
    for (const Eigen::VectorXd& variant : variants) {
      for (double value : turns) {
        widened.push_back(variant);
        widened.back()[i] = value;
      }
    }
    variants = std::move(widened);
  }
  return variants;
}

bool nearest_turns(const KinematicChain& chain, const Eigen::Matrix<double, 6, 1>& q,
                   const Eigen::VectorXd& q_near, Eigen::Matrix<double, 6, 1>& out) {
  for (int i = 0; i < 6; ++i) {
    const ChainJoint& joint = chain.joints[static_cast<std::size_t>(i)];
    const double k_low = std::ceil((joint.minimum - kLimitSlack - q[i]) / (2 * kPi));
    const double k_high = std::floor((joint.maximum + kLimitSlack - q[i]) / (2 * kPi));
    if (k_low > k_high) return false;
    // |q + 2 pi k - q_near| is convex in k: the admissible k nearest the unconstrained best.
    const double k = std::clamp(std::round((q_near[i] - q[i]) / (2 * kPi)), k_low, k_high);
    out[i] = std::clamp(q[i] + 2 * kPi * k, joint.minimum, joint.maximum);
  }
  return true;
}

}  // namespace grpvss::kinematics::detail
