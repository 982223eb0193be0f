#pragma once
/// \file
/// \brief Builds the motion stage's KinematicsAccess from the kinematics stage (FK of the DH
/// chain, an InverseKinematics), and picks the IK by the CLI's `--ik` name.

#include <memory>
#include <string>

#include "grpvss/kinematics/inverse_kinematics.hpp"
#include "grpvss/model/robot_model.hpp"
#include "grpvss/motion/kinematics_access.hpp"

namespace grpvss::motion {

/// \brief The IK named by `spec`: "auto" (kinematics::make_automatic_ik: the IBM 7545 closed
/// form, else OPW, else UR closed form, else numeric), "ibm7545", "opw", "ur", "numeric", or
/// "plugin:PATH.so" (docs/ik.md).
/// \throws grpvss::InputError for an unknown name (file "--ik", line 0), a robot that is not
/// of the IBM 7545 structure for "ibm7545" or not of the family for "opw" / "ur" (the robot
/// file, line 0, found: the reason), or a plug-in that cannot be loaded.
std::shared_ptr<const kinematics::InverseKinematics> select_ik(const std::string& spec,
                                                              const RobotModel& robot,
                                                              const std::string& robot_file);

/// \brief forward = end_effector_pose(make_chain(robot), q); inverse = ik->solve(X_WE, q_near)
/// (std::nullopt unless kSolved). The access keeps the chain and `ik` alive.
KinematicsAccess make_kinematics_access(const RobotModel& robot,
                                        std::shared_ptr<const kinematics::InverseKinematics> ik);

}  // namespace grpvss::motion
