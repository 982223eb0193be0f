#pragma once
/// \file
/// \brief How a parametric model (OPW, UR) sits in a KinematicChain: where its base is, how the
/// chain's joint values map onto the model's angles, and where the chain's tool is on the
/// model's flange. For every q:
/// \f[ X_{WE}(q)\,X_{ET} = X_{WB}\; X_{BF}(\theta(q))\; X_{FT},
///     \qquad \theta_i = s_i\,q_i + o_i, \f]
/// with signs s_i = +1 or -1 and offsets o_i (rad). (opw_kinematics' own parameter files use
/// theta = s q - o: their offsets have the opposite sign.)

#include <array>

#include <Eigen/Core>
#include <Eigen/Geometry>

#include "grpvss/kinematics/opw_kinematics.hpp"

namespace grpvss::kinematics {

struct ModelPlacement {
  Eigen::Isometry3d X_WB = Eigen::Isometry3d::Identity();  ///< model base B in the world W
  std::array<double, 6> sign{1, 1, 1, 1, 1, 1};             ///< s_i, +1 or -1
  std::array<double, 6> offset{0, 0, 0, 0, 0, 0};           ///< o_i (rad)
  Eigen::Isometry3d X_FT = Eigen::Isometry3d::Identity();  ///< tool T in the model flange F

  /// theta_i = s_i q_i + o_i; q must have 6 values.
  ModelAngles to_model(const Eigen::VectorXd& q) const;
  /// q_i = s_i (theta_i - o_i), for joint index i = 0..5.
  double to_chain(int i, double theta) const;
  /// The flange pose X_BF that puts the tool at X_WT.
  Eigen::Isometry3d flange_target(const Eigen::Isometry3d& X_WT) const;
};

}  // namespace grpvss::kinematics
