#include "grpvss/kinematics/inverse_kinematics.hpp"

#include "grpvss/kinematics/ibm7545_ik.hpp"
#include "grpvss/kinematics/numeric_ik.hpp"

namespace grpvss::kinematics {

InverseKinematics::~InverseKinematics() = default;

std::unique_ptr<InverseKinematics> make_default_ik(const RobotModel& model) {
  if (is_ibm7545_structure(model)) return make_ibm7545_ik(model);
  return make_numeric_ik(model);
}

}  // namespace grpvss::kinematics
