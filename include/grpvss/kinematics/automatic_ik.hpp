#pragma once
/// \file
/// \brief Choosing the IK for a robot file's model by its kinematic family: the closed forms
/// (IBM 7545 structure, OPW, UR) where they apply, damped least squares otherwise.

#include <memory>
#include <string>

#include "grpvss/kinematics/inverse_kinematics.hpp"
#include "grpvss/model/robot_model.hpp"

namespace grpvss::kinematics {

/// \brief A solver, or none and the reason (why the robot is not of the family).
struct FamilyIk {
  std::unique_ptr<InverseKinematics> ik;
  std::string reason;
};

/// \brief The OPW closed form (AnalyticIk) when make_chain(model) is of the OPW family.
FamilyIk make_opw_ik(const RobotModel& model);

/// \brief The UR closed form (AnalyticIk) when make_chain(model) is of the UR family.
FamilyIk make_ur_ik(const RobotModel& model);

/// \brief The IBM 7545 closed form for that structure (exactly make_default_ik's choice), else
/// the OPW closed form, else the UR closed form, else make_default_ik (damped least squares).
std::unique_ptr<InverseKinematics> make_automatic_ik(const RobotModel& model);

}  // namespace grpvss::kinematics
