#pragma once
/// \file
/// \brief Closed-form IK of a chain recognised as OPW or UR (family_recognition.hpp): every
/// solution with its configuration, or the one nearest given joints.
///
/// Solutions are in the chain's joint values q (rad). Each closed-form branch (up to 8) is
/// mapped through the placement (theta = s q + o), refined by Newton steps on the chain itself
/// when the chain is only approximately of the family (fitted model's FK deviation > 1e-13, e.g.
/// a URDF whose angles are rounded to 9 digits), and widened to every 2 pi turn of each joint
/// that lies within the joint limits (a slack of 1e-10 rad is admitted and clamped onto the
/// limit).

#include <array>
#include <memory>
#include <string>
#include <variant>
#include <vector>

#include <Eigen/Core>
#include <Eigen/Geometry>

#include "grpvss/kinematics/arm_configuration.hpp"
#include "grpvss/kinematics/family_recognition.hpp"
#include "grpvss/kinematics/inverse_kinematics.hpp"
#include "grpvss/kinematics/kinematic_chain.hpp"

namespace grpvss::kinematics {

/// \brief One IK solution: joint values and the configuration they are in.
struct ConfiguredSolution {
  Eigen::VectorXd q;
  ArmConfiguration configuration;
};

class AnalyticIk final : public InverseKinematics {
 public:
  /// The chain's own limits apply; `model` must come from recognise_opw / recognise_ur of
  /// this chain (its X_ET is the tool whose pose the solver takes).
  AnalyticIk(KinematicChain chain, OpwChainModel model);
  AnalyticIk(KinematicChain chain, UrChainModel model);

  /// \brief Every solution for the tool pose X_WT (= X_WE X_ET) within the joint limits: each
  /// branch with every admissible turn of each joint, no two equal. At a singular pose the free
  /// angle is the one q = 0 has (OPW: theta_1 on axis 1, theta_4 at theta_5 = 0; UR: theta_6).
  /// Empty when the pose is out of reach.
  std::vector<ConfiguredSolution> solutions(const Eigen::Isometry3d& X_WT) const;
  /// \brief As above; at a singular pose the free angle is taken from q_near.
  std::vector<ConfiguredSolution> solutions(const Eigen::Isometry3d& X_WT,
                                            const Eigen::VectorXd& q_near) const;

  /// \brief The configuration of joint values q (6 values).
  ArmConfiguration configuration_of(const Eigen::VectorXd& q) const;

  /// \brief The solution nearest to q_near (Euclidean in joint space) for the tool pose X_WT
  /// (the chain's end-effector pose when X_ET is the identity, as for robot files).
  IkSolution solve(const Eigen::Isometry3d& X_WT, const Eigen::VectorXd& q_near) const override;

  /// "OPW closed form" or "UR closed form".
  std::string name() const override;

  const KinematicChain& chain() const { return chain_; }
  /// The OPW model, or nullptr for a UR solver.
  const OpwChainModel* opw() const { return std::get_if<OpwChainModel>(&model_); }
  /// The UR model, or nullptr for an OPW solver.
  const UrChainModel* ur() const { return std::get_if<UrChainModel>(&model_); }

 private:
  const ModelPlacement& placement() const;
  const Eigen::Isometry3d& X_ET() const;
  using Vector6d = Eigen::Matrix<double, 6, 1>;
  // One chain-space q per valid closed-form branch, not yet fitted to the limits (fixed
  // size: solve() allocates nothing on the exact-chain path).
  struct Branches {
    std::array<Vector6d, 8> q;
    int count = 0;
  };
  Branches branch_solutions(const Eigen::Isometry3d& X_WT, const Eigen::VectorXd& q_free) const;
  void refine(const Eigen::Isometry3d& X_WT, Vector6d& q) const;

  KinematicChain chain_;
  std::variant<OpwChainModel, UrChainModel> model_;
  double length_scale_ = 1.0;
  bool refine_ = false;
};

}  // namespace grpvss::kinematics
