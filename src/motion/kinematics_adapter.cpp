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

std::shared_ptr<const kinematics::InverseKinematics> select_ik(const kinematics::IkChoice& choice,
                                                              const RobotModel& robot,
                                                              const std::string& robot_file) {
  switch (choice.method) {
    case kinematics::IkMethod::kAuto: return kinematics::make_automatic_ik(robot);
    case kinematics::IkMethod::kNumeric: return kinematics::make_numeric_ik(robot);
    case kinematics::IkMethod::kIbm7545:
      if (!kinematics::is_ibm7545_structure(robot))
        throw InputError(robot_file, 0, "a robot of the IBM 7545 structure for --ik ibm7545");
      return kinematics::make_ibm7545_ik(robot);
    case kinematics::IkMethod::kOpw:
    case kinematics::IkMethod::kUr: {
      const bool opw = choice.method == kinematics::IkMethod::kOpw;
      kinematics::FamilyIk family = opw ? kinematics::make_opw_ik(robot) : kinematics::make_ur_ik(robot);
      if (!family.ik) {
        throw InputError(robot_file, 0,
                         std::string("a robot of the ") + (opw ? "OPW" : "UR") + " family for --ik " +
                             (opw ? "opw" : "ur"),
                         family.reason);
      }
      return std::move(family.ik);
    }
    case kinematics::IkMethod::kPlugin:
      return kinematics::load_ik_plugin(choice.plugin_path, robot);
  }
  throw std::logic_error("select_ik: unknown IK method");
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
