#pragma once
/// \file
/// \brief Deterministic random joint configurations within limits, for property tests.

#include <random>

#include <Eigen/Core>

#include "grpvss/model/robot_model.hpp"

namespace grpvss::test {

/// Uniform within each joint's [minimum, maximum].
inline Eigen::VectorXd random_configuration(const RobotModel& model, std::mt19937_64& generator) {
  Eigen::VectorXd q(model.joint_count());
  for (int i = 0; i < model.joint_count(); ++i) {
    const Joint& joint = model.joints[static_cast<std::size_t>(i)];
    q[i] = std::uniform_real_distribution<double>(joint.minimum, joint.maximum)(generator);
  }
  return q;
}

}  // namespace grpvss::test
