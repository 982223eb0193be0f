#pragma once
/// \file
/// \brief Closed-form IK of the IBM 7545 SCARA structure (thesis Appendix A.1.1.1).
///
/// Structure: joints R, R, P, R with alpha = 0, 180 deg, 0, 0 and a_3 = a_4 = 0. The tool z
/// axis is always (0,0,-1); reachable poses are position + yaw, with
/// yaw = theta_1 + theta_2 - theta_3(offset) - theta_4.

#include <memory>

#include "grpvss/kinematics/inverse_kinematics.hpp"
#include "grpvss/model/robot_model.hpp"

namespace grpvss::kinematics {

/// \brief True when the model has the IBM 7545 kinematic structure (angles within 1e-9 rad,
/// lengths within 1e-12).
bool is_ibm7545_structure(const RobotModel& model);

/// \brief Closed form: both elbow branches, revolute joints shifted by multiples of 2 pi to fit
/// their limits, nearest valid solution to q_near; kOutOfWorkspace when the target's tool z is
/// not (0,0,-1) within 1e-9 or no branch fits the limits.
/// Throws std::invalid_argument when !is_ibm7545_structure(model).
std::unique_ptr<InverseKinematics> make_ibm7545_ik(const RobotModel& model);

}  // namespace grpvss::kinematics
