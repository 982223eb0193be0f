#pragma once
/// \file
/// \brief The inverse-kinematics interface (the thesis's user routine INVERS) and the default
/// choice: closed form for the IBM 7545 structure, damped least squares otherwise.

#include <memory>
#include <string>

#include <Eigen/Core>
#include <Eigen/Geometry>

#include "grpvss/model/robot_model.hpp"

namespace grpvss::kinematics {

enum class IkStatus { kSolved, kOutOfWorkspace };

struct IkSolution {
  IkStatus status = IkStatus::kOutOfWorkspace;
  Eigen::VectorXd q;  ///< joint values (rad / length) when solved, empty otherwise
};

/// \brief Solves X_WE(q) = X_WE_target for q within the joint limits; among several solutions
/// returns the one nearest (Euclidean in joint space) to q_near.
class InverseKinematics {
 public:
  virtual ~InverseKinematics();
  virtual IkSolution solve(const Eigen::Isometry3d& X_WE_target,
                           const Eigen::VectorXd& q_near) const = 0;
  virtual std::string name() const = 0;
};

/// \brief Which IK a run uses (the CLI's `--ik`, parsed by the app).
enum class IkMethod {
  kAuto,     ///< a closed form where the robot's family has one (IBM 7545, OPW, UR), else numeric
  kIbm7545,  ///< the IBM 7545 closed form (the robot must have its structure)
  kOpw,      ///< the OPW closed form (6-axis, spherical wrist; docs/ik.md)
  kUr,       ///< the UR closed form (docs/ik.md)
  kNumeric,  ///< damped least squares
  kPlugin,   ///< a user's solver through the C ABI (docs/ik-plugin.md)
};

struct IkChoice {
  IkMethod method = IkMethod::kAuto;
  std::string plugin_path;  ///< the shared object, for IkMethod::kPlugin
};

/// \brief Closed form when is_ibm7545_structure(model), numeric (default options) otherwise.
std::unique_ptr<InverseKinematics> make_default_ik(const RobotModel& model);

}  // namespace grpvss::kinematics
