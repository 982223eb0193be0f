#include "grpvss/kinematics/automatic_ik.hpp"

#include "grpvss/kinematics/analytic_ik.hpp"
#include "grpvss/kinematics/family_recognition.hpp"
#include "grpvss/kinematics/ibm7545_ik.hpp"

namespace grpvss::kinematics {

FamilyIk make_opw_ik(const RobotModel& model) {
  KinematicChain chain = make_chain(model);
  Recognition<OpwChainModel> recognition = recognise_opw(chain);
  if (!recognition.model) return {nullptr, recognition.reason};
  return {std::make_unique<AnalyticIk>(std::move(chain), *recognition.model), ""};
}

FamilyIk make_ur_ik(const RobotModel& model) {
  KinematicChain chain = make_chain(model);
  Recognition<UrChainModel> recognition = recognise_ur(chain);
  if (!recognition.model) return {nullptr, recognition.reason};
  return {std::make_unique<AnalyticIk>(std::move(chain), *recognition.model), ""};
}

std::unique_ptr<InverseKinematics> make_automatic_ik(const RobotModel& model) {
  if (is_ibm7545_structure(model)) return make_ibm7545_ik(model);
  if (FamilyIk opw = make_opw_ik(model); opw.ik) return std::move(opw.ik);
  if (FamilyIk ur = make_ur_ik(model); ur.ik) return std::move(ur.ik);
  return make_default_ik(model);
}

}  // namespace grpvss::kinematics
