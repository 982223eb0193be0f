#include "grpvss/motion/kinematics_adapter.hpp"

#include <stdexcept>

#include "grpvss/common/input_error.hpp"
#include "grpvss/kinematics/automatic_ik.hpp"
#include "grpvss/kinematics/forward_kinematics.hpp"
#include "grpvss/kinematics/ibm7545_ik.hpp"
#include "grpvss/kinematics/ik_plugin_loader.hpp"
#include "grpvss/kinematics/kinematic_chain.hpp"
#include "grpvss/kinematics/numeric_ik.hpp"

namespace grpvss::motion {

std::shared_ptr<const kinematics::InverseKinematics> select_ik(const std::string& spec,
                                                              const RobotModel& robot,
                                                              const std::string& robot_file) {
  const std::string plugin_prefix = "plugin:";
  if (spec == "auto") return kinematics::make_automatic_ik(robot);
  if (spec == "numeric") return kinematics::make_numeric_ik(robot);
  if (spec == "ibm7545") {
    if (!kinematics::is_ibm7545_structure(robot))
      throw InputError(robot_file, 0, "a robot of the IBM 7545 structure for --ik ibm7545");
    return kinematics::make_ibm7545_ik(robot);
  }
  if (spec == "opw" || spec == "ur") {
    kinematics::IkChoice choice =
        spec == "opw" ? kinematics::make_opw_ik(robot) : kinematics::make_ur_ik(robot);
    if (!choice.ik) {
      throw InputError(robot_file, 0, "a robot of the " + std::string(spec == "opw" ? "OPW" : "UR") +
                                          " family for --ik " + spec, choice.reason);
    }
    return std::move(choice.ik);
  }
  if (spec.rfind(plugin_prefix, 0) == 0 && spec.size() > plugin_prefix.size())
    return kinematics::load_ik_plugin(spec.substr(plugin_prefix.size()), robot);
  throw InputError("--ik", 0, "auto, ibm7545, opw, ur, numeric or plugin:PATH.so", "'" + spec + "'");
}

KinematicsAccess make_kinematics_access(const RobotModel& robot,
                                        std::shared_ptr<const kinematics::InverseKinematics> ik) {
  auto chain = std::make_shared<const kinematics::KinematicChain>(kinematics::make_chain(robot));
  KinematicsAccess access;
  access.forward = [chain](const Eigen::VectorXd& q) {
    return kinematics::end_effector_pose(*chain, q);
  };
  access.inverse = [ik](const Eigen::Isometry3d& X_WE,
                        const Eigen::VectorXd& q_near) -> std::optional<Eigen::VectorXd> {
    kinematics::IkSolution solution = ik->solve(X_WE, q_near);
    if (solution.status != kinematics::IkStatus::kSolved) return std::nullopt;
    return std::move(solution.q);
  };
  return access;
}

}  // namespace grpvss::motion
