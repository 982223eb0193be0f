#pragma once
/// \file
/// \brief What the motion stage needs from kinematics, as two functions, so that motion can
/// be tested against simple reference robots and does not depend on how IK is provided
/// (motion/kinematics_adapter.hpp builds it from the chain and the chosen IK).

#include <functional>
#include <optional>

#include <Eigen/Core>
#include <Eigen/Geometry>

#include "grpvss/model/robot_model.hpp"

namespace grpvss::motion {

struct KinematicsAccess {
  /// X_WE(q): pose of the end-effector frame E in the world W.
  std::function<Eigen::Isometry3d(const Eigen::VectorXd& q)> forward;
  /// Joints reaching X_WE, the solution nearest q_near; std::nullopt when out of workspace.
  std::function<std::optional<Eigen::VectorXd>(const Eigen::Isometry3d& X_WE,
                                               const Eigen::VectorXd& q_near)>
      inverse;
};

/// Index of the first joint of q outside [minimum, maximum] (tolerance `slack`), or -1.
int first_joint_outside_limits(const RobotModel& robot, const Eigen::VectorXd& q,
                               double slack = 1e-9);

}  // namespace grpvss::motion
