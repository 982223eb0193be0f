#include "grpvss/kinematics/jacobian.hpp"

#include <stdexcept>
#include <string>

namespace grpvss::kinematics {
namespace {

void check_link(const KinematicChain& chain, const Workspace& ws, int link) {
  if (link < 0 || link > chain.joint_count() ||
      ws.X_WL.size() != chain.joints.size() + 1 || ws.X_WJ.size() != chain.joints.size()) {
    throw std::logic_error("jacobian: link " + std::to_string(link) + " out of 0.." +
                           std::to_string(chain.joint_count()) + " or workspace mismatch");
  }
}

}  // namespace

Eigen::Matrix<double, 3, Eigen::Dynamic> point_jacobian(const KinematicChain& chain,
                                                        const Workspace& ws, int link,
                                                        const Eigen::Vector3d& p_L) {
  check_link(chain, ws, link);
  Eigen::Matrix<double, 3, Eigen::Dynamic> J =
      Eigen::Matrix<double, 3, Eigen::Dynamic>::Zero(3, chain.joint_count());
  const Eigen::Vector3d p_W = ws.X_WL[static_cast<std::size_t>(link)] * p_L;
  // Joint j (1-based) moves frames j..N, so only joints 1..link move a point of link `link`.
  for (int j = 0; j < link; ++j) {
    const Eigen::Isometry3d& X_WJ = ws.X_WJ[static_cast<std::size_t>(j)];
    const Eigen::Vector3d z_W = X_WJ.linear().col(2);
    if (chain.joints[static_cast<std::size_t>(j)].type == JointType::kRevolute) {
      J.col(j) = z_W.cross(p_W - X_WJ.translation());
    } else {
      J.col(j) = z_W;
    }
  }
  return J;
}

Eigen::Matrix<double, 6, Eigen::Dynamic> end_effector_jacobian(const KinematicChain& chain,
                                                               const Workspace& ws) {
  const int n = chain.joint_count();
  check_link(chain, ws, n);
  Eigen::Matrix<double, 6, Eigen::Dynamic> J =
      Eigen::Matrix<double, 6, Eigen::Dynamic>::Zero(6, n);
  const Eigen::Vector3d p_W = ws.X_WL[static_cast<std::size_t>(n)].translation();
  for (int j = 0; j < n; ++j) {
    const Eigen::Isometry3d& X_WJ = ws.X_WJ[static_cast<std::size_t>(j)];
    const Eigen::Vector3d z_W = X_WJ.linear().col(2);
    if (chain.joints[static_cast<std::size_t>(j)].type == JointType::kRevolute) {
      J.col(j).head<3>() = z_W.cross(p_W - X_WJ.translation());
      J.col(j).tail<3>() = z_W;
    } else {
      J.col(j).head<3>() = z_W;
    }
  }
  return J;
}

}  // namespace grpvss::kinematics
