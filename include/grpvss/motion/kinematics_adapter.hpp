#pragma once
/// \file
/// \brief Builds the motion stage's KinematicsAccess from the kinematics stage (FK of the DH
/// chain, an InverseKinematics), and builds the IK a run chose.

#include <memory>
#include <string>

#include "grpvss/kinematics/inverse_kinematics.hpp"
#include "grpvss/model/robot_model.hpp"
#include "grpvss/motion/kinematics_access.hpp"

namespace grpvss::motion {

/// \brief The IK `choice` names, for `robot` (docs/ik.md): kAuto is
/// kinematics::make_automatic_ik (the IBM 7545 closed form, else OPW, else UR closed form, else
/// numeric).
/// \throws grpvss::InputError for a robot that is not of the IBM 7545 structure for kIbm7545 or
/// not of the family for kOpw / kUr (the robot file, line 0, found: the reason), or a plug-in
/// that cannot be loaded.
std::shared_ptr<const kinematics::InverseKinematics> select_ik(const kinematics::IkChoice& choice,
                                                              const RobotModel& robot,
                                                              const std::string& robot_file);

/// \brief forward = end_effector_pose(make_chain(robot), q); inverse = ik->solve(X_WE, q_near)
/// (std::nullopt unless kSolved). The access keeps the chain and `ik` alive.
KinematicsAccess make_kinematics_access(const RobotModel& robot,
                                        std::shared_ptr<const kinematics::InverseKinematics> ik);

}  // namespace grpvss::motion
