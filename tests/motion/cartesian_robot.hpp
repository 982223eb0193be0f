#pragma once
// A reference robot for motion tests whose IK is trivially exact: three prismatic joints
// x, y, z along the world axes and a revolute yaw about z, X_WE = Trans(x, y, z) Rot_z(yaw).
// Its workspace is the box of its joint limits, so reachability is known in closed form.

#include <cmath>
#include <optional>

#include <Eigen/Geometry>

#include "grpvss/model/robot_model.hpp"
#include "grpvss/motion/kinematics_access.hpp"

namespace grpvss::motion::testing {

inline RobotModel cartesian_robot(double box = 10.0) {
  RobotModel robot;
  robot.name = "cartesian";
  for (int j = 0; j < 4; ++j) {
    Joint joint;
    joint.type = j < 3 ? JointType::kPrismatic : JointType::kRevolute;
    joint.minimum = j < 3 ? -box : -M_PI;
    joint.maximum = j < 3 ? box : M_PI;
    joint.acceleration = 1.0 + 0.5 * j;
    joint.deceleration = 0.8 + 0.3 * j;
    robot.joints.push_back(joint);
  }
  robot.links.resize(5);
  return robot;
}

inline KinematicsAccess cartesian_kinematics() {
  KinematicsAccess access;
  access.forward = [](const Eigen::VectorXd& q) {
    Eigen::Isometry3d X_WE = Eigen::Isometry3d::Identity();
    X_WE.translation() = q.head<3>();
    X_WE.linear() = Eigen::AngleAxisd(q[3], Eigen::Vector3d::UnitZ()).toRotationMatrix();
    return X_WE;
  };
  // Out of workspace when the tool z axis is not vertical; the yaw nearest q_near[3] among
  // yaw + 2 pi k (the limits decide afterwards).
  access.inverse = [](const Eigen::Isometry3d& X_WE,
                      const Eigen::VectorXd& q_near) -> std::optional<Eigen::VectorXd> {
    const Eigen::Matrix3d R = X_WE.linear();
    if (std::abs(R(2, 2) - 1.0) > 1e-9) return std::nullopt;
    double yaw = std::atan2(R(1, 0), R(0, 0));
    yaw += 2 * M_PI * std::round((q_near[3] - yaw) / (2 * M_PI));
    Eigen::VectorXd q(4);
    q << X_WE.translation(), yaw;
    return q;
  };
  return access;
}

}  // namespace grpvss::motion::testing
