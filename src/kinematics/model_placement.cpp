#include "grpvss/kinematics/model_placement.hpp"

#include <stdexcept>

namespace grpvss::kinematics {

ModelAngles ModelPlacement::to_model(const Eigen::VectorXd& q) const {
  if (q.size() != 6) throw std::logic_error("ModelPlacement::to_model: q must have 6 values");
  ModelAngles theta{};
  for (int i = 0; i < 6; ++i) {
    const auto k = static_cast<std::size_t>(i);
    theta[k] = sign[k] * q[i] + offset[k];
  }
  return theta;
}

double ModelPlacement::to_chain(int i, double theta) const {
  const auto k = static_cast<std::size_t>(i);
  return sign[k] * (theta - offset[k]);  // sign is +-1, its own inverse
}

Eigen::Isometry3d ModelPlacement::flange_target(const Eigen::Isometry3d& X_WT) const {
  return X_WB.inverse() * X_WT * X_FT.inverse();
}

}  // namespace grpvss::kinematics
